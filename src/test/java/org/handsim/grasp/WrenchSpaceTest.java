package org.handsim.grasp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/** Force closure, ε and volume of grasps derived by hand, the ε fast path against the whole hull, invariances, degenerate grasps. */
class WrenchSpaceTest {
    static final double TIGHT = 1e-12;

    /** The six face centres of a cube of half-size a, normals into the cube. */
    static final double A = 0.03;
    static final double[] FACE_POINTS = {A, 0, 0, -A, 0, 0, 0, A, 0, 0, -A, 0, 0, 0, A, 0, 0, -A};
    static final double[] FACE_NORMALS = {-1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1};

    /**
     * The face centres of a cube (half-size a, c its centre): contact k at σa·e_k pushing −σe_k.
     * Each edge's force is −σe_k + μ(cos θ_i t1 + sin θ_i t2) with t1, t2 = ∓e_j (the other two
     * axes, FrictionCone's azimuth), so its torque (p − c) × f / R = σ(a/R) e_k × μ(...) lies in
     * the plane of the two other axes with length μa/R. In the pure-torque direction
     * u = (0, 0, 0, 1, 1, −1)/√3 the support of the wrenches is therefore
     * h(u) = max_i u·w_i = (μa/R) · max over the edges of (cos θ, sin θ)·(±1, ±1)/√3
     * = (μa/R)/√3 for m = 4 (edges along the axes) and (μa/R)·√2/√3 for m = 8 (the diagonal
     * edges). The ball of radius ε lies in the hull, so ε ≤ h(u); the hull finds its nearest facet
     * in exactly that direction (ε = h(u)), and no other direction has a smaller support (checked
     * on 20 000 random directions).
     */
    @Test
    void cubeFaceCentresHaveTheHandDerivedEpsilon() {
        Random rnd = new Random(11);
        for (double r : new double[] {0.03, 0.052, 0.1}) {
            for (double mu : new double[] {0.1, 0.5, 1.0, 1.5}) {
                for (int m : new int[] {4, 8}) {
                    double[] w = GraspWrenches.of(6, FACE_POINTS, FACE_NORMALS, mu, m, new double[3], r);
                    double expected = mu * A / r * (m == 4 ? 1 : Math.sqrt(2)) / Math.sqrt(3);
                    GraspQuality q = WrenchSpace.quality(w, 6 * m, 6);
                    String id = "R " + r + ", mu " + mu + ", m " + m;
                    assertTrue(q.forceClosure(), id);
                    assertEquals(expected, q.epsilon(), TIGHT * expected, id);
                    assertEquals(expected, WrenchSpace.epsilon(w, 6 * m, 6).epsilon(), TIGHT * expected, id);
                    for (int s = 0; s < 20_000 / 24; s++) {
                        double[] u = new double[6];
                        double len = 0;
                        for (int c = 0; c < 6; c++) { u[c] = rnd.nextGaussian(); len += u[c] * u[c]; }
                        double h = Double.NEGATIVE_INFINITY;
                        for (int j = 0; j < 6 * m; j++) {
                            double dot = 0;
                            for (int c = 0; c < 6; c++) dot += u[c] * w[6 * j + c];
                            h = Math.max(h, dot / Math.sqrt(len));
                        }
                        assertTrue(h >= expected * (1 - TIGHT), id + ": support " + h + " below epsilon");
                    }
                }
            }
        }
    }

    /**
     * Two point contacts never give force closure, whatever μ and m: every wrench's torque about
     * the line through the two contact points is zero (the forces pass through the points), so
     * the wrenches lie in a 5-dimensional subspace (Murray, Li, Sastry §5.4). Antipodal pairs on
     * a sphere, and any two contacts on a box.
     */
    @Test
    void twoContactsNeverGiveForceClosure() {
        Random rnd = new Random(2);
        for (int trial = 0; trial < 200; trial++) {
            SeededGrasps.Contacts c = SeededGrasps.on(trial % 3, 2, 0.3, rnd);
            if (trial % 2 == 0) {   // antipodal: the second contact opposite the first through the centre
                for (int k = 0; k < 3; k++) { c.points()[3 + k] = -c.points()[k]; c.normals()[3 + k] = -c.normals()[k]; }
            }
            double mu = 0.1 + 2 * rnd.nextDouble();
            int m = 3 + rnd.nextInt(14);
            double[] w = SeededGrasps.wrenches(c, mu, m);
            GraspQuality q = WrenchSpace.quality(w, 2 * m, 2);
            assertFalse(q.forceClosure(), "trial " + trial);
            assertEquals(0.0, q.volume());
            assertEquals(0.0, q.epsilon());
            assertFalse(WrenchSpace.epsilon(w, 2 * m, 2).forceClosure());
        }
    }

