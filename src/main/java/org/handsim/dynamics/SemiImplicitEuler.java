package org.handsim.dynamics;

/**
 * Semi-implicit (symplectic) Euler, order 1, for a mechanical state {@code y = (q, v)} with
 * {@code q̇ = v}: the velocity is advanced first and the position with the new velocity,
 * <pre>
 *   v ← v + h·a(t, q, v),   q ← q + h·v
 * </pre>
 * (Hairer–Lubich–Wanner, <i>Geometric Numerical Integration</i>, ch. I). One evaluation per
 * step like {@link ExplicitEuler}, but for separable Hamiltonians its energy error stays bounded
 * instead of drifting, which is why games and many simulators use it.
 *
 * <p>The first half of y holds q, the second half v; the first half of f is ignored (it is
 * v by the layout, {@link Ode}).
 */
public final class SemiImplicitEuler extends AbstractIntegrator {
    private final int positions;
    private final double[] k;

    /** @param positions the number of positions q; the state has 2·positions values */
    public SemiImplicitEuler(int positions) {
        super(2 * positions);
        this.positions = positions;
        k = new double[2 * positions];
    }

    @Override
    public String name() {
        return "semi-implicit-euler";
    }

    @Override
    public int order() {
        return 1;
    }

    @Override
    public boolean step(Ode ode, double t, double[] y, double h) {
        check(ode, y, h);
        if (!eval(ode, t, y, k)) return false;
        for (int i = 0; i < positions; i++) {
            double v = y[positions + i] + h * k[positions + i];
            y[positions + i] = v;
            y[i] += h * v;
        }
        return true;
    }
}
