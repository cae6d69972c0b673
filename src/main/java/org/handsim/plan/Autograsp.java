package org.handsim.plan;

import org.handsim.math.RigidTransform;
import org.handsim.model.HandClearance;

/**
 * The approach of GraspIt!'s autograsp (Miller and Allen, "GraspIt!", IEEE RAM 2004;
 * {@code Grasp::approachToContact}): the open hand is placed clear of the object, moved in along
 * its approach direction until the palm or a finger meets the object, and then (in
 * {@link TrialRunner}) closes every finger.
 *
 * <p><b>Pose.</b> The palm's z axis is the approach a (from the hand toward the object's
 * centroid c); its x axis is x₀ turned by the roll about a, with x₀ the unit projection of
 * e_z on the plane normal to a (of e_x when |a_z| ≥ 0.9); y = z × x. The palm origin stays on
 * the line through c along a: p(d) = c − d·a, d the distance from the palm origin to c.
 *
 * <p><b>Rule.</b> Start at d₀ = R_object + R_hand + 1 mm (R the largest distance from c to a
 * vertex of the object, and from the palm origin to a vertex of the open hand): clear of the
 * object by construction, no query needed. Move in by steps of {@link #STEP_M} — half the
 * thinnest part of the hand (the 11 mm fingertip), so no hand part can pass through any part of
 * the object between two samples — and test the whole hand at each (palm and nine links, the
 * simulator's contact query, {@link HandClearance}). At the first step that touches, bisect on
 * d between the last clear and the touching distance down to {@link #TOL_M}; the hand is then
 * backed off by the trial's standoff from the last clear distance. If the hand reaches d = 0
 * (the palm origin at the centroid) without touching, it stops there.
 */
public final class Autograsp {
    /** March step along the approach, metres: half the thinnest hand part (the fingertip, 11 mm). */
    public static final double STEP_M = 0.005;
    /** The first touch is located to this distance, metres. */
    public static final double TOL_M = 1e-6;

    private Autograsp() {}

    /**
     * The approach's outcome.
     *
     * @param worldFromPalm the palm pose to close the fingers from
     * @param position      its translation, metres (the scenario's {@code hand.position_m})
     * @param rotation      its rotation as an axis-angle vector, radians ({@code hand.rotation_rad})
     * @param distance      d of the final pose (palm origin to centroid), metres
     * @param touched       whether the approach met the object (false: it stopped at d = 0)
     * @param queries       whole-hand tests made
     */
    public record Approach(RigidTransform worldFromPalm, double[] position, double[] rotation, double distance,
                           boolean touched, int queries) {}

    /**
     * The palm rotation for an approach and a roll, as the axis-angle vector the scenario
     * stores (the pose is then rebuilt from it, so the planner and {@code handsim run} use the
     * same matrix to the last bit).
     */
    public static double[] palmRotation(double[] a, double roll) {
        double[] x0 = rollZeroX(a);
        double[] y0 = {a[1] * x0[2] - a[2] * x0[1], a[2] * x0[0] - a[0] * x0[2], a[0] * x0[1] - a[1] * x0[0]};
        double c = StrictMath.cos(roll), s = StrictMath.sin(roll);
        double[] x = new double[3], y = new double[3];
        for (int i = 0; i < 3; i++) {
            x[i] = c * x0[i] + s * y0[i];
            y[i] = -s * x0[i] + c * y0[i];
        }
        double[] m = {x[0], y[0], a[0], 0, x[1], y[1], a[1], 0, x[2], y[2], a[2], 0};
        return RigidTransform.of(m).rotationVector();
    }

    /** The palm's x axis at roll 0: the unit projection of e_z on the plane normal to a (of e_x when |a_z| ≥ 0.9). */
    static double[] rollZeroX(double[] a) {
        double[] ref = Math.abs(a[2]) < 0.9 ? new double[] {0, 0, 1} : new double[] {1, 0, 0};
        double dot = ref[0] * a[0] + ref[1] * a[1] + ref[2] * a[2];
        double[] x0 = {ref[0] - dot * a[0], ref[1] - dot * a[1], ref[2] - dot * a[2]};
        double l = StrictMath.sqrt(x0[0] * x0[0] + x0[1] * x0[1] + x0[2] * x0[2]);
        for (int i = 0; i < 3; i++) x0[i] /= l;
        return x0;
    }

