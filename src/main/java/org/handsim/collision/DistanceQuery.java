package org.handsim.collision;

import java.util.Arrays;

/**
 * The smallest distance between two meshes' surfaces through their {@link KdopTree}s, B placed
 * in A's frame by a rigid transform: FCL's {@code distance} for two BVH models, on k-DOPs.
 *
 * <p><b>The walk</b> (branch and bound, as FCL's {@code distanceRecurse} and PQP's
 * {@code DistanceRecurse}): a depth-first walk over node pairs with a lower bound on the distance
 * between anything they hold — the larger of their k-DOPs' separation ({@link Kdop#separation})
 * and {@link #shapeGap} (spheres and slabs along the nodes' mean normals, made once per tree: the
 * k-DOPs' fixed directions bound loosely across a diagonal, two spheres near along (1, 1, 1) at
 * k = 18) — as the bound: a pair whose bound is not below the best distance found so far is dropped; a pair
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
    private int[] nodeStamp = new int[0], vertStamp = new int[0], centreStamp = new int[0];
    private int stamp;
    private final double[] pa = new double[3], pb = new double[3];
    // node spheres (cx, cy, cz, r per node) of the last trees seen, with the root bounds they were made for
    private final NodeShapes shapesA = new NodeShapes(), shapesB = new NodeShapes();
    private double[] placedShapes = new double[0];
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
        final double[] sa = shapesA.of(a), sb = shapesB.of(b);
        if (placedShapes.length < 6 * b.nodeCount) placedShapes = new double[6 * b.nodeCount];
        double best = Double.POSITIVE_INFINITY;
        final double[] ba = a.bounds, va = a.vertices(), vb = placedVerts;
        final int[] childA = a.child, childB = b.child, sizeA = a.size, sizeB = b.size;
        final int[] orderA = a.order, orderB = b.order, trisA = a.tris, trisB = b.tris;
        final boolean[] degA = a.degenerate, degB = b.degenerate;
        placeNode(b, 0);
        int sp = 0;
        stack[sp++] = 0;
        stack[sp++] = 0;
        bound[0] = Math.max(kd.separation(ba, 0, placedBounds, 0), shapeGap(sa, 0, sb, 0));
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
                        // a triangle wholly farther than the best from the other's plane: skipped
                        // (6 dot products instead of 15 closest-point problems)
                        if (planeGap(va, a0, a1, a2, vb, b0, b1, b2) >= best || planeGap(vb, b0, b1, b2, va, a0, a1, a2) >= best) continue;
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
            double s1 = Math.max(kd.separation(ba, n1a * k, placedBounds, n1b * k), shapeGap(sa, n1a, sb, n1b));
            double s2 = Math.max(kd.separation(ba, n2a * k, placedBounds, n2b * k), shapeGap(sa, n2a, sb, n2b));
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

    /**
     * A lower bound on the distance between A's node na and B's node nb from their shapes
     * ({@link NodeShapes}: centre c, radius r, mean normal n, half-thickness t about c along n):
     * the larger of the spheres' gap |c_A − c_B| − r_A − r_B and the gaps of the two nodes'
     * projections on n_A and on n_B, where a node projects onto a unit u within
     * u·c ± (t|u·n| + r·√(1 − (u·n)²)). Two nearly parallel patches facing each other (a near
     * miss) project thin on each other's normal, where the k-DOPs' fixed directions and the
     * spheres both bound loosely. B's centre and normal are placed once per query.
     */
    private double shapeGap(double[] sa, int na, double[] sb, int nb) {
        int o = 8 * nb, c = 6 * nb;
        double[] pc = placedShapes;
        if (centreStamp[nb] != stamp) {
            centreStamp[nb] = stamp;
            double x = sb[o], y = sb[o + 1], z = sb[o + 2];
            pc[c] = m[0] * x + m[1] * y + m[2] * z + m[3];
            pc[c + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
            pc[c + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
            x = sb[o + 4]; y = sb[o + 5]; z = sb[o + 6];
            pc[c + 3] = m[0] * x + m[1] * y + m[2] * z;
            pc[c + 4] = m[4] * x + m[5] * y + m[6] * z;
            pc[c + 5] = m[8] * x + m[9] * y + m[10] * z;
        }
        int p = 8 * na;
        double ax = sa[p], ay = sa[p + 1], az = sa[p + 2], ra = sa[p + 3], ux = sa[p + 4], uy = sa[p + 5], uz = sa[p + 6], ta = sa[p + 7];
        double bx = pc[c], by = pc[c + 1], bz = pc[c + 2], rb = sb[o + 3], wx = pc[c + 3], wy = pc[c + 4], wz = pc[c + 5], tb = sb[o + 7];
        double dx = bx - ax, dy = by - ay, dz = bz - az;
        double gap = Math.sqrt(dx * dx + dy * dy + dz * dz) - ra - rb;
        double cosAB = Math.abs(ux * wx + uy * wy + uz * wz), sinAB = Math.sqrt(Math.max(0, 1 - cosAB * cosAB));
        // on n_A: A within ±t_A, B within ±(t_B|cos| + r_B sin)
        double along = Math.abs(ux * dx + uy * dy + uz * dz) - ta - (tb * cosAB + rb * sinAB);
        // on n_B: B within ±t_B, A within ±(t_A|cos| + r_A sin)
        double along2 = Math.abs(wx * dx + wy * dy + wz * dz) - tb - (ta * cosAB + ra * sinAB);
        return Math.max(gap, Math.max(along, along2)) * (1 - 1e-12) - 1e-15 * (Math.abs(ax) + Math.abs(ay) + Math.abs(az) + ra + rb);
    }

    /**
     * The shape of each node of a tree, made when a tree is first seen (and again if its root
     * bounds changed: a refit), from the node's own vertices: centre c (its box's centre), radius
     * r (the farthest vertex), unit mean normal n (the area-weighted normals' sum, or +z when it
     * cancels) and half-thickness t (the farthest vertex from the plane through c normal to n);
     * 8 values per node. O(n · depth) once per tree.
     */
    private static final class NodeShapes {
        private KdopTree tree;
        private double[] root = new double[0];
        private double[] shapes = new double[0];
        private int[] first = new int[0];

        double[] of(KdopTree t) {
            int k = t.k();
            boolean same = t == tree && root.length == k;
            for (int i = 0; same && i < k; i++) same = root[i] == t.bounds[i];
            if (same) return shapes;
            tree = t;
            root = java.util.Arrays.copyOf(t.bounds, k);
            int n = t.nodeCount;
            if (shapes.length < 8 * n) shapes = new double[8 * n];
            if (first.length < n) first = new int[n];
            for (int i = n - 1; i >= 0; i--) first[i] = t.child[i] < 0 ? ~t.child[i] : first[i + 1];
            double[] v = t.vertices(), b = t.bounds, s = shapes;
            for (int i = 0; i < n; i++) {
                int o = i * k;
                double cx = 0.5 * (b[o] + b[o + 1]), cy = 0.5 * (b[o + 2] + b[o + 3]), cz = 0.5 * (b[o + 4] + b[o + 5]);
                double sx = 0, sy = 0, sz = 0;
                for (int j = first[i], e = j + t.size[i]; j < e; j++) {
                    int tri = 3 * t.order[j];
                    int a = 3 * t.tris[tri], bb = 3 * t.tris[tri + 1], c = 3 * t.tris[tri + 2];
                    double ux = v[bb] - v[a], uy = v[bb + 1] - v[a + 1], uz = v[bb + 2] - v[a + 2];
                    double wx = v[c] - v[a], wy = v[c + 1] - v[a + 1], wz = v[c + 2] - v[a + 2];
                    sx += uy * wz - uz * wy; sy += uz * wx - ux * wz; sz += ux * wy - uy * wx;
                }
                double len = Math.sqrt(sx * sx + sy * sy + sz * sz);
                if (len > 0) { sx /= len; sy /= len; sz /= len; } else { sx = 0; sy = 0; sz = 1; }
                double r2 = 0, th = 0;
                for (int j = first[i], e = j + t.size[i]; j < e; j++) {
                    int tri = 3 * t.order[j];
                    for (int q = 0; q < 3; q++) {
                        int p = 3 * t.tris[tri + q];
                        double dx = v[p] - cx, dy = v[p + 1] - cy, dz = v[p + 2] - cz;
                        r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
                        th = Math.max(th, Math.abs(sx * dx + sy * dy + sz * dz));
                    }
                }
                double r = Math.sqrt(r2);
                s[8 * i] = cx; s[8 * i + 1] = cy; s[8 * i + 2] = cz;
                s[8 * i + 3] = r * (1 + 1e-12) + 1e-15 * (Math.abs(cx) + Math.abs(cy) + Math.abs(cz));
                s[8 * i + 4] = sx; s[8 * i + 5] = sy; s[8 * i + 6] = sz;
                s[8 * i + 7] = th * (1 + 1e-12) + 1e-15 * (Math.abs(cx) + Math.abs(cy) + Math.abs(cz) + r);
            }
            return s;
        }
    }

    /**
     * How far triangle q lies from the plane of triangle p on one side (the smallest of its
     * vertices' distances when all are on the same side; 0 otherwise): a lower bound on the
     * distance between the triangles.
     */
    private static double planeGap(double[] vp, int p0, int p1, int p2, double[] vq, int q0, int q1, int q2) {
        double ux = vp[p1] - vp[p0], uy = vp[p1 + 1] - vp[p0 + 1], uz = vp[p1 + 2] - vp[p0 + 2];
        double wx = vp[p2] - vp[p0], wy = vp[p2 + 1] - vp[p0 + 1], wz = vp[p2 + 2] - vp[p0 + 2];
        double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 0)) return 0;
        double ox = vp[p0], oy = vp[p0 + 1], oz = vp[p0 + 2];
        double d0 = nx * (vq[q0] - ox) + ny * (vq[q0 + 1] - oy) + nz * (vq[q0 + 2] - oz);
        double d1 = nx * (vq[q1] - ox) + ny * (vq[q1 + 1] - oy) + nz * (vq[q1 + 2] - oz);
        double d2 = nx * (vq[q2] - ox) + ny * (vq[q2 + 1] - oy) + nz * (vq[q2 + 2] - oz);
        double g;
        if (d0 > 0 && d1 > 0 && d2 > 0) g = Math.min(d0, Math.min(d1, d2));
        else if (d0 < 0 && d1 < 0 && d2 < 0) g = -Math.max(d0, Math.max(d1, d2));
        else return 0;
        // less a rounding allowance: the bound must not exceed the true distance
        return g / len * (1 - 1e-12) - 1e-15 * (Math.abs(ox) + Math.abs(oy) + Math.abs(oz) + len);
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
        if (centreStamp.length < b.nodeCount) centreStamp = new int[b.nodeCount];
        if (++stamp == Integer.MAX_VALUE) {
            Arrays.fill(nodeStamp, 0);
            Arrays.fill(centreStamp, 0);
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
