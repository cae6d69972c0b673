package org.handsim.collision;

import org.handsim.math.RigidTransform;

/**
 * The collision query of one pair of bodies that is asked again and again as they move a little
 * (a finger link closing on an object step by step, the bisection of its first touch): the
 * same result as {@link TreeQuery#collide(KdopTree, KdopTree, double[], int, CollisionResult)}
 * with B placed in A's frame by A⁻¹·B ({@link RigidTransform#inverseTimes}) every time, bit for
 * bit, mostly without walking the trees (temporal coherence).
 *
 * <p><b>How.</b> It keeps the {@link NearPairs} gathered at an anchor (the two bodies' poses in a
 * common frame, e.g. the world). A query bounds how far the bodies moved relative to each other
 * since the anchor by the sum of their own motions, each ‖R − R₀‖·r + |Rc + t − (R₀c + t₀)|
 * over its tree's {@linkplain KdopTree#boundingSphere() bounding sphere} (c, r) (for a point p
 * with |p − c| ≤ r, |(R − R₀)(p − c)| ≤ ‖R − R₀‖·r, the spectral norm, which for rotations is
 * the Frobenius norm over √2): two points that touch now were at most
 * that far apart at the anchor. A body that did not move adds exactly 0. If the bound is below
 * the clearance, the near pairs answer (only those whose own separation is below it are tested;
 * none at all while the bodies are farther apart than they have moved), and the relative pose
 * is not even computed when there is nothing to test. Otherwise it re-anchors, gathering the
 * pairs within a reach of {@link #REACH_MOVES} times the relative motion since the previous
 * query, so the new pairs last for about that many more such moves, and for the bisection
 * inside the last one.
 *
 * <p>Holds no query scratch: the {@link TreeQuery} is passed in (one per thread, shared by any
 * number of coherent queries). Not thread-safe.
 */
public final class CoherentQuery {
    /**
     * Reach of a gathering in units of the last relative motion. Chosen on the mug grasp
     * (docs/BENCHMARKS.md, simulation): 8, 16, 32 and 64 cost 338, 251, 199 and 195 walks and
     * 9 400, 12 400, 16 100 and 17 600 triangle tests; 8 and 16 ran equally fast, 32 and 64 6 %
     * slower (interleaved in one process). A reach adapted to each anchor's costs (halved or
     * doubled to balance the gathering against the extra tests) was 8 % slower there and no
     * faster on a sphere moving through another.
     */
    public static final double REACH_MOVES = 16;
    /** Bounds of the reach, in units of the smaller bounding radius. */
    public static final double REACH_MIN = 1e-5, REACH_MAX = 0.05;

    private final NearPairs near = new NearPairs();
    private final double[] anchorA = new double[12], anchorB = new double[12], lastA = new double[12], lastB = new double[12];
    private final double[] pose = new double[12], scratch = new double[12];
    private boolean hasLast;
    private long walks, reused;

    /** Forgets the near pairs and the last poses (the next query walks the trees). */
    public void reset() {
        near.clear();
        hasLast = false;
    }

    /**
     * All intersecting triangle pairs of A and B placed in a common frame by {@code worldFromA}
     * and {@code worldFromB} (12 row-major values each): exactly
     * {@code q.collide(a, b, A⁻¹·B, out)}, segments in A's frame. The trees must be the same
     * ones from call to call (call {@link #reset()} before changing them).
     *
     * @return {@code out}, whose node tests count the walk if this call walked the trees
     */
    public CollisionResult collide(TreeQuery q, KdopTree a, double[] worldFromA, KdopTree b, double[] worldFromB, CollisionResult out) {
        run(q, a, worldFromA, b, worldFromB, out, false);
        return out;
    }

    /** True if A and B intersect (exactly {@code collide(...).intersecting()}); stops at the first pair. */
    public boolean intersects(TreeQuery q, KdopTree a, double[] worldFromA, KdopTree b, double[] worldFromB, CollisionResult out) {
        run(q, a, worldFromA, b, worldFromB, out, true);
        return out.intersecting();
    }

    /**
     * Puts this query in the state of a new one (no near pairs, last poses or placement hints,
     * counters 0), keeping its arrays: for reuse on other trees by a new owner.
     */
    public void recycle() {
        reset();
        near.forgetHints();
        walks = 0;
        reused = 0;
    }

    /** @return how many calls walked the trees (gathered near pairs) */
    public long walks() { return walks; }

    /** @return how many calls were answered from near pairs gathered earlier */
    public long reused() { return reused; }

    /** @return the near pairs in use (read only) */
    public NearPairs nearPairs() { return near; }

    /**
     * The pose of B in A's frame the last call used, A⁻¹·B (12 values, row-major; a live array).
     * Up to date only after a call that tested or gathered pairs; {@link #placeRelative} makes it so.
     */
    public double[] relativePose() { return pose; }

