package org.handsim.collision;

/**
 * Triangle–triangle intersection with the intersection segment, decided exactly.
 *
 * <p><b>Algorithm (Guigue–Devillers 2003).</b> Triangles are closed sets: touching counts.
 * <ol>
 *   <li>The signs of T1's vertices against T2's plane, d1ᵢ = orient3d(p2, q2, r2, vᵢ); if all
 *       three are non-zero and equal, T1 lies on one side: no intersection. The same for T2
 *       against T1's plane (d2ᵢ).</li>
 *   <li>If every d1ᵢ is zero the triangles are coplanar: a 2-D closed-triangle overlap test
 *       (every edge pair, then one vertex of each in the other) on the projection onto the
 *       coordinate plane where T1 is not degenerate, all with exact {@code orient2d}.</li>
 *   <li>Otherwise both triangles are permuted circularly (and one of them mirrored) into the
 *       canonical form of the paper: p1 alone on its side of π2, p2 alone on its side of π1.
 *       Then the segments T1 ∩ π2 = [i, j] and T2 ∩ π1 = [k, l] lie on the line π1 ∩ π2, and
 *       their overlap is decided by two orientation tests, orient3d(p1, q1, p2, q2) and
 *       orient3d(p1, r1, r2, p2); two more pick which end points bound the overlap. No
 *       intersection line is ever computed, so there is no division before the decision.</li>
 *   <li>Each end point of the overlap is an edge of one triangle crossing the other's plane:
 *       x + (y − x)·dₓ/(dₓ − d_y). dₓ and d_y have opposite signs (or one is 0), so the
 *       denominator never cancels; the end point is as accurate as the two orientation values.</li>
 * </ol>
 *
 * <p><b>Robustness (docs/STYLE.md, item 7).</b> Every sign above comes from {@link Predicates}: a
 * floating-point value with Shewchuk's error bound, and exact expansion arithmetic only when
 * the bound cannot certify the sign (a vertex on or within rounding distance of a plane, a
 * shared edge, coplanar faces). So the answer "intersect or not" is the exact answer for the
 * double coordinates given, whatever the configuration; the test suite checks it against an
 * independent rational reference on more than a million pairs.
 *
 * <p><b>Output.</b> {@link #intersect} returns {@link #DISJOINT}, {@link #SEGMENT} or
 * {@link #COPLANAR}. A non-coplanar intersection is one segment (of zero length when the
 * triangles touch at one point), oriented along n1 × n2 (the two triangles' right-handed
 * normals), so that segments chained along an intersection curve run the same way round. A
 * coplanar intersection is the boundary of the overlap polygon (Sutherland–Hodgman clipping of
 * T2 by T1; up to six segments, one zero-length segment when the triangles only touch), and
 * {@link #coplanarArea()} is the polygon's area. The segment end points are in the frame of the
 * input coordinates (metres).
 *
 * <p>Degenerate (zero-area) triangles must be filtered out by the caller ({@link KdopTree}
 * marks them exactly at build time and the walk skips and counts them): for a segment-shaped
 * T1 every d2ᵢ is 0 and the pair would look coplanar.
 *
 * <p><b>Threads.</b> Holds its scratch and its last result: one instance per thread.
 *
 * <p>References: P. Guigue, O. Devillers, "Fast and robust triangle-triangle overlap test using
 * orientation predicates", Journal of Graphics Tools 8(1):25–32, 2003; T. Möller, "A fast
 * triangle-triangle intersection test", Journal of Graphics Tools 2(2):25–30, 1997 (the
 * interval-on-the-line idea); J. R. Shewchuk 1997 (see {@link Predicates}).
 */
public final class TriangleIntersector {
    /** No intersection. */
    public static final int DISJOINT = 0;
    /** One segment (possibly of zero length). */
    public static final int SEGMENT = 1;
    /** Coplanar overlap: the segments are the overlap polygon's boundary. */
    public static final int COPLANAR = 2;

    private final Predicates pred = new Predicates();
    private final double[] v1 = new double[9], v2 = new double[9];
    private final double[] d1 = new double[3], d2 = new double[3];
    private final double[] nrm = new double[6], nAbs = new double[6];
    private final double[] seg = new double[36];
    private int segCount;
    private double area;
    // coplanar clipping scratch: up to 9 points
    private final double[] polyA = new double[27], polyB = new double[27];
    private final double[] side = new double[9];

    /** @return the predicates (for their exact-stage counter) */
    public Predicates predicates() { return pred; }

