package org.handsim.collision;

/**
 * Closest points between the features of triangles, in double precision: point–triangle,
 * segment–segment and triangle–triangle (C. Ericson, <i>Real-Time Collision Detection</i>,
 * Morgan Kaufmann 2005, §5.1.5 {@code ClosestPtPointTriangle}, §5.1.9
 * {@code ClosestPtSegmentSegment}; the triangle pair as E. Larsen, S. Gottschalk, M. Lin,
 * D. Manocha, "Fast proximity queries with swept sphere volumes", 1999 — PQP's {@code TriDist},
 * FCL's {@code TriangleDistance}: the smallest of the nine edge pairs and the six vertices
 * against the other triangle's face, or 0 when the triangles intersect).
 *
 * <p>Coordinates are read from flat arrays at offsets (x, y, z); results go into this object's
 * fields ({@link #pointA}, {@link #pointB}, {@link #s}, {@link #t}). One instance per thread;
 * allocation-free.
 */
public final class TriangleDistance {
    /** The closest point on the first feature, then on the second (the last call's). */
    public final double[] pointA = new double[3], pointB = new double[3];
    /** The segment parameters of the last {@link #segments} call, in [0, 1]. */
    public double s, t;
    private final TriangleIntersector intersector = new TriangleIntersector();

    /**
     * The squared distance from point p to triangle (a, b, c); the closest point goes to
     * {@link #pointB} (and p to {@link #pointA}). Ericson's Voronoi-region walk: vertex regions,
     * then edge regions, then the face.
     */
    public double pointTriangle(double px, double py, double pz, double[] v, int a, int b, int c) {
        pointA[0] = px; pointA[1] = py; pointA[2] = pz;
        double ax = v[a], ay = v[a + 1], az = v[a + 2];
        double abx = v[b] - ax, aby = v[b + 1] - ay, abz = v[b + 2] - az;
        double acx = v[c] - ax, acy = v[c + 1] - ay, acz = v[c + 2] - az;
        double apx = px - ax, apy = py - ay, apz = pz - az;
        double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
        if (d1 <= 0 && d2 <= 0) return set(px, py, pz, ax, ay, az);
        double bpx = px - v[b], bpy = py - v[b + 1], bpz = pz - v[b + 2];
        double d3 = abx * bpx + aby * bpy + abz * bpz, d4 = acx * bpx + acy * bpy + acz * bpz;
        if (d3 >= 0 && d4 <= d3) return set(px, py, pz, v[b], v[b + 1], v[b + 2]);
        double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            double w = d1 / (d1 - d3);
            return set(px, py, pz, ax + w * abx, ay + w * aby, az + w * abz);
        }
        double cpx = px - v[c], cpy = py - v[c + 1], cpz = pz - v[c + 2];
        double d5 = abx * cpx + aby * cpy + abz * cpz, d6 = acx * cpx + acy * cpy + acz * cpz;
        if (d6 >= 0 && d5 <= d6) return set(px, py, pz, v[c], v[c + 1], v[c + 2]);
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            double w = d2 / (d2 - d6);
            return set(px, py, pz, ax + w * acx, ay + w * acy, az + w * acz);
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
            double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            double bx = v[b], by = v[b + 1], bz = v[b + 2];
            return set(px, py, pz, bx + w * (v[c] - bx), by + w * (v[c + 1] - by), bz + w * (v[c + 2] - bz));
        }
        double denom = 1 / (va + vb + vc);
        double vv = vb * denom, ww = vc * denom;
        return set(px, py, pz, ax + abx * vv + acx * ww, ay + aby * vv + acy * ww, az + abz * vv + acz * ww);
    }

    private double set(double px, double py, double pz, double qx, double qy, double qz) {
        pointB[0] = qx; pointB[1] = qy; pointB[2] = qz;
        double dx = px - qx, dy = py - qy, dz = pz - qz;
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * The squared distance between segments p1→q1 (in {@code va}) and p2→q2 (in {@code vb});
     * closest points into {@link #pointA}, {@link #pointB}, parameters into {@link #s}, {@link #t}
     * (Ericson §5.1.9, degenerate segments handled).
     */
    public double segments(double[] va, int p1, int q1, double[] vb, int p2, int q2) {
        double d1x = va[q1] - va[p1], d1y = va[q1 + 1] - va[p1 + 1], d1z = va[q1 + 2] - va[p1 + 2];
        double d2x = vb[q2] - vb[p2], d2y = vb[q2 + 1] - vb[p2 + 1], d2z = vb[q2 + 2] - vb[p2 + 2];
        double rx = va[p1] - vb[p2], ry = va[p1 + 1] - vb[p2 + 1], rz = va[p1 + 2] - vb[p2 + 2];
        double a = d1x * d1x + d1y * d1y + d1z * d1z, e = d2x * d2x + d2y * d2y + d2z * d2z;
        double f = d2x * rx + d2y * ry + d2z * rz;
        double ss, tt;
        if (a <= 0 && e <= 0) {
            ss = tt = 0;
        } else if (a <= 0) {
            ss = 0;
            tt = clamp(f / e);
        } else {
            double c = d1x * rx + d1y * ry + d1z * rz;
            if (e <= 0) {
                tt = 0;
                ss = clamp(-c / a);
            } else {
                double b = d1x * d2x + d1y * d2y + d1z * d2z;
                double denom = a * e - b * b;
                ss = denom > 0 ? clamp((b * f - c * e) / denom) : 0;
                tt = (b * ss + f) / e;
                if (tt < 0) {
                    tt = 0;
                    ss = clamp(-c / a);
                } else if (tt > 1) {
                    tt = 1;
                    ss = clamp((b - c) / a);
                }
            }
        }
        s = ss;
        t = tt;
        pointA[0] = va[p1] + d1x * ss; pointA[1] = va[p1 + 1] + d1y * ss; pointA[2] = va[p1 + 2] + d1z * ss;
        pointB[0] = vb[p2] + d2x * tt; pointB[1] = vb[p2 + 1] + d2y * tt; pointB[2] = vb[p2 + 2] + d2z * tt;
        double dx = pointA[0] - pointB[0], dy = pointA[1] - pointB[1], dz = pointA[2] - pointB[2];
        return dx * dx + dy * dy + dz * dz;
    }

    private static double clamp(double x) {
        return x < 0 ? 0 : (x > 1 ? 1 : x);
    }

    /**
     * The distance between triangles (a0, a1, a2) of {@code va} and (b0, b1, b2) of {@code vb}
     * (offsets of x): 0 when they intersect (decided exactly by {@link TriangleIntersector}), else
     * the smallest of the nine edge–edge and six vertex–face distances; the closest points go to
     * {@link #pointA} (on A) and {@link #pointB} (on B).
     */
    public double triangles(double[] va, int a0, int a1, int a2, double[] vb, int b0, int b1, int b2) {
        double best = Double.POSITIVE_INFINITY;
        double bax = 0, bay = 0, baz = 0, bbx = 0, bby = 0, bbz = 0;
        for (int i = 0; i < 3; i++) {
            int pa = i == 0 ? a0 : i == 1 ? a1 : a2, qa = i == 0 ? a1 : i == 1 ? a2 : a0;
            for (int j = 0; j < 3; j++) {
                int pb = j == 0 ? b0 : j == 1 ? b1 : b2, qb = j == 0 ? b1 : j == 1 ? b2 : b0;
                double d = segments(va, pa, qa, vb, pb, qb);
                if (d < best) {
                    best = d;
                    bax = pointA[0]; bay = pointA[1]; baz = pointA[2];
                    bbx = pointB[0]; bby = pointB[1]; bbz = pointB[2];
                }
            }
        }
        for (int i = 0; i < 3; i++) {
            int p = i == 0 ? b0 : i == 1 ? b1 : b2;
            double d = pointTriangle(vb[p], vb[p + 1], vb[p + 2], va, a0, a1, a2);
            if (d < best) {
                best = d;
                bax = pointB[0]; bay = pointB[1]; baz = pointB[2];
                bbx = pointA[0]; bby = pointA[1]; bbz = pointA[2];
            }
            p = i == 0 ? a0 : i == 1 ? a1 : a2;
            d = pointTriangle(va[p], va[p + 1], va[p + 2], vb, b0, b1, b2);
            if (d < best) {
                best = d;
                bax = pointA[0]; bay = pointA[1]; baz = pointA[2];
                bbx = pointB[0]; bby = pointB[1]; bbz = pointB[2];
            }
        }
        pointA[0] = bax; pointA[1] = bay; pointA[2] = baz;
        pointB[0] = bbx; pointB[1] = bby; pointB[2] = bbz;
        if (best > 0 && intersects(va, a0, a1, a2, vb, b0, b1, b2)) return 0;
        return Math.sqrt(best);
    }

    /** Whether the triangles intersect (touching included), by the exact test. */
    public boolean intersects(double[] va, int a0, int a1, int a2, double[] vb, int b0, int b1, int b2) {
        return intersector.intersect(va, a0, a1, a2, vb, b0, b1, b2) != TriangleIntersector.DISJOINT;
    }
}
