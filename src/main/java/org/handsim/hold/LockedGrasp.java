package org.handsim.hold;

import org.handsim.body.MassProperties;
import org.handsim.dynamics.ChainDynamics;
import org.handsim.dynamics.HandDynamics;
import org.handsim.grasp.GraspAssessment;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.HandModel;
import org.handsim.model.SceneGeometry;
import org.handsim.scenario.SceneMeshes;

/**
 * A closed grasp with every finger joint locked where the closing left it — the BarrettHand's
 * finger joints are driven through worms, which a load on the link does not back-drive (BH8
 * manual; DESIGN.md decision 6) — and the object released there: the hand's ten bodies (the palm
 * and the nine finger links) as static bodies at their world poses, and the object's mesh, mass
 * properties and pose at release. An immutable value; its meshes are shared, read-only.
 */
public final class LockedGrasp {
    /** Body index of the palm; finger k's link j is {@code 3(k − 1) + j}. */
    public static final int PALM = 0;
    /** The hand's bodies: the palm and three links of each of the three fingers. */
    public static final int BODIES = 10;

    private final TriangleMesh objectMesh;
    private final MassProperties mass;
    private final double[] worldFromObject;
    private final TriangleMesh[] meshes = new TriangleMesh[BODIES];
    private final double[][] poses = new double[BODIES][];
    private final double friction;
    private final double[] gravity;
    /** Per finger (0..2) and flexion joint (0: k2, 1: k3): {zx, zy, zz, ox, oy, oz, D, τ} (world; kg·m²; N·m). */
    private final double[][][] joints = new double[3][2][];
    private final boolean[] engaged = new boolean[3];
    private double tauBreak = Double.POSITIVE_INFINITY;

    private LockedGrasp(TriangleMesh objectMesh, MassProperties mass, double[] worldFromObject, double friction, double[] gravity) {
        this.objectMesh = objectMesh;
        this.mass = mass;
        this.worldFromObject = worldFromObject;
        this.friction = friction;
        this.gravity = gravity;
    }

    /**
     * The grasp a model reached: its links at their DH frames {kj} (the link meshes' frames,
     * {@link HandModel#framesWorld}), the palm at the scenario's palm pose, the object where the
     * scenario (or its free motion) put it, μ and gravity of the scenario.
     *
     * @param geometry the model's collision back end (its link and object meshes)
     * @param mass     the object's mass properties (its mesh frame)
     */
    public static LockedGrasp of(HandModel model, SceneGeometry geometry, MassProperties mass) {
        LockedGrasp g = new LockedGrasp(geometry.objectMesh(), mass, geometry.worldFromObject(), model.scenario().friction(),
            model.scenario().gravity());
        g.meshes[PALM] = SceneMeshes.mesh(SceneMeshes.palmFile(), SceneMeshes.LINK_DIVISIONS, 1.0);
        g.poses[PALM] = model.scenario().worldFromPalm().toArray();
        GraspAssessment.Input in = model.graspInput();
        // the squeeze the grasp keeps once freed: the balanced forces nearest the closing's (BalancedPreload)
        double[] com = RigidTransform.of(g.worldFromObject).apply(mass.centreOfMass());
        double[] kept = BalancedPreload.of(in.contacts(), com, g.friction);
        java.util.List<GraspAssessment.Contact> squeeze = new java.util.ArrayList<>();
        for (int i = 0; i < in.contacts().size(); i++) {
            GraspAssessment.Contact c = in.contacts().get(i);
            squeeze.add(new GraspAssessment.Contact(c.finger(), c.link(), c.point(), c.normal(), java.util.Arrays.copyOfRange(kept, 3 * i, 3 * i + 3)));
        }
        HandDynamics dyn = HandDynamics.barrettHand();
        g.tauBreak = in.hand().tauBreak();
        for (int k = 1; k <= 3; k++) {
            g.engaged[k - 1] = model.clutchEngaged(k);
            double[] frames = model.framesWorld(k);
            for (int j = 1; j <= 3; j++) {
                int b = body(k, j);
                g.meshes[b] = geometry.linkMesh(j);
                g.poses[b] = java.util.Arrays.copyOfRange(frames, 12 * j, 12 * j + 12);
            }
            ChainDynamics chain = dyn.finger(k);
            double[] q = model.joints(k);
            double[] qa = chain.dof() == 3 ? q : new double[] {q[1], q[2]};
            double[] d = chain.massMatrix(qa, null);
            int n = chain.dof();
            for (int j = 2; j <= 3; j++) {
                int o = 12 * (j - 1);
                double[] z = {frames[o + 2], frames[o + 6], frames[o + 10]}, org = {frames[o + 3], frames[o + 7], frames[o + 11]};
                int col = n - 4 + j;   // k2, k3: the last two active joints
                g.joints[k - 1][j - 2] = new double[] {z[0], z[1], z[2], org[0], org[1], org[2], d[col * n + col],
                    Math.max(0, pressing(squeeze, k, j, z, org)), arm(in.contacts(), k, j, z, org)};
            }
        }
        return g;
    }

