package org.handsim.grasp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/** The d-dimensional Quickhull on polytopes known in closed form, against brute force, and on degenerate input. */
class ConvexHullTest {
    static final double TIGHT = 1e-12;

    /** The 2^d vertices of the cube [-1, 1]^d shifted by t along the first axis. */
    static double[] cube(int d, double t) {
        double[] p = new double[d << d];
        for (int v = 0; v < (1 << d); v++) {
            for (int c = 0; c < d; c++) p[v * d + c] = ((v >> c & 1) == 0 ? -1 : 1) + (c == 0 ? t : 0);
        }
        return p;
    }

    /** The 2d vertices ±e_i of the cross-polytope. */
    static double[] crossPolytope(int d) {
        double[] p = new double[2 * d * d];
        for (int i = 0; i < d; i++) {
            p[(2 * i) * d + i] = 1;
            p[(2 * i + 1) * d + i] = -1;
        }
        return p;
    }

    static double factorial(int d) {
        double f = 1;
        for (int i = 2; i <= d; i++) f *= i;
        return f;
    }

    /**
     * Cube [-1,1]^d: volume 2^d, 2d facets (each triangulated: merged back), the origin at
     * distance 1 from each; shifted by t along x1 the nearest facet is at 1 - t.
     */
    @Test
    void cubes() {
        for (int d = 2; d <= 6; d++) {
            ConvexHull h = new ConvexHull(d);
            assertTrue(h.build(cube(d, 0), 1 << d));
            assertEquals(Math.pow(2, d), h.volume(), TIGHT * Math.pow(2, d), "volume, d = " + d);
            assertEquals(2 * d, h.facetCount(), "facets, d = " + d);
            assertEquals(1.0, h.minOffset(), TIGHT, "offset, d = " + d);
            assertEquals(1.0, h.epsilon(cube(d, 0), 1 << d), TIGHT);
            assertTrue(h.build(cube(d, 0.25), 1 << d));
            assertEquals(0.75, h.minOffset(), TIGHT);
            assertEquals(0.75, h.epsilon(cube(d, 0.25), 1 << d), TIGHT);
            // the origin outside: shifted by 1.5, the nearest facet hyperplane x1 = 0.5 has it 0.5 beyond
            assertEquals(-0.5, h.epsilon(cube(d, 1.5), 1 << d), TIGHT);
        }
    }

    /**
     * Cross-polytope conv{±e_i}: volume 2^d / d!, 2^d facets x·s = 1 (s a sign vector) at
     * distance 1/√d from the origin.
     */
    @Test
    void crossPolytopes() {
        for (int d = 2; d <= 8; d++) {
            ConvexHull h = new ConvexHull(d);
            assertTrue(h.build(crossPolytope(d), 2 * d));
            assertEquals(Math.pow(2, d) / factorial(d), h.volume(), TIGHT, "volume, d = " + d);
            assertEquals(1 << d, h.facetCount());
            assertEquals(1 << d, h.simplicialFacetCount(), "already simplicial");
            assertEquals(1 / Math.sqrt(d), h.minOffset(), TIGHT);
            assertEquals(1 / Math.sqrt(d), h.epsilon(crossPolytope(d), 2 * d), TIGHT);
        }
    }

