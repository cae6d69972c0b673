package org.handsim.collision;

/**
 * Discrete-orientation polytopes (k-DOPs): the bounding volume of {@link KdopTree}.
 *
 * <p><b>What a k-DOP is (Klosowski et al. 1998).</b> Fix k/2 directions d₀ … d_{k/2−1}. The
 * k-DOP of a point set S is the intersection of the k/2 slabs
 * {@code min_{p∈S} dᵢ·p ≤ dᵢ·x ≤ max_{p∈S} dᵢ·p}: the tightest convex polytope whose faces
 * have those k fixed normals. k = 6 is the axis-aligned box; more directions cut the box's
 * edges (18) and corners (14) or both (26), so the volume hugs curved and slanted geometry
 * better at the price of more numbers per test. Because the directions are the same for every
 * k-DOP in one frame, two k-DOPs are disjoint exactly when one of the k/2 interval pairs is
 * disjoint: the overlap test is two comparisons per direction, and the merge of two k-DOPs is
 * a min and a max per direction.
 *
 * <p><b>Direction sets.</b> Integer, unnormalised (as FCL's {@code kDOP.h}), so a projection
 * is a sum of coordinates; listed in the order they are stored (axes first, because they
 * reject most often):
 * <table border="1"><caption>directions by k</caption>
 * <tr><th>index i</th><th>dᵢ</th><th>6</th><th>14</th><th>18</th><th>26</th></tr>
 * <tr><td>0, 1, 2</td><td>x, y, z</td><td>✓</td><td>✓</td><td>✓</td><td>✓</td></tr>
 * <tr><td>next 6</td><td>x+y, x+z, y+z, x−y, x−z, y−z</td><td></td><td></td><td>✓ (3..8)</td><td>✓ (3..8)</td></tr>
 * <tr><td>next 4</td><td>x+y+z, x+y−z, x−y+z, −x+y+z</td><td></td><td>✓ (3..6)</td><td></td><td>✓ (9..12)</td></tr>
 * </table>
 *
 * <p><b>Slot table (docs/STYLE.md, item 6).</b> The bounds of one k-DOP are k doubles at
 * {@code b[off .. off+k−1]}: slot {@code 2i} = min over the set of dᵢ·p, slot {@code 2i+1} =
 * max. So for every k, slots 0..5 are the axis-aligned box (xmin, xmax, ymin, ymax, zmin,
 * zmax); for k = 26, slots 6, 7 are min/max of x+y and slots 24, 25 min/max of −x+y+z. An
 * empty k-DOP has min = +∞ and max = −∞ in every slot.
 *
 * <p><b>Rounding.</b> A bounds array must contain the exact projection of every point of the
 * set, or a pair of meshes that touch in one point could be culled. Axis slots are exact;
 * the sums of two or three coordinates are rounded, so {@link #addPoint} widens them outward
 * by 4ε·(|x| + |y| + |z|), ε = 2⁻⁵³, which exceeds the rounding error of the sum and of the
 * widening itself.
 *
 * <p>Instances are immutable and shared ({@link #of}); all methods are allocation-free and
 * thread-safe (they write only into the caller's arrays).
 *
 * <p>References: J. T. Klosowski, M. Held, J. S. B. Mitchell, H. Sowizral, K. Zikan,
 * "Efficient collision detection using bounding volume hierarchies of k-DOPs", IEEE TVCG
 * 4(1):21–36, 1998; FCL {@code include/fcl/math/bv/kDOP.h}.
 */
public final class Kdop {
    /** The supported values of k. */
    public static final int[] SUPPORTED_K = {6, 14, 18, 26};