    /**
     * The first touch of an approach: the palm's rotation (as the axis-angle vector the scenario
     * stores, and the matrix rebuilt from it), the approach as that matrix has it, the centroid,
     * and the last distance d at which the hand was clear ({@code touched} false: it reached d = 0).
     */
    public record Touch(double[] rotationVector, RigidTransform rotation, double[] approach, double[] centroid,
                        double clearDistance, boolean touched, int queries) {}

    /**
     * Moves the open hand in along {@code approach} until it meets the object (the rule above),
     * without backing off: where the standoff is measured from.
     *
     * @param hc           the object's clearance test
     * @param approach     unit approach direction, world frame
     * @param roll         radians
     * @param spreadCounts q_M4
     * @param fingerCounts motor counts of the three fingers during the approach (the template's start counts)
     */
    public static Touch touch(HandClearance hc, double[] approach, double roll, double spreadCounts, double[] fingerCounts) {
        double[] r = palmRotation(approach, roll);
        RigidTransform rot = RigidTransform.fromPose(0, 0, 0, r[0], r[1], r[2]);
        double[] a = rot.axis(2);            // the approach as the rebuilt matrix has it
        double[] c = hc.objectCentroid();
        double d0 = hc.objectReach() + hc.handReach(spreadCounts, fingerCounts) + 1e-3;
        int queries = 0;
        double[] w = rot.toArray();          // the pose of each test: this rotation, the translation set per test
        double clear = d0, hit = Double.NaN;
        for (double d = d0 - STEP_M; ; d -= STEP_M) {
            if (d < 0) d = 0;
            queries++;
            if (hc.touches(place(w, c, a, d), spreadCounts, fingerCounts)) {
                hit = d;
                break;
            }
            clear = d;
            if (d == 0) break;
        }
        boolean touched = !Double.isNaN(hit);
        if (touched) {
            while (clear - hit > TOL_M) {
                double mid = 0.5 * (clear + hit);
                queries++;
                if (hc.touches(place(w, c, a, mid), spreadCounts, fingerCounts)) hit = mid; else clear = mid;
            }
        }
        return new Touch(r, rot, a, c, touched ? clear : 0, touched, queries);
    }

    /** The pose {@code standoff} metres back from the first touch (the centroid when the approach touched nothing). */
    public static Approach backOff(Touch t, double standoff) {
        double d = t.touched() ? t.clearDistance() + standoff : 0;
        RigidTransform p = pose(t.centroid(), t.approach(), t.rotationVector(), d);
        return new Approach(p, p.origin(), t.rotationVector(), d, t.touched(), t.queries());
    }

    /**
     * Moves the open hand in along {@code approach} until it meets the object (the rule above).
     *
     * @param hc           the object's clearance test
     * @param approach     unit approach direction, world frame
     * @param roll         radians
     * @param spreadCounts q_M4
     * @param fingerCounts motor counts of the three fingers during the approach (the template's start counts)
     * @param standoff     back-off from the first touch, metres ≥ 0
     */
    public static Approach approach(HandClearance hc, double[] approach, double roll, double spreadCounts,
                                    double[] fingerCounts, double standoff) {
        return backOff(touch(hc, approach, roll, spreadCounts, fingerCounts), standoff);
    }

    private static RigidTransform pose(double[] c, double[] a, double[] r, double d) {
        return RigidTransform.fromPose(c[0] - d * a[0], c[1] - d * a[1], c[2] - d * a[2], r[0], r[1], r[2]);
    }

    /**
     * {@link #pose} into {@code w}, which holds its rotation already ({@link RigidTransform#fromPose}
     * makes the rotation from r alone and stores the translation as given: the same 12 numbers).
     */
    private static double[] place(double[] w, double[] c, double[] a, double d) {
        w[3] = c[0] - d * a[0];
        w[7] = c[1] - d * a[1];
        w[11] = c[2] - d * a[2];
        return w;
    }
}
