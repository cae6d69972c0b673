package org.handsim.plan;

import org.handsim.math.RigidTransform;

/**
 * How far the hand backs off from its first touch before the fingers close, for the object's
 * size: one of two grasps, drawn per trial ({@link TrialParameters#wrap()}).
 *
 * <ul>
 *   <li><b>Wrap</b> (a share {@link #WRAP_SHARE} of the trials): the palm stays close, backed off
 *       uniformly in [0, {@link #WRAP_MAX_M}): the inner links meet the object's near side and
 *       the outer links wrap its far side — the grasp of an object about as large as the hand
 *       (the mug).</li>
 *   <li><b>Fingertips</b> (the others): the object's centroid is put at a distance d from the
 *       palm origin drawn uniformly in [h − {@link #BELOW_M}, h + {@link #ABOVE_M}), where h is
 *       the height at which the closing fingertips come within w of the palm's axis
 *       ({@link FingertipPath#heightAtReach}) and w is how far the object reaches toward the
 *       fingers: the largest of its supports from the centroid toward the three fingers, each
 *       against the direction that finger closes in ({@link ObjectFrame#support}). The fingertips
 *       then meet the object about its widest part, where their pushes have components both
 *       toward and away from the palm. The standoff is d less the first touch's distance, 0 when
 *       the hand touched farther out than that (an object too large for it).</li>
 * </ul>
 *
 * <p>Why: the simulator's palm carries no contact force, so a grasp must hold by its finger
 * contacts alone. With the old rule (a standoff of at most 10 mm) a 60 mm sphere sat between
 * the knuckles and every fingertip closed over its far pole: 0 of 300 trials in force closure.
 * Measured over 300 trials per shape (docs/BENCHMARKS.md, "Planning any shape"): force closure
 * of the 40 and 60 mm spheres is 70 % with the centroid 30 mm below h to 10 mm above it and
 * 0 % elsewhere; the mug and the ring need the wrap; a 40 % share of wraps gave the best
 * smallest rate over the set.
 */
public final class StandoffRule {
    /** Share of the trials that wrap (a close palm) for a flat object ... */
    public static final double WRAP_SHARE_FLAT = 0.6;
    /** ... and for any other. */
    public static final double WRAP_SHARE = 0.35;
    /**
     * An object is flat (a plate, a ring) when its smallest extent is below this fraction of its
     * middle one (the ring: 0.21; a box 40 × 40 × 120: 1; the banana: 0.48, long rather than flat).
     */
    public static final double FLAT = 0.35;

    /** The share of wraps for this object. */
    public static double wrapShare(ObjectFrame o) {
        return o != null && o.extent(2) < FLAT * o.extent(1) ? WRAP_SHARE_FLAT : WRAP_SHARE;
    }
    /** Largest standoff of a wrap, metres (the planner's standoff before this rule). */
    public static final double WRAP_MAX_M = 0.010;
    /** The fingertip window: the centroid from this far below the fingertips' reach height ... */
    public static final double BELOW_M = 0.030;
    /** ... to this far above it, metres. */
    public static final double ABOVE_M = 0.010;

    private final ObjectFrame object;
    private final FingertipPath path;

    public StandoffRule(ObjectFrame object, FingertipPath path) {
        this.object = object;
        this.path = path;
    }

    /**
     * The standoff of trial {@code p}, metres ≥ 0.
     *
     * @param touch the approach's first touch (its palm rotation and the distance it was clear at)
     */
    public double standoff(TrialParameters p, Autograsp.Touch touch) {
        if (p.wrap()) return WRAP_MAX_M * p.depth();
        double w = reach(touch.rotation(), p.spreadCounts());
        double h = path.heightAtReach(w);
        double d = h - BELOW_M + (BELOW_M + ABOVE_M) * p.depth();
        return Math.max(0, d - touch.clearDistance());
    }

    /**
     * How far the object reaches toward the fingers with the palm turned by {@code rotation}: the
     * largest, over the three fingers, of its support against the direction the finger closes in.
     */
    double reach(RigidTransform rotation, int spread) {
        double[] x = rotation.axis(0), y = rotation.axis(1);
        double w = 0;
        for (int k = 1; k <= 3; k++) {
            double[] u = path.closingDirection(k, spread);
            double[] out = {-(u[0] * x[0] + u[1] * y[0]), -(u[0] * x[1] + u[1] * y[1]), -(u[0] * x[2] + u[1] * y[2])};
            w = Math.max(w, object.support(out));
        }
        return w;
    }
}