    private static final double[][] AXES = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    private static final double[][] EDGES = {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}};
    private static final double[][] CORNERS = {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
    /** Outward widening of the rounded slots, per unit of |x| + |y| + |z|. */
    static final double MARGIN = 4 * Predicates.EPSILON;

    private static final Kdop K6 = new Kdop(6, AXES);
    private static final Kdop K14 = new Kdop(14, AXES, CORNERS);
    private static final Kdop K18 = new Kdop(18, AXES, EDGES);
    private static final Kdop K26 = new Kdop(26, AXES, EDGES, CORNERS);

    private final int k;
    private final int m;
    final double[] dx, dy, dz;
    /** 1/|dᵢ| per direction: a slab gap times this is a Euclidean distance. */
    final double[] invLength;
    private final TransformedBounds.Facets facets;

    private Kdop(int k, double[][]... groups) {
        this.k = k;
        this.m = k / 2;
        dx = new double[m];
        dy = new double[m];
        dz = new double[m];
        invLength = new double[m];
        int i = 0;
        for (double[][] g : groups) {
            for (double[] d : g) {
                dx[i] = d[0];
                dy[i] = d[1];
                dz[i] = d[2];
                invLength[i] = 1 / Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                i++;
            }
        }
        facets = new TransformedBounds.Facets(dx, dy, dz);
    }

    /**
     * @param k 6, 14, 18 or 26
     * @return the shared instance for k
     * @throws IllegalArgumentException naming k if it is not supported
     */
    public static Kdop of(int k) {
        switch (k) {
            case 6: return K6;
            case 14: return K14;
            case 18: return K18;
            case 26: return K26;
            default: throw new IllegalArgumentException("k must be 6, 14, 18 or 26, got " + k);
        }
    }

    /** @return k, the number of slots (twice the number of directions) */
    public int k() { return k; }

    /** @return k/2, the number of directions */
    public int directionCount() { return m; }

    TransformedBounds.Facets facets() { return facets; }

    /** Makes {@code b[off..off+k−1]} the empty k-DOP (min = +∞, max = −∞). */
    public void setEmpty(double[] b, int off) {
        for (int j = 0; j < k; j += 2) {
            b[off + j] = Double.POSITIVE_INFINITY;
            b[off + j + 1] = Double.NEGATIVE_INFINITY;
        }
    }

    /** Grows the k-DOP at {@code b[off..]} to contain the point (x, y, z) (metres). */
    public void addPoint(double[] b, int off, double x, double y, double z) {
        // axes: exact
        if (x < b[off]) b[off] = x;
        if (x > b[off + 1]) b[off + 1] = x;
        if (y < b[off + 2]) b[off + 2] = y;
        if (y > b[off + 3]) b[off + 3] = y;
        if (z < b[off + 4]) b[off + 4] = z;
        if (z > b[off + 5]) b[off + 5] = z;
        if (m == 3) return;
        double mg = MARGIN * (Math.abs(x) + Math.abs(y) + Math.abs(z));
        int s = off + 6;
        if (k != 14) {   // edge directions, slots 6..17
            slot(b, s, x + y, mg);
            slot(b, s + 2, x + z, mg);
            slot(b, s + 4, y + z, mg);
            slot(b, s + 6, x - y, mg);
            slot(b, s + 8, x - z, mg);
            slot(b, s + 10, y - z, mg);
            s += 12;
        }
        if (k != 18) {   // corner directions
            slot(b, s, x + y + z, mg);
            slot(b, s + 2, x + y - z, mg);
            slot(b, s + 4, x - y + z, mg);
            slot(b, s + 6, -x + y + z, mg);
        }
    }

    private static void slot(double[] b, int s, double p, double mg) {
        double lo = p - mg, hi = p + mg;
        if (lo < b[s]) b[s] = lo;
        if (hi > b[s + 1]) b[s + 1] = hi;
    }

    /**
     * Fits the k-DOP of points {@code pts[3i..3i+2]}, i in [0, n), into {@code b[off..]}.
     */
    public void fit(double[] pts, int n, double[] b, int off) {
        setEmpty(b, off);
        for (int i = 0; i < n; i++) addPoint(b, off, pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
    }

    /**
     * out = the k-DOP of the union of a and c (slot-wise min and max). {@code out} may alias
     * either input.
     */
    public static void merge(double[] a, int ao, double[] c, int co, double[] out, int oo, int k) {
        for (int j = 0; j < k; j += 2) {
            out[oo + j] = Math.min(a[ao + j], c[co + j]);
            out[oo + j + 1] = Math.max(a[ao + j + 1], c[co + j + 1]);
        }
    }

    /**
     * True when the two k-DOPs (same k, same frame) overlap: no direction separates them.
     * Closed: k-DOPs that only touch overlap. Two comparisons per direction, stops at the first
     * separating one.
     */
    public static boolean overlap(double[] a, int ao, double[] c, int co, int k) {
        // unrolled per k: about a fifth faster than the loop in the tree walk (docs/BENCHMARKS.md, collision)
        switch (k) {
            case 18: return overlap18(a, ao, c, co);
            case 26: return overlap26(a, ao, c, co);
            case 14: return overlap14(a, ao, c, co);
            default: return overlap6(a, ao, c, co);
        }
    }

    private static boolean overlap6(double[] a, int ao, double[] c, int co) {
        return !(a[ao] > c[co + 1] || c[co] > a[ao + 1])
            && !(a[ao + 2] > c[co + 3] || c[co + 2] > a[ao + 3])
            && !(a[ao + 4] > c[co + 5] || c[co + 4] > a[ao + 5]);
    }

    private static boolean overlap14(double[] a, int ao, double[] c, int co) {
        return !(a[ao] > c[co + 1] || c[co] > a[ao + 1])
            && !(a[ao + 2] > c[co + 3] || c[co + 2] > a[ao + 3])
            && !(a[ao + 4] > c[co + 5] || c[co + 4] > a[ao + 5])
            && !(a[ao + 6] > c[co + 7] || c[co + 6] > a[ao + 7])
            && !(a[ao + 8] > c[co + 9] || c[co + 8] > a[ao + 9])
            && !(a[ao + 10] > c[co + 11] || c[co + 10] > a[ao + 11])
            && !(a[ao + 12] > c[co + 13] || c[co + 12] > a[ao + 13]);
    }

    private static boolean overlap18(double[] a, int ao, double[] c, int co) {
        return !(a[ao] > c[co + 1] || c[co] > a[ao + 1])
            && !(a[ao + 2] > c[co + 3] || c[co + 2] > a[ao + 3])
            && !(a[ao + 4] > c[co + 5] || c[co + 4] > a[ao + 5])
            && !(a[ao + 6] > c[co + 7] || c[co + 6] > a[ao + 7])
            && !(a[ao + 8] > c[co + 9] || c[co + 8] > a[ao + 9])
            && !(a[ao + 10] > c[co + 11] || c[co + 10] > a[ao + 11])
            && !(a[ao + 12] > c[co + 13] || c[co + 12] > a[ao + 13])
            && !(a[ao + 14] > c[co + 15] || c[co + 14] > a[ao + 15])
            && !(a[ao + 16] > c[co + 17] || c[co + 16] > a[ao + 17]);
    }

    private static boolean overlap26(double[] a, int ao, double[] c, int co) {
        return !(a[ao] > c[co + 1] || c[co] > a[ao + 1])
            && !(a[ao + 2] > c[co + 3] || c[co + 2] > a[ao + 3])
            && !(a[ao + 4] > c[co + 5] || c[co + 4] > a[ao + 5])
            && !(a[ao + 6] > c[co + 7] || c[co + 6] > a[ao + 7])
            && !(a[ao + 8] > c[co + 9] || c[co + 8] > a[ao + 9])
            && !(a[ao + 10] > c[co + 11] || c[co + 10] > a[ao + 11])
            && !(a[ao + 12] > c[co + 13] || c[co + 12] > a[ao + 13])
            && !(a[ao + 14] > c[co + 15] || c[co + 14] > a[ao + 15])
            && !(a[ao + 16] > c[co + 17] || c[co + 16] > a[ao + 17])
            && !(a[ao + 18] > c[co + 19] || c[co + 18] > a[ao + 19])
            && !(a[ao + 20] > c[co + 21] || c[co + 20] > a[ao + 21])
            && !(a[ao + 22] > c[co + 23] || c[co + 22] > a[ao + 23])
            && !(a[ao + 24] > c[co + 25] || c[co + 24] > a[ao + 25]);
    }

    /**
     * A lower bound on the Euclidean distance between the contents of two k-DOPs (same k, same
     * frame): the widest gap between their slabs along one direction, divided by the
     * direction's length; zero or negative when they overlap. All k/2 directions, no early exit
     * (the coherent gathering of {@link NearPairs} wants the best bound).
     */
    public double separation(double[] a, int ao, double[] c, int co) {
        double s = Double.NEGATIVE_INFINITY;
        for (int j = 0, i = 0; j < k; j += 2, i++) {
            double g = Math.max(a[ao + j] - c[co + j + 1], c[co + j] - a[ao + j + 1]) * invLength[i];
            if (g > s) s = g;
        }
        return s;
    }

    /**
     * {@link #separation} when it is at most {@code limit}; otherwise some value above
     * {@code limit} that is still a lower bound on the distance (the first direction whose gap
     * exceeds the limit: the rest are not looked at).
     */
    public double separationUpTo(double[] a, int ao, double[] c, int co, double limit) {
        double s = Double.NEGATIVE_INFINITY;
        for (int j = 0, i = 0; j < k; j += 2, i++) {
            double g = Math.max(a[ao + j] - c[co + j + 1], c[co + j] - a[ao + j + 1]) * invLength[i];
            if (g > limit) return g;
            if (g > s) s = g;
        }
        return s;
    }

    /** True when the point's projections lie inside every slab (closed). */
    public boolean contains(double[] b, int off, double x, double y, double z) {
        for (int i = 0; i < m; i++) {
            double p = dx[i] * x + dy[i] * y + dz[i] * z;
            if (p < b[off + 2 * i] || p > b[off + 2 * i + 1]) return false;
        }
        return true;
    }
}
