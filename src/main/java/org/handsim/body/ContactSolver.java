package org.handsim.body;

import org.handsim.math.Cholesky;

/**
 * Solves a {@link ContactProblem} exactly (to rounding): Newton's method on the convex,
 * continuously differentiable primal cost
 * <pre>  ℓ(v) = ½(v − v*)ᵀA(v − v*) + Σ_c ½|P_F(y_c)|²·r_c,   y_c = −(J_c v − b_c)/r_c,</pre>
 * whose gradient is A(v − v*) − Σ J_cᵀγ_c with γ_c = P_F(y_c) and whose (generalised) Hessian
 * is A + Σ J_cᵀ (∂P_F/∂y)/r_c J_c — the Semi-Analytic Primal method of Castro et al. 2023
 * (see {@link ContactProblem}) with an isotropic regularisation, so the projection onto the
 * regularised cone is the Euclidean projection onto Coulomb's exact circular cone: no
 * polyhedral approximation. Each Newton direction (a dense Cholesky solve of nv × nv, nv = 6
 * plus the following joints) is followed by an exact line search (a safeguarded Newton–bisection
 * on the directional derivative, convex along the line). ℓ is piecewise smooth with finitely
 * many pieces; once the pieces settle, Newton converges quadratically, and the solve stops when
 * the gradient, scaled per velocity by 1/√A_jj, is below {@code 1e-12} of the momenta involved,
 * or when a Newton step moves v by less than {@code 1e-14} of its size (the gradient has then
 * reached its floor of rounding, which a sliding contact raises: its impulse is the projection
 * of a y of size |v|/r onto the cone's boundary).
 *
 * <p><b>Projection onto F = {(γ_n, γ_t): |γ_t| ≤ μγ_n}</b> (Euclidean; three cases): inside,
 * y itself; in the polar cone (μ|y_t| ≤ −y_n), 0; otherwise onto the boundary ray through
 * y_t's direction, γ_n = (y_n + μ|y_t|)/(1 + μ²), γ_t = μγ_n·y_t/|y_t|.
 *
 * <p>Not thread-safe (scratch); allocation-free once its buffers have grown to the problem.
 */
public final class ContactSolver {
    /** Most Newton iterations before the solve gives up (not reached in the tests: 3–12 are typical). */
    public static final int MAX_ITERATIONS = 100;
    /** Relative size of the scaled gradient at which the solve stops. */
    public static final double TOLERANCE = 1e-12;
    /** Relative size of a Newton step (in √A-scaled velocities) below which v has converged to rounding. */
    public static final double STEP_TOLERANCE = 1e-14;

    /** How a solve ended. */
    public enum Outcome { CONVERGED, MAX_ITERATIONS, NOT_POSITIVE_DEFINITE }

    private double[] v = new double[0], grad = new double[0], dir = new double[0], hess = new double[0], av = new double[0];
    private double[] vc = new double[0], jd = new double[0], gamma = new double[0], g = new double[0];
    private double[] col = new double[0], dps = new double[0];
    // per solve: √A_jj, and each constraint's nonzero Jacobian columns (a contact on a link touches the
    // object's six and the joints that move the link; a worm, one): the loops skip the zeros, which
    // add nothing, so the sums are the dense loops' sums term for term
    private double[] rootA = new double[0];
    private int[] cols = new int[0], colCount = new int[0];
    private double[] packed = new double[0];    // J's rows with only those columns, in their order (row stride nv)
    private final double[] gm = new double[3], second = new double[1];
    private double[] base = new double[0];
    private int fixedPoint;
    private int iterations;
    private Outcome outcome = Outcome.CONVERGED;
    private double lastGradient;

    /**
     * Solves {@code p}; the velocities are then {@link #velocity}, the impulses {@link #impulse}.
     *
     * @return how it ended ({@link Outcome#CONVERGED} unless the problem is broken)
     */
    public Outcome solve(ContactProblem p) {
        return solve(p, false);
    }

