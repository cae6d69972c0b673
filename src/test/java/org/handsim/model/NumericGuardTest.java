package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.dynamics.HandDynamics;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Test;

/**
 * The simulator's numeric guard: a non-finite torque (here injected by a dynamics that goes bad
 * at t = 0.5 s) stops the run in that very step with a message naming the step, the time, the
 * finger, the joint and the value — never a NaN passed on into the trace.
 */
class NumericGuardTest {
    @Test
    void aNonFiniteTorqueStopsTheRunNamingStepAndTime() {
        Scenario s = Scenario.load(Home.paperScenario());
        HandDynamics good = HandDynamics.barrettHand();
        double[] now = {0};
        TorqueModel goesBad = (k, q, qd, qdd, g, tau) -> {
            good.inverseDynamics(k, q, qd, qdd, g, tau);
            if (k == 3 && now[0] >= 0.5) tau[2] = Double.NaN;
        };
        HandModel m = new HandModel(s, new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K), goesBad, true);
        SimulationException e = assertThrows(SimulationException.class, () -> {
            while (m.running()) {
                now[0] = (m.stepIndex() + 1) * s.dt();
                m.step();
            }
        });
        assertTrue(e.getMessage().startsWith("step 500 (t = 0.5 s): finger 3 joint 3 is not finite"), e.getMessage());
        assertTrue(e.getMessage().contains("torque NaN"), e.getMessage());
        // nothing after the bad step was recorded, and every recorded torque is finite
        Recorder r = m.recorder();
        for (int row = 0; row < r.rows() - 1; row++) assertTrue(Double.isFinite(r.get(3, Recorder.TAU3, row)), "row " + row);
        assertTrue(r.rows() <= 501, "rows " + r.rows());
    }
}
