package org.handsim.collision;

import java.util.Arrays;

/**
 * The smallest distance between two meshes' surfaces through their {@link KdopTree}s, B placed
 * in A's frame by a rigid transform: FCL's {@code distance} for two BVH models, on k-DOPs.
 *
 * <p><b>The walk</b> (branch and bound, as FCL's {@code distanceRecurse} and PQP's
 * {@code DistanceRecurse}): a depth-first walk over node pairs with the separation of their
 * k-DOPs ({@link Kdop#separation}, a lower bound on the distance between anything they hold) as
 * the bound: a pair whose bound is not below the best distance found so far is dropped; a pair
 * of leaves has its triangle pairs measured ({@link TriangleDistance}: the nine edge pairs and
 * six vertices over faces, and, only when that is below the best, the exact intersection test,
 * which makes it 0); otherwise the node with more triangles is split and the child pair with the
 * smaller bound is walked first. It stops at 0 (the meshes touch or intersect: FCL reports 0
 * then too). B is placed as {@link TreeQuery.Placement#TRANSFORM} places it: B's k-DOPs mapped by
 * a conservative linear map only where the walk goes ({@link TransformedBounds}; still lower
 * bounds), a leaf's bound fitted exactly to its placed vertices.
 *
 * <p>Results: {@link #distance}, the closest points {@link #pointA()}, {@link #pointB()} (A's
 * frame) and the counters of the last query. One instance per thread; allocation-free once its
 * scratch has grown to the trees.
 */
public final class DistanceQuery {
    private final TransformedBounds tb = new TransformedBounds();
    private final TriangleDistance td = new TriangleDistance();
    private final double[] m = new double[12];
    private int[] stack = new int[256];
    private double[] bound = new double[128];
    private double[] placedBounds = new double[0], placedVerts = new double[0];
    private int[] nodeStamp = new int[0], vertStamp = new int[0];
    private int stamp;
    private final double[] pa = new double[3], pb = new double[3];
    private long nodeTests, triangleTests;

    /**
     * The distance (m) between A and B, B placed in A's frame by the 12 row-major values at
     * {@code pose[off..]}: 0 when they touch or intersect; +∞ when either mesh is empty.
     *
     * @throws IllegalArgumentException if the trees have different k
     */
    public double distance(KdopTree a, KdopTree b, double[] pose, int off) {
        if (a.k() != b.k()) throw new IllegalArgumentException("trees have different k: " + a.k() + " and " + b.k());
        System.arraycopy(pose, off, m, 0, 12);
        nodeTests = triangleTests = 0;
        if (a.nodeCount == 0 || b.nodeCount == 0) return Double.POSITIVE_INFINITY;
        place(b);
        int k = a.k();
        Kdop kd = a.kdop();
        double best = Double.POSITIVE_INFINITY;
        final double[] ba = a.bounds, va = a.vertices(), vb = placedVerts;
        final int[] childA = a.child, childB = b.child, sizeA = a.size, sizeB = b.size;
        final int[] orderA = a.order, orderB = b.order, trisA = a.tris, trisB = b.tris;
        final boolean[] degA = a.degenerate, degB = b.degenerate;
        placeNode(b, 0);
        int sp = 0;
        stack[sp++] = 0;
        stack[sp++] = 0;
        bound[0] = kd.separation(ba, 0, placedBounds, 0);
        nodeTests = 1;
        while (sp > 0) {
            int nb = stack[--sp], na = stack[--sp];
            if (bound[sp >> 1] >= best) continue;
            int ca = childA[na], cb = childB[nb];
            if (ca < 0 && cb < 0) {
                for (int i = ~ca, ea = i + sizeA[na]; i < ea; i++) {
                    int ta = orderA[i];
                    if (degA[ta]) continue;
                    int a0 = 3 * trisA[3 * ta], a1 = 3 * trisA[3 * ta + 1], a2 = 3 * trisA[3 * ta + 2];
                    for (int j = ~cb, eb = j + sizeB[nb]; j < eb; j++) {
                        int tbi = orderB[j];
                        if (degB[tbi]) continue;
                        int b0 = 3 * trisB[3 * tbi], b1 = 3 * trisB[3 * tbi + 1], b2 = 3 * trisB[3 * tbi + 2];
                        triangleTests++;
                        double d = features(va, a0, a1, a2, vb, b0, b1, b2, best);
                        if (d < best) {
                            if (td.intersects(va, a0, a1, a2, vb, b0, b1, b2)) {
                                best = 0;
                                pa[0] = pb[0] = td.pointA[0]; pa[1] = pb[1] = td.pointA[1]; pa[2] = pb[2] = td.pointA[2];
                                return 0;
                            }
                            best = d;
                        }
                    }
                }
                continue;
            }
            if (sp + 4 > stack.length) {
                stack = Arrays.copyOf(stack, 2 * stack.length);
                bound = Arrays.copyOf(bound, stack.length / 2);
            }
            int n1a, n1b, n2a, n2b;
            if (cb < 0 || (ca >= 0 && sizeA[na] >= sizeB[nb])) {
                n1a = na + 1; n1b = nb; n2a = ca; n2b = nb;
            } else {
                placeChild(b, nb + 1);
                placeChild(b, cb);
                n1a = na; n1b = nb + 1; n2a = na; n2b = cb;
            }
            double s1 = kd.separation(ba, n1a * k, placedBounds, n1b * k), s2 = kd.separation(ba, n2a * k, placedBounds, n2b * k);
            nodeTests += 2;
            // the nearer pair last, so that it is walked first
            if (s1 <= s2) {
                if (s2 < best) { bound[sp >> 1] = s2; stack[sp++] = n2a; stack[sp++] = n2b; }
                if (s1 < best) { bound[sp >> 1] = s1; stack[sp++] = n1a; stack[sp++] = n1b; }
            } else {
                if (s1 < best) { bound[sp >> 1] = s1; stack[sp++] = n1a; stack[sp++] = n1b; }
                if (s2 < best) { bound[sp >> 1] = s2; stack[sp++] = n2a; stack[sp++] = n2b; }
            }
        }
        return best;
    }

