package org.handsim.dynamics;

/**
 * A first-order ordinary differential equation {@code ẏ = f(t, y)} for the {@link Integrator}s.
 * A mechanical system is written with {@code y = (q, q̇)} and {@code f = (q̇, q̈)}
 * ({@link FingerDynamicsOde}); {@link SemiImplicitEuler} relies on that layout.
 */
public interface Ode {
    /** @return the length of the state y */
    int dimension();

    /**
     * Evaluates {@code ẏ = f(t, y)} into {@code yDot} (allocation-free; {@code yDot} never
     * aliases {@code y}).
     *
     * @return true; false if f is undefined at (t, y) (e.g. a mass matrix that is not positive
     *         definite) — the integrator then reports a failed step and leaves y as it was
     */
    boolean derivative(double t, double[] y, double[] yDot);
}