    /**
     * Solves {@code p} for Coulomb's law itself rather than its convex relaxation. In the relaxed
     * problem a sliding contact must also separate at μ|v_t| (the velocity lies in the dual cone):
     * harmless on a table (the object would hover μ|v_t|h above it) but it locks an object squeezed
     * between two links that cannot open — it could not slide out of a pinch however little
     * friction held it. So, after the relaxed solve, each contact's friction is bounded by a disk of
     * radius μ·γ̂_n, γ̂_n its last normal impulse, with the normal impulse free and unilateral
     * ({γ_n ≥ 0} × {|γ_t| ≤ μγ̂_n}: a convex set, projected onto separably), and the problem solved
     * again, warm-started, until the normal impulses settle (to {@value #SHIFT_TOLERANCE} of the
     * largest): a fixed point is a solution of the exact Coulomb problem — no penetration and no
     * separation, v_n ≥ b_n complementary to γ_n, friction on the disk of radius μγ_n opposite the
     * slip (the staggered projections of Kaufman, Sueda, James, Pai, SIGGRAPH Asia 2008; the
     * "fixed normal force" friction of ODE and Bullet, iterated to consistency). Each iteration is
     * one convex problem solved exactly; {@link #fixedPointIterations} counts them. The
     * iteration x → γ_n(x) (x the disks' normal impulses) converges only linearly, at a rate of
     * 0.3–0.7 on a grasp, and on a contact that separates it shrinks x geometrically to 0; so
     * each next x is Anderson's mixing of the last {@value #ANDERSON_MEMORY} maps (the
     * combination of γ_n(x_i) whose residual γ_n(x_i) − x_i is least by least squares: exact in
     * a few solves where the map is affine, as it is while the contacts keep their pieces — Walker
     * and Ni, SIAM J. Numer. Anal. 49, 2011), clamped at 0. A residual that grows by more than
     * {@value #GROWTH}× (a piece changed) drops the history and halves the plain update. The
     * fixed point and its test are unchanged, only the way to it: on the planner's mug grasps
     * 5.7 instead of 17 solves a step. The problem keeps the disks of the last solve.
     *
     * @return how the last solve ended; {@link Outcome#MAX_ITERATIONS} also when the normal
     *         impulses did not settle within {@value #MAX_FIXED_POINT} solves
     */
    public Outcome solveCoulomb(ContactProblem p) {
        int nc = p.nc;
        if (base.length < nc) {
            base = new double[nc]; residual = new double[nc]; mapped = new double[nc];
            dMapped = new double[ANDERSON_MEMORY * nc]; dResidual = new double[ANDERSON_MEMORY * nc];
        }
        Outcome o = solve(p, false, true);
        fixedPoint = 1;
        if (o == Outcome.NOT_POSITIVE_DEFINITE) return o;
        boolean any = false;
        for (int c = 0; c < nc; c++) {
            if (p.mu[c] > 0) {
                base[c] = gamma[3 * c];
                any = true;
            }
        }
        if (!any) return o;
        int stored = 0;
        double damping = 1, lastChange = Double.POSITIVE_INFINITY;
        for (int k = 1; k < MAX_FIXED_POINT; k++) {
            for (int c = 0; c < nc; c++) if (p.mu[c] > 0) p.radius[c] = p.mu[c] * base[c];
            o = solve(p, true, false);
            fixedPoint++;
            if (o == Outcome.NOT_POSITIVE_DEFINITE) return o;
            double change = 0, size = 0;
            for (int c = 0; c < nc; c++) {
                if (p.mu[c] == 0) continue;
                change = Math.max(change, Math.abs(gamma[3 * c] - base[c]));
                size = Math.max(size, Math.max(gamma[3 * c], base[c]));
            }
            if (change <= SHIFT_TOLERANCE * size || change == 0) return o;
            // Anderson's mixing: the next radii from the last few maps x -> γ_n(x) and their residuals
            // (the differences of successive ones), the combination whose residual is least; a
            // residual that grew drops the history (the map's pieces changed)
            boolean grew = change > GROWTH * lastChange;
            if (grew) {
                stored = 0;
                damping = Math.max(0.125, 0.5 * damping);
            } else if (k > 1) {
                // newest first: shift the older ones up
                System.arraycopy(dMapped, 0, dMapped, nc, (ANDERSON_MEMORY - 1) * nc);
                System.arraycopy(dResidual, 0, dResidual, nc, (ANDERSON_MEMORY - 1) * nc);
                for (int c = 0; c < nc; c++) {
                    double r = p.mu[c] > 0 ? gamma[3 * c] - base[c] : 0;
                    dMapped[c] = (p.mu[c] > 0 ? gamma[3 * c] : 0) - mapped[c];
                    dResidual[c] = r - residual[c];
                }
                stored = Math.min(stored + 1, ANDERSON_MEMORY);
            }
            lastChange = change;
            for (int c = 0; c < nc; c++) {
                mapped[c] = p.mu[c] > 0 ? gamma[3 * c] : 0;
                residual[c] = p.mu[c] > 0 ? gamma[3 * c] - base[c] : 0;
            }
            int m = stored;
            while (m > 0 && !mix(nc, m)) m--;   // dependent differences: the newest that are not
            if (m == 0) {
                for (int c = 0; c < nc; c++) if (p.mu[c] > 0) base[c] += damping * (mapped[c] - base[c]);
            }
        }
        return Outcome.MAX_ITERATIONS;
    }

