package org.handsim.dynamics;

import java.util.function.DoubleConsumer;

/**
 * One finger swinging freely: zero joint torque (clutch disengaged, motor off), no friction,
 * gravity g in the base frame {k0}, integrated from a start state over a duration with one
 * {@link Integrator} at output step dt, every step checked by an {@link EnergyGuard}. The
 * engine of {@code handsim swing}; it hands each accepted state to a {@link Sink} and touches
 * no files (the caller decides what to keep).
 *
 * <p>Steps: {@code N = ⌈duration/dt⌉} (to 1e-9 of a step), step i reaching
 * {@code t_i = min(i·dt, duration)}, so the last step is clipped to end at the duration exactly.
 * A fixed-step method takes one step of that size; {@link DormandPrince54} covers it with as
 * many internal steps as its tolerance needs.
 */
public final class FreeSwing {
    private FreeSwing() {}

    /** Receives the start state (step 0, t = 0) and the state after every step. */
    @FunctionalInterface
    public interface Sink {
        /**
         * @param step   0 for the start, then 1..N
         * @param t      time, s
         * @param y      state (q, q̇) of the active joints, rad and rad/s (do not keep)
         * @param energy total energy, J
         */
        void accept(long step, double t, double[] y, double energy);
    }

    /** The outcome of a completed run. */
    public record Result(long steps, double duration, double initialEnergy, double finalEnergy, double worstGrowth,
                         double driftScale, long evaluations, double[] finalState) {
        /**
         * {@code |E(T) − E(0)| / max(|E(0)|, largest kinetic energy of the run)} ({@link EnergyGuard#driftScale()};
         * the plain difference, J, if that scale is 0: a chain at rest without gravity).
         */
        public double relativeDrift() {
            double d = Math.abs(finalEnergy - initialEnergy);
            return driftScale == 0 ? d : d / driftScale;
        }
    }

    /** @return the number of steps covering {@code duration} with steps of {@code dt} */
    public static long steps(double dt, double duration) {
        if (!(dt > 0) || !Double.isFinite(dt)) throw new IllegalArgumentException("dt must be finite and > 0, got " + dt);
        if (!(duration > 0) || !Double.isFinite(duration)) throw new IllegalArgumentException("duration must be finite and > 0, got " + duration);
        return Math.max(1, (long) Math.ceil(duration / dt - 1e-9));
    }

    /**
     * Integrates the free finger.
     *
     * @param ode        the finger under zero torque ({@link FingerDynamicsOde.Torques#ZERO}) and gravity
     * @param integrator built for {@code ode.dimension()}
     * @param y          start state (q, q̇) of the active joints; advanced in place to the last accepted state
     * @param dt         output step, s
     * @param duration   simulated time, s
     * @param sink       receives every accepted state (may be null)
     * @param progress   told the fraction done about a hundred times (may be null)
     * @throws IntegrationStoppedException when the guard stops the run (y holds the last accepted state)
     */
    public static Result run(FingerDynamicsOde ode, Integrator integrator, double[] y, double dt, double duration,
                             Sink sink, DoubleConsumer progress) {
        if (integrator.dimension() != ode.dimension()) {
            throw new IllegalArgumentException("integrator dimension " + integrator.dimension() + " != ode dimension " + ode.dimension());
        }
        long steps = steps(dt, duration);
        EnergyGuard guard = new EnergyGuard(ode, y);
        double e0 = guard.initialEnergy();
        if (sink != null) sink.accept(0, 0.0, y, e0);
        int n = ode.dimension();
        double[] trial = new double[n];
        long every = Math.max(1, steps / 100);
        long evals0 = integrator.evaluations();
        double t = 0, e = e0, worst = 0;
        org.handsim.process.StepClock clock = new org.handsim.process.StepClock(dt);
        for (long i = 1; i <= steps; i++) {
            double tNext = i == steps ? duration : Math.min(clock.at(i), duration);   // i × dt in decimal, never accumulated
            System.arraycopy(y, 0, trial, 0, n);
            if (!integrator.step(ode, t, trial, tNext - t)) throw guard.failedStep(i, tNext, integrator.name());
            e = guard.check(i, tNext, trial);
            System.arraycopy(trial, 0, y, 0, n);
            t = tNext;
            worst = Math.max(worst, e - e0);
            if (sink != null) sink.accept(i, t, y, e);
            if (progress != null && i % every == 0) progress.accept((double) i / steps);
        }
        if (progress != null) progress.accept(1.0);
        return new Result(steps, duration, e0, e, worst, guard.driftScale(), integrator.evaluations() - evals0, y.clone());
    }
}
