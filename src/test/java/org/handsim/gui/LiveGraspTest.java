package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.TestPaths;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.junit.jupiter.api.Test;

/**
 * The window's live grasp without a window: the grasp the runner's evaluation thread publishes
 * for the mug grasp is, bit for bit, {@link GraspAssessment#of(GraspAssessment.Input, double, int)} on a model
 * of its own run to the same time (a second run, not the copy); an unchanged grasp is not
 * evaluated again; evaluations start at least {@link LiveGrasp#MIN_INTERVAL_NS} apart.
 */
class LiveGraspTest {
    static Scenario mug() {
        return Scenario.load(TestPaths.root().resolve("scenarios/mug-grasp.json"));
    }

    @Test
    void theRunnersGraspAtTheEndIsTheGraspOfAnIndependentRun() throws Exception {
        Scenario s = mug();
        HandModel reference = Simulation.model(s, false);
        reference.run(null);
        GraspAssessment want = GraspAssessment.of(reference.graspInput(), s.friction(), s.coneEdges());
        assertTrue(want.quality().forceClosure(), "the mug grasp has force closure at μ = 0.5");

        try (SimulationRunner r = new SimulationRunner()) {
            r.load(s);
            r.setSpeed(0);
            long wall0 = System.nanoTime();
            r.play();
            SimulationRunner.State st = SimulationRunnerTest.await(r);
            assertTrue(st.finished(), "played to the end");
            r.grasp().awaitIdle();
            double wall = (System.nanoTime() - wall0) / 1e9;
            LiveGrasp.Result g = r.grasp().latest();
            assertNotNull(g);
            assertNull(g.error());
            assertEquals(st.generation(), g.generation());
            GraspAssessment a = g.assessment();
            assertEquals(want.quality().forceClosure(), a.quality().forceClosure());
            assertEquals(want.quality().epsilon(), a.quality().epsilon(), "ε to the last bit");
            assertEquals(want.quality().volume(), a.quality().volume(), "volume to the last bit");
            assertArrayEquals(want.holdN(), a.holdN(), "hold in the six directions");
            assertEquals(want.contacts().size(), a.contacts().size());
            // the contacts stop changing when the fingers stall: the grasp evaluated is of that time
            assertTrue(a.timeS() <= st.time() && a.timeS() > 2.0, "evaluated at t = " + a.timeS());
            // throttled: evaluations start at least 0.1 s apart (+1: the first needs no wait)
            assertTrue(g.serial() <= 1 + wall / (LiveGrasp.MIN_INTERVAL_NS / 1e9) + 1e-9,
                g.serial() + " evaluations in " + wall + " s of wall time");

            // reset: a new generation, evaluated again (no contacts at t = 0)
            r.reset();
            r.sync();
            r.grasp().awaitIdle();
            LiveGrasp.Result z = r.grasp().latest();
            assertEquals(r.latest().generation(), z.generation());
            assertEquals(0, z.assessment().contacts().size());
            assertFalse(z.assessment().quality().forceClosure());
        }
    }

    @Test
    void anUnchangedGraspIsNotEvaluatedAgainAndFrictionZeroHasNoForceClosure() throws Exception {
        Scenario s = mug();
        HandModel m = Simulation.model(s, false);
        m.run(null);
        LiveGrasp g = new LiveGrasp();
        try {
            g.offer(1, m, 0.5, 8);
            g.awaitIdle();
            assertEquals(1, g.latest().serial());
            assertTrue(g.latest().assessment().quality().forceClosure());
            g.offer(1, m, 0.5, 8);          // the same grasp: nothing to do
            g.awaitIdle();
            assertEquals(1, g.latest().serial());
            g.offer(1, m, 0.0, 8);          // frictionless contacts never give force closure
            g.awaitIdle();
            assertEquals(2, g.latest().serial());
            assertFalse(g.latest().assessment().quality().forceClosure());
            assertEquals(0.0, g.latest().assessment().quality().epsilon());
            g.offer(2, m, 0.0, 8);          // another generation: evaluated again
            g.awaitIdle();
            assertEquals(3, g.latest().serial());
            assertEquals(2, g.latest().generation());
            g.offer(2, m, 0.0, 8, true);    // at rest at the time already evaluated: nothing to do
            g.awaitIdle();
            assertEquals(3, g.latest().serial());
        } finally {
            g.close();
        }
    }

    /**
     * A model at rest is evaluated at its own time even when its contacts have not changed since
     * the last evaluation (which a run offers at whichever publication first saw them): the
     * panel's "as at" time is then the time shown, the same however the run was batched.
     */
    @Test
    void aModelAtRestIsEvaluatedAtItsTime() throws Exception {
        Scenario s = mug();
        HandModel m = Simulation.model(s, false);
        LiveGrasp g = new LiveGrasp();
        try {
            // 4.5 s: the motors hold (3.7 to 4.7 s), every finger stalled on the mug: the contacts rest
            while (m.time() < 4.5 - 1e-9) m.step();
            g.offer(1, m, 0.5, 8);
            g.awaitIdle();
            assertEquals(1, g.latest().serial());
            assertEquals(4.5, g.latest().assessment().timeS());
            assertTrue(g.latest().assessment().contacts().size() >= 3, "every finger touches the mug");
            while (m.time() < 4.6 - 1e-9) m.step();
            g.offer(1, m, 0.5, 8);           // a playing run's publication of the same contacts: nothing new
            g.awaitIdle();
            assertEquals(1, g.latest().serial(), "the contacts did not change from 4.5 to 4.6 s");
            assertEquals(4.5, g.latest().assessment().timeS());
            g.offer(1, m, 0.5, 8, true);     // the run pauses here: evaluated at this time
            g.awaitIdle();
            assertEquals(2, g.latest().serial());
            assertEquals(4.6, g.latest().assessment().timeS(), "as at the time shown");
        } finally {
            g.close();
        }
    }
}