    /**
     * base = mapped − ΔG·θ with θ the least-squares minimiser of |residual − ΔF·θ| over the
     * {@code m} stored differences (normal equations, m ≤ {@value #ANDERSON_MEMORY}), clamped at
     * 0 (a normal impulse); false, base untouched, when the differences are (nearly) dependent.
     */
    private boolean mix(int nc, int m) {
        for (int i = 0; i < m; i++) {
            for (int j = 0; j <= i; j++) {
                double s = 0;
                for (int c = 0; c < nc; c++) s += dResidual[i * nc + c] * dResidual[j * nc + c];
                gram[i * ANDERSON_MEMORY + j] = s;
                gram[j * ANDERSON_MEMORY + i] = s;
            }
            double s = 0;
            for (int c = 0; c < nc; c++) s += dResidual[i * nc + c] * residual[c];
            theta[i] = s;
        }
        // Cholesky of the m × m Gram matrix in place (row stride ANDERSON_MEMORY), refused when nearly singular
        for (int j = 0; j < m; j++) {
            double d = gram[j * ANDERSON_MEMORY + j];
            for (int k = 0; k < j; k++) d -= gram[j * ANDERSON_MEMORY + k] * gram[j * ANDERSON_MEMORY + k];
            if (!(d > 1e-14 * gram[j * ANDERSON_MEMORY + j])) return false;
            d = Math.sqrt(d);
            gram[j * ANDERSON_MEMORY + j] = d;
            for (int i = j + 1; i < m; i++) {
                double s = gram[i * ANDERSON_MEMORY + j];
                for (int k = 0; k < j; k++) s -= gram[i * ANDERSON_MEMORY + k] * gram[j * ANDERSON_MEMORY + k];
                gram[i * ANDERSON_MEMORY + j] = s / d;
            }
        }
        for (int i = 0; i < m; i++) {
            double s = theta[i];
            for (int k = 0; k < i; k++) s -= gram[i * ANDERSON_MEMORY + k] * theta[k];
            theta[i] = s / gram[i * ANDERSON_MEMORY + i];
        }
        for (int i = m - 1; i >= 0; i--) {
            double s = theta[i];
            for (int k = i + 1; k < m; k++) s -= gram[k * ANDERSON_MEMORY + i] * theta[k];
            theta[i] = s / gram[i * ANDERSON_MEMORY + i];
        }
        for (int c = 0; c < nc; c++) {
            double x = mapped[c];
            for (int i = 0; i < m; i++) x -= dMapped[i * nc + c] * theta[i];
            base[c] = Math.max(0, x);
        }
        return true;
    }

