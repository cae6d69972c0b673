package org.handsim.dynamics;

/**
 * Explicit (forward) Euler, order 1: {@code y ← y + h·f(t, y)} (Hairer–Nørsett–Wanner,
 * <i>Solving ODEs I</i>, ch. I). The cheapest step and the baseline of the speed-versus-accuracy
 * study; it gains energy on oscillatory mechanical systems.
 */
public final class ExplicitEuler extends AbstractIntegrator {
    private final double[] k;

    public ExplicitEuler(int dimension) {
        super(dimension);
        k = new double[dimension];
    }

    @Override
    public String name() {
        return "euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public boolean step(Ode ode, double t, double[] y, double h) {
        check(ode, y, h);
        if (!eval(ode, t, y, k)) return false;
        for (int i = 0; i < n; i++) y[i] += h * k[i];
        return true;
    }
}
