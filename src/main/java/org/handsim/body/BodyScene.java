package org.handsim.body;

import java.util.ArrayList;
import java.util.List;
import org.handsim.collision.KdopTree;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * The free object among static supports, under gravity and a disturbance: the body-level
 * simulation (DESIGN.md decision 7) without the hand. Each {@link #step} finds the contacts
 * with every support by proximity ({@link ProximityContacts}) and advances the object
 * ({@link BodyStepper}).
 *
 * <p>Not thread-safe; allocation-free per step once grown.
 */
public final class BodyScene {
    /** k of the k-DOP trees (the simulator's default). */
    public static final int K = 18;

    private final TriangleMesh objectMesh;
    private final KdopTree objectTree;
    private final MeshTopology objectTopology;
    private final FreeBody body;
    private final BodyStepper stepper;
    private final BodyContacts contacts = new BodyContacts();
    private final List<double[]> supportPoses = new ArrayList<>(), supportBase = new ArrayList<>();
    private final List<ProximityContacts> supportQueries = new ArrayList<>();
    private final double[] gravity = {0, 0, -9.80665};
    private final double[] force = new double[3], torque = new double[3], disturbForce = new double[3], disturbTorque = new double[3];
    private final double[] objectPose = new double[12];
    // axis, origin, inertia, torque, worm (1/0), release angle, turned since set, turned since added, where the worm holds it
    private final List<double[]> joints = new ArrayList<>();
    private final double[] turn = new double[9], moved = new double[12];
    private final List<int[]> supportJoints = new ArrayList<>();
    private final double[] axis = new double[3], origin = new double[3];
    private double friction = 0.5, margin = ProximityContacts.DEFAULT_MARGIN, depth = 5 * ProximityContacts.DEFAULT_MARGIN;
    private double time;
    private final double reach;

    /** The object with its mesh at {@code worldFromMesh}, at rest. */
    public BodyScene(TriangleMesh objectMesh, MassProperties props, RigidTransform worldFromMesh) {
        this(KdopTree.build(objectMesh, K), new MeshTopology(objectMesh), props, worldFromMesh);
    }

    /**
     * As {@link #BodyScene(TriangleMesh, MassProperties, RigidTransform)} with the object's tree
     * (any k; the supports' of the same k) and topology built already, shared read-only (a
     * caller that makes many scenes of one object builds them once).
     */
    public BodyScene(KdopTree objectTree, MeshTopology objectTopology, MassProperties props, RigidTransform worldFromMesh) {
        this.objectMesh = objectTree.mesh();
        this.objectTree = objectTree;
        this.objectTopology = objectTopology;
        this.body = new FreeBody(props, worldFromMesh);
        this.stepper = new BodyStepper(body);
        this.reach = Tunnelling.reach(objectMesh, props);
        stepper.watchTunnelling(margin, reach);
    }

    /** Adds a static support: {@code mesh} placed by {@code pose}; returns its id (0, 1, …). */
    public int addSupport(TriangleMesh mesh, RigidTransform pose) {
        return addSupport(KdopTree.build(mesh, K), new MeshTopology(mesh), pose);
    }

    /** Adds a static support whose tree (the object's k) and topology are built already, shared read-only; returns its id. */
    public int addSupport(KdopTree tree, MeshTopology topology, RigidTransform pose) {
        supportPoses.add(pose.toArray());
        supportBase.add(pose.toArray());
        supportQueries.add(new ProximityContacts(tree, topology, objectTree, objectTopology));
        return supportQueries.size() - 1;
    }

    /**
     * Adds a joint that presses supports on the object (a finger joint of a locked grasp): each
     * step it is a follower of {@link BodyStepper#addFollower(double[], double[], double, double, boolean)}
     * — at rest at the step's start, torque τ closing, held against opening by its worm or not —
     * and the contacts of the supports it {@link #moves} depend on it. The supports it moves turn
     * with it: each step they are placed rotated about its axis (through its origin, as added)
     * by the angle it has turned since it was added, so a link that closed into a gap is there
     * the next step and the gap is gone. (Were they left where they were, the joint would close
     * the same gap step after step — its turned angle, and with it the release of its preload,
     * growing while nothing moves — and the freed object, its squeeze let go, would drift out
     * with the momentum the pressing gave it.)
     *
     * @return its index
     */
    public int addJoint(double[] axis, double[] origin, double inertia, double torqueNm, boolean wormHeld) {
        return addJoint(axis, origin, inertia, torqueNm, wormHeld, Double.POSITIVE_INFINITY);
    }

    /**
     * {@link #addJoint(double[], double[], double, double, boolean)} whose torque is an elastic
     * preload: it falls linearly from τ to 0 as the joint turns closing by {@code releaseRad}
     * (τ·(1 − θ/θ_r), θ the angle it has turned since it was added), as a link held by its worm
     * presses with the energy its drive train and the contacts stored, which a tiny motion
     * releases; infinity: τ throughout.
     */
    public int addJoint(double[] axis, double[] origin, double inertia, double torqueNm, boolean wormHeld, double releaseRad) {
        if (!(releaseRad > 0) || !(torqueNm >= 0) || !Double.isFinite(torqueNm)) {
            throw new IllegalArgumentException("a joint's torque must be finite and >= 0 and its release angle > 0, got " + torqueNm
                + " N*m over " + releaseRad + " rad");
        }
        joints.add(new double[] {axis[0], axis[1], axis[2], origin[0], origin[1], origin[2], inertia, torqueNm, wormHeld ? 1 : 0,
            releaseRad, 0, 0, 0});
        return joints.size() - 1;
    }

    /**
     * Changes joint {@code joint}'s press and hold from the next step on: torque τ (N·m, ≥ 0),
     * held by its worm or not, its preload let go over {@code releaseRad} (infinity: τ
     * throughout) from here (its turned angle starts again at 0) — as a clutch that slips once
     * its torque passes its threshold, transmits that torque while it slips, and grips again
     * where it stops.
     */
    public void setJoint(int joint, double torqueNm, boolean wormHeld, double releaseRad) {
        if (!(releaseRad > 0) || !(torqueNm >= 0) || !Double.isFinite(torqueNm)) {
            throw new IllegalArgumentException("a joint's torque must be finite and >= 0 and its release angle > 0, got " + torqueNm
                + " N*m over " + releaseRad + " rad");
        }
        double[] j = joints.get(joint);
        j[7] = torqueNm;
        j[8] = wormHeld ? 1 : 0;
        j[9] = releaseRad;
        j[10] = 0;
        j[12] = j[11];
    }

    /** Joint {@code joint}'s velocity in the last step, rad/s (closing positive). */
    public double jointVelocity(int joint) {
        return stepper.followerVelocity(joint);
    }

    /** Joint {@code joint}'s worm reaction in the last step, N·m (what held it against opening; 0 without the worm). */
    public double jointWormTorque(int joint, double h) {
        return stepper.wormImpulse(joint) / h;
    }

    /**
     * Each joint's angles, rad, n joints: [0, n) turned since its press was last set (what is left
     * of its preload follows from it), [n, 2n) turned since it was added (where the supports it
     * moves are), [2n, 3n) where its worm holds it (the farthest it has closed while held); a new
     * array.
     */
    public double[] jointTurns() {
        int n = joints.size();
        double[] t = new double[3 * n];
        for (int j = 0; j < n; j++) {
            t[j] = joints.get(j)[10];
            t[n + j] = joints.get(j)[11];
            t[2 * n + j] = joints.get(j)[12];
        }
        return t;
    }

    /** Sets each joint's angles (as {@link #jointTurns} gave them), rad. */
    public void setJointTurns(double[] turns) {
        int n = joints.size();
        if (turns.length != 3 * n) throw new IllegalArgumentException("expected " + 3 * n + " joint angles, got " + turns.length);
        for (int j = 0; j < n; j++) {
            joints.get(j)[10] = turns[j];
            joints.get(j)[11] = turns[n + j];
            joints.get(j)[12] = turns[2 * n + j];
        }
    }

    /** Says that {@code joint} ({@link #addJoint}) moves {@code support} ({@link #addSupport}). */
    public void moves(int joint, int support) {
        while (supportJoints.size() <= support) supportJoints.add(new int[0]);
        int[] a = supportJoints.get(support);
        int[] b = java.util.Arrays.copyOf(a, a.length + 1);
        b[a.length] = joint;
        supportJoints.set(support, b);
    }

    /** Sets gravity (m/s², world); returns this. */
    public BodyScene gravity(double x, double y, double z) {
        gravity[0] = x; gravity[1] = y; gravity[2] = z;
        return this;
    }

    /** Sets Coulomb's μ of every contact; returns this. */
    public BodyScene friction(double mu) {
        this.friction = mu;
        return this;
    }

    /** Sets the contact margin δ (m) and the deepest penetration D (m) the proximity query reports (the tunnelling watch starts again with δ); returns this. */
    public BodyScene margin(double marginM, double depthM) {
        this.margin = marginM;
        this.depth = depthM;
        stepper.watchTunnelling(marginM, reach);
        return this;
    }

    /** Sets the disturbance (world; N at the centre of mass, N·m about it) applied from now on. */
    public void disturbance(double[] forceN, double[] torqueNm) {
        System.arraycopy(forceN, 0, disturbForce, 0, 3);
        System.arraycopy(torqueNm, 0, disturbTorque, 0, 3);
    }

    /**
     * One step of h seconds.
     *
     * @return how the contact solve ended
     */
    public ContactSolver.Outcome step(double h) {
        contacts.clear();
        body.worldFromMesh(objectPose, 0);
        stepper.clearFollowers();
        for (double[] j : joints) {
            axis[0] = j[0]; axis[1] = j[1]; axis[2] = j[2];
            origin[0] = j[3]; origin[1] = j[4]; origin[2] = j[5];
            boolean spring = j[9] != Double.POSITIVE_INFINITY && j[10] < j[9];
            double left = j[9] == Double.POSITIVE_INFINITY ? 1 : Math.max(0, 1 - j[10] / j[9]);
            // the preload's fall over the step taken implicitly; the worm takes back what it let open
            stepper.addFollower(axis, origin, j[6], j[7] * left, spring ? j[7] / j[9] : 0, j[8] != 0,
                j[8] != 0 ? BodyStepper.PUSH_OUT * Math.max(0, j[12] - j[11]) / h : 0);
        }
        for (int s = 0; s < supportJoints.size(); s++) place(s);
        for (int s = 0; s < supportQueries.size(); s++) {
            int first = contacts.size();
            supportQueries.get(s).find(supportPoses.get(s), objectPose, margin, depth, friction, null, s, contacts);
            if (s < supportJoints.size()) {
                for (int joint : supportJoints.get(s)) {
                    for (int i = first; i < contacts.size(); i++) contacts.dependsOn(i, joint);
                }
            }
        }
        double m = body.mass();
        for (int i = 0; i < 3; i++) {
            force[i] = m * gravity[i] + disturbForce[i];
            torque[i] = disturbTorque[i];
        }
        ContactSolver.Outcome o = stepper.step(h, force, torque, contacts);
        for (int j = 0; j < joints.size(); j++) {
            double d = h * stepper.followerVelocity(j);
            double[] jt = joints.get(j);
            jt[10] += d;
            jt[11] += d;
            if (jt[8] != 0) jt[12] = Math.max(jt[12], jt[11]);
        }
        time += h;
        return o;
    }

    /**
     * Places support s where its joints have turned it: its pose as added, rotated about each
     * joint's axis by that joint's angle since it was added, the joint added last (the one
     * farthest out along the finger) first, so each turns about its axis as it was added.
     */
    private void place(int s) {
        int[] js = supportJoints.get(s);
        if (js.length == 0) return;
        double[] pose = supportPoses.get(s);
        System.arraycopy(supportBase.get(s), 0, pose, 0, 12);
        for (int k = js.length - 1; k >= 0; k--) {
            double[] j = joints.get(js[k]);
            double a = j[11];
            if (a == 0) continue;
            // Rodrigues: R = cI + s[z]x + (1 − c)zzᵀ; pose' = (R·Rp, R·(tp − o) + o)
            double zx = j[0], zy = j[1], zz = j[2], c = Math.cos(a), sn = Math.sin(a), c1 = 1 - c;
            turn[0] = c + c1 * zx * zx; turn[1] = c1 * zx * zy - sn * zz; turn[2] = c1 * zx * zz + sn * zy;
            turn[3] = c1 * zy * zx + sn * zz; turn[4] = c + c1 * zy * zy; turn[5] = c1 * zy * zz - sn * zx;
            turn[6] = c1 * zz * zx - sn * zy; turn[7] = c1 * zz * zy + sn * zx; turn[8] = c + c1 * zz * zz;
            for (int r = 0; r < 3; r++) {
                for (int col = 0; col < 3; col++) {
                    moved[4 * r + col] = turn[3 * r] * pose[col] + turn[3 * r + 1] * pose[4 + col] + turn[3 * r + 2] * pose[8 + col];
                }
                moved[4 * r + 3] = turn[3 * r] * (pose[3] - j[3]) + turn[3 * r + 1] * (pose[7] - j[4]) + turn[3 * r + 2] * (pose[11] - j[5])
                    + j[3 + r];
            }
            System.arraycopy(moved, 0, pose, 0, 12);
        }
    }

    /** Support s's pose of the last step (as added, turned by its joints), world, 12 values row-major; a copy. */
    public double[] supportPose(int s) { return supportPoses.get(s).clone(); }

    /** @return the object */
    public FreeBody body() { return body; }

    /** @return the contacts of the last step, with their impulses */
    public BodyContacts contacts() { return contacts; }

    /** @return the steps in which a point of the object moved more than the contact margin */
    public Tunnelling tunnelling() { return stepper.tunnelling(); }

    /** @return the stepper (its solver's counters) */
    public BodyStepper stepper() { return stepper; }

    /** @return the time stepped, s */
    public double time() { return time; }

    /** @return the object's mesh */
    public TriangleMesh objectMesh() { return objectMesh; }
}