    /** How many past iterates Anderson's mixing combines. */
    static final int ANDERSON_MEMORY = 3;
    /** A residual that grew by more than this factor drops the history and halves the plain update. */
    static final double GROWTH = 1.5;
    private final double[] gram = new double[ANDERSON_MEMORY * ANDERSON_MEMORY], theta = new double[ANDERSON_MEMORY];
    private double[] residual = new double[0], mapped = new double[0], dMapped = new double[0], dResidual = new double[0];

    /** Most convex solves of one {@link #solveCoulomb}. */
    public static final int MAX_FIXED_POINT = 50;
    /** The normal impulses have settled when they change by less than this fraction of the largest. */
    public static final double SHIFT_TOLERANCE = 1e-9;

    private Outcome solve(ContactProblem p, boolean warm) {
        return solve(p, warm, true);
    }

    /** One convex solve; {@code regularise}: set R_c first (else the problem's, from a solve of the same A and J). */
    private Outcome solve(ContactProblem p, boolean warm, boolean regularise) {
        int nv = p.nv, nc = p.nc;
        grow(nv, nc);
        double[] a = p.a;
        // a solve of the same A and J as the last (solveCoulomb's next): the regularisation and the columns stand
        if (regularise) {
            // A⁻¹ columns, for the regularisation R_c = ε·(J_c A⁻¹ J_cᵀ)_nn
            System.arraycopy(a, 0, hess, 0, nv * nv);
            if (!Cholesky.decompose(hess, nv)) return outcome = Outcome.NOT_POSITIVE_DEFINITE;
            for (int c = 0; c < nc; c++) {
                int row = 3 * c * nv;
                System.arraycopy(p.jac, row, col, 0, nv);
                Cholesky.solve(hess, nv, col);
                double w = 0;
                for (int j = 0; j < nv; j++) w += p.jac[row + j] * col[j];
                p.reg[c] = p.epsilon * Math.max(w, 1e-300);
            }
            for (int j = 0; j < nv; j++) rootA[j] = Math.sqrt(a[j * nv + j]);
            for (int c = 0; c < nc; c++) {
                int m = 0, row = 3 * c * nv;
                for (int j = 0; j < nv; j++) {
                    if (p.jac[row + j] != 0 || p.jac[row + nv + j] != 0 || p.jac[row + 2 * nv + j] != 0) cols[c * nv + m++] = j;
                }
                colCount[c] = m;
                for (int k = 0; k < 3; k++) {
                    for (int x = 0; x < m; x++) packed[row + k * nv + x] = p.jac[row + k * nv + cols[c * nv + x]];
                }
            }
        }
        if (!warm) System.arraycopy(p.vStar, 0, v, 0, nv);
        if (!warm) iterations = 0;
        outcome = Outcome.MAX_ITERATIONS;
        for (int it = 0; it < MAX_ITERATIONS; it++) {
            evaluate(p, true);
            // convergence: |grad_j|/√A_jj against the momenta's size
            double gmax = 0, scale = 0;
            for (int j = 0; j < nv; j++) {
                double s = 1 / rootA[j];
                gmax = Math.max(gmax, Math.abs(grad[j]) * s);
                scale = Math.max(scale, Math.abs(av[j]) * s);
            }
            for (int c = 0; c < nc; c++) {
                int cb = c * nv, m = colCount[c];
                for (int k = 0; k < 3; k++) {
                    double gk = gamma[3 * c + k];
                    int row = (3 * c + k) * nv;
                    for (int x = 0; x < m; x++) scale = Math.max(scale, Math.abs(packed[row + x] * gk) / rootA[cols[cb + x]]);
                }
            }
            lastGradient = gmax;
            if (gmax <= TOLERANCE * scale || gmax == 0) {
                outcome = Outcome.CONVERGED;
                break;
            }
            iterations++;
            hessian(p);
            if (!Cholesky.decompose(hess, nv)) return outcome = Outcome.NOT_POSITIVE_DEFINITE;
            for (int j = 0; j < nv; j++) dir[j] = -grad[j];
            Cholesky.solve(hess, nv, dir);
            double alpha = lineSearch(p);
            // a step below the rounding of v itself: the gradient is at its floor of rounding
            double step = 0, size = 0;
            for (int j = 0; j < nv; j++) {
                double s = rootA[j];
                v[j] += alpha * dir[j];
                step = Math.max(step, Math.abs(alpha * dir[j]) * s);
                size = Math.max(size, Math.max(Math.abs(v[j]), Math.abs(p.vStar[j])) * s);
            }
            if (step <= STEP_TOLERANCE * size) {
                evaluate(p, false);
                outcome = Outcome.CONVERGED;
                break;
            }
        }
        return outcome;
    }

