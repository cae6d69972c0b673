package org.handsim.dynamics;

/**
 * The classical fourth-order Runge–Kutta method (Kutta 1901; Hairer–Nørsett–Wanner, <i>Solving ODEs
 * I</i>, §II.1):
 * <pre>
 *   k1 = f(t, y),            k2 = f(t + h/2, y + h/2·k1),
 *   k3 = f(t + h/2, y + h/2·k2),  k4 = f(t + h, y + h·k3),
 *   y ← y + h/6·(k1 + 2k2 + 2k3 + k4)
 * </pre>
 * Four evaluations per step, global error O(h⁴). The simulator's default.
 */
public final class RungeKutta4 extends AbstractIntegrator {
    private final double[] k1, k2, k3, k4, tmp;

    public RungeKutta4(int dimension) {
        super(dimension);
        k1 = new double[dimension];
        k2 = new double[dimension];
        k3 = new double[dimension];
        k4 = new double[dimension];
        tmp = new double[dimension];
    }

    @Override
    public String name() {
        return "rk4";
    }

    @Override
    public int order() {
        return 4;
    }

    @Override
    public boolean step(Ode ode, double t, double[] y, double h) {
        check(ode, y, h);
        double h2 = 0.5 * h;
        if (!eval(ode, t, y, k1)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h2 * k1[i];
        if (!eval(ode, t + h2, tmp, k2)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h2 * k2[i];
        if (!eval(ode, t + h2, tmp, k3)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h * k3[i];
        if (!eval(ode, t + h, tmp, k4)) return false;
        double h6 = h / 6.0;
        for (int i = 0; i < n; i++) y[i] += h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        return true;
    }
}
