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
    private final List<double[]> supportPoses = new ArrayList<>();
    private final List<ProximityContacts> supportQueries = new ArrayList<>();
    private final double[] gravity = {0, 0, -9.80665};
    private final double[] force = new double[3], torque = new double[3], disturbForce = new double[3], disturbTorque = new double[3];
    private final double[] objectPose = new double[12];
    private final List<double[]> joints = new ArrayList<>();    // axis, origin, inertia, torque, worm (1/0), release angle, turned
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
        supportQueries.add(new ProximityContacts(tree, topology, objectTree, objectTopology));
        return supportQueries.size() - 1;
    }

    /**
     * Adds a joint that presses supports on the object (a finger joint of a locked grasp): each
     * step it is a follower of {@link BodyStepper#addFollower(double[], double[], double, double, boolean)}
     * — at rest at the step's start, torque τ closing, held against opening by its worm or not —
     * and the contacts of the supports it {@link #moves} depend on it. The supports keep their
     * poses: the joint's motion acts within each step, as a press, which is what a link held by
     * its worm does (it turns by no visible angle while the object stays).
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
            releaseRad, 0});
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
    }

    /** Joint {@code joint}'s velocity in the last step, rad/s (closing positive). */
    public double jointVelocity(int joint) {
        return stepper.followerVelocity(joint);
    }

    /** Joint {@code joint}'s worm reaction in the last step, N·m (what held it against opening; 0 without the worm). */
    public double jointWormTorque(int joint, double h) {
        return stepper.wormImpulse(joint) / h;
    }

    /** Each joint's angle turned since it was added, rad (what is left of its preload follows from it); a new array. */
    public double[] jointTurns() {
        double[] t = new double[joints.size()];
        for (int j = 0; j < t.length; j++) t[j] = joints.get(j)[10];
        return t;
    }

    /** Sets each joint's turned angle (as {@link #jointTurns} gave them), rad. */
    public void setJointTurns(double[] turns) {
        for (int j = 0; j < turns.length; j++) joints.get(j)[10] = turns[j];
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
            double left = j[9] == Double.POSITIVE_INFINITY ? 1 : Math.max(0, 1 - j[10] / j[9]);
            stepper.addFollower(axis, origin, j[6], j[7] * left, j[8] != 0);
        }
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
        for (int j = 0; j < joints.size(); j++) joints.get(j)[10] += h * stepper.followerVelocity(j);
        time += h;
        return o;
    }

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
