package org.handsim.sim.trajectory;

/**
 * A motor set-point q(t) in encoder counts for t ∈ [0, duration] seconds; before 0 it is
 * {@link #start()}, after the end {@link #end()}, with zero velocity and acceleration.
 */
public interface Trajectory {
    /** @return the length in seconds (≥ 0) */
    double duration();

    /** @return q(0) in counts */
    double start();

    /** @return q(duration) in counts */
    double end();

    /**
     * Writes q (counts), q̇ (counts/s) and q̈ (counts/s²) at time t into {@code out[0..2]}
     * (allocation-free).
     */
    void sample(double t, double[] out);

    /** @return q(t) in counts */
    default double position(double t) {
        double[] o = new double[3];
        sample(t, o);
        return o[0];
    }
}