    /**
     * The torque finger k's joint j turns closing with to press its contacts as the closing left
     * them, N·m: Σ (z × (p − o))·f over the contacts on the links it carries (eq 9 with the
     * contact forces the simulation gave them: the drive's, or what the worm locked in).
     */
    static double pressing(java.util.List<GraspAssessment.Contact> contacts, int k, int j, double[] z, double[] o) {
        double t = 0;
        for (GraspAssessment.Contact c : contacts) {
            if (c.finger() != k || c.link() < j) continue;
            double[] p = c.point(), f = c.forceN();
            double rx = p[0] - o[0], ry = p[1] - o[1], rz = p[2] - o[2];
            t += (z[1] * rz - z[2] * ry) * f[0] + (z[2] * rx - z[0] * rz) * f[1] + (z[0] * ry - z[1] * rx) * f[2];
        }
        return t;
    }

    /** The largest distance from finger k's joint j axis to a contact on the links it carries, m (0: none). */
    static double arm(java.util.List<GraspAssessment.Contact> contacts, int k, int j, double[] z, double[] o) {
        double r = 0;
        for (GraspAssessment.Contact c : contacts) {
            if (c.finger() != k || c.link() < j) continue;
            double[] p = c.point();
            double rx = p[0] - o[0], ry = p[1] - o[1], rz = p[2] - o[2];
            double cx = z[1] * rz - z[2] * ry, cy = z[2] * rx - z[0] * rz, cz = z[0] * ry - z[1] * rx;
            r = Math.max(r, Math.sqrt(cx * cx + cy * cy + cz * cz));
        }
        return r;
    }

    /**
     * Finger k's flexion joint j (2: inner, 3: outer) as the test holds it: {zx, zy, zz, ox, oy,
     * oz, D, τ, r} — its axis and a point on it (world), the inertia about the axis of the links it
     * carries (D_jj of eq 8's mass matrix, kg·m²), the torque it presses with (N·m, ≥ 0) and the
     * largest distance from its axis to a contact it carries (m, 0 without one); a copy.
     */
    public double[] joint(int finger, int j) { return joints[finger - 1][j - 2].clone(); }

    /**
     * Finger k's clutch was engaged when the closing ended (it never broke away): its inner joint
     * is held through the clutch, which slips above {@link #tauBreak()} (the hold LP's limit of
     * that joint, {@code GraspAssessment.jointLimit}); otherwise its worm holds it.
     */
    public boolean clutchEngaged(int finger) { return engaged[finger - 1]; }

    /** The clutches' breakaway torque τ_break, N·m (the hand's). */
    public double tauBreak() { return tauBreak; }

    /** The body index of finger k's link j (k, j in 1..3). */
    public static int body(int finger, int link) {
        return 3 * (finger - 1) + link;
    }

    /** The name of body b as the outputs write it: {@code palm}, {@code finger K link J}. */
    public static String name(int b) {
        return b == PALM ? "palm" : "finger " + ((b - 1) / 3 + 1) + " link " + ((b - 1) % 3 + 1);
    }

    public TriangleMesh objectMesh() { return objectMesh; }
    public MassProperties mass() { return mass; }
    /** The object's mesh pose at release, world, 12 values row-major (a copy). */
    public double[] worldFromObject() { return worldFromObject.clone(); }
    public RigidTransform worldFromObjectTransform() { return RigidTransform.of(worldFromObject); }
    public TriangleMesh mesh(int body) { return meshes[body]; }
    /** Body b's pose, world, 12 values row-major (a copy). */
    public double[] pose(int body) { return poses[body].clone(); }
    /** Coulomb's μ of every contact. */
    public double friction() { return friction; }
    /** The scenario's gravity, m/s², world (a copy). */
    public double[] gravity() { return gravity.clone(); }
}
