package org.handsim.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import java.util.SplittableRandom;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/**
 * {@link TriangleIntersector} against the exact reference {@link ExactTriTri} on more than a
 * million random pairs (fixed seed), most of them built to be nearly or exactly degenerate.
 *
 * <p><b>Why this reference and this size.</b> A BigDecimal evaluation of every predicate of a
 * million pairs would take minutes. {@link ExactTriTri} is exact yet fast: each sign is
 * certified by a floating-point error bound and only the uncertified ones (the degenerate
 * configurations this test is about) are recomputed in BigDecimal. It uses another algorithm
 * (intervals on the intersection line, separating axes for coplanar pairs) so that a mistake in
 * the Guigue–Devillers case analysis cannot be repeated in the reference. Every pair is compared
 * on "intersect or not" (zero disagreement allowed) and, when the intersection is a
 * well-conditioned segment (not coplanar; the planes and every crossing edge meet at a sine of
 * at least 1e-3, so that the end points are determined to ~1e-15 by the data), on the segment's
 * end points within 1e-12.
 *
 * <p>Families (each a fixed number of pairs): generic (vertices in the unit cube); grid
 * (coordinates k/4, k = 0..4: exactly touching vertices, edges and faces everywhere);
 * nearly coplanar (T2's vertices computed on T1's plane, then moved by 0 to 1e-9 along the
 * normal); exactly coplanar (both in a plane z = c, x = c or x + y = c with dyadic
 * coordinates); shared edge; shared vertex; vertex on the other's plane (an exact edge midpoint
 * or a computed interior point); slivers (a vertex within 1e-14 of the opposite edge); and small
 * triangles far from the origin (centimetre triangles 10 m out).
 */
class TriangleIntersectorTest {
    static final double END_POINT_TOL = 1e-12;
    static final double MIN_SINE = 1e-3;
    /**
     * Pairs per family (generic, grid, nearly coplanar, coplanar, shared edge, shared vertex,
     * vertex on plane, sliver, far): 1 080 000 in all. The near-degenerate families cost the
     * reference 10–30 µs a pair (exact stage), the others 1–5 µs.
     */
    static final int[] PER_FAMILY = {400_000, 150_000, 60_000, 150_000, 60_000, 60_000, 60_000, 40_000, 100_000};
    static final int FAMILIES = PER_FAMILY.length;

    private final TriangleIntersector tt = new TriangleIntersector();

    @Test
    void agreesWithTheExactReferenceOnAMillionPairs() {
        SplittableRandom rnd = new SplittableRandom(20240607L);
        double[] t1 = new double[9], t2 = new double[9];
        int compared = 0, intersecting = 0, coplanar = 0, conditioned = 0, disagree = 0, endPointFail = 0;
        double worst = 0;
        StringBuilder report = new StringBuilder();
        long t0 = System.nanoTime();
        for (int fam = 0; fam < FAMILIES; fam++) {
            int famIntersect = 0, famCoplanar = 0;
            for (int n = 0; n < TestEffort.cases(PER_FAMILY[fam]); n++) {
                generate(fam, rnd, t1, t2);
                ExactTriTri.Answer ref = ExactTriTri.intersect(t1, t2, MIN_SINE);
                if (ref.degenerateInput) {
                    n--;          // draw again: zero-area triangles are filtered before this test
                    continue;
                }
                int r = tt.intersect(t1, 0, 3, 6, t2, 0, 3, 6);
                compared++;
                boolean got = r != TriangleIntersector.DISJOINT;
                if (got != ref.intersects || (got && (r == TriangleIntersector.COPLANAR) != ref.coplanar)) {
                    if (disagree < 5) {
                        report.append(String.format(Locale.ROOT, "family %d: got %d, reference %s%s%n  t1=%s%n  t2=%s%n", fam, r,
                            ref.intersects, ref.coplanar ? " coplanar" : "", java.util.Arrays.toString(t1), java.util.Arrays.toString(t2)));
                    }
                    disagree++;
                    continue;
                }
                if (!got) continue;
                intersecting++;
                famIntersect++;
                if (ref.coplanar) {
                    coplanar++;
                    famCoplanar++;
                    continue;
                }
                if (!ref.wellConditioned) continue;
                conditioned++;
                double[] s = tt.segments();
                double e1 = Math.max(dist(s, 0, ref.a), dist(s, 3, ref.b));
                double e2 = Math.max(dist(s, 0, ref.b), dist(s, 3, ref.a));
                double e = Math.min(e1, e2);
                worst = Math.max(worst, e);
                if (e > END_POINT_TOL) {
                    if (endPointFail < 5) {
                        report.append(String.format(Locale.ROOT, "family %d: end point error %.3g%n  t1=%s%n  t2=%s%n", fam, e,
                            java.util.Arrays.toString(t1), java.util.Arrays.toString(t2)));
                    }
                    endPointFail++;
                }
            }
            System.out.printf(Locale.ROOT, "tri-tri family %d: %d pairs, %d intersect (%d coplanar)%n", fam, TestEffort.cases(PER_FAMILY[fam]), famIntersect, famCoplanar);
        }
        System.out.printf(Locale.ROOT, "tri-tri: %d pairs compared, %d intersect (%d coplanar), %d end points checked, worst error %.3g;"
                + " %d exact-stage predicate calls; whole test %.1f s%n",
            compared, intersecting, coplanar, conditioned, worst, tt.predicates().exactCalls(), (System.nanoTime() - t0) / 1e9);
        assertEquals(0, disagree, "disagreements with the exact reference:\n" + report);
        assertEquals(0, endPointFail, "end points off by more than 1e-12:\n" + report);
        int total = 0;
        for (int n : PER_FAMILY) total += TestEffort.cases(n);   // 1 080 000 in ./test --all, a quarter in ./test
        assertEquals(total, compared, "compared");
        assertTrue(conditioned > total / 10, "only " + conditioned + " well-conditioned segments of " + total);
    }

