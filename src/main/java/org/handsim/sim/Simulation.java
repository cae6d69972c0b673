package org.handsim.sim;

import org.handsim.dynamics.HandDynamics;

/** Builds a ready-to-run {@link HandModel} for a scenario: collision back end and dynamics. */
public final class Simulation {
    private Simulation() {}

    /**
     * @param scenario what to run
     * @param record   keep a trace (one row per step)
     */
    public static HandModel model(Scenario scenario, boolean record) {
        if (scenario.object() != null) {
            throw new ScenarioException(scenario.file() + ": field object: objects need the collision back end, not built in yet");
        }
        return new HandModel(scenario, null, HandDynamics.barrettHand()::inverseDynamics, record);
    }
}
