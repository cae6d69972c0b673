package org.handsim.collision;

/**
 * The collision query of one pair of bodies that is asked again and again as they move a little
 * (a finger link closing on an object step by step, the bisection of its first touch): the
 * same result as {@link TreeQuery#collide(KdopTree, KdopTree, double[], int, CollisionResult)}
 * every time, bit for bit, mostly without walking the trees (temporal coherence).
 *
 * <p><b>How.</b> It keeps the {@link NearPairs} gathered at an anchor pose. A query at pose P
 * bounds how far the bodies moved relative to each other since the anchor,
 * δ(P) = min(‖R − R₀‖_F·r_A + |P⁻¹c_A − P₀⁻¹c_A|, ‖R − R₀‖_F·r_B + |Pc_B − P₀c_B|) with (c, r)
 * each tree's {@linkplain KdopTree#boundingSphere() bounding sphere}: the first term bounds the
 * motion of A's points seen from B, the second that of B's points seen from A (for a point p at
 * distance ≤ r from c, |(R − R₀)(p − c)| ≤ ‖R − R₀‖_F·r); either bounds the distance a pair
 * touching at P had at the anchor. If δ is below the clearance, the near pairs answer (only
 * those whose own separation is below δ are tested; none at all while the bodies are farther
 * apart than they have moved). Otherwise it re-anchors at P, gathering the pairs within a reach
 * of {@link #REACH_MOVES} times the relative motion since the previous query, so the new pairs
 * last for about that many more such moves, and for the bisection inside the last one.
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
    private final double[] anchor = new double[12], last = new double[12], pose = new double[12];
    private boolean hasLast;
    private long walks, reused;

    /** Forgets the near pairs and the last pose (the next query walks the trees). */
    public void reset() {
        near.clear();
        hasLast = false;
    }

    /**
     * All intersecting triangle pairs of A and B, B placed in A's frame by the 12 row-major
     * values at {@code pose[off..]}: exactly {@code q.collide(a, b, pose, off, out)}. The trees
     * must be the same ones from call to call (call {@link #reset()} before changing them).
     *
     * @return {@code out}, whose node tests count the walk if this call walked the trees
     */
    public CollisionResult collide(TreeQuery q, KdopTree a, KdopTree b, double[] pose, int off, CollisionResult out) {
        run(q, a, b, pose, off, out, false);
        return out;
    }

    /** True if A and B placed by {@code pose} intersect (exactly {@code collide(...).intersecting()}); stops at the first pair. */
    public boolean intersects(TreeQuery q, KdopTree a, KdopTree b, double[] pose, int off, CollisionResult out) {
        run(q, a, b, pose, off, out, true);
        return out.intersecting();
    }

    /** @return how many calls walked the trees (gathered near pairs) */
    public long walks() { return walks; }

    /** @return how many calls were answered from near pairs gathered earlier */
    public long reused() { return reused; }

    /** @return the near pairs in use (read only) */
    public NearPairs nearPairs() { return near; }

    private void run(TreeQuery q, KdopTree a, KdopTree b, double[] p, int off, CollisionResult out, boolean firstOnly) {
        System.arraycopy(p, off, pose, 0, 12);
        double moved = Double.NaN;
        if (near.clearance() > 0) {
            double c = near.clearance(), ra = a.sphere[3], rb = b.sphere[3];
            rot2 = rotation2(anchor, pose);
            if (near.size() == 0) {
                // (x + y)² ≤ 2(x² + y²): covered without a root, and with no pair to test the motion itself
                // is not needed; the side with the smaller sphere first (its bound is usually the smaller)
                boolean aSmaller = ra <= rb;
                double r1 = aSmaller ? ra : rb;
                double t1 = aSmaller ? seenFromB2(a, anchor, pose) : seenFromA2(b, anchor, pose);
                if (2 * (rot2 * r1 * r1 + t1) < c * c) {
                    reused++;
                    keepLast();
                    out.clear();
                    return;
                }
            }
            fromA2 = seenFromA2(b, anchor, pose);
            fromB2 = seenFromB2(a, anchor, pose);
            moved = motion(ra, rb);
            if (!near.covers(moved)) moved = Double.NaN;
        }
        boolean walked = Double.isNaN(moved);
        if (walked) {
            double step = 0;
            if (hasLast) {
                terms(a, b, last, pose);
                step = motion(a.sphere[3], b.sphere[3]);
            }
            double r = Math.min(a.sphere[3], b.sphere[3]);
            double reach = Math.min(REACH_MAX * r, Math.max(REACH_MIN * r, REACH_MOVES * step));
            q.near(a, b, pose, 0, reach, near);
            System.arraycopy(pose, 0, anchor, 0, 12);
            moved = 0;
            walks++;
        } else {
            reused++;
        }
        keepLast();
        if (near.size() == 0) {
            out.clear();
        } else if (firstOnly) {
            q.intersects(a, b, pose, 0, near, moved, out);
        } else {
            q.collide(a, b, pose, 0, near, moved, out);
        }
        if (walked) out.nodeTests = near.nodeTests();
    }

    private void keepLast() {
        System.arraycopy(pose, 0, last, 0, 12);
        hasLast = true;
    }

    // the squared terms of the motion bound between two poses (terms(), then motion())
    private double rot2, fromA2, fromB2;

    /** The squared terms of δ between poses p0 and p1 (class comment), into {@link #rot2}, {@link #fromA2}, {@link #fromB2}. */
    private void terms(KdopTree a, KdopTree b, double[] p0, double[] p1) {
        rot2 = rotation2(p0, p1);
        fromA2 = seenFromA2(b, p0, p1);
        fromB2 = seenFromB2(a, p0, p1);
    }

    /** ‖R₁ − R₀‖²_F. */
    private static double rotation2(double[] p0, double[] p1) {
        double f = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) f += sq(p1[4 * i + j] - p0[4 * i + j]);
        }
        return f;
    }

    /** |P₁c_B − P₀c_B|²: how far B's sphere centre moved seen from A. */
    private static double seenFromA2(KdopTree b, double[] p0, double[] p1) {
        double[] cb = b.sphere;
        double g = 0;
        for (int i = 0; i < 3; i++) {
            g += sq((p1[4 * i] - p0[4 * i]) * cb[0] + (p1[4 * i + 1] - p0[4 * i + 1]) * cb[1] + (p1[4 * i + 2] - p0[4 * i + 2]) * cb[2]
                + (p1[4 * i + 3] - p0[4 * i + 3]));
        }
        return g;
    }

    /** |P₁⁻¹c_A − P₀⁻¹c_A|² with P⁻¹c = Rᵀ(c − t): how far A's sphere centre moved seen from B. */
    private static double seenFromB2(KdopTree a, double[] p0, double[] p1) {
        double[] ca = a.sphere;
        double h = 0;
        for (int j = 0; j < 3; j++) {
            double x1 = p1[j] * (ca[0] - p1[3]) + p1[4 + j] * (ca[1] - p1[7]) + p1[8 + j] * (ca[2] - p1[11]);
            double x0 = p0[j] * (ca[0] - p0[3]) + p0[4 + j] * (ca[1] - p0[7]) + p0[8 + j] * (ca[2] - p0[11]);
            h += sq(x1 - x0);
        }
        return h;
    }

    /** δ between poses p0 and p1 of B in A's frame (metres; for tests). */
    static double motion(KdopTree a, KdopTree b, double[] p0, double[] p1) {
        CoherentQuery c = new CoherentQuery();
        c.terms(a, b, p0, p1);
        return c.motion(a.sphere[3], b.sphere[3]);
    }

    /** δ from the last {@link #terms}: the smaller of the two bounds (metres). */
    private double motion(double ra, double rb) {
        double rot = Math.sqrt(rot2);
        return Math.min(rot * rb + Math.sqrt(fromA2), rot * ra + Math.sqrt(fromB2));
    }

    private static double sq(double x) { return x * x; }
}
