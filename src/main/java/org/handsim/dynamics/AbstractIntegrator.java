package org.handsim.dynamics;

/** Shared argument checks and the evaluation counter of the fixed-step integrators. */
abstract class AbstractIntegrator implements Integrator {
    final int n;
    long evaluations;

    AbstractIntegrator(int dimension) {
        if (dimension < 1) throw new IllegalArgumentException("dimension must be >= 1, got " + dimension);
        n = dimension;
    }

    @Override
    public final int dimension() {
        return n;
    }

    @Override
    public final long evaluations() {
        return evaluations;
    }

    void check(Ode ode, double[] y, double h) {
        if (ode.dimension() != n) throw new IllegalArgumentException("ode.dimension() must be " + n + ", got " + ode.dimension());
        if (y.length < n) throw new IllegalArgumentException("y needs " + n + " values, got " + y.length);
        if (!(h > 0) || !Double.isFinite(h)) throw new IllegalArgumentException("h must be finite and > 0, got " + h);
    }

    boolean eval(Ode ode, double t, double[] y, double[] yDot) {
        evaluations++;
        return ode.derivative(t, y, yDot);
    }

    @Override
    public String toString() {
        return name() + " (order " + order() + ", dimension " + n + ")";
    }
}
