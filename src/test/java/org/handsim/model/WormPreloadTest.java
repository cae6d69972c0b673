package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Test;

/**
 * A link held by its worm keeps the load it carried when the worm locked (DESIGN.md, "Which
 * contact forces"): after the breakaway the inner contact keeps its breakaway force while the
 * outer link closes and stalls — as the paper's Fig. 7 keeps τ32 at τ_break — until the finger
 * opens (the clutch re-engages at the breakaway count), and the inner joint's worm carries that
 * load plus what the outer contact puts on it, which the model reports
 * ({@link HandModel#carriedTorque}, the trace's {@code carried{k}2_Nm}, the summary's largest).
 */
class WormPreloadTest {

    /** Largest |f − f_break| / f_break of the inner contact from the breakaway to the re-engagement (or the end). */
    static double innerForceDrift(HandModel m, int k, double[] wormOut) {
        double worst = 0, fb = Double.NaN;
        boolean broke = false;
        while (m.running()) {
            m.step();
            ClutchState st = m.state(k);
            if (st == ClutchState.BROKEN || st == ClutchState.STALLED && !m.clutchEngaged(k)) {
                broke = true;
                fb = m.breakawayForce(k);
                ContactSet cs = m.contacts(k);
                double inner = 0;
                for (int i = 0; i < cs.size(); i++) if (cs.link(i) == 2) inner += cs.force(i);
                worst = Math.max(worst, Math.abs(inner - fb) / fb);
                wormOut[0] = Math.max(wormOut[0], m.carriedTorque(k, 2));
            } else if (broke) {
                break;                                         // re-engaged: the finger opens
            }
        }
        assertTrue(broke, "finger " + k + " broke away");
        return worst;
    }

    /**
     * The paper's run with μ = 0.5: the breakaway as the paper's (1.80 s, 1.26 N·m, 20.09 N); the
     * inner contact keeps those 20.09 N (within 1e-12 relative, the test allows 1 %) through the
     * outer link's closing and stall until the finger opens; the inner joint's worm then carries
     * 1.26 N·m of preload plus what the outer contact adds, 2.634 N·m; frictionless 20.41 N and
     * 2.98 N·m.
     */
    @Test
    void thePaperRunKeepsTheInnerContactsBreakawayForce() {
        double[][] expect = {{0.5, 20.09, 2.634}, {0, 20.41, 2.980}};
        for (double[] e : expect) {
            HandModel m = Simulation.model(Scenario.load(Home.paperScenario()).withFriction(e[0]), true);
            double[] worm = new double[1];
            double drift = innerForceDrift(m, 3, worm);
            assertEquals(1.80, m.breakawayTime(3), 1e-3);
            assertEquals(1.26, m.breakawayTorque(3), 1e-12);
            assertEquals(e[1], m.breakawayForce(3), 0.005, "mu " + e[0]);
            assertTrue(drift <= 0.01, "mu " + e[0] + ": the inner contact's force moved by " + drift);
            assertTrue(drift <= 1e-12, "mu " + e[0] + ": it does not move at all: " + drift);
            assertEquals(e[2], worm[0], 0.0005, "mu " + e[0] + ": the worm's largest reaction");
            m.run(null);
            assertEquals(worm[0], m.maxWormReaction(3), 1e-12, "mu " + e[0] + ": the summary's largest worm reaction");
            Recorder r = m.recorder();
            double trace = 0;
            for (int row = 0; row < r.rows(); row++) trace = Math.max(trace, r.carried(3, 2, row));
            assertEquals(worm[0], trace, 1e-12, "mu " + e[0] + ": the trace's carried32_Nm");
        }
    }

    /** The mug grasp, each finger: the inner contact keeps its 39.57 N to the end (the fingers never open). */
    @Test
    void theMugGraspKeepsEachInnerContactsBreakawayForce() {
        for (int k = 1; k <= 3; k++) {
            HandModel m = Simulation.model(Scenario.load(Home.dir().resolve("scenarios/mug-grasp.json")), false);
            double[] worm = new double[1];
            double drift = innerForceDrift(m, k, worm);
            assertEquals(39.57, m.breakawayForce(k), 0.005, "finger " + k);
            assertTrue(drift <= 1e-12, "finger " + k + ": the inner contact's force moved by " + drift);
            assertTrue(worm[0] > 2.6, "finger " + k + ": the worm carries the preload and the outer contact's share: " + worm[0]);
            assertEquals(worm[0], m.maxWormReaction(k), 1e-12, "finger " + k);
        }
    }
}
