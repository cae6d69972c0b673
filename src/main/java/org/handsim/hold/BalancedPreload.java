package org.handsim.hold;

import java.util.List;
import org.handsim.grasp.FrictionCone;
import org.handsim.grasp.GraspAssessment;
import org.ojalgo.optimisation.Expression;
import org.ojalgo.optimisation.ExpressionsBasedModel;
import org.ojalgo.optimisation.Optimisation;
import org.ojalgo.optimisation.Variable;

/**
 * The squeeze a locked grasp keeps once its object is freed. A closing on a fixed object leaves
 * contact forces f⁰ that need not balance — the fixed object took the rest. Freed, the object
 * gives way by the contacts' elastic deflection (micrometres for stiff contacts, the links held
 * by their worms) until the forces do balance; by the model of the forces' distribution (DESIGN.md
 * decision 5: one isotropic contact stiffness, the least complementary energy of the change) they
 * become the balanced forces nearest f⁰:
 * <pre>  minimise Σ_i |f_i − f⁰_i|²  over f_i in the cones (8 edges, {@link FrictionCone}),
 *   subject to  Σ_i f_i = 0,  Σ_i (p_i − c) × f_i = 0,</pre>
 * c the centre of mass — a quadratic program (ojAlgo's convex solver; one per grasp, a few dozen
 * unknowns). All zero is always feasible: contacts that cannot squeeze the object against each
 * other keep nothing.
 */
public final class BalancedPreload {
    /** Edges of the cones. */
    static final int EDGES = FrictionCone.DEFAULT_EDGES;

    private BalancedPreload() {}

    /**
     * The balanced forces nearest the contacts' own, 3 per contact (world, N, on the object), in
     * the order of {@code contacts}; the contacts' own when ojAlgo reports no optimum (not seen).
     *
     * @param contacts the grasp's contacts with their forces
     * @param com      the object's centre of mass, world, m
     * @param mu       Coulomb's μ
     */
    public static double[] of(List<GraspAssessment.Contact> contacts, double[] com, double mu) {
        int n = contacts.size();
        double[] f0 = new double[3 * n];
        for (int i = 0; i < n; i++) System.arraycopy(contacts.get(i).forceN(), 0, f0, 3 * i, 3);
        if (n == 0) return f0;
        // frictionless: the cone is its normal ray, one edge (eight equal edges leave ojAlgo's
        // solver at zero, an optimum it reports although any balanced squeeze is nearer)
        int edges = mu > 0 ? EDGES : 1;
        double[] cones = new double[3 * edges * n];
        for (int i = 0; i < n; i++) {
            double[] d = contacts.get(i).normal();
            if (edges == 1) System.arraycopy(d, 0, cones, 3 * i, 3);
            else FrictionCone.edges(d[0], d[1], d[2], mu, edges, cones, 3 * edges * i);
        }
        ExpressionsBasedModel model = new ExpressionsBasedModel();
        Variable[] lam = new Variable[n * edges];
        for (int v = 0; v < n * edges; v++) lam[v] = model.addVariable("l" + v).lower(0);
        Expression obj = model.addExpression("objective").weight(1);
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < edges; a++) {
                int ea = 3 * edges * i + 3 * a;
                obj.set(lam[i * edges + a], -2 * (f0[3 * i] * cones[ea] + f0[3 * i + 1] * cones[ea + 1] + f0[3 * i + 2] * cones[ea + 2]));
                for (int b = 0; b < edges; b++) {
                    int eb = 3 * edges * i + 3 * b;
                    obj.set(lam[i * edges + a], lam[i * edges + b], cones[ea] * cones[eb] + cones[ea + 1] * cones[eb + 1] + cones[ea + 2] * cones[eb + 2]);
                }
            }
        }
        // Σ f = 0 and Σ r × f = 0 (r from the centre of mass; the torque rows divided by the grasp's size, for conditioning)
        double size = 1e-3;
        for (GraspAssessment.Contact c : contacts) {
            double[] p = c.point();
            size = Math.max(size, Math.sqrt(sq(p[0] - com[0]) + sq(p[1] - com[1]) + sq(p[2] - com[2])));
        }
        // coefficients below rounding (1e-12 of the largest; a frictionless wrap's rows along the
        // cylinder's axis are 1e-16s) are zeros, and a row of zeros no constraint: ojAlgo's solver
        // stops at zero on such near-empty equality rows
        double[] coef = new double[n * edges];
        double biggest = 0;
        double[][] rows = new double[6][];
        for (int row = 0; row < 6; row++) {
            for (int i = 0; i < n; i++) {
                double[] p = contacts.get(i).point();
                double rx = p[0] - com[0], ry = p[1] - com[1], rz = p[2] - com[2];
                for (int k = 0; k < edges; k++) {
                    int o = 3 * edges * i + 3 * k;
                    double ex = cones[o], ey = cones[o + 1], ez = cones[o + 2];
                    coef[i * edges + k] = row == 0 ? ex : row == 1 ? ey : row == 2 ? ez
                        : (row == 3 ? ry * ez - rz * ey : row == 4 ? rz * ex - rx * ez : rx * ey - ry * ex) / size;
                    biggest = Math.max(biggest, Math.abs(coef[i * edges + k]));
                }
            }
            rows[row] = coef.clone();
        }
        for (int row = 0; row < 6; row++) {
            Expression e = null;
            for (int v = 0; v < n * edges; v++) {
                if (Math.abs(rows[row][v]) <= 1e-12 * biggest) continue;
                if (e == null) e = model.addExpression("balance" + row).level(0);
                e.set(lam[v], rows[row][v]);
            }
        }
        Optimisation.Result r = model.minimise();
        if (!r.getState().isOptimal()) return f0;
        double[] f = new double[3 * n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < edges; k++) {
                double w = Math.max(0, lam[i * edges + k].getValue().doubleValue());
                for (int c = 0; c < 3; c++) f[3 * i + c] += w * cones[3 * edges * i + 3 * k + c];
            }
        }
        return f;
    }

    private static double sq(double a) { return a * a; }
}
