package org.handsim.grasp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;
import org.ojalgo.optimisation.Expression;
import org.ojalgo.optimisation.ExpressionsBasedModel;
import org.ojalgo.optimisation.Optimisation;
import org.ojalgo.optimisation.Variable;

/**
 * The hold LP ({@link HoldCapacity}: ojAlgo's simplex through its double-valued
 * {@code LinearSolver.Builder}) against a second formulation of the same LP written here from
 * the raw contacts and joints with ojAlgo's {@link ExpressionsBasedModel} (BigDecimal
 * coefficients, presolve, one model per direction — HoldCapacity's own path until the
 * planner's speed work): 1 200 seeded grasps of 2–6 contacts on a sphere, a box and a cylinder,
 * 1–4 joints with random axes, origins, limits (some 0) and chains, μ from 0 to 1, the six
 * directions each. The optimum F is unique (the contact forces need not be), so the two must
 * agree: to 1e-9 relative, or 1e-9 N for holds below 1 N (measured here: at most 2.1e-12 of
 * max(1 N, F); on the grasps of 1 000 mug trials at most 1.3e-11 relative and 1.4e-11 N — both
 * solvers' rounding: a hold of 0 comes out as 0 or 1e-14 from the model, 0 or 7.1e-15, an ulp
 * of F_cap, from the builder). Of the 7 200 answers 987 are held, 1 360 capped, 4 853 zero.
 */
class HoldCapacityReferenceTest {
    @Test
    void theBuilderLpAgreesWithTheExpressionsModelOnSeededGrasps() {
        Random rnd = new Random(2026);
        int held = 0, capped = 0, zero = 0;
        int grasps = TestEffort.cases(1200);   // all 1200 in ./test --all
        for (int g = 0; g < grasps; g++) {
            double mu = g % 10 == 0 ? 0 : rnd.nextDouble();
            int n = 2 + rnd.nextInt(5), m = g % 7 == 0 ? 4 : 8;
            SeededGrasps.Contacts cs = SeededGrasps.on(g % 3, n, 0.2, rnd);
            double[] c = {0.005 * rnd.nextGaussian(), 0.005 * rnd.nextGaussian(), 0.005 * rnd.nextGaussian()};
            double radius = 0.06, cap = g % 5 == 0 ? 5 : 58.84;
            int nj = 1 + rnd.nextInt(4);
            double[][] joints = new double[nj][];
            for (int j = 0; j < nj; j++) {
                double[] z = unit(rnd);
                double limit = j == 0 && g % 11 == 0 ? 0 : 0.1 + 2 * rnd.nextDouble();
                joints[j] = new double[] {z[0], z[1], z[2], 0.08 * rnd.nextGaussian(), 0.08 * rnd.nextGaussian(), 0.08 * rnd.nextGaussian(), limit};
            }
            int[][] chains = new int[n][];
            HoldCapacity hc = new HoldCapacity(mu, m, c, radius, cap);
            for (double[] j : joints) hc.addJoint(new double[] {j[0], j[1], j[2]}, new double[] {j[3], j[4], j[5]}, j[6]);
            for (int i = 0; i < n; i++) {
                int k = rnd.nextInt(nj + 1);            // 0: a link fixed to the palm
                chains[i] = new int[k];
                for (int q = 0; q < k; q++) chains[i][q] = q;
                hc.addContact(new double[] {cs.points()[3 * i], cs.points()[3 * i + 1], cs.points()[3 * i + 2]},
                    new double[] {cs.normals()[3 * i], cs.normals()[3 * i + 1], cs.normals()[3 * i + 2]}, chains[i]);
            }
            for (double[] d : HoldCapacity.SIX_DIRECTIONS) {
                double expected = reference(cs, chains, joints, mu, m, c, radius, cap, d);
                double got = hc.hold(d).forceN();
                double tol = 1e-9 * Math.max(1, expected);
                assertEquals(expected, got, tol, "grasp " + g + " direction " + java.util.Arrays.toString(d));
                if (expected >= cap * (1 - 1e-9)) capped++; else if (expected > 1e-9) held++; else zero++;
            }
        }
        // every kind of answer is exercised
        double share = grasps / 1200.0;   // of the full run's 987 held, 1 360 capped, 4 853 zero
        assertTrue(held > 800 * share && capped > 1000 * share && zero > 1000 * share, "held " + held + ", capped " + capped + ", zero " + zero);
    }

    /** The LP of HoldCapacity's Javadoc as an {@link ExpressionsBasedModel}, from the raw grasp. */
    private static double reference(SeededGrasps.Contacts cs, int[][] chains, double[][] joints, double mu, int m,
                                    double[] c, double radius, double cap, double[] d) {
        int n = cs.n();
        double[] e = new double[3 * m * n];
        for (int i = 0; i < n; i++) {
            FrictionCone.edges(cs.normals()[3 * i], cs.normals()[3 * i + 1], cs.normals()[3 * i + 2], mu, m, e, 3 * m * i);
        }
        ExpressionsBasedModel model = new ExpressionsBasedModel();
        Variable load = model.addVariable("F").lower(0).upper(cap).weight(1);
        Variable[] lambda = new Variable[n * m];
        for (int v = 0; v < n * m; v++) lambda[v] = model.addVariable("l" + v).lower(0);
        Expression[] rows = new Expression[6];
        for (int r = 0; r < 6; r++) {
            rows[r] = model.addExpression("balance" + r).level(0);
            if (r < 3) rows[r].set(load, d[r]);
        }
        for (int i = 0; i < n; i++) {
            double[] p = {cs.points()[3 * i] - c[0], cs.points()[3 * i + 1] - c[1], cs.points()[3 * i + 2] - c[2]};
            for (int k = 0; k < m; k++) {
                int o = 3 * (m * i + k);
                double[] f = {e[o], e[o + 1], e[o + 2]};
                double[] t = cross(p, f);
                Variable l = lambda[m * i + k];
                for (int a = 0; a < 3; a++) {
                    rows[a].set(l, f[a]);
                    rows[3 + a].set(l, t[a] / radius);
                }
            }
        }
        for (int j = 0; j < joints.length; j++) {
            Expression row = model.addExpression("joint" + j).lower(-joints[j][6]).upper(joints[j][6]);
            for (int i = 0; i < n; i++) {
                boolean loads = false;
                for (int q : chains[i]) loads |= q == j;
                if (!loads) continue;
                double[] r = {cs.points()[3 * i] - joints[j][3], cs.points()[3 * i + 1] - joints[j][4], cs.points()[3 * i + 2] - joints[j][5]};
                double[] arm = cross(new double[] {joints[j][0], joints[j][1], joints[j][2]}, r);
                for (int k = 0; k < m; k++) {
                    int o = 3 * (m * i + k);
                    row.set(lambda[m * i + k], arm[0] * e[o] + arm[1] * e[o + 1] + arm[2] * e[o + 2]);
                }
            }
        }
        Optimisation.Result r = model.maximise();
        assertTrue(r.getState().isOptimal(), "reference LP: " + r.getState());
        BigDecimal f = load.getValue();
        return Math.max(0, Math.min(cap, f.doubleValue()));
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] unit(Random rnd) {
        double[] v = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }
}
