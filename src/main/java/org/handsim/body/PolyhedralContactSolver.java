package org.handsim.body;

import org.handsim.math.Cholesky;
import org.ojalgo.optimisation.Optimisation;
import org.ojalgo.optimisation.convex.ConvexSolver;
import org.ojalgo.structure.Mutate2D;

/**
 * The same step problem as {@link ContactSolver}, solved the other way the design weighed
 * (DESIGN.md decision 7, "which solver"): the dual quadratic program in the impulses,
 * <pre>  min ½ γᵀ(W + R)γ + γᵀ(J v* − b)   over γ_c in a pyramid inscribed in Coulomb's cone,</pre>
 * W = J A⁻¹ Jᵀ, by ojAlgo's active-set {@link ConvexSolver}; then v = v* + A⁻¹Jᵀγ. The pyramid
 * has m facets {cos φ_k γ_t1 + sin φ_k γ_t2 ≤ μ cos(π/m) γ_n}, φ_k = (2k + 1)π/m, so its
 * friction falls short of Coulomb's by at most 1 − cos(π/m) (7.6 % at m = 8, 0.86 % at m = 24,
 * {@link #DEFAULT_FACETS}). Kept for the benchmark and the tests, which measure it against the
 * exact-cone Newton solver on the same problems.
 *
 * <p>Allocates per solve (ojAlgo's builder). Not thread-safe.
 */
public final class PolyhedralContactSolver {
    /** Facets of the pyramid: the fewest whose friction error is below 1 % in every direction. */
    public static final int DEFAULT_FACETS = 24;

    private final int facets;
    private double[] v = new double[0], gamma = new double[0];
    private Optimisation.State state;

    /** @param facets m ≥ 3 */
    public PolyhedralContactSolver(int facets) {
        if (facets < 3) throw new IllegalArgumentException("a pyramid needs at least 3 facets, got " + facets);
        this.facets = facets;
    }

    /**
     * Solves {@code p} with the regularisation its last {@link ContactSolver} solve set (or, if
     * none, ε·W_c,nn computed here).
     *
     * @return true when ojAlgo reports an optimum
     */
    public boolean solve(ContactProblem p) {
        int nv = p.nv, nc = p.nc, n = 3 * nc;
        double[] l = new double[nv * nv];
        System.arraycopy(p.a, 0, l, 0, nv * nv);
        if (!Cholesky.decompose(l, nv)) return false;
        // A⁻¹Jᵀ, column by column (n columns of nv)
        double[] aij = new double[n * nv];
        double[] col = new double[nv];
        for (int r = 0; r < n; r++) {
            System.arraycopy(p.jac, r * nv, col, 0, nv);
            Cholesky.solve(l, nv, col);
            System.arraycopy(col, 0, aij, r * nv, nv);
        }
        for (int c = 0; c < nc; c++) {
            if (!(p.reg[c] > 0)) {
                double w = 0;
                for (int j = 0; j < nv; j++) w += p.jac[3 * c * nv + j] * aij[3 * c * nv + j];
                p.reg[c] = p.epsilon * Math.max(w, 1e-300);
            }
        }
        ConvexSolver.Builder qp = ConvexSolver.newBuilder(n);
        for (int r = 0; r < n; r++) {
            for (int s = 0; s < n; s++) {
                double w = 0;
                for (int j = 0; j < nv; j++) w += p.jac[r * nv + j] * aij[s * nv + j];
                if (r == s) w += p.reg[r / 3];
                qp.objective(r, s, w);
            }
        }
        // ojAlgo minimises ½xᵀQx − cᵀx: c = −(J v* − b)
        double[] lin = new double[n];
        for (int r = 0; r < n; r++) {
            double s = 0;
            for (int j = 0; j < nv; j++) s += p.jac[r * nv + j] * p.vStar[j];
            lin[r] = -(s - p.bias[r]);
        }
        qp.linear(lin);
        int rows = 0;
        // a frictionless contact's tangential impulses are fixed at 0 by equalities: as the pair of
        // opposite inequalities γ_t ≤ 0, −γ_t ≤ 0 they make a degenerate working set on which
        // ojAlgo's active-set solver stops at γ = 0 and still reports OPTIMAL (seed 77, cases 26,
        // 39, 51 and 54 of ContactSolverTest)
        int eqs = 0;
        for (int c = 0; c < nc; c++) { rows += p.mu[c] > 0 ? facets + 1 : 1; if (!(p.mu[c] > 0)) eqs += 2; }
        if (eqs > 0) {
            Mutate2D eq = qp.equalities(new double[eqs]);
            int e = 0;
            for (int c = 0; c < nc; c++) if (!(p.mu[c] > 0)) { eq.set(e++, 3 * c + 1, 1); eq.set(e++, 3 * c + 2, 1); }
        }
        Mutate2D in = qp.inequalities(new double[rows]);
        int row = 0;
        double k = Math.cos(Math.PI / facets);
        for (int c = 0; c < nc; c++) {
            int o = 3 * c;
            in.set(row++, o, -1);                                   // γ_n ≥ 0
            if (p.mu[c] > 0) {
                for (int f = 0; f < facets; f++) {
                    double phi = (2 * f + 1) * Math.PI / facets;
                    in.set(row, o, -p.mu[c] * k);
                    in.set(row, o + 1, Math.cos(phi));
                    in.set(row, o + 2, Math.sin(phi));
                    row++;
                }
            }
        }
        Optimisation.Result r = qp.build().solve();
        state = r.getState();
        if (!state.isOptimal()) return false;
        if (gamma.length < n) gamma = new double[n];
        if (v.length < nv) v = new double[nv];
        for (int i = 0; i < n; i++) gamma[i] = r.doubleValue(i);
        for (int j = 0; j < nv; j++) {
            double s = p.vStar[j];
            for (int i = 0; i < n; i++) s += aij[i * nv + j] * gamma[i];
            v[j] = s;
        }
        return true;
    }

    /** @return ojAlgo's final state of the last solve */
    public Optimisation.State state() { return state; }

    /** @return velocity j of the last solve */
    public double velocity(int j) { return v[j]; }

    /** @return component k (0 normal, 1 t₁, 2 t₂) of constraint c's impulse, N·s */
    public double impulse(int c, int k) { return gamma[3 * c + k]; }
}
