package org.handsim.collision;

import java.util.Arrays;

/**
 * The triangle pairs of two meshes that can intersect while their relative pose stays near the
 * pose they were gathered at: temporal coherence for a query that is repeated as a body moves a
 * little at a time (a finger link closing on an object, step after step and through the
 * bisection of an event).
 *
 * <p><b>Contract.</b> {@link TreeQuery#near} walks the two trees at a pose P₀ and keeps every
 * triangle pair whose bounds (k-DOPs down the trees, then the triangles' axis-aligned boxes)
 * are within the {@linkplain #reach() reach} δ of each other; every other pair is separated at
 * P₀ by more than δ, and the smallest of those separations, less a rounding margin, is the
 * {@linkplain #clearance() clearance} D ≥ δ (+∞ when no pair was dropped). Then for every pose
 * P such that no point of one mesh moves by D or more relative to the other between P₀ and P,
 * {@link TreeQuery#collide(KdopTree, KdopTree, double[], int, NearPairs, double, CollisionResult)} at P
 * returns exactly what the full query at P returns — the same pairs in the same order, the same
 * segments bit for bit:
 * <ul>
 *   <li>a pair that intersects at P has a common point; at P₀ that point of one mesh is at most
 *       the displacement away from the other mesh, so the pair's bounds are within D of each
 *       other there and the pair was kept;</li>
 *   <li>the kept pairs are tested with the same coordinates (the same placement formula) and
 *       the same exact triangle test as the full walk, and they are stored in the order the
 *       walk meets them, which does not depend on the bounds (a pre-order of the fixed tree of
 *       node pairs that bounds only prune).</li>
 * </ul>
 * Each kept pair also keeps its own separation at P₀ ({@link #separation(int)}: the largest of
 * its leaf k-DOPs' separation, its triangles' box gap and their gaps along the separating axes —
 * both normals and the nine edge–edge cross products, C. Ericson, "Real-Time Collision
 * Detection", 2005, §4.4): a pose displaced by less than it cannot make that pair intersect, so
 * the query skips it with one comparison, and a generous reach costs little. With no kept pair,
 * the meshes are certified apart for every such pose: conservative advancement (B. Mirtich,
 * "Impulse-based dynamic simulation of rigid body systems", PhD thesis, UC Berkeley 1996,
 * ch. 2) with the k-DOP tree's separations as the distance bound.
 *
 * <p>Not thread-safe; one per (moving body, other body) and thread.
 */
public final class NearPairs {
    int count;
    int[] triA = new int[32], triB = new int[32];
    /** Per pair: a lower bound on the distance between its two triangles at the gathering pose (≤ 0: may touch). */
    double[] gap = new double[32];
    /**
     * Per pair whose edge–edge axes are still to be tried ({@link #pending}): its gap before them
     * (not less the margin) and B's three vertices at the gathering pose (9 values from 9·i).
     */
    double[] boundWithoutEdges = new double[32], anchorB = new double[9 * 32];
    boolean[] pending = new boolean[32];
    /** The rounding margin the gathering took off every separation. */
    double margin;
    double reach, clearance = Double.NEGATIVE_INFINITY;
    /** Node pairs compared by the walk that gathered these pairs (for the counters). */
    long nodeTests;
    /** The facets the last gathering placed B's k-DOPs with (a first guess for the next; −1: none). */
    final int[] facetHints = newHints();

    private static int[] newHints() {
        int[] h = new int[TransformedBounds.FACET_HINTS];
        Arrays.fill(h, -1);
        return h;
    }

    /** Empties the set; its clearance becomes −∞ (it covers no pose until gathered). */
    public void clear() {
        count = 0;
        reach = 0;
        clearance = Double.NEGATIVE_INFINITY;
        nodeTests = 0;
    }

    /** Drops the placement hints (−1, as a new set has them). */
    void forgetHints() {
        Arrays.fill(facetHints, -1);
    }

    void add(int a, int b, double separation) {
        if (count == triA.length) grow();
        triA[count] = a;
        triB[count] = b;
        gap[count] = separation;
        pending[count] = false;
        count++;
    }

    /**
     * Adds a pair whose separation along the nine edge–edge axes is made only when a query
     * first needs it ({@link TreeQuery}: most kept pairs are never within the displacement of a
     * query): {@code bound} is its separation without those axes (&gt; 0, before the margin),
     * B's vertices at the gathering pose are {@code vb[b0..b0+2]}, {@code [b1..]}, {@code [b2..]}.
     */
    void addPending(int a, int b, double bound, double[] vb, int b0, int b1, int b2) {
        if (count == triA.length) grow();
        int i = count;
        triA[i] = a;
        triB[i] = b;
        gap[i] = bound - margin;
        boundWithoutEdges[i] = bound;
        pending[i] = true;
        double[] v = anchorB;
        int o = 9 * i;
        v[o] = vb[b0]; v[o + 1] = vb[b0 + 1]; v[o + 2] = vb[b0 + 2];
        v[o + 3] = vb[b1]; v[o + 4] = vb[b1 + 1]; v[o + 5] = vb[b1 + 2];
        v[o + 6] = vb[b2]; v[o + 7] = vb[b2 + 1]; v[o + 8] = vb[b2 + 2];
        count++;
    }

    private void grow() {
        int n = 2 * triA.length;
        triA = Arrays.copyOf(triA, n);
        triB = Arrays.copyOf(triB, n);
        gap = Arrays.copyOf(gap, n);
        boundWithoutEdges = Arrays.copyOf(boundWithoutEdges, n);
        pending = Arrays.copyOf(pending, n);
        anchorB = Arrays.copyOf(anchorB, 9 * n);
    }

    /** @return the node pairs the gathering walk compared (its k-DOP separations), the roots included */
    public long nodeTests() { return nodeTests; }

    /** @return the number of kept triangle pairs */
    public int size() { return count; }

    /** @return triangle of mesh A of kept pair i */
    public int triangleA(int i) { return triA[i]; }

    /** @return triangle of mesh B of kept pair i */
    public int triangleB(int i) { return triB[i]; }

    /**
     * @return a lower bound (metres) on the distance between kept pair i's triangles at the
     *         gathering pose, less the rounding margin; ≤ 0 when they may touch there. A pose
     *         displaced by less than this cannot make them intersect. The edge–edge axes'
     *         part of it is added when a query first needs it (until then the bound is lower).
     */
    public double separation(int i) { return gap[i]; }

    /** @return δ, the distance (metres) within which pairs were kept */
    public double reach() { return reach; }

    /**
     * @return D (metres): the set stands for the full query at any pose whose relative
     *         displacement from the gathering pose is less than D; −∞ before the first gathering
     */
    public double clearance() { return clearance; }

    /** @return true if a relative displacement of {@code metres} keeps the set exact */
    public boolean covers(double metres) { return metres < clearance; }
}