    /** The smallest edge–edge and vertex–face distance of a triangle pair, the closest points kept when below {@code best}. */
    private double features(double[] va, int a0, int a1, int a2, double[] vb, int b0, int b1, int b2, double best) {
        double best2 = best * best, found = Double.POSITIVE_INFINITY;
        for (int i = 0; i < 3; i++) {
            int p = i == 0 ? a0 : i == 1 ? a1 : a2, q = i == 0 ? a1 : i == 1 ? a2 : a0;
            for (int j = 0; j < 3; j++) {
                int r = j == 0 ? b0 : j == 1 ? b1 : b2, s = j == 0 ? b1 : j == 1 ? b2 : b0;
                double d = td.segments(va, p, q, vb, r, s);
                if (d < found) {
                    found = d;
                    if (d < best2) keep(false);
                }
            }
        }
        for (int i = 0; i < 3; i++) {
            int p = i == 0 ? b0 : i == 1 ? b1 : b2;
            double d = td.pointTriangle(vb[p], vb[p + 1], vb[p + 2], va, a0, a1, a2);
            if (d < found) {
                found = d;
                if (d < best2) keep(true);
            }
            p = i == 0 ? a0 : i == 1 ? a1 : a2;
            d = td.pointTriangle(va[p], va[p + 1], va[p + 2], vb, b0, b1, b2);
            if (d < found) {
                found = d;
                if (d < best2) keep(false);
            }
        }
        return Math.sqrt(found);
    }

    /** Keeps the last feature call's points (swapped when B's vertex was measured against A's face). */
    private void keep(boolean swapped) {
        double[] x = swapped ? td.pointB : td.pointA, y = swapped ? td.pointA : td.pointB;
        pa[0] = x[0]; pa[1] = x[1]; pa[2] = x[2];
        pb[0] = y[0]; pb[1] = y[1]; pb[2] = y[2];
    }

    private void place(KdopTree b) {
        double[] bv = b.vertices();
        if (placedVerts.length < bv.length) placedVerts = new double[bv.length];
        if (placedBounds.length < b.bounds.length) placedBounds = new double[b.bounds.length];
        if (vertStamp.length < bv.length / 3) vertStamp = new int[bv.length / 3];
        if (nodeStamp.length < b.nodeCount) nodeStamp = new int[b.nodeCount];
        if (++stamp == Integer.MAX_VALUE) {
            Arrays.fill(nodeStamp, 0);
            Arrays.fill(vertStamp, 0);
            stamp = 1;
        }
        tb.prepare(b.kdop(), m);
    }

    private void placeChild(KdopTree b, int nb) {
        if (nodeStamp[nb] != stamp) placeNode(b, nb);
    }

    /** B node nb's bounds in A's frame: a leaf's fitted to its placed vertices, an inner node's mapped. */
    private void placeNode(KdopTree b, int nb) {
        nodeStamp[nb] = stamp;
        int k = b.k(), o = nb * k;
        int c = b.child[nb];
        if (c < 0) {
            Kdop kd = b.kdop();
            kd.setEmpty(placedBounds, o);
            double[] src = b.vertices();
            for (int j = ~c, e = j + b.size[nb]; j < e; j++) {
                int t = 3 * b.order[j];
                for (int q = 0; q < 3; q++) {
                    int p = 3 * b.tris[t + q];
                    if (vertStamp[p / 3] != stamp) {
                        KdopTree.transformPoint(m, src, p, placedVerts, p);
                        vertStamp[p / 3] = stamp;
                    }
                    kd.addPoint(placedBounds, o, placedVerts[p], placedVerts[p + 1], placedVerts[p + 2]);
                }
            }
        } else {
            tb.apply(b.bounds, o, placedBounds, o);
        }
    }

    /** @return the closest point on A of the last query (A's frame, a copy) */
    public double[] pointA() { return pa.clone(); }

    /** @return the closest point on B of the last query (A's frame, a copy) */
    public double[] pointB() { return pb.clone(); }

    /** @return node pairs whose bounds the last query compared */
    public long nodeTests() { return nodeTests; }

    /** @return triangle pairs the last query measured */
    public long triangleTests() { return triangleTests; }
}