    /** γ_c and the gradient at v; with {@code hessian}, each projection's Jacobian too, for {@link #hessian}. */
    private void evaluate(ContactProblem p, boolean hessian) {
        int nv = p.nv, nc = p.nc;
        double[] a = p.a;
        for (int i = 0; i < nv; i++) {
            double s = 0;
            for (int j = 0; j < nv; j++) s += a[i * nv + j] * (v[j] - p.vStar[j]);
            av[i] = s;
            grad[i] = s;
        }
        for (int c = 0; c < nc; c++) {
            int o = 3 * c, cb = c * nv, m = colCount[c];
            for (int k = 0; k < 3; k++) {
                double s = 0;
                int row = (o + k) * nv;
                for (int x = 0; x < m; x++) s += packed[row + x] * v[cols[cb + x]];
                vc[o + k] = s;
            }
            double r = p.reg[c];
            project(-(vc[o] - p.bias[o]) / r, -(vc[o + 1] - p.bias[o + 1]) / r, -(vc[o + 2] - p.bias[o + 2]) / r, p.mu[c],
                p.radius[c], gamma, o, hessian ? dps : null, 9 * c);
            for (int k = 0; k < 3; k++) {
                double gk = gamma[o + k];
                if (gk == 0) continue;
                int row = (o + k) * nv;
                for (int x = 0; x < m; x++) grad[cols[cb + x]] -= packed[row + x] * gk;
            }
        }
    }

    /**
     * The Hessian at the last {@link #evaluate}d v (with its projections' Jacobians): A + Σ J_cᵀ
     * (dP/r) J_c, its lower triangle (all the Cholesky factorisation reads). Apart from the
     * evaluation, since the evaluation that finds the solve converged does not need it.
     */
    private void hessian(ContactProblem p) {
        int nv = p.nv, nc = p.nc;
        System.arraycopy(p.a, 0, hess, 0, nv * nv);
        for (int c = 0; c < nc; c++) {
            int o = 3 * c, cb = c * nv, m = colCount[c];
            double r = p.reg[c];
            for (int k = 0; k < 3; k++) {
                for (int l = 0; l < 3; l++) {
                    double gkl = dps[9 * c + 3 * k + l] / r;
                    if (gkl == 0) continue;
                    int rk = (o + k) * nv, rl = (o + l) * nv;
                    for (int x = 0; x < m; x++) {
                        double ji = packed[rk + x] * gkl;
                        if (ji == 0) continue;
                        int hi = cols[cb + x] * nv;
                        for (int y = 0; y <= x; y++) hess[hi + cols[cb + y]] += ji * packed[rl + y];
                    }
                }
            }
        }
    }