    /** @return the number of segments of the last intersection (0 if disjoint) */
    public int segmentCount() { return segCount; }

    /**
     * The last result's segments: segment s has its start at {@code [6s..6s+2]} and its end at
     * {@code [6s+3..6s+5]} (internal array; valid until the next call).
     */
    public double[] segments() { return seg; }

    /** @return the overlap polygon's area (m²) of the last coplanar intersection, else 0 */
    public double coplanarArea() { return area; }

    /**
     * Intersects triangle (va[a0..], va[a1..], va[a2..]) with (vb[b0..], vb[b1..], vb[b2..]);
     * the offsets index the x coordinate of each vertex (3 × vertex index for a flat vertex
     * array). Allocation-free.
     *
     * @return {@link #DISJOINT}, {@link #SEGMENT} or {@link #COPLANAR}
     */
    public int intersect(double[] va, int a0, int a1, int a2, double[] vb, int b0, int b1, int b2) {
        load(va, a0, a1, a2, vb, b0, b1, b2);
        double[] p = v1, q = v2;
        Predicates.normal(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7], q[8], nrm, nAbs, 3);
        Predicates.normal(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], nrm, nAbs, 0);
        return decide();
    }

    /**
     * As {@link #intersect(double[], int, int, int, double[], int, int, int)}, with each
     * triangle's normal and permanent terms precomputed by {@link Predicates#normal} from the
     * same coordinates ({@code nA[oA..oA+2]}, {@code nAbsA[oA..]}; likewise for B), as the
     * tree query caches them.
     */
    public int intersect(double[] va, int a0, int a1, int a2, double[] nA, double[] nAbsA, int oA,
                         double[] vb, int b0, int b1, int b2, double[] nB, double[] nAbsB, int oB) {
        load(va, a0, a1, a2, vb, b0, b1, b2);
        nrm[0] = nA[oA]; nrm[1] = nA[oA + 1]; nrm[2] = nA[oA + 2];
        nAbs[0] = nAbsA[oA]; nAbs[1] = nAbsA[oA + 1]; nAbs[2] = nAbsA[oA + 2];
        nrm[3] = nB[oB]; nrm[4] = nB[oB + 1]; nrm[5] = nB[oB + 2];
        nAbs[3] = nAbsB[oB]; nAbs[4] = nAbsB[oB + 1]; nAbs[5] = nAbsB[oB + 2];
        return decide();
    }

    /**
     * As {@link #intersect(double[], int, int, int, double[], double[], int, double[], int, int, int, double[], double[], int)}
     * with the six plane sides already evaluated by the caller with
     * {@link Predicates#orient3dFiltered} on exactly the arguments {@link #decide} would use:
     * {@code f}ᵢ = T1's vertex i against T2's plane ({@code nB} at oB, T2's vertex 0),
     * {@code e}ᵢ = T2's vertex i against T1's plane ({@code nA} at oA, T1's vertex 0); NaN where
     * the filter could not certify the sign (the exact stage is then run here). The tree walk
     * evaluates them first to drop most disjoint pairs without loading them; the answer and the
     * segments are bit-identical to the other entry's.
     */
    int intersect(double[] va, int a0, int a1, int a2, double[] nA, double[] nAbsA, int oA,
                  double[] vb, int b0, int b1, int b2, double[] nB, double[] nAbsB, int oB,
                  double f0, double f1, double f2, double e0, double e1, double e2) {
        load(va, a0, a1, a2, vb, b0, b1, b2);
        nrm[0] = nA[oA]; nrm[1] = nA[oA + 1]; nrm[2] = nA[oA + 2];
        nAbs[0] = nAbsA[oA]; nAbs[1] = nAbsA[oA + 1]; nAbs[2] = nAbsA[oA + 2];
        nrm[3] = nB[oB]; nrm[4] = nB[oB + 1]; nrm[5] = nB[oB + 2];
        nAbs[3] = nAbsB[oB]; nAbs[4] = nAbsB[oB + 1]; nAbs[5] = nAbsB[oB + 2];
        d1[0] = f0 == f0 ? f0 : side2(0);
        d1[1] = f1 == f1 ? f1 : side2(1);
        d1[2] = f2 == f2 ? f2 : side2(2);
        if ((d1[0] > 0 && d1[1] > 0 && d1[2] > 0) || (d1[0] < 0 && d1[1] < 0 && d1[2] < 0)) return DISJOINT;
        d2[0] = e0 == e0 ? e0 : side1(0);
        d2[1] = e1 == e1 ? e1 : side1(1);
        d2[2] = e2 == e2 ? e2 : side1(2);
        return decideFromSides();
    }

    private void load(double[] va, int a0, int a1, int a2, double[] vb, int b0, int b1, int b2) {
        segCount = 0;
        area = 0;
        double[] p = v1, q = v2;
        p[0] = va[a0]; p[1] = va[a0 + 1]; p[2] = va[a0 + 2];
        p[3] = va[a1]; p[4] = va[a1 + 1]; p[5] = va[a1 + 2];
        p[6] = va[a2]; p[7] = va[a2 + 1]; p[8] = va[a2 + 2];
        q[0] = vb[b0]; q[1] = vb[b0 + 1]; q[2] = vb[b0 + 2];
        q[3] = vb[b1]; q[4] = vb[b1 + 1]; q[5] = vb[b1 + 2];
        q[6] = vb[b2]; q[7] = vb[b2 + 1]; q[8] = vb[b2 + 2];
    }

    private int decide() {
        // T1's vertices against T2's plane
        for (int i = 0; i < 3; i++) d1[i] = side2(i);
        if ((d1[0] > 0 && d1[1] > 0 && d1[2] > 0) || (d1[0] < 0 && d1[1] < 0 && d1[2] < 0)) return DISJOINT;
        // T2's vertices against T1's plane
        for (int i = 0; i < 3; i++) d2[i] = side1(i);
        return decideFromSides();
    }

    /** {@link #decide} once d1 and d2 hold the exact sides and d1 did not separate. */
    private int decideFromSides() {
        if ((d2[0] > 0 && d2[1] > 0 && d2[2] > 0) || (d2[0] < 0 && d2[1] < 0 && d2[2] < 0)) return DISJOINT;

        double dp1 = d1[0], dq1 = d1[1], dr1 = d1[2];
        if (dp1 > 0) {
            if (dq1 > 0) return inter(2, 0, 1, 0, 2, 1);
            if (dr1 > 0) return inter(1, 2, 0, 0, 2, 1);
            return inter(0, 1, 2, 0, 1, 2);
        }
        if (dp1 < 0) {
            if (dq1 < 0) return inter(2, 0, 1, 0, 1, 2);
            if (dr1 < 0) return inter(1, 2, 0, 0, 1, 2);
            return inter(0, 1, 2, 0, 2, 1);
        }
        if (dq1 < 0) {
            if (dr1 >= 0) return inter(1, 2, 0, 0, 2, 1);
            return inter(0, 1, 2, 0, 1, 2);
        }
        if (dq1 > 0) {
            if (dr1 > 0) return inter(0, 1, 2, 0, 2, 1);
            return inter(1, 2, 0, 0, 1, 2);
        }
        if (dr1 > 0) return inter(2, 0, 1, 0, 1, 2);
        if (dr1 < 0) return inter(2, 0, 1, 0, 2, 1);
        return coplanar();
    }

    /** Side of T1's vertex i against T2's plane (sign exact). */
    private double side2(int i) {
        double[] p = v1, q = v2;
        int o = 3 * i;
        double d = Predicates.orient3dFiltered(nrm, nAbs, 3, q[0], q[1], q[2], p[o], p[o + 1], p[o + 2]);
        if (d == d) return d;
        return pred.orient3d(q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7], q[8], p[o], p[o + 1], p[o + 2]);
    }

    /** Side of T2's vertex i against T1's plane (sign exact). */
    private double side1(int i) {
        double[] p = v1, q = v2;
        int o = 3 * i;
        double d = Predicates.orient3dFiltered(nrm, nAbs, 0, p[0], p[1], p[2], q[o], q[o + 1], q[o + 2]);
        if (d == d) return d;
        return pred.orient3d(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], q[o], q[o + 1], q[o + 2]);
    }

    /** The paper's TRI_TRI_INTER_3D: T1 in canonical order (p1, q1, r1); T2 to be permuted. */
    private int inter(int p1, int q1, int r1, int p2, int q2, int r2) {
        double dp2 = d2[p2], dq2 = d2[q2], dr2 = d2[r2];
        if (dp2 > 0) {
            if (dq2 > 0) return construct(p1, r1, q1, r2, p2, q2);
            if (dr2 > 0) return construct(p1, r1, q1, q2, r2, p2);
            return construct(p1, q1, r1, p2, q2, r2);
        }
        if (dp2 < 0) {
            if (dq2 < 0) return construct(p1, q1, r1, r2, p2, q2);
            if (dr2 < 0) return construct(p1, q1, r1, q2, r2, p2);
            return construct(p1, r1, q1, p2, q2, r2);
        }
        if (dq2 < 0) {
            if (dr2 >= 0) return construct(p1, r1, q1, q2, r2, p2);
            return construct(p1, q1, r1, p2, q2, r2);
        }
        if (dq2 > 0) {
            if (dr2 > 0) return construct(p1, r1, q1, p2, q2, r2);
            return construct(p1, q1, r1, q2, r2, p2);
        }
        if (dr2 > 0) return construct(p1, q1, r1, r2, p2, q2);
        if (dr2 < 0) return construct(p1, r1, q1, r2, p2, q2);
        return coplanar(); // unreachable for non-degenerate triangles
    }

    /** orient3d(a, b, c, x) with a, b, c, x vertex indices: T1 vertices 0..2, T2 vertices 3..5. */
    private double orient(int a, int b, int c, int x) {
        double[] pa = a < 3 ? v1 : v2, pb = b < 3 ? v1 : v2, pc = c < 3 ? v1 : v2, px = x < 3 ? v1 : v2;
        int oa = a < 3 ? 3 * a : 3 * a - 9, ob = b < 3 ? 3 * b : 3 * b - 9;
        int oc = c < 3 ? 3 * c : 3 * c - 9, ox = x < 3 ? 3 * x : 3 * x - 9;
        return pred.orient3d(pa[oa], pa[oa + 1], pa[oa + 2], pb[ob], pb[ob + 1], pb[ob + 2],
            pc[oc], pc[oc + 1], pc[oc + 2], px[ox], px[ox + 1], px[ox + 2]);
    }

    /**
     * The paper's CONSTRUCT_INTERSECTION, canonical form: p1 alone on its side of π2, p2 alone
     * on its side of π1 (indices: T1 vertices 0..2, T2 vertices 0..2).
     */
    private int construct(int p1, int q1, int r1, int p2, int q2, int r2) {
        int P2 = p2 + 3, Q2 = q2 + 3, R2 = r2 + 3;
        if (orient(p1, q1, R2, P2) > 0) {
            if (orient(p1, r1, R2, P2) <= 0) {
                if (orient(p1, r1, Q2, P2) > 0) {
                    edge1(p1, r1, 0);
                    edge2(p2, r2, 3);
                } else {
                    edge2(p2, q2, 0);
                    edge2(p2, r2, 3);
                }
            } else {
                return DISJOINT;
            }
        } else {
            if (orient(p1, q1, Q2, P2) < 0) return DISJOINT;
            if (orient(p1, r1, Q2, P2) >= 0) {
                edge1(p1, r1, 0);
                edge1(p1, q1, 3);
            } else {
                edge2(p2, q2, 0);
                edge1(p1, q1, 3);
            }
        }
        segCount = 1;
        orientSegment();
        return SEGMENT;
    }

    /** T1's edge x→y crossing π2, into seg[o..o+2]. */
    private void edge1(int x, int y, int o) {
        cross(v1, d1, x, y, o);
    }

    /** T2's edge x→y crossing π1, into seg[o..o+2]. */
    private void edge2(int x, int y, int o) {
        cross(v2, d2, x, y, o);
    }

    private void cross(double[] v, double[] d, int x, int y, int o) {
        double dx = d[x], dy = d[y];
        int ox = 3 * x, oy = 3 * y;
        if (dx == 0) {
            seg[o] = v[ox]; seg[o + 1] = v[ox + 1]; seg[o + 2] = v[ox + 2];
        } else if (dy == 0) {
            seg[o] = v[oy]; seg[o + 1] = v[oy + 1]; seg[o + 2] = v[oy + 2];
        } else {
            double t = dx / (dx - dy);
            seg[o] = v[ox] + t * (v[oy] - v[ox]);
            seg[o + 1] = v[ox + 1] + t * (v[oy + 1] - v[ox + 1]);
            seg[o + 2] = v[ox + 2] + t * (v[oy + 2] - v[ox + 2]);
        }
    }

    /** Orients the single segment along n1 × n2. */
    private void orientSegment() {
        double[] n = nrm;
        double lx = n[1] * n[5] - n[2] * n[4];
        double ly = n[2] * n[3] - n[0] * n[5];
        double lz = n[0] * n[4] - n[1] * n[3];
        double dot = (seg[3] - seg[0]) * lx + (seg[4] - seg[1]) * ly + (seg[5] - seg[2]) * lz;
        if (dot < 0) {
            for (int i = 0; i < 3; i++) {
                double s = seg[i];
                seg[i] = seg[i + 3];
                seg[i + 3] = s;
            }
        }
    }

    // ------------------------------------------------------------------ coplanar

    private int cu, cv;  // the two coordinates kept by the 2-D projection

    private double o2(double[] a, int ia, double[] b, int ib, double[] c, int ic) {
        return pred.orient2d(a[ia + cu], a[ia + cv], b[ib + cu], b[ib + cv], c[ic + cu], c[ic + cv]);
    }

    private int coplanar() {
        // project by dropping the axis along which T1's projection is non-degenerate, preferring
        // the largest normal component (exact test: T1 is non-degenerate, so one axis works)
        double[] n = nrm;
        int best = -1;
        double s1 = 0;
        double ax = Math.abs(n[0]), ay = Math.abs(n[1]), az = Math.abs(n[2]);
        int first = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
        for (int t = 0; t < 3 && best < 0; t++) {
            int drop = (first + t) % 3;
            cu = (drop + 1) % 3;
            cv = (drop + 2) % 3;
            double o = o2(v1, 0, v1, 3, v1, 6);
            if (o != 0) {
                best = drop;
                s1 = o;
            }
        }
        if (best < 0) return DISJOINT; // T1 degenerate: callers filter these out
        double s2 = o2(v2, 0, v2, 3, v2, 6);
        if (s2 == 0) return DISJOINT;   // T2 degenerate
        if (!overlap2d(s1, s2)) return DISJOINT;
        clipPolygon(s1);
        return COPLANAR;
    }

    /** Closed 2-D overlap of T1 and T2 (exact). */
    private boolean overlap2d(double s1, double s2) {
        for (int i = 0; i < 3; i++) {
            int a = 3 * i, b = 3 * ((i + 1) % 3);
            for (int j = 0; j < 3; j++) {
                int c = 3 * j, d = 3 * ((j + 1) % 3);
                if (segmentsMeet(a, b, c, d)) return true;
            }
        }
        return inside(v2, 0, v1, s1) || inside(v1, 0, v2, s2);
    }

    /** Closed segment intersection of T1's edge (a, b) and T2's edge (c, d) in the projection. */
    private boolean segmentsMeet(int a, int b, int c, int d) {
        double o1 = Math.signum(o2(v1, a, v1, b, v2, c));
        double o2v = Math.signum(o2(v1, a, v1, b, v2, d));
        double o3 = Math.signum(o2(v2, c, v2, d, v1, a));
        double o4 = Math.signum(o2(v2, c, v2, d, v1, b));
        if (o1 * o2v < 0 && o3 * o4 < 0) return true;
        if (o1 == 0 && onSegment(v1, a, v1, b, v2, c)) return true;
        if (o2v == 0 && onSegment(v1, a, v1, b, v2, d)) return true;
        if (o3 == 0 && onSegment(v2, c, v2, d, v1, a)) return true;
        return o4 == 0 && onSegment(v2, c, v2, d, v1, b);
    }

    /** For x collinear with (a, b): is x within the segment's bounding box (exact comparisons). */
    private boolean onSegment(double[] pa, int a, double[] pb, int b, double[] px, int x) {
        double xu = px[x + cu], xv = px[x + cv];
        return Math.min(pa[a + cu], pb[b + cu]) <= xu && xu <= Math.max(pa[a + cu], pb[b + cu])
            && Math.min(pa[a + cv], pb[b + cv]) <= xv && xv <= Math.max(pa[a + cv], pb[b + cv]);
    }

    /** Is point x of {@code px} in the closed triangle {@code t} whose orientation sign is s. */
    private boolean inside(double[] px, int x, double[] t, double s) {
        for (int i = 0; i < 3; i++) {
            double o = o2(t, 3 * i, t, 3 * ((i + 1) % 3), px, x);
            if (o != 0 && (o > 0) != (s > 0)) return false;
        }
        return true;
    }

    /** Clips T2 by T1's three half-planes (floating point), writes the boundary segments and area. */
    private void clipPolygon(double s1) {
        double[] in = polyA, out = polyB;
        System.arraycopy(v2, 0, in, 0, 9);
        int n = 3;
        double sign = s1 > 0 ? 1 : -1;
        for (int e = 0; e < 3 && n > 0; e++) {
            int a = 3 * e, b = 3 * ((e + 1) % 3);
            double au = v1[a + cu], av = v1[a + cv];
            double eu = v1[b + cu] - au, ev = v1[b + cv] - av;
            for (int i = 0; i < n; i++) {
                side[i] = sign * (eu * (in[3 * i + cv] - av) - ev * (in[3 * i + cu] - au));
            }
            int m = 0;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double si = side[i], sj = side[j];
                if (si >= 0) {
                    out[3 * m] = in[3 * i]; out[3 * m + 1] = in[3 * i + 1]; out[3 * m + 2] = in[3 * i + 2];
                    m++;
                }
                if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
                    double t = si / (si - sj);
                    out[3 * m] = in[3 * i] + t * (in[3 * j] - in[3 * i]);
                    out[3 * m + 1] = in[3 * i + 1] + t * (in[3 * j + 1] - in[3 * i + 1]);
                    out[3 * m + 2] = in[3 * i + 2] + t * (in[3 * j + 2] - in[3 * i + 2]);
                    m++;
                }
            }
            double[] tmp = in; in = out; out = tmp;
            n = m;
        }
        // drop repeated points
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = m == 0 ? -1 : m - 1;
            if (j >= 0 && in[3 * i] == in[3 * j] && in[3 * i + 1] == in[3 * j + 1] && in[3 * i + 2] == in[3 * j + 2]) continue;
            if (m != i) { in[3 * m] = in[3 * i]; in[3 * m + 1] = in[3 * i + 1]; in[3 * m + 2] = in[3 * i + 2]; }
            m++;
        }
        while (m > 1 && in[0] == in[3 * m - 3] && in[1] == in[3 * m - 2] && in[2] == in[3 * m - 1]) m--;
        if (m == 0) {
            touchPoint(in);
            m = 1;
        }
        if (m == 1) {
            segCount = 1;
            for (int c = 0; c < 3; c++) { seg[c] = in[c]; seg[c + 3] = in[c]; }
            return;
        }
        if (m == 2) {
            segCount = 1;
            System.arraycopy(in, 0, seg, 0, 6);
            return;
        }
        double ax = 0, ay = 0, az = 0;
        for (int i = 0; i < m; i++) {
            int j = (i + 1) % m;
            System.arraycopy(in, 3 * i, seg, 6 * i, 3);
            System.arraycopy(in, 3 * j, seg, 6 * i + 3, 3);
            double x0 = in[3 * i] - in[0], y0 = in[3 * i + 1] - in[1], z0 = in[3 * i + 2] - in[2];
            double x1 = in[3 * j] - in[0], y1 = in[3 * j + 1] - in[1], z1 = in[3 * j + 2] - in[2];
            ax += y0 * z1 - z0 * y1;
            ay += z0 * x1 - x0 * z1;
            az += x0 * y1 - y0 * x1;
        }
        segCount = m;
        area = 0.5 * Math.sqrt(ax * ax + ay * ay + az * az);
    }

    /**
     * The exact test said the triangles meet but floating-point clipping lost the contact (they
     * touch): a point where they touch, from the exact tests, into out[0..2].
     */
    private void touchPoint(double[] out) {
        double s1 = o2(v1, 0, v1, 3, v1, 6), s2 = o2(v2, 0, v2, 3, v2, 6);
        for (int i = 0; i < 3; i++) {
            if (inside(v2, 3 * i, v1, s1)) { System.arraycopy(v2, 3 * i, out, 0, 3); return; }
            if (inside(v1, 3 * i, v2, s2)) { System.arraycopy(v1, 3 * i, out, 0, 3); return; }
        }
        // crossing edges: intersect the two lines in the projection
        for (int i = 0; i < 3; i++) {
            int a = 3 * i, b = 3 * ((i + 1) % 3);
            for (int j = 0; j < 3; j++) {
                int c = 3 * j, d = 3 * ((j + 1) % 3);
                if (!segmentsMeet(a, b, c, d)) continue;
                double oc = o2(v1, a, v1, b, v2, c), od = o2(v1, a, v1, b, v2, d);
                double t = oc == od ? 0 : oc / (oc - od);
                for (int k = 0; k < 3; k++) out[k] = v2[c + k] + t * (v2[d + k] - v2[c + k]);
                return;
            }
        }
        System.arraycopy(v1, 0, out, 0, 3);
    }
}