    /** The polygon of random points: area by the shoelace formula over the hull vertices sorted by angle (an independent algorithm). */
    @Test
    void polygonAreaAgainstShoelace() {
        Random rnd = new Random(345);
        for (int trial = 0; trial < 200; trial++) {
            int n = 3 + rnd.nextInt(60);
            double[] p = new double[2 * n];
            for (int i = 0; i < 2 * n; i++) p[i] = rnd.nextGaussian();
            ConvexHull h = new ConvexHull(2);
            assertTrue(h.build(p, n));
            // Andrew's monotone chain
            Integer[] idx = new Integer[n];
            for (int i = 0; i < n; i++) idx[i] = i;
            Arrays.sort(idx, (a, b) -> p[2 * a] != p[2 * b] ? Double.compare(p[2 * a], p[2 * b]) : Double.compare(p[2 * a + 1], p[2 * b + 1]));
            int[] hull = new int[2 * n];
            int k = 0;
            for (int pass = 0; pass < 2; pass++) {
                int start = k;
                for (int j = 0; j < n; j++) {
                    int i = idx[pass == 0 ? j : n - 1 - j];
                    while (k >= start + 2 && cross(p, hull[k - 2], hull[k - 1], i) <= 0) k--;
                    hull[k++] = i;
                }
                k--;
            }
            double area = 0;
            for (int i = 0; i < k; i++) {
                int a = hull[i], b = hull[(i + 1) % k];
                area += p[2 * a] * p[2 * b + 1] - p[2 * b] * p[2 * a + 1];
            }
            area = Math.abs(area) / 2;
            assertEquals(area, h.volume(), 1e-12 * area, "trial " + trial);
            assertEquals(k, h.facetCount(), "edges, trial " + trial);
            assertEquals(k, h.vertexCount(), "vertices, trial " + trial);
        }
    }

    private static double cross(double[] p, int o, int a, int b) {
        return (p[2 * a] - p[2 * o]) * (p[2 * b + 1] - p[2 * o + 1]) - (p[2 * a + 1] - p[2 * o + 1]) * (p[2 * b] - p[2 * o]);
    }

    /**
     * Against brute force in 6-D: every input point lies on or below every facet (a supporting
     * hyperplane), every hull vertex is on some facet, and the nearest facet offset equals the
     * best-first one; random points in a ball, on a sphere (all are vertices) and on a cube's
     * lattice (exact coplanarities).
     */
    @Test
    void sixDimensionalHullsSupportEveryPoint() {
        Random rnd = new Random(2026);
        ConvexHull h = new ConvexHull(6);
        for (int trial = 0; trial < TestEffort.cases(60); trial++) {
            int n = 7 + rnd.nextInt(80);
            double[] p = new double[6 * n];
            for (int i = 0; i < n; i++) {
                double len = 0;
                for (int c = 0; c < 6; c++) { p[6 * i + c] = trial % 3 == 2 ? rnd.nextInt(3) - 1 : rnd.nextGaussian(); len += p[6 * i + c] * p[6 * i + c]; }
                if (trial % 3 == 1) for (int c = 0; c < 6; c++) p[6 * i + c] /= Math.sqrt(len);
            }
            if (!h.build(p, n)) continue;
            double tau = h.tolerance();
            double[][] planes = h.facetPlanes();
            for (double[] pl : planes) {
                for (int i = 0; i < n; i++) {
                    double s = -pl[6];
                    for (int c = 0; c < 6; c++) s += pl[c] * p[6 * i + c];
                    assertTrue(s <= tau * 10, "trial " + trial + ": point " + i + " is " + s + " above a facet");
                }
            }
            double ball = h.minOffset();
            assertEquals(ball, h.epsilon(p, n), 1e-12 * Math.max(1, Math.abs(ball)), "trial " + trial);
        }
    }

