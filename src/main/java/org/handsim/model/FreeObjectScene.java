package org.handsim.model;

import java.util.List;
import org.handsim.body.BodyContacts;
import org.handsim.body.BodyStepper;
import org.handsim.body.BoxMesh;
import org.handsim.body.ContactSolver;
import org.handsim.body.FreeBody;
import org.handsim.body.MassProperties;
import org.handsim.body.MeshTopology;
import org.handsim.body.ProximityContacts;
import org.handsim.body.Tunnelling;
import org.handsim.collision.KdopTree;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.Disturbance;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;
import org.handsim.scenario.Support;

/**
 * The free object of a run among the hand's bodies and the scenario's supports (DESIGN.md
 * decision 7): each step the model places the palm and the nine finger links (each with its
 * velocity, and the finger joints that press through it as followers of {@link BodyStepper}),
 * this class finds their contacts with the object by proximity ({@link ProximityContacts}, a
 * bounding-sphere test first), adds the supports' (static), gravity and the disturbances acting
 * at the step's start, and advances the object by one {@link BodyStepper} step: one convex
 * contact problem over the object's twist and the pressing joints' velocities.
 *
 * <p>Bodies are numbered {@link #PALM} = 0, finger k's link j = 3(k − 1) + j, support s =
 * {@link #HAND_BODIES} + s. Not thread-safe; allocation-free per step once grown.
 */
final class FreeObjectScene {
    /** Body id of the palm. */
    static final int PALM = 0;
    /** The hand's bodies: the palm and three links of each finger; supports follow. */
    static final int HAND_BODIES = 10;

    private final FreeBody body;
    private final BodyStepper stepper;
    private final BodyContacts contacts = new BodyContacts();
    private final ProximityContacts[] queries;
    private final double[][] spheres;            // each body's bounding sphere in its own frame {cx, cy, cz, r}
    private final double[][] supportPoses;
    private final double[] objectSphere;
    private final double[] gravity, objectPose = new double[12], force = new double[3], torque = new double[3];
    private final List<Disturbance> disturbances;
    private final double friction, margin = ProximityContacts.DEFAULT_MARGIN, depth = 5 * ProximityContacts.DEFAULT_MARGIN;
    private final double[] releaseV, releaseW;
    private final double reach;

    /**
     * @param scenario a scenario with a free object
     * @param geometry its collision back end (the object's and the links' meshes and trees)
     * @param props    the object's mass properties (mesh frame)
     */
    FreeObjectScene(Scenario scenario, SceneGeometry geometry, MassProperties props) {
        TriangleMesh om = geometry.objectMesh();
        KdopTree objectTree = geometry.objectTree();
        MeshTopology objectTopology = new MeshTopology(om);
        body = new FreeBody(props, RigidTransform.of(geometry.worldFromObject()));
        stepper = new BodyStepper(body);
        int ns = scenario.supports().size();
        queries = new ProximityContacts[HAND_BODIES + ns];
        spheres = new double[HAND_BODIES + ns][];
        supportPoses = new double[ns][];
        TriangleMesh palm = SceneMeshes.mesh(SceneMeshes.palmFile(), SceneMeshes.LINK_DIVISIONS, 1.0);
        KdopTree palmTree = KdopTree.build(palm, objectTree.k());
        queries[PALM] = new ProximityContacts(palmTree, new MeshTopology(palm), objectTree, objectTopology);
        spheres[PALM] = SceneGeometry.boundingSphere(palm);
        MeshTopology[] linkTopology = new MeshTopology[3];
        for (int j = 1; j <= 3; j++) linkTopology[j - 1] = new MeshTopology(geometry.linkMesh(j));
        for (int k = 1; k <= 3; k++) {
            for (int j = 1; j <= 3; j++) {
                int b = linkBody(k, j);
                queries[b] = new ProximityContacts(geometry.linkTree(j), linkTopology[j - 1], objectTree, objectTopology);
                spheres[b] = SceneGeometry.boundingSphere(geometry.linkMesh(j));
            }
        }
        for (int s = 0; s < ns; s++) {
            Support sp = scenario.supports().get(s);
            TriangleMesh mesh = sp.boxM() != null ? BoxMesh.of("supports[" + s + "]", sp.boxM()[0], sp.boxM()[1], sp.boxM()[2])
                : SceneMeshes.mesh(sp.file(), Scenario.DEFAULT_DIVISIONS, 1.0);
            queries[HAND_BODIES + s] = new ProximityContacts(KdopTree.build(mesh, objectTree.k()), new MeshTopology(mesh), objectTree, objectTopology);
            spheres[HAND_BODIES + s] = SceneGeometry.boundingSphere(mesh);
            supportPoses[s] = sp.worldFromSupport().toArray();
        }
        objectSphere = SceneGeometry.boundingSphere(om);
        gravity = scenario.gravity().clone();
        disturbances = scenario.disturbances();
        friction = scenario.friction();
        releaseV = scenario.freeObject().velocityMS().clone();
        releaseW = scenario.freeObject().angularVelocityRadS().clone();
        reach = Tunnelling.reach(om, props);
    }

