package org.handsim.dynamics;

import org.handsim.math.Cholesky;

/**
 * Forward dynamics of a chain: the accelerations a torque produces, eq (8) solved for Θ̈,
 * <pre>
 *   D(q)·q̈ = τ − H(q, q̇) − C(q)
 * </pre>
 * by a Cholesky factorisation of D ({@link Cholesky}) and two triangular solves, with no explicit
 * inverse (the inertia-matrix method of Featherstone, <i>Rigid Body Dynamics Algorithms</i>,
 * 2008, ch. 6). D is symmetric positive definite for a chain whose every joint moves some
 * inertia, since ½·q̇ᵀ·D·q̇ is the kinetic energy (AbstractChainDynamicsTest checks it over the
 * finger's joint range). D, H and C come from any
 * {@link ChainDynamics}; with {@link ClosedFormFinger} one call costs one closed-form evaluation
 * plus an n = 3 factorisation.
 *
 * <p><b>Failure is an outcome</b> (docs/STYLE.md, item 8): if D is not numerically positive definite
 * (a non-physical hand description, NaN inputs) {@link #accelerations} returns false and leaves
 * its output untouched, instead of returning NaN accelerations.
 *
 * <p>Allocation-free; not thread-safe (scratch).
 */
public final class ForwardDynamics {
    private final ChainDynamics dynamics;
    private final int n;
    private final double[] d, h, c;

    /** Forward dynamics with the D, H and C of {@code dynamics}. */
    public ForwardDynamics(ChainDynamics dynamics) {
        this.dynamics = dynamics;
        n = dynamics.dof();
        d = new double[n * n];
        h = new double[n];
        c = new double[n];
    }

    /** @return the dynamics that supply D, H and C */
    public ChainDynamics dynamics() {
        return dynamics;
    }

    /** @return the number of active joints */
    public int dof() {
        return n;
    }

    /**
     * Joint accelerations {@code q̈ = D⁻¹·(τ − H − C)} (paper eq 8 inverted).
     *
     * @param q      joint angles, rad
     * @param qd     joint velocities, rad/s
     * @param tau    joint torques, N·m
     * @param g      gravity in the base frame, m/s²
     * @param qddOut joint accelerations, rad/s² (must not alias an input)
     * @return true; false if D(q) is not numerically positive definite ({@code qddOut} untouched)
     */
    public boolean accelerations(double[] q, double[] qd, double[] tau, double[] g, double[] qddOut) {
        Check.vec("tau", tau, n);
        Check.outNonNull("qddOut", qddOut, n, q, qd, tau);
        if (qddOut == g) throw new IllegalArgumentException("qddOut must not be the same array as an input");
        dynamics.terms(q, qd, g, d, h, c);
        if (!Cholesky.decompose(d, n)) return false;
        for (int i = 0; i < n; i++) h[i] = tau[i] - h[i] - c[i];
        Cholesky.solve(d, n, h);
        for (int i = 0; i < n; i++) {
            if (!Double.isFinite(h[i])) return false;
        }
        System.arraycopy(h, 0, qddOut, 0, n);
        return true;
    }
}
