package org.handsim.model;

/** A run stopped by a numerical guard; the message names the step, the time and the value. */
public final class SimulationException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public SimulationException(String message) {
        super(message);
    }
}
