package org.handsim.trajectory;

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

    /**
     * This trajectory as one segment of a scenario file's motor list ({@code Scenario}'s format:
     * {@code type} and its fields, in the order a file writes them; the start is the previous
     * segment's end). A {@link Sequence} is a list of segments, not one.
     */
    java.util.Map<String, Object> segment();

    /** @return q(t) in counts */
    default double position(double t) {
        double[] o = new double[3];
        sample(t, o);
        return o[0];
    }
}
