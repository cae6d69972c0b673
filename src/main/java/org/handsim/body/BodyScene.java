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
    private double friction = 0.5, margin = ProximityContacts.DEFAULT_MARGIN, depth = 5 * ProximityContacts.DEFAULT_MARGIN;
    private double time;

    /** The object with its mesh at {@code worldFromMesh}, at rest. */
    public BodyScene(TriangleMesh objectMesh, MassProperties props, RigidTransform worldFromMesh) {
        this.objectMesh = objectMesh;
        this.objectTree = KdopTree.build(objectMesh, K);
        this.objectTopology = new MeshTopology(objectMesh);
        this.body = new FreeBody(props, worldFromMesh);
        this.stepper = new BodyStepper(body);
    }

    /** Adds a static support: {@code mesh} placed by {@code pose}; returns its id (0, 1, …). */
    public int addSupport(TriangleMesh mesh, RigidTransform pose) {
        KdopTree tree = KdopTree.build(mesh, K);
        supportPoses.add(pose.toArray());
        supportQueries.add(new ProximityContacts(tree, new MeshTopology(mesh), objectTree, objectTopology));
        return supportQueries.size() - 1;
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

    /** Sets the contact margin δ (m) and the deepest penetration D (m) the proximity query reports; returns this. */
    public BodyScene margin(double marginM, double depthM) {
        this.margin = marginM;
        this.depth = depthM;
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
        for (int s = 0; s < supportQueries.size(); s++) {
            supportQueries.get(s).find(supportPoses.get(s), objectPose, margin, depth, friction, null, s, contacts);
        }
        double m = body.mass();
        for (int i = 0; i < 3; i++) {
            force[i] = m * gravity[i] + disturbForce[i];
            torque[i] = disturbTorque[i];
        }
        ContactSolver.Outcome o = stepper.step(h, force, torque, contacts);
        time += h;
        return o;
    }

    /** @return the object */
    public FreeBody body() { return body; }

    /** @return the contacts of the last step, with their impulses */
    public BodyContacts contacts() { return contacts; }

    /** @return the stepper (its solver's counters) */
    public BodyStepper stepper() { return stepper; }

    /** @return the time stepped, s */
    public double time() { return time; }

    /** @return the object's mesh */
    public TriangleMesh objectMesh() { return objectMesh; }
}
