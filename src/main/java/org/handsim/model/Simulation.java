package org.handsim.model;

import org.handsim.dynamics.HandDynamics;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;

/** Builds a ready-to-run {@link HandModel} for a scenario: collision back end and dynamics. */
public final class Simulation {
    private Simulation() {}

    /**
     * @param scenario what to run
     * @param record   keep a trace (one row per step)
     * @throws ScenarioException if the object cannot be loaded (the message names file, line, column)
     */
    public static HandModel model(Scenario scenario, boolean record) {
        return model(scenario, record, SceneGeometry.DEFAULT_K);
    }

    /** As {@link #model(Scenario, boolean)} with the trace going to {@code recorder} (null: none). */
    public static HandModel model(Scenario scenario, Recorder recorder) {
        LinkContacts contacts = scenario.object() == null ? null : new SceneGeometry(scenario.object(), SceneGeometry.DEFAULT_K);
        return new HandModel(scenario, contacts, HandDynamics.barrettHand()::inverseDynamics, recorder);
    }

    /**
     * A model of the scenario without a trace whose object collision is {@code contacts} (null:
     * no object) — e.g. a {@link SceneGeometry} that took over a retired one's query scratch
     * (the planner, one model per trial).
     */
    public static HandModel model(Scenario scenario, LinkContacts contacts) {
        return new HandModel(scenario, contacts, HandDynamics.barrettHand()::inverseDynamics, false);
    }

    /** As {@link #model(Scenario, boolean)} with k-DOPs of the given k (6, 14, 18, 26). */
    public static HandModel model(Scenario scenario, boolean record, int k) {
        LinkContacts contacts = scenario.object() == null ? null : new SceneGeometry(scenario.object(), k);
        return new HandModel(scenario, contacts, HandDynamics.barrettHand()::inverseDynamics, record);
    }
}
