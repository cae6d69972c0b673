package org.handsim.body;

import java.util.Arrays;

/**
 * The convex problem of one time step (DESIGN.md decision 7): generalised velocities v — the
 * object's twist (u, w) in world axes, then any finger joints that follow the object — with
 * metric A and free velocity v*, and constraints c, each a contact frame (normal, two tangents)
 * with Jacobian J_c (3 × nv: the relative velocity there, object minus other body, is
 * J_c v − b_c), a bias b_c and Coulomb's coefficient μ_c. {@link ContactSolver} finds
 * <pre>  v = argmin ½(v − v*)ᵀA(v − v*) + Σ_c ½ γ_cᵀ R_c γ_c,   γ_c = P_F(−R_c⁻¹(J_c v − b_c)),</pre>
 * the primal of Anitescu's convex relaxation of Coulomb friction (the velocity J_c v − b_c lies
 * in the dual cone {v_n ≥ μ|v_t|}, the impulse γ_c in Coulomb's cone F = {|γ_t| ≤ μγ_n},
 * complementary), regularised by R_c = ε·W_c,nn (W the Delassus operator J A⁻¹ Jᵀ) so the
 * impulses are unique: Castro, Han, Permenter, Sherman, "An unconstrained convex formulation of
 * compliant contact", IEEE T-RO 39(2), 2023 (SAP); M. Anitescu, "Optimization-based simulation
 * of nonsmooth rigid multibody dynamics", Math. Programming 105, 2006.
 *
 * <p>A one-sided bound on a velocity (a worm: a joint may close, not open) is a constraint with
 * μ = 0 and zero tangent rows: its impulse is a non-negative reaction.
 *
 * <p>Frames: row 0 of a constraint is along its normal n, rows 1 and 2 along t₁, t₂ (any
 * orthonormal pair with t₁ × t₂ = n). Units: velocities m/s or rad/s, impulses N·s or N·m·s.
 * Buffers grow as needed and are kept: no allocation per step once grown. Not thread-safe.
 */
public final class ContactProblem {
    /**
     * The default relative regularisation ε (R_c = ε·W_c,nn). It makes a contact a stiff spring: a
     * sticking contact creeps at ε·W·γ_t (a box held by friction on a 25° incline: 0.35 µm in 0.5 s),
     * a resting one sinks by ε·g·h² (7.5e-9 m on a table). 1e-6 creeps 100× less, but Newton then
     * needs hundreds of iterations on 4 % of seeded problems; 1e-4 converges within 25 on all.
     */
    public static final double DEFAULT_REGULARISATION = 1e-4;

    int nv;
    double[] a = new double[0];
    double[] vStar = new double[0];
    int nc;
    double[] jac = new double[0];        // constraint c, row k, column j at (3c + k)·nv + j
    double[] bias = new double[0];       // 3 per constraint
    double[] mu = new double[0];
    double[] reg = new double[0];        // R_c, per constraint (isotropic)
    double[] radius = new double[0];     // NaN: Coulomb's cone; else the friction disk's radius (ContactSolver.solveCoulomb)
    double epsilon = DEFAULT_REGULARISATION;

    /** Starts a new problem of {@code nv} velocities: A = 0, v* = 0, no constraints. */
    public void begin(int nv) {
        if (nv < 1) throw new IllegalArgumentException("a problem needs at least one velocity, got " + nv);
        this.nv = nv;
        if (a.length < nv * nv) {
            a = new double[nv * nv];
            vStar = new double[nv];
        }
        Arrays.fill(a, 0, nv * nv, 0);
        Arrays.fill(vStar, 0, nv, 0);
        nc = 0;
    }

    /** @return the number of velocities */
    public int velocityCount() { return nv; }

    /** @return the number of constraints */
    public int constraintCount() { return nc; }

    /** Sets the relative regularisation ε (&gt; 0); returns this. */
    public ContactProblem regularisation(double eps) {
        if (!(eps > 0) || !(eps < 1)) throw new IllegalArgumentException("regularisation must be in (0, 1), got " + eps);
        epsilon = eps;
        return this;
    }

    /**
     * The object's block: velocities 0–5 are its twist (u: m/s, w: rad/s, world axes), metric
     * diag(m·E, I_w), free twist {@code freeTwist}.
     */
    public void setObject(double mass, double[] worldInertia, double[] freeTwist) {
        if (nv < 6) throw new IllegalStateException("the object needs 6 velocities, the problem has " + nv);
        for (int i = 0; i < 3; i++) {
            a[i * nv + i] = mass;
            for (int k = 0; k < 3; k++) a[(3 + i) * nv + 3 + k] = worldInertia[3 * i + k];
        }
        System.arraycopy(freeTwist, 0, vStar, 0, 6);
    }

    /** Velocity {@code j}'s own block: metric {@code inertia} (kg·m²), free velocity (rad/s). */
    public void setScalar(int j, double inertia, double freeVelocity) {
        if (!(inertia > 0)) throw new IllegalArgumentException("inertia of velocity " + j + " must be > 0, got " + inertia);
        a[j * nv + j] = inertia;
        vStar[j] = freeVelocity;
    }

    /**
     * Adds a constraint with zero Jacobian rows and bias; fill them with {@link #jacobian} and
     * {@link #bias}.
     *
     * @param frictionCoefficient μ ≥ 0 (0: frictionless, or a one-sided bound with zero tangent rows)
     * @return its index
     */
    public int addConstraint(double frictionCoefficient) {
        if (!(frictionCoefficient >= 0) || !Double.isFinite(frictionCoefficient)) {
            throw new IllegalArgumentException("friction coefficient must be finite and >= 0, got " + frictionCoefficient);
        }
        int c = nc++;
        if (mu.length < nc) {
            int cap = Math.max(8, 2 * nc);
            mu = Arrays.copyOf(mu, cap);
            reg = Arrays.copyOf(reg, cap);
            radius = Arrays.copyOf(radius, cap);
            bias = Arrays.copyOf(bias, 3 * cap);
        }
        if (jac.length < 3 * nc * nv) jac = Arrays.copyOf(jac, 3 * Math.max(8, 2 * nc) * nv);
        Arrays.fill(jac, 3 * c * nv, 3 * (c + 1) * nv, 0);
        bias[3 * c] = bias[3 * c + 1] = bias[3 * c + 2] = 0;
        mu[c] = frictionCoefficient;
        reg[c] = 0;
        radius[c] = Double.NaN;
        return c;
    }

    /** @return the Jacobian array; constraint c's row k, velocity j at {@code (3c + k)·nv + j} */
    public double[] jacobian() { return jac; }

    /** @return the bias array, 3 per constraint (normal, t₁, t₂) */
    public double[] bias() { return bias; }

    /** @return constraint c's friction coefficient */
    public double frictionCoefficient(int c) { return mu[c]; }

    /** @return the metric A (nv × nv row-major; do not modify) */
    public double[] metric() { return a; }

    /** @return the free velocities v* (do not modify) */
    public double[] freeVelocity() { return vStar; }

    /** @return constraint c's regularisation R_c as the last solve set it */
    public double regularisationOf(int c) { return reg[c]; }
}