    /**
     * Frictionless contacts (μ = 0) give one wrench each. Never force closure with 6 or fewer:
     * positively spanning R^6 takes at least 7 vectors (Steinitz; Mishra, Schwartz, Sharir 1987).
     * Never on a sphere with c at its centre, however many: every normal passes through c, the
     * torques vanish and the wrenches span 3 dimensions. (With 7 or more contacts on a box it can
     * hold — the reference sets have such cases — so "μ = 0 never" is not a theorem.)
     */
    @Test
    void frictionlessContactsWhereTheyCannotHold() {
        Random rnd = new Random(3);
        for (int trial = 0; trial < 150; trial++) {
            int n = 1 + rnd.nextInt(6);
            SeededGrasps.Contacts c = SeededGrasps.on(trial % 3, n, 0.3, rnd);
            double[] w = SeededGrasps.wrenches(c, 0, 1 + rnd.nextInt(8));
            int count = w.length / 6;
            assertFalse(WrenchSpace.quality(w, count, n).forceClosure(), "trial " + trial);
            assertFalse(WrenchSpace.epsilon(w, count, n).forceClosure(), "trial " + trial);
            SeededGrasps.Contacts s = SeededGrasps.on(0, 7 + rnd.nextInt(20), 0, rnd);
            double[] ws = SeededGrasps.wrenches(s, 0, 8);
            GraspQuality q = WrenchSpace.quality(ws, ws.length / 6, s.n());
            assertFalse(q.forceClosure());
            assertEquals(0.0, q.volume(), "sphere, frictionless: 3-dimensional");
        }
    }

    /** The ε fast path equals the whole hull's ε (1e-12 relative) and force closure on 400 seeded grasps of 3–16 contacts. */
    @Test
    void epsilonAloneEqualsTheWholeHull() {
        Random rnd = new Random(4);
        int closure = 0, trials = TestEffort.cases(400);   // all 400 in ./test --all
        for (int trial = 0; trial < trials; trial++) {
            int n = 3 + rnd.nextInt(14);
            SeededGrasps.Contacts c = SeededGrasps.on(trial % 3, n, trial % 4 == 0 ? 0.3 : 0, rnd);
            double mu = new double[] {0, 0.2, 0.5, 1}[rnd.nextInt(4)];
            int m = 4 + rnd.nextInt(7);
            double[] w = SeededGrasps.wrenches(c, mu, m);
            GraspQuality whole = WrenchSpace.quality(w, n * m, n), fast = WrenchSpace.epsilon(w, n * m, n);
            assertEquals(whole.forceClosure(), fast.forceClosure(), "trial " + trial);
            assertRel(whole.epsilon(), fast.epsilon(), TIGHT, "trial " + trial);
            if (whole.forceClosure()) closure++;
        }
        assertTrue(closure > 150 * trials / 400, "enough force-closure grasps: " + closure + " of " + trials);
    }

    /** Shuffling the wrenches or the contacts changes nothing; scaling the wrenches by λ scales ε by λ and the volume by λ^6. */
    @Test
    void invariantUnderPermutationAndScaledAsExpected() {
        Random rnd = new Random(5);
        for (int trial = 0; trial < 60; trial++) {
            int n = 3 + rnd.nextInt(8), m = 4 + rnd.nextInt(5);
            double[] w = SeededGrasps.wrenches(SeededGrasps.on(trial % 3, n, 0.2, rnd), 0.5, m);
            GraspQuality q = WrenchSpace.quality(w, n * m, n);
            double[] shuffled = w.clone();
            for (int j = n * m - 1; j > 0; j--) {
                int i = rnd.nextInt(j + 1);
                for (int c = 0; c < 6; c++) {
                    double t = shuffled[6 * i + c]; shuffled[6 * i + c] = shuffled[6 * j + c]; shuffled[6 * j + c] = t;
                }
            }
            GraspQuality s = WrenchSpace.quality(shuffled, n * m, n);
            assertEquals(q.forceClosure(), s.forceClosure());
            assertRel(q.epsilon(), s.epsilon(), 1e-11, "trial " + trial);
            assertRel(q.volume(), s.volume(), 1e-11, "trial " + trial);
            assertEquals(q.facets(), s.facets(), "trial " + trial);
            double lambda = 3.5;
            double[] scaled = w.clone();
            for (int i = 0; i < scaled.length; i++) scaled[i] *= lambda;
            GraspQuality z = WrenchSpace.quality(scaled, n * m, n);
            assertRel(lambda * q.epsilon(), z.epsilon(), 1e-11, "scaled, trial " + trial);
            assertRel(Math.pow(lambda, 6) * q.volume(), z.volume(), 1e-11, "scaled, trial " + trial);
        }
    }