    /**
     * Nearly coplanar points, the hard case of floating-point hulls: random subsets of the
     * lattice {-1, 0, 1}^6 (many exactly coplanar points; the hull of the exact subset is the
     * reference) blurred by 1e-13 to 1e-7. Never an exception; the facet graph is a closed
     * manifold; no point lies above a facet by more than 1e-6 S (a step that needed a retry
     * gets the whole hull checked and, if rounding spoiled it, rebuilt on joggled points, as
     * qhull's QJ); the volume within 1e-5 of the exact subset's, and the two ε paths within 1e-6.
     */
    @Test
    void blurredLatticesStayConvex() {
        Random rnd = new Random(99);
        ConvexHull h = new ConvexHull(6), exact = new ConvexHull(6);
        for (int trial = 0; trial < TestEffort.cases(120); trial++) {
            int n = 10 + rnd.nextInt(90);
            double[] lattice = new double[6 * n], p = new double[6 * n];
            double blur = Math.pow(10, -13 + rnd.nextInt(7));
            for (int i = 0; i < 6 * n; i++) {
                lattice[i] = rnd.nextInt(3) - 1;
                p[i] = lattice[i] + blur * rnd.nextGaussian();
            }
            if (!exact.build(lattice, n)) continue;
            assertTrue(h.build(p, n), "trial " + trial);
            assertEquals(null, h.checkTopology(), "trial " + trial);
            for (double[] pl : h.facetPlanes()) {
                for (int i = 0; i < n; i++) {
                    double s = -pl[6];
                    for (int c = 0; c < 6; c++) s += pl[c] * p[6 * i + c];
                    assertTrue(s <= 1e-6, "trial " + trial + " (blur " + blur + "): point " + i + " is " + s + " above a facet");
                }
            }
            assertEquals(exact.volume(), h.volume(), 1e-5 * exact.volume(), "trial " + trial + " (blur " + blur + ")");
            double full = h.minOffset(), fast = h.epsilon(p, n);
            if (full > h.tolerance()) assertEquals(full, fast, 1e-6, "trial " + trial + " (blur " + blur + ")");
            else assertTrue(fast <= h.tolerance(), "trial " + trial + ": the origin outside, both paths say so");
        }
    }

    /** Fewer than d+1 points, duplicates, all points equal, points on a hyperplane or a line: lower-dimensional, never an exception. */
    @Test
    void degenerateInputIsLowerDimensional() {
        ConvexHull h = new ConvexHull(6);
        Random rnd = new Random(7);
        double[] none = new double[0];
        assertFalse(h.build(none, 0));
        assertEquals(0.0, h.volume());
        assertEquals(0, h.facetCount());
        assertTrue(Double.isNaN(h.epsilon(none, 0)));
        double[] six = new double[36];
        for (int i = 0; i < 36; i++) six[i] = rnd.nextGaussian();
        assertFalse(h.build(six, 6), "6 points span at most 5 dimensions");
        double[] same = new double[6 * 50];
        for (int i = 0; i < 50; i++) for (int c = 0; c < 6; c++) same[6 * i + c] = c + 0.5;
        assertFalse(h.build(same, 50));
        double[] flat = new double[6 * 40];          // on the hyperplane x1 + x2 = 1
        double[] line = new double[6 * 40];          // on a line through (1,..,1)
        for (int i = 0; i < 40; i++) {
            for (int c = 1; c < 6; c++) flat[6 * i + c] = rnd.nextGaussian();
            flat[6 * i] = 1 - flat[6 * i + 1];
            double t = rnd.nextGaussian();
            for (int c = 0; c < 6; c++) line[6 * i + c] = 1 + t * (c + 1);
        }
        assertFalse(h.build(flat, 40));
        assertFalse(h.build(line, 40));
        assertTrue(Double.isNaN(h.epsilon(flat, 40)));
        assertEquals(0.0, h.volume());
        // duplicates of a full-dimensional set change nothing
        double[] cross = crossPolytope(6);
        double[] twice = new double[2 * cross.length];
        System.arraycopy(cross, 0, twice, 0, cross.length);
        System.arraycopy(cross, 0, twice, cross.length, cross.length);
        assertTrue(h.build(twice, 24));
        assertEquals(64 / 720.0, h.volume(), TIGHT);
        assertEquals(64, h.facetCount());
    }

    @Test
    void nonFiniteCoordinatesAreRefusedWithTheirPlace() {
        double[] p = crossPolytope(6);
        p[6 * 3 + 2] = Double.NaN;
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ConvexHull(6).build(p, 12));
        assertTrue(e.getMessage().contains("coordinate 2 of point 3"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new ConvexHull(6).build(new double[10], 2));
        assertThrows(IllegalArgumentException.class, () -> new ConvexHull(9));
    }
}