    /**
     * The step length along {@link #dir}: the minimiser of ℓ on [0, 1] (1 when ℓ still falls
     * there), by a safeguarded Newton–bisection on φ'(α), which is increasing.
     */
    private double lineSearch(ContactProblem p) {
        int nv = p.nv, nc = p.nc;
        double[] a = p.a;
        double dAd = 0, dAv = 0;
        for (int i = 0; i < nv; i++) {
            double s = 0;
            for (int j = 0; j < nv; j++) s += a[i * nv + j] * dir[j];
            dAd += dir[i] * s;
            dAv += dir[i] * av[i];
        }
        for (int c = 0; c < nc; c++) {
            int cb = c * nv, m = colCount[c];
            for (int k = 0; k < 3; k++) {
                double s = 0;
                int row = (3 * c + k) * nv;
                for (int x = 0; x < m; x++) s += packed[row + x] * dir[cols[cb + x]];
                jd[3 * c + k] = s;
            }
        }
        double d1 = derivative(p, 1, dAd, dAv, null);
        if (d1 <= 0) return 1;
        double lo = 0, hi = 1, alpha = 1;
        for (int it = 0; it < 60; it++) {
            double d = derivative(p, alpha, dAd, dAv, second);
            if (d > 0) hi = alpha; else lo = alpha;
            double next = second[0] > 0 ? alpha - d / second[0] : Double.NaN;
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (Math.abs(next - alpha) <= 1e-14 * Math.max(1e-3, alpha) || hi - lo <= 1e-15) return next;
            alpha = next;
        }
        return alpha;
    }

    /** φ'(α) (and φ''(α) into second[0] when given) along dir from v. */
    private double derivative(ContactProblem p, double alpha, double dAd, double dAv, double[] secondOut) {
        double d = dAv + alpha * dAd, dd = dAd;
        double[] gg = secondOut == null ? null : g;
        for (int c = 0; c < p.nc; c++) {
            int o = 3 * c;
            double r = p.reg[c];
            double y0 = -(vc[o] + alpha * jd[o] - p.bias[o]) / r;
            double y1 = -(vc[o + 1] + alpha * jd[o + 1] - p.bias[o + 1]) / r;
            double y2 = -(vc[o + 2] + alpha * jd[o + 2] - p.bias[o + 2]) / r;
            project(y0, y1, y2, p.mu[c], p.radius[c], gm, 0, gg, 0);
            d -= jd[o] * gm[0] + jd[o + 1] * gm[1] + jd[o + 2] * gm[2];
            if (gg != null) {
                for (int k = 0; k < 3; k++) {
                    for (int l = 0; l < 3; l++) dd += jd[o + k] * gg[3 * k + l] / r * jd[o + l];
                }
            }
        }
        if (secondOut != null) secondOut[0] = dd;
        return d;
    }

    /**
     * The Euclidean projection of (y_n, y_t1, y_t2) onto Coulomb's cone of coefficient μ into
     * {@code out[o..o+2]}, and its Jacobian (3×3 row-major) into {@code dp[po..]} when given.
     */
    static void project(double yn, double y1, double y2, double mu, double radius, double[] out, int o, double[] dp, int po) {
        double t = Math.sqrt(y1 * y1 + y2 * y2);
        if (!Double.isNaN(radius)) {                          // {γ_n ≥ 0} × {|γ_t| ≤ radius}
            if (dp != null) zero9(dp, po);
            out[o] = Math.max(yn, 0);
            if (dp != null && yn > 0) dp[po] = 1;
            if (t <= radius) {
                out[o + 1] = y1; out[o + 2] = y2;
                if (dp != null) dp[po + 4] = dp[po + 8] = 1;
            } else {
                double s = radius / t, ux = y1 / t, uy = y2 / t;
                out[o + 1] = s * y1; out[o + 2] = s * y2;
                if (dp != null) {
                    dp[po + 4] = s * (1 - ux * ux);
                    dp[po + 5] = dp[po + 7] = -s * ux * uy;
                    dp[po + 8] = s * (1 - uy * uy);
                }
            }
            return;
        }
        if (yn >= 0 && t <= mu * yn) {                       // inside
            out[o] = yn; out[o + 1] = y1; out[o + 2] = y2;
            if (dp != null) {
                zero9(dp, po);
                dp[po] = dp[po + 4] = dp[po + 8] = 1;
            }
            return;
        }
        if (mu * t <= -yn) {                                  // polar cone
            out[o] = out[o + 1] = out[o + 2] = 0;
            if (dp != null) zero9(dp, po);
            return;
        }
        double k = 1 / (1 + mu * mu);
        double gn = (yn + mu * t) * k;
        out[o] = gn;
        if (t == 0) {                                         // μ = 0: onto the normal ray
            out[o + 1] = out[o + 2] = 0;
            if (dp != null) {
                zero9(dp, po);
                dp[po] = k;
            }
            return;
        }
        double ux = y1 / t, uy = y2 / t;
        out[o + 1] = mu * gn * ux;
        out[o + 2] = mu * gn * uy;
        if (dp != null) {
            double c = mu * k, s = mu * gn / t;
            dp[po] = k;
            dp[po + 1] = c * ux; dp[po + 2] = c * uy;
            dp[po + 3] = c * ux; dp[po + 6] = c * uy;
            // μ(μ uuᵀ k + s (E − uuᵀ))
            dp[po + 4] = mu * c * ux * ux + s * (1 - ux * ux);
            dp[po + 5] = mu * c * ux * uy - s * ux * uy;
            dp[po + 7] = dp[po + 5];
            dp[po + 8] = mu * c * uy * uy + s * (1 - uy * uy);
        }
    }