    /** The body id of finger k's link j. */
    static int linkBody(int finger, int link) {
        return 3 * (finger - 1) + link;
    }

    /**
     * Gives the object its velocity at release (the scenario's, world frame) at time {@code t},
     * and from then on watches each step for tunnelling ({@link Tunnelling}: a point of the object
     * moving more than the contact margin in one step).
     */
    void release(double t) {
        body.setVelocity(releaseV, releaseW);
        stepper.watchTunnelling(margin, reach);
        stepper.setTime(t);
    }

    /** What the tunnelling watch saw since the release, or null before it. */
    Tunnelling tunnelling() { return stepper.tunnelling(); }

    /** Starts a step: no contacts, no followers. */
    void begin() {
        contacts.clear();
        stepper.clearFollowers();
        body.worldFromMesh(objectPose, 0);
    }

    /**
     * A joint that presses on the object this step (a finger joint held by its worm, driven by
     * its clutch or motor): {@link BodyStepper#addFollower(double[], double[], double, double, boolean)}.
     *
     * @return its index, for {@link #hand}
     */
    int follower(double[] axis, double[] origin, double inertia, double torqueNm, boolean wormHeld) {
        return stepper.addFollower(axis, origin, inertia, torqueNm, wormHeld);
    }

    /**
     * The contacts of hand body {@code b} placed at {@code pose} (12 values at {@code off}) moving
     * with {@code twist} (velocity of its frame's origin, angular velocity; world), which the
     * followers f1, f2 (−1: none) move as well.
     */
    void hand(int b, double[] pose, int off, double[] twist, int f1, int f2) {
        if (apart(b, pose, off)) return;
        double[] p = off == 0 ? pose : place(pose, off);
        int first = contacts.size();
        queries[b].find(p, objectPose, margin, depth, friction, twist, b, contacts);
        for (int i = first; i < contacts.size(); i++) {
            if (f1 >= 0) contacts.dependsOn(i, f1);
            if (f2 >= 0) contacts.dependsOn(i, f2);
        }
    }

    private final double[] placed = new double[12];

    private double[] place(double[] pose, int off) {
        System.arraycopy(pose, off, placed, 0, 12);
        return placed;
    }

    /** Whether body b's bounding sphere (placed) and the object's are farther apart than the margin. */
    private boolean apart(int b, double[] w, int o) {
        double[] s = spheres[b], c = objectSphere, q = objectPose;
        double x = w[o] * s[0] + w[o + 1] * s[1] + w[o + 2] * s[2] + w[o + 3] - (q[0] * c[0] + q[1] * c[1] + q[2] * c[2] + q[3]);
        double y = w[o + 4] * s[0] + w[o + 5] * s[1] + w[o + 6] * s[2] + w[o + 7] - (q[4] * c[0] + q[5] * c[1] + q[6] * c[2] + q[7]);
        double z = w[o + 8] * s[0] + w[o + 9] * s[1] + w[o + 10] * s[2] + w[o + 11] - (q[8] * c[0] + q[9] * c[1] + q[10] * c[2] + q[11]);
        double reach = s[3] + c[3] + margin;
        return x * x + y * y + z * z > reach * reach;
    }

    /**
     * Ends the step begun by {@link #begin}: the supports' contacts, gravity and the disturbances
     * acting at {@code time} (the step's start), one step of h.
     */
    ContactSolver.Outcome step(double time, double h) {
        for (int s = 0; s < supportPoses.length; s++) {
            int b = HAND_BODIES + s;
            if (!apart(b, supportPoses[s], 0)) queries[b].find(supportPoses[s], objectPose, margin, depth, friction, null, b, contacts);
        }
        double m = body.mass();
        for (int i = 0; i < 3; i++) {
            force[i] = m * gravity[i];
            torque[i] = 0;
        }
        for (int d = 0, n = disturbances.size(); d < n; d++) {
            Disturbance w = disturbances.get(d);
            if (!w.actsAt(time)) continue;
            for (int i = 0; i < 3; i++) {
                force[i] += w.forceN()[i];
                torque[i] += w.torqueNm()[i];
            }
        }
        return stepper.step(h, force, torque, contacts);
    }

    FreeBody body() { return body; }
    BodyContacts contacts() { return contacts; }
    BodyStepper stepper() { return stepper; }
    /** The object mesh's pose now (12 values into out). */
    double[] pose(double[] out) { return body.worldFromMesh(out, 0); }
}
