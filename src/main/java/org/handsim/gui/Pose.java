package org.handsim.gui;

import org.handsim.kinematics.FingerKinematics;
import org.handsim.math.RigidTransform;
import org.handsim.model.Snapshot;

/**
 * What the 3D view draws at one instant, immutable: where the palm and the nine links are,
 * where a free object is, the contacts, and optional markers (an inverse-kinematics target and the closest reachable
 * point). Built on the simulation thread from a {@link Snapshot} or on the event dispatch
 * thread from joint values (the Kinematics panel's preview); read by {@link SceneView}.
 *
 * @param worldFromPalm  12 row-major values, world ← palm
 * @param framesWorld    per finger (index 0..2) the frames {k0}..{k3} in the world, 4 × 12
 * @param contactPoints  3 per contact, world frame, m
 * @param contactNormals 3 per contact, outward object normal, world frame
 * @param contactForces  per contact, N
 * @param contactFingers per contact, the finger 1..3 that touches
 * @param target         a marker in the world (m), or null
 * @param closest        a second marker (the closest reachable point), or null
 * @param worldFromObject a free object's pose, world ← object, 12 row-major values; null: the
 *                        object stays where the scenario places it (a fixed object, a preview)
 */
public record Pose(double[] worldFromPalm, double[][] framesWorld, double[] contactPoints, double[] contactNormals,
                   double[] contactForces, int[] contactFingers, double[] target, double[] closest, double[] worldFromObject) {

    private static final double[] NONE = new double[0];
    private static final int[] NO_FINGERS = new int[0];

    /**
     * The pose of a simulation snapshot (the arrays are shared with the immutable snapshot): the
     * palm where the model has it (moved by {@code hand.moves}), a free object where it is.
     */
    public static Pose of(Snapshot s) {
        double[][] frames = new double[3][];
        int n = 0;
        for (Snapshot.FingerSnapshot f : s.fingers()) n += f.contactCount();
        double[] p = new double[3 * n], nn = new double[3 * n], force = new double[n];
        int[] fingers = new int[n];
        int at = 0;
        for (int k = 0; k < 3; k++) {
            Snapshot.FingerSnapshot f = s.fingers()[k];
            frames[k] = f.framesWorld();
            int c = f.contactCount();
            System.arraycopy(f.contactPoints(), 0, p, 3 * at, 3 * c);
            System.arraycopy(f.contactNormals(), 0, nn, 3 * at, 3 * c);
            System.arraycopy(f.contactForces(), 0, force, at, c);
            java.util.Arrays.fill(fingers, at, at + c, k + 1);
            at += c;
        }
        return new Pose(s.worldFromPalm(), frames, p, nn, force, fingers, null, null, s.object() == null ? null : s.object().worldFromMesh());
    }

    /**
     * The pose of joint values by forward kinematics (no contacts).
     *
     * @param joints per finger {θk1, θk2, θk3}, rad
     */
    public static Pose ofJoints(double[][] joints, RigidTransform worldFromPalm) {
        double[] wp = worldFromPalm.toArray();
        double[][] frames = new double[3][48];
        double[] inPalm = new double[48];
        for (int k = 1; k <= 3; k++) {
            FingerKinematics.of(k).framesInPalm(joints[k - 1], inPalm);
            for (int j = 0; j < 4; j++) RigidTransform.multiply(wp, 0, inPalm, 12 * j, frames[k - 1], 12 * j);
        }
        return new Pose(wp, frames, NONE, NONE, NONE, NO_FINGERS, null, null, null);
    }

    /** A copy with markers (world frame, m; either may be null). */
    public Pose withMarkers(double[] targetWorld, double[] closestWorld) {
        return new Pose(worldFromPalm, framesWorld, contactPoints, contactNormals, contactForces, contactFingers, targetWorld, closestWorld, worldFromObject);
    }

    /**
     * A copy with the contacts of a set (points and outward normals, forces 0: a preview's, not
     * solved), finger by finger: the first {@code perFinger[0]} are finger 1's, and so on.
     */
    public Pose withContacts(org.handsim.model.ContactSet c, int[] perFinger) {
        int n = c.size();
        double[] p = new double[3 * n], nn = new double[3 * n];
        int[] fingers = new int[n];
        for (int i = 0, k = 0, left = perFinger[0]; i < n; i++, left--) {
            while (left == 0 && k < 2) left = perFinger[++k];
            fingers[i] = k + 1;
            System.arraycopy(c.point(i), 0, p, 3 * i, 3);
            System.arraycopy(c.normal(i), 0, nn, 3 * i, 3);
        }
        return new Pose(worldFromPalm, framesWorld, p, nn, new double[n], fingers, target, closest, worldFromObject);
    }

    /** @return the number of contacts */
    public int contactCount() { return contactForces.length; }
}