    /**
     * Degenerate grasps give "no force closure, ε 0, volume 0, facets 0", never an exception or
     * NaN: no contacts, one contact, coincident contacts, collinear contacts, all contacts on one
     * face (full-dimensional but the normal force is one-sided), and wrenches perturbed off a
     * degenerate set by 1e-15 to 1e-6 (nearly coplanar facets): finite, and both paths agree.
     */
    @Test
    void degenerateGraspsAreHandled() {
        assertEquals(GraspQuality.none(0, 0), WrenchSpace.quality(new double[0], 0, 0));
        GraspQuality e0 = WrenchSpace.epsilon(new double[0], 0, 0);
        assertFalse(e0.forceClosure());
        assertEquals(0.0, e0.epsilon());
        Random rnd = new Random(6);
        for (int trial = 0; trial < 100; trial++) {
            int n = 1 + rnd.nextInt(8);
            SeededGrasps.Contacts c = SeededGrasps.on(trial % 3, n, 0.5, rnd);
            if (trial % 2 == 0) {            // coincident: every contact at the first point
                for (int i = 1; i < n; i++) System.arraycopy(c.points(), 0, c.points(), 3 * i, 3);
            } else {                          // collinear: on the line through the first point along (1, 2, 3)
                for (int i = 1; i < n; i++) for (int k = 0; k < 3; k++) c.points()[3 * i + k] = c.points()[k] + 0.004 * i * (k + 1);
            }
            double[] w = SeededGrasps.wrenches(c, 0.8, 8);
            assertEquals(GraspQuality.none(n, 8 * n), WrenchSpace.quality(w, 8 * n, n), "trial " + trial);
            for (double eps : new double[] {1e-15, 1e-12, 1e-9, 1e-6}) {
                double[] p = w.clone();
                for (int i = 0; i < p.length; i++) p[i] += eps * rnd.nextGaussian();
                GraspQuality q = WrenchSpace.quality(p, 8 * n, n), f = WrenchSpace.epsilon(p, 8 * n, n);
                assertTrue(Double.isFinite(q.epsilon()) && Double.isFinite(q.volume()) && q.volume() >= 0 && q.epsilon() >= 0);
                assertEquals(q.forceClosure(), f.forceClosure());
                // nearly flat hulls: ε may be ~1e-9 of the wrench scale S, known to τ = 1e-11 S
                double scale = 0;
                for (double x : p) scale = Math.max(scale, Math.abs(x));
                assertEquals(q.epsilon(), f.epsilon(), ConvexHull.DISTANCE_TOLERANCE * scale, "trial " + trial + ", perturbation " + eps);
            }
        }
        for (int trial = 0; trial < 50; trial++) {   // one face of the box: every force has the same normal component
            int n = 2 + rnd.nextInt(12);
            double[] p = new double[3 * n], nm = new double[3 * n];
            for (int i = 0; i < n; i++) {
                p[3 * i] = 0.1 * rnd.nextDouble(); p[3 * i + 1] = 0.1 * rnd.nextDouble(); p[3 * i + 2] = 0.02;
                nm[3 * i + 2] = -1;
            }
            double[] w = GraspWrenches.of(n, p, nm, 1.0, 8, new double[3], 0.1);
            assertFalse(WrenchSpace.quality(w, 8 * n, n).forceClosure());
            assertFalse(WrenchSpace.epsilon(w, 8 * n, n).forceClosure());
        }
    }

    /** |expected − actual| ≤ rel·|expected| (exact equality when expected is 0). */
    static void assertRel(double expected, double actual, double rel, String what) {
        assertTrue(expected == actual || Math.abs(expected - actual) <= rel * Math.abs(expected),
            what + ": expected " + expected + ", got " + actual);
    }

    @Test
    void badArgumentsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> WrenchSpace.quality(new double[11], 2, 1));
        assertThrows(IllegalArgumentException.class, () -> WrenchSpace.epsilon(new double[12], -1, 1));
        double[] w = new double[6 * 8];
        w[13] = Double.POSITIVE_INFINITY;
        assertThrows(IllegalArgumentException.class, () -> WrenchSpace.quality(w, 8, 1));
    }
}