    private static double dist(double[] s, int o, double[] p) {
        return Math.max(Math.abs(s[o] - p[0]), Math.max(Math.abs(s[o + 1] - p[1]), Math.abs(s[o + 2] - p[2])));
    }

    /** Fills t1 and t2 with a pair of family {@code fam}. */
    static void generate(int fam, SplittableRandom r, double[] t1, double[] t2) {
        switch (fam) {
            case 0: // generic
                for (int i = 0; i < 9; i++) { t1[i] = r.nextDouble(); t2[i] = r.nextDouble(); }
                break;
            case 1: // grid: exact touching everywhere
                for (int i = 0; i < 9; i++) { t1[i] = r.nextInt(5) / 4.0; t2[i] = r.nextInt(5) / 4.0; }
                break;
            case 2: { // nearly coplanar
                for (int i = 0; i < 9; i++) t1[i] = r.nextDouble();
                double[] n = normal(t1);
                double scale = r.nextInt(4) == 0 ? 0 : Math.pow(10, -9 - 8 * r.nextDouble());
                for (int v = 0; v < 3; v++) {
                    double a = 2 * r.nextDouble() - 0.5, b = 2 * r.nextDouble() - 0.5;
                    double h = (2 * r.nextDouble() - 1) * scale;
                    for (int c = 0; c < 3; c++) {
                        t2[3 * v + c] = t1[c] + a * (t1[3 + c] - t1[c]) + b * (t1[6 + c] - t1[c]) + h * n[c];
                    }
                }
                break;
            }
            case 3: { // exactly coplanar, dyadic coordinates
                int plane = r.nextInt(3);
                double c0 = r.nextInt(64) / 64.0;
                for (int v = 0; v < 6; v++) {
                    double[] t = v < 3 ? t1 : t2;
                    int o = 3 * (v % 3);
                    double x = r.nextInt(17) / 16.0, y = r.nextInt(17) / 16.0;
                    if (plane == 0) { t[o] = x; t[o + 1] = y; t[o + 2] = c0; }
                    else if (plane == 1) { t[o] = c0; t[o + 1] = x; t[o + 2] = y; }
                    else { t[o] = x; t[o + 1] = c0 - x; t[o + 2] = y; }
                }
                break;
            }
            case 4: { // shared edge (same or opposite direction), third vertex anywhere or on the plane
                for (int i = 0; i < 9; i++) t1[i] = r.nextDouble();
                boolean flip = r.nextBoolean();
                int e = r.nextInt(3);
                int a = 3 * e, b = 3 * ((e + 1) % 3);
                System.arraycopy(t1, flip ? b : a, t2, 0, 3);
                System.arraycopy(t1, flip ? a : b, t2, 3, 3);
                if (r.nextInt(3) == 0) {
                    onPlane(t1, r, t2, 6);
                } else {
                    for (int c = 0; c < 3; c++) t2[6 + c] = r.nextDouble();
                }
                break;
            }
            case 5: { // shared vertex
                for (int i = 0; i < 9; i++) { t1[i] = r.nextDouble(); t2[i] = r.nextDouble(); }
                int v = r.nextInt(3), w = r.nextInt(3);
                System.arraycopy(t1, 3 * v, t2, 3 * w, 3);
                if (r.nextBoolean()) onPlane(t1, r, t2, 3 * ((w + 1) % 3));
                break;
            }
            case 6: { // a vertex of T2 on T1's plane: exact edge midpoint or a computed point
                for (int i = 0; i < 9; i++) { t1[i] = r.nextDouble(); t2[i] = r.nextDouble(); }
                int w = r.nextInt(3);
                if (r.nextBoolean()) {
                    int e = r.nextInt(3);
                    for (int c = 0; c < 3; c++) t2[3 * w + c] = (t1[3 * e + c] + t1[3 * ((e + 1) % 3) + c]) / 2;
                } else {
                    onPlane(t1, r, t2, 3 * w);
                }
                break;
            }
            case 7: { // sliver T1: r1 within 1e-14 of the edge p1 q1
                for (int i = 0; i < 6; i++) t1[i] = r.nextDouble();
                double s = r.nextDouble();
                for (int c = 0; c < 3; c++) t1[6 + c] = t1[c] + s * (t1[3 + c] - t1[c]) + (r.nextDouble() - 0.5) * 1e-14;
                for (int i = 0; i < 9; i++) t2[i] = r.nextDouble();
                break;
            }
            default: { // centimetre triangles 10 m from the origin
                double ox = 10 + r.nextDouble(), oy = -10, oz = 5;
                for (int v = 0; v < 3; v++) {
                    t1[3 * v] = ox + 0.01 * r.nextDouble(); t1[3 * v + 1] = oy + 0.01 * r.nextDouble(); t1[3 * v + 2] = oz + 0.01 * r.nextDouble();
                    t2[3 * v] = ox + 0.01 * r.nextDouble(); t2[3 * v + 1] = oy + 0.01 * r.nextDouble(); t2[3 * v + 2] = oz + 0.01 * r.nextDouble();
                }
                break;
            }
        }
    }