    /** Computes {@link #relativePose()} for the given poses. */
    public void placeRelative(double[] worldFromA, double[] worldFromB) {
        RigidTransform.inverseTimes(worldFromA, worldFromB, scratch, pose);
    }

    private void run(TreeQuery q, KdopTree a, double[] wa, KdopTree b, double[] wb, CollisionResult out, boolean firstOnly) {
        double moved = Double.NaN;
        if (near.clearance() > 0) {
            double c = near.clearance();
            boolean aStill = same(anchorA, wa), bStill = same(anchorB, wb);
            double ra2 = aStill ? 0 : rotation2(anchorA, wa), ta2 = aStill ? 0 : centre2(a.sphere, anchorA, wa);
            double rb2 = bStill ? 0 : rotation2(anchorB, wb), tb2 = bStill ? 0 : centre2(b.sphere, anchorB, wb);
            double ra = a.sphere[3], rb = b.sphere[3];
            // (x₁ + … + x_n)² ≤ n(x₁² + … + x_n²), n the non-zero terms (2 for each body that moved): covered
            // without a root; with no pair to test the motion itself is not needed
            int terms = (aStill ? 0 : 2) + (bStill ? 0 : 2);
            if (near.size() == 0 && terms * (ra2 * ra * ra + ta2 + rb2 * rb * rb + tb2) < c * c) {
                reused++;
                keepLast(wa, wb);
                out.clear();
                return;
            }
            moved = Math.sqrt(ra2) * ra + Math.sqrt(ta2) + Math.sqrt(rb2) * rb + Math.sqrt(tb2);
            if (!near.covers(moved)) moved = Double.NaN;
        }
        placeRelative(wa, wb);
        boolean walked = Double.isNaN(moved);
        if (walked) {
            double step = hasLast ? motion(a.sphere, lastA, wa) + motion(b.sphere, lastB, wb) : 0;
            double r = Math.min(a.sphere[3], b.sphere[3]);
            double reach = Math.min(REACH_MAX * r, Math.max(REACH_MIN * r, REACH_MOVES * step));
            q.near(a, b, pose, 0, reach, near);
            System.arraycopy(wa, 0, anchorA, 0, 12);
            System.arraycopy(wb, 0, anchorB, 0, 12);
            moved = 0;
            walks++;
        } else {
            reused++;
        }
        keepLast(wa, wb);
        if (near.size() == 0) {
            out.clear();
        } else if (firstOnly) {
            q.intersects(a, b, pose, 0, near, moved, out);
        } else {
            q.collide(a, b, pose, 0, near, moved, out);
        }
        if (walked) out.nodeTests = near.nodeTests();
    }

    private static boolean same(double[] w0, double[] w1) {
        for (int i = 0; i < 12; i++) {
            if (w0[i] != w1[i]) return false;
        }
        return true;
    }

    private void keepLast(double[] wa, double[] wb) {
        System.arraycopy(wa, 0, lastA, 0, 12);
        System.arraycopy(wb, 0, lastB, 0, 12);
        hasLast = true;
    }

    /**
     * How far (metres) the points of a body inside {@code sphere} {cx, cy, cz, r} can move
     * between poses w0 and w1: ‖R₁ − R₀‖·r + |R₁c + t₁ − (R₀c + t₀)| (class comment).
     */
    static double motion(double[] sphere, double[] w0, double[] w1) {
        return Math.sqrt(rotation2(w0, w1)) * sphere[3] + Math.sqrt(centre2(sphere, w0, w1));
    }

    /**
     * ‖R₁ − R₀‖², the spectral norm squared, as ½‖R₁ − R₀‖²_F: for rotations R₁ − R₀ =
     * R₀(Q − I) with Q a rotation by some φ, whose singular values are 2 sin(φ/2) twice and 0, so
     * the Frobenius norm is exactly √2 times the spectral one. The poses are orthonormal to about
     * 10⁻¹⁵, an error the clearance's rounding margin (10⁻⁹ of the coordinates) covers many
     * times over.
     */
    private static double rotation2(double[] w0, double[] w1) {
        double f = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) f += sq(w1[4 * i + j] - w0[4 * i + j]);
        }
        return 0.5 * f;
    }

    /** |R₁c + t₁ − (R₀c + t₀)|² for the sphere's centre c. */
    private static double centre2(double[] sphere, double[] w0, double[] w1) {
        double s = 0;
        for (int i = 0; i < 3; i++) {
            s += sq((w1[4 * i] - w0[4 * i]) * sphere[0] + (w1[4 * i + 1] - w0[4 * i + 1]) * sphere[1]
                + (w1[4 * i + 2] - w0[4 * i + 2]) * sphere[2] + (w1[4 * i + 3] - w0[4 * i + 3]));
        }
        return s;
    }

    private static double sq(double x) { return x * x; }
}
