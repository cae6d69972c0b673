package org.handsim.contact;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.grasp.FrictionCone;
import org.junit.jupiter.api.Test;

/**
 * The projection onto a linearised friction cone against its definition (Moreau's
 * decomposition, Boyd–Vandenberghe §8.1): p = Π_K(v) iff p ∈ K, r = v − p lies in the polar
 * cone (r · e_k ≤ 0 for every edge) and r · p = 0. Checked on seeded random vectors and cones,
 * plus cases by hand.
 */
class ConeProjectionTest {
    static final double TOL = 1e-12;

    /** n = +z, μ = 0.5, m = 4: edges (0, .5, 1), (−.5, 0, 1), (0, −.5, 1), (.5, 0, 1) (FrictionCone's example). */
    @Test
    void casesByHand() {
        int m = 4;
        double[] e = new double[3 * m], nrm = new double[3 * m], p = new double[3];
        FrictionCone.edges(0, 0, 1, 0.5, m, e, 0);
        ConeProjection.facetNormals(e, 0, m, nrm, 0);
        // inside: unchanged
        assertEquals(2 * m, ConeProjection.project(e, 0, nrm, 0, m, 0.1, 0.1, 1, p, 0));
        assertEquals(0.1, p[0]); assertEquals(1, p[2]);
        // straight down (in the polar cone): the apex
        assertEquals(ConeProjection.APEX, ConeProjection.project(e, 0, nrm, 0, m, 0, 0, -1, p, 0));
        assertEquals(0, p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        // along +y beyond edge 0 (0, .5, 1): v = (0, 1, 0) projects onto the edge ray,
        // t = v·e/|e|² = 0.5/1.25 = 0.4, p = (0, 0.2, 0.4)
        assertEquals(0, ConeProjection.project(e, 0, nrm, 0, m, 0, 1, 0, p, 0));
        assertEquals(0.2, p[1], TOL);
        assertEquals(0.4, p[2], TOL);
        // the facet between edges 0 (0,.5,1) and 1 (−.5,0,1): its plane has normal ∝ (e0 × e1) =
        // (.5, −.5, .25)/0.75; v = (−1, 1, 1) is outside it and projects into the facet
        int code = ConeProjection.project(e, 0, nrm, 0, m, -1, 1, 1, p, 0);
        assertEquals(m + 0, code);
        moreau(e, m, new double[] {0, 0, 1}, new double[] {-1, 1, 1}, p);
    }

    @Test
    void randomVectorsSatisfyMoreausConditions() {
        Random rnd = new Random(345);
        double[] p = new double[3], d = new double[3];
        for (int trial = 0; trial < 20_000; trial++) {
            int m = 1 + rnd.nextInt(12);
            double mu = trial % 10 == 0 ? 1e-6 : 1.5 * rnd.nextDouble();
            double[] n = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double[] e = new double[3 * m], nrm = new double[3 * m];
            FrictionCone.edges(n[0], n[1], n[2], mu, m, e, 0);
            ConeProjection.facetNormals(e, 0, m, nrm, 0);
            double[] v = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            int code = ConeProjection.project(e, 0, nrm, 0, m, v[0], v[1], v[2], p, 0);
            moreau(e, m, n, v, p);
            // on its piece the projection is linear: DΠ·v = Π(v)
            ConeProjection.derivative(code, e, 0, nrm, 0, m, v[0], v[1], v[2], d, 0);
            for (int c = 0; c < 3; c++) assertEquals(p[c], d[c], 1e-9 * (1 + Math.abs(p[c])), "DΠ·v, trial " + trial);
        }
    }

    /** μ so small that every edge is the normal to rounding: the cone is a ray, never "everything inside". */
    @Test
    void aVanishingConeIsARay() {
        int m = 8;
        double[] e = new double[3 * m], nrm = new double[3 * m], p = new double[3];
        FrictionCone.edges(0, 0, 1, 1e-300, m, e, 0);
        ConeProjection.facetNormals(e, 0, m, nrm, 0);
        assertEquals(0, ConeProjection.project(e, 0, nrm, 0, m, 1, 0, 2, p, 0), "edge 0, the ray");
        assertEquals(0, p[0]);
        assertEquals(2, p[2]);
        assertEquals(ConeProjection.APEX, ConeProjection.project(e, 0, nrm, 0, m, 1, 0, -2, p, 0));
    }

    /** p ∈ K (a non-negative combination of the edges), v − p in the polar cone, (v − p) ⟂ p. */
    static void moreau(double[] e, int m, double[] n, double[] v, double[] p) {
        double scale = 1 + Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        double[] r = {v[0] - p[0], v[1] - p[1], v[2] - p[2]};
        for (int k = 0; k < m; k++) {
            double re = r[0] * e[3 * k] + r[1] * e[3 * k + 1] + r[2] * e[3 * k + 2];
            assertTrue(re <= 1e-9 * scale, "v − Π(v) not in the polar cone: r·e_" + k + " = " + re);
        }
        assertEquals(0, r[0] * p[0] + r[1] * p[1] + r[2] * p[2], 1e-9 * scale * scale, "(v − Π(v)) ⟂ Π(v)");
        assertTrue(inCone(e, m, n, p, 1e-9 * scale), () -> "Π(v) in K: m " + m + " v " + java.util.Arrays.toString(v) + " p " + java.util.Arrays.toString(p) + " n " + java.util.Arrays.toString(n) + " e " + java.util.Arrays.toString(e));
    }

    /**
     * p ∈ cone(e_0..e_{m−1}), from the edges alone: for m ≥ 3 the cone is the cone over the
     * convex polygon of the edge tips at normal component 1, so p is in it iff p·n ≥ 0 and
     * p/(p·n) lies inside that polygon (left of every side going round n); for m ≤ 2, p is a
     * non-negative combination of the edges (least squares with ~0 residual).
     */
    static boolean inCone(double[] e, int m, double[] n, double[] p, double tol) {
        double pl = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (pl <= tol) return true;
        double nl = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double[] u = {n[0] / nl, n[1] / nl, n[2] / nl};
        double pn = p[0] * u[0] + p[1] * u[1] + p[2] * u[2];
        if (pn < -tol) return false;
        if (m >= 3) {
            if (pn <= tol) return false;
            double[] q = {p[0] / pn, p[1] / pn, p[2] / pn};
            for (int k = 0; k < m; k++) {
                int a = 3 * k, b = 3 * ((k + 1) % m);
                double[] side = {e[b] - e[a], e[b + 1] - e[a + 1], e[b + 2] - e[a + 2]};
                double[] to = {q[0] - e[a], q[1] - e[a + 1], q[2] - e[a + 2]};
                double c = (side[1] * to[2] - side[2] * to[1]) * u[0] + (side[2] * to[0] - side[0] * to[2]) * u[1]
                    + (side[0] * to[1] - side[1] * to[0]) * u[2];
                if (c < -tol / pn) return false;
            }
            return true;
        }
        double[] e0 = {e[0], e[1], e[2]}, e1 = {e[3 * (m - 1)], e[3 * (m - 1) + 1], e[3 * (m - 1) + 2]};
        double l0 = Math.sqrt(dot(e0, 0, e0, 0));
        if (m == 1) {
            double[] c = cross(p, e0);
            return Math.sqrt(dot(c, 0, c, 0)) <= tol * l0 && dot(p, 0, e0, 0) >= 0;
        }
        // the flat wedge: p in the plane of e0, e1 and between them
        double[] sn = cross(e0, e1);
        double sl = Math.sqrt(dot(sn, 0, sn, 0));
        return Math.abs(dot(p, 0, sn, 0)) <= tol * sl && dot(cross(e0, p), 0, sn, 0) >= -tol * l0 * sl
            && dot(cross(p, e1), 0, sn, 0) >= -tol * l0 * sl;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] x, int i, double[] y, int j) {
        return x[i] * y[j] + x[i + 1] * y[j + 1] + x[i + 2] * y[j + 2];
    }
}