    /** dp[po..po+8] = 0 (unrolled: Arrays.fill's range checks cost more than the nine stores, in the line search's inner loop). */
    private static void zero9(double[] dp, int po) {
        dp[po] = 0; dp[po + 1] = 0; dp[po + 2] = 0; dp[po + 3] = 0; dp[po + 4] = 0;
        dp[po + 5] = 0; dp[po + 6] = 0; dp[po + 7] = 0; dp[po + 8] = 0;
    }

    private void grow(int nv, int nc) {
        if (v.length < nv) {
            v = new double[nv]; grad = new double[nv]; dir = new double[nv]; av = new double[nv]; col = new double[nv];
            hess = new double[nv * nv]; rootA = new double[nv];
        }
        if (hess.length < nv * nv) hess = new double[nv * nv];
        if (cols.length < nc * nv || colCount.length < nc) {
            int cap = Math.max(8, 2 * nc);
            cols = new int[cap * nv];
            colCount = new int[cap];
            packed = new double[3 * cap * nv];
        }
        if (vc.length < 3 * nc) {
            int cap = 3 * Math.max(8, 2 * nc);
            vc = new double[cap]; jd = new double[cap]; gamma = new double[cap]; dps = new double[3 * cap];
        }
        if (g.length < 9) g = new double[9];
    }

    /** @return velocity j of the last solve */
    public double velocity(int j) { return v[j]; }

    /** Copies the first n velocities of the last solve into out. */
    public void velocities(double[] out, int n) { System.arraycopy(v, 0, out, 0, n); }

    /** @return component k (0 normal, 1 t₁, 2 t₂) of constraint c's impulse, N·s */
    public double impulse(int c, int k) { return gamma[3 * c + k]; }

    /** @return the convex solves of the last {@link #solveCoulomb} */
    public int fixedPointIterations() { return fixedPoint; }

    /**
     * How the outputs say that some steps' fixed point did not settle ({@link #solveCoulomb}
     * returned {@link Outcome#MAX_ITERATIONS}): "{@code count} steps did not settle …", count
     * being e.g. "38 of 4785".
     */
    public static String unsettledSteps(String count) {
        return count + " steps did not settle Coulomb's fixed point within " + MAX_FIXED_POINT + " solves and used the last";
    }

    /** @return the Newton iterations of the last solve (all of a {@link #solveCoulomb}'s together) */
    public int iterations() { return iterations; }

    /** @return how the last solve ended */
    public Outcome outcome() { return outcome; }

    /** @return the last scaled gradient's largest entry (the optimality the solve reached) */
    public double lastGradient() { return lastGradient; }
}
