package org.handsim.dynamics;

/**
 * One step of a numerical integrator for {@code ẏ = f(t, y)} ({@link Ode}): the common face of
 * {@link ExplicitEuler}, {@link SemiImplicitEuler}, {@link RungeKutta4} and
 * {@link DormandPrince54}, so that the simulator and the speed-versus-accuracy study can swap
 * them.
 *
 * <p><b>Contract.</b> {@link #step} advances the state in place from t to exactly t + h. A
 * fixed-step method takes one step of size h; the adaptive method takes as many internal
 * steps as its error control needs (its step size carries over between calls). A failed step —
 * f undefined somewhere ({@link Ode#derivative} returned false) or the adaptive step size
 * collapsing — returns false and leaves y as it was (docs/STYLE.md, item 8: an outcome, not NaN).
 *
 * <p><b>Cost accounting.</b> {@link #evaluations()} counts calls of f since construction, the
 * currency of the speed-versus-accuracy comparison.
 *
 * <p>Implementations preallocate scratch for one {@link #dimension()}: allocation-free per step,
 * not thread-safe.
 */
public interface Integrator {
    /** @return a short name for tables and charts, e.g. "rk4" */
    String name();

    /** @return the order p of the global error, O(hᵖ) */
    int order();

    /** @return the state length this instance was built for */
    int dimension();

    /**
     * Advances {@code y} in place from {@code t} to {@code t + h}.
     *
     * @param h step, s (> 0)
     * @return true on success; false if the step failed (y unchanged)
     */
    boolean step(Ode ode, double t, double[] y, double h);

    /** @return how many times f has been evaluated since construction */
    long evaluations();
}
