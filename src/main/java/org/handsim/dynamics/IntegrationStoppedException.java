package org.handsim.dynamics;

import java.util.Locale;

/**
 * A time integration stopped by {@link EnergyGuard}: the step index, the time and the
 * offending value, so that a command can say where and why the run stopped. Thrown before the
 * offending state is handed on, so no caller ever records it.
 */
public final class IntegrationStoppedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** Why the run stopped. */
    public enum Reason {
        /** A state value (angle or velocity) became NaN or infinite. */
        NON_FINITE,
        /** The integrator could not take the step (f undefined, step size collapsed). */
        STEP_FAILED,
        /** The total energy grew beyond the guard's bound (impossible under zero torque). */
        ENERGY_GROWTH
    }

    private final Reason reason;
    private final long step;
    private final double time, value, initialEnergy, bound;

    /**
     * @param step          1-based index of the step that failed (the step from t − dt to t)
     * @param time          the time the step was to reach, s
     * @param value         the offending value (the energy, J, or the non-finite state value; NaN for a failed step)
     * @param initialEnergy the energy at t = 0, J
     * @param bound         the allowed growth of the energy, J
     */
    public IntegrationStoppedException(Reason reason, long step, double time, double value, double initialEnergy, double bound, String detail) {
        super(String.format(Locale.ROOT, "stopped at step %d (t = %s s): %s", step, fmt(time), detail));
        this.reason = reason;
        this.step = step;
        this.time = time;
        this.value = value;
        this.initialEnergy = initialEnergy;
        this.bound = bound;
    }

    static String fmt(double v) {
        return String.format(Locale.ROOT, "%.6g", v).replaceFirst("(\\.\\d*?)0+($|e)", "$1$2").replaceFirst("\\.($|e)", "$1");
    }

    public Reason reason() { return reason; }

    /** @return the 1-based index of the step that was refused */
    public long step() { return step; }

    /** @return the time that step was to reach, s */
    public double time() { return time; }

    /** @return the offending value: the energy (J) for {@link Reason#ENERGY_GROWTH}, the bad state value for {@link Reason#NON_FINITE}, NaN for {@link Reason#STEP_FAILED} */
    public double value() { return value; }

    /** @return the energy at t = 0, J */
    public double initialEnergy() { return initialEnergy; }

    /** @return the allowed energy growth, J */
    public double bound() { return bound; }
}
