package org.handsim.sim;

import org.handsim.hand.HandDescription;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * Whether the whole hand — palm and the nine links, the fingers FREE at given motor counts
 * and spread — touches the object when the palm is placed at a given pose: the question the
 * planner's approach asks ({@code plan.Autograsp}). The links are placed exactly as
 * {@link HandModel} places them (world ← palm ← {k0}, forward kinematics of the FREE joint
 * angles of eqs 1–4), and tested by the contact query's own trees ({@link SceneGeometry#touches}),
 * so a pose this class calls clear starts the simulation without contacts.
 *
 * <p>Not thread-safe (query scratch): one per thread.
 */
public final class HandClearance {
    private final SceneGeometry scene;
    private final HandDescription hand = HandDescription.barrettHand();
    private final Transmission tr = new Transmission(hand);
    private final FingerKinematics[] fk = new FingerKinematics[3];
    private final double[] frames = new double[FingerKinematics.FRAMES_LENGTH];
    private final double[] joints = new double[3], base = new double[12], palm = new double[12], link = new double[12];
    private final double[] centroid;
    private final double objectReach;

    /**
     * @param object the object and its placement (a scenario's)
     * @throws ScenarioException naming file, line and column if the object cannot be loaded
     */
    public HandClearance(Scenario.ObjectPlacement object) {
        scene = new SceneGeometry(object, SceneGeometry.DEFAULT_K);
        for (int k = 1; k <= 3; k++) fk[k - 1] = new FingerKinematics(hand.finger(k));
        double[] cr = scene.centroidAndRadius();   // the torque origin c and R of the grasp evaluation
        centroid = new double[] {cr[0], cr[1], cr[2]};
        objectReach = cr[3];
    }

    /** The object's centroid, world frame, metres (the grasp evaluation's torque origin, {@link SceneGeometry#centroidAndRadius}); a new array. */
    public double[] objectCentroid() { return centroid.clone(); }

    /** The largest distance from the centroid to a vertex of the object, metres. */
    public double objectReach() { return objectReach; }

    /** The object's thinnest width, metres (an estimate from above, {@link SceneGeometry#minThickness}). */
    public double objectMinThickness() { return scene.minThickness(); }

    /**
     * True if the palm placed by {@code worldFromPalm}, or a link of a finger at motor counts
     * {@code fingerCounts[k−1]} (FREE) with the spread at {@code spreadCounts}, intersects the
     * object. Parts are tested palm first, then fingers 1–3 from the outer link in.
     */
    public boolean touches(RigidTransform worldFromPalm, double spreadCounts, double[] fingerCounts) {
        worldFromPalm.copyTo(palm, 0);
        if (scene.touches(0, palm)) return true;
        for (int k = 1; k <= 3; k++) {
            placeFinger(worldFromPalm, k, spreadCounts, fingerCounts[k - 1]);
            for (int j = 3; j >= 1; j--) {
                System.arraycopy(frames, 12 * j, link, 0, 12);
                if (scene.touches(j, link)) return true;
            }
        }
        return false;
    }

    /**
     * The largest distance from the palm origin to a vertex of the palm or of a link, metres,
     * for the given spread and finger counts (FREE): no point of the hand is farther, so a palm
     * origin more than {@code handReach + objectReach} from the centroid is clear of the object.
     */
    public double handReach(double spreadCounts, double[] fingerCounts) {
        double r = reach(SceneGeometry.mesh(SceneGeometry.palmFile(), SceneGeometry.LINK_DIVISIONS, 1.0), RigidTransform.IDENTITY.toArray(), 0);
        for (int k = 1; k <= 3; k++) {
            placeFinger(RigidTransform.IDENTITY, k, spreadCounts, fingerCounts[k - 1]);
            for (int j = 1; j <= 3; j++) r = Math.max(r, reach(scene.linkMesh(j), frames, 12 * j));
        }
        return r;
    }

    private static double reach(TriangleMesh m, double[] w, int o) {
        double[] v = m.vertices();
        double r = 0;
        for (int i = 0; i < v.length; i += 3) {
            double x = w[o] * v[i] + w[o + 1] * v[i + 1] + w[o + 2] * v[i + 2] + w[o + 3];
            double y = w[o + 4] * v[i] + w[o + 5] * v[i + 1] + w[o + 6] * v[i + 2] + w[o + 7];
            double z = w[o + 8] * v[i] + w[o + 9] * v[i + 1] + w[o + 10] * v[i + 2] + w[o + 11];
            r = Math.max(r, x * x + y * y + z * z);
        }
        return Math.sqrt(r);
    }

    /** Frames {k0}..{k3} of finger k in the world, as {@link HandModel} computes them. */
    private void placeFinger(RigidTransform worldFromPalm, int k, double spreadCounts, double counts) {
        worldFromPalm.compose(hand.finger(k).baseInPalm()).copyTo(base, 0);
        joints[0] = hand.finger(k).spreadRadPerCount() * spreadCounts;
        joints[1] = tr.innerAngle(counts);
        joints[2] = tr.outerAngle(counts);
        fk[k - 1].framesFrom(base, joints, frames);
    }
}
