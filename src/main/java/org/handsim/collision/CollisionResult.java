package org.handsim.collision;

import java.util.Arrays;

/**
 * The result of one collision query (tree walk or brute force): every intersecting triangle
 * pair with its segments, and the walk's counters. Flat, growable arrays reused from query to
 * query ({@link #clear()} keeps the capacity), so a query allocates nothing once the buffers
 * are big enough.
 *
 * <p>Pair p: triangle {@link #triangleA(int)} of mesh A, {@link #triangleB(int)} of mesh B,
 * {@link #isCoplanar(int)}, segments {@link #segmentStart(int)} up to (not including)
 * {@link #segmentStart(int) segmentStart(p + 1)}. Segment s: start at
 * {@code segments()[6s .. 6s+2]}, end at {@code [6s+3 .. 6s+5]}, in A's frame, metres. A
 * non-coplanar pair has one segment (zero length if the triangles touch at a point), oriented
 * along n_A × n_B; a coplanar pair the boundary of its overlap polygon
 * ({@link #coplanarArea(int)} m²). Pairs appear in the order the walk met them.
 *
 * <p>Not thread-safe; one per query object.
 */
public final class CollisionResult {
    private int pairs;
    private int[] triA = new int[64], triB = new int[64], segStart = new int[65];
    private boolean[] coplanar = new boolean[64];
    private double[] copArea = new double[64];
    private int segs;
    private double[] seg = new double[6 * 64];

    /**
     * Node pairs visited: every pair of nodes (one of A, one of B) whose k-DOPs the walk
     * compared, the roots included; one k-DOP overlap test each (the CLI's {@code node_tests}).
     */
    public long nodeTests;
    /** Triangle–triangle tests. */
    public long triangleTests;
    /** Triangle pairs skipped because one triangle has zero area. */
    public long degenerateSkipped;
    /** Orientation predicates that needed the exact stage. */
    public long exactPredicates;

    private int maxPairs = Integer.MAX_VALUE;

    /**
     * More intersecting triangle pairs than {@link #limitPairs} allows: the query stopped (the
     * result holds the pairs found up to the limit).
     */
    public static final class TooManyPairsException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        TooManyPairsException(int limit) {
            super("more than " + limit + " triangle pairs");
        }
    }

    /**
     * Stops a query with {@link TooManyPairsException} once it has found {@code max} pairs
     * (default: no limit; the simulation's contacts are a few hundred pairs).
     */
    public CollisionResult limitPairs(int max) {
        if (max < 1) throw new IllegalArgumentException("max pairs must be >= 1, got " + max);
        this.maxPairs = max;
        return this;
    }

    /** Empties the result and zeroes the counters (capacity kept). */
    public void clear() {
        pairs = 0;
        segs = 0;
        segStart[0] = 0;
        nodeTests = triangleTests = degenerateSkipped = exactPredicates = 0;
    }

    /** @return true if some pair intersects */
    public boolean intersecting() { return pairs > 0; }

    /** @return the number of intersecting triangle pairs */
    public int pairCount() { return pairs; }

    /** @return the total number of segments */
    public int segmentCount() { return segs; }

    public int triangleA(int p) { return triA[p]; }
    public int triangleB(int p) { return triB[p]; }
    public boolean isCoplanar(int p) { return coplanar[p]; }
    /** @return the overlap polygon's area of a coplanar pair (m²), else 0 */
    public double coplanarArea(int p) { return copArea[p]; }
    /** @return index of pair p's first segment; {@code segmentStart(pairCount())} = segmentCount() */
    public int segmentStart(int p) { return segStart[p]; }

    /** Internal segment array (6 doubles per segment); do not modify. */
    public double[] segments() { return seg; }

    /** @return the pairs as a sorted array of {@code (long) a << 32 | b} (tests, comparisons) */
    public long[] sortedPairKeys() {
        long[] k = new long[pairs];
        for (int i = 0; i < pairs; i++) k[i] = ((long) triA[i] << 32) | (triB[i] & 0xffffffffL);
        Arrays.sort(k);
        return k;
    }

    /** Appends the intersector's current result as pair (a, b). */
    void add(int a, int b, TriangleIntersector tt, int kind) {
        if (pairs == maxPairs) throw new TooManyPairsException(maxPairs);
        if (pairs == triA.length) {
            int c = 2 * pairs;
            triA = Arrays.copyOf(triA, c);
            triB = Arrays.copyOf(triB, c);
            coplanar = Arrays.copyOf(coplanar, c);
            copArea = Arrays.copyOf(copArea, c);
            segStart = Arrays.copyOf(segStart, c + 1);
        }
        int n = tt.segmentCount();
        if (6 * (segs + n) > seg.length) seg = Arrays.copyOf(seg, Math.max(2 * seg.length, 6 * (segs + n)));
        System.arraycopy(tt.segments(), 0, seg, 6 * segs, 6 * n);
        triA[pairs] = a;
        triB[pairs] = b;
        coplanar[pairs] = kind == TriangleIntersector.COPLANAR;
        copArea[pairs] = tt.coplanarArea();
        segs += n;
        pairs++;
        segStart[pairs] = segs;
    }
}