    /** A point computed (rounded) on t's plane, into out[o..o+2]. */
    private static void onPlane(double[] t, SplittableRandom r, double[] out, int o) {
        double a = 2 * r.nextDouble() - 0.5, b = 2 * r.nextDouble() - 0.5;
        for (int c = 0; c < 3; c++) out[o + c] = t[c] + a * (t[3 + c] - t[c]) + b * (t[6 + c] - t[c]);
    }

    private static double[] normal(double[] t) {
        double ux = t[3] - t[0], uy = t[4] - t[1], uz = t[5] - t[2];
        double wx = t[6] - t[0], wy = t[7] - t[1], wz = t[8] - t[2];
        double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
        double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
        return new double[] {nx / l, ny / l, nz / l};
    }

    /** Hand-made cases: a vertex touch, an edge touch, coplanar overlap and its polygon. */
    @Test
    void handMadeCases() {
        // T2 pierces T1 (unit right triangle in z = 0) along x = 0.25 from y = 0 to y = 0.5
        double[] t1 = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        double[] t2 = {0.25, 0.5, -1, 0.25, 0.5, 1, 0.25, -1, 0};
        assertEquals(TriangleIntersector.SEGMENT, tt.intersect(t1, 0, 3, 6, t2, 0, 3, 6));
        double[] s = tt.segments();
        double ylo = Math.min(s[1], s[4]), yhi = Math.max(s[1], s[4]);
        assertEquals(0.25, s[0], 1e-15);
        assertEquals(0.25, s[3], 1e-15);
        assertEquals(0, ylo, 1e-15);
        assertEquals(0.5, yhi, 1e-15);
        // touching at one vertex: T2's apex on T1's interior point from below
        double[] t3 = {0.2, 0.2, 0, 0.2, 0.3, -1, 0.4, 0.2, -1};
        assertEquals(TriangleIntersector.SEGMENT, tt.intersect(t1, 0, 3, 6, t3, 0, 3, 6));
        assertEquals(0.0, Math.abs(s[0] - s[3]) + Math.abs(s[1] - s[4]) + Math.abs(s[2] - s[5]), "a point segment");
        // separated by 1e-300 below the plane: not touching
        double[] t4 = {0.2, 0.2, -1e-300, 0.2, 0.3, -1, 0.4, 0.2, -1};
        assertEquals(TriangleIntersector.DISJOINT, tt.intersect(t1, 0, 3, 6, t4, 0, 3, 6));
        // coplanar: T1 and T1 shifted by (0.5, 0): overlap is the triangle (0.5,0),(1,0),(0.5,0.5), area 1/8
        double[] t5 = {0.5, 0, 0, 1.5, 0, 0, 0.5, 1, 0};
        assertEquals(TriangleIntersector.COPLANAR, tt.intersect(t1, 0, 3, 6, t5, 0, 3, 6));
        assertEquals(0.125, tt.coplanarArea(), 1e-15);
        assertEquals(3, tt.segmentCount());
        // coplanar, touching along an edge from outside: zero area, still intersecting
        double[] t6 = {1, 0, 0, 0, 1, 0, 1, 1, 0};
        assertEquals(TriangleIntersector.COPLANAR, tt.intersect(t1, 0, 3, 6, t6, 0, 3, 6));
        assertEquals(0, tt.coplanarArea(), 1e-15);
        // coplanar and apart
        double[] t7 = {2, 2, 0, 3, 2, 0, 2, 3, 0};
        assertEquals(TriangleIntersector.DISJOINT, tt.intersect(t1, 0, 3, 6, t7, 0, 3, 6));
    }
}
