package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Test;

/**
 * The model does no more than a scene needs: the work the model saves (HandModel.lazy) must
 * not change a single recorded number, and must actually be saved. Compared on the paper's
 * experiment (fingers 1 and 2 never move) and the three-finger mug grasp, against the same run
 * with every finger fully computed every step.
 */
class WorkSavingTest {
    private static HandModel run(Scenario s, boolean lazy) {
        HandModel m = Simulation.model(s, true).lazy(lazy);
        m.run(null);
        return m;
    }

    private static void assertSameTrace(HandModel a, HandModel b) {
        Recorder ra = a.recorder(), rb = b.recorder();
        assertEquals(ra.rows(), rb.rows());
        for (int row = 0; row < ra.rows(); row++) {
            for (int k = 1; k <= 3; k++) {
                for (int c = Recorder.Q; c <= Recorder.TAU3; c++) {
                    assertEquals(rb.get(k, c, row), ra.get(k, c, row), 1e-12, "finger " + k + " column " + c + " row " + row);
                }
                assertEquals(rb.state(k, row), ra.state(k, row), "state, finger " + k + " row " + row);
                assertEquals(rb.contacts(k, row), ra.contacts(k, row), "contacts, finger " + k + " row " + row);
                assertEquals(rb.force(k, row), ra.force(k, row), 1e-9, "force, finger " + k + " row " + row);
            }
        }
        for (int k = 1; k <= 3; k++) {
            assertEquals(Double.valueOf(b.breakawayTime(k)), Double.valueOf(a.breakawayTime(k)), "breakaway time, finger " + k);
            assertEquals(b.maxContactForce(k), a.maxContactForce(k), 1e-9, "max force, finger " + k);
        }
    }

    @Test
    void paperExperimentSameResultsLessWork() {
        Scenario s = Scenario.load(Home.paperScenario());
        HandModel lazy = run(s, true), full = run(s, false);
        assertSameTrace(lazy, full);
        long steps = lazy.stepIndex();
        // fingers 1 and 2 never move: after t = 0 they are never updated again
        assertTrue(lazy.counter(HandModel.Counter.FINGERS_IDLE) >= 2 * steps, "idle " + lazy.counter(HandModel.Counter.FINGERS_IDLE));
        assertEquals(0, full.counter(HandModel.Counter.FINGERS_IDLE));
        assertTrue(lazy.counter(HandModel.Counter.COLLISION_QUERIES) * 5 < full.counter(HandModel.Counter.COLLISION_QUERIES),
            lazy.counter(HandModel.Counter.COLLISION_QUERIES) + " vs " + full.counter(HandModel.Counter.COLLISION_QUERIES));
        assertTrue(lazy.counter(HandModel.Counter.DYNAMICS_CALLS) * 5 < full.counter(HandModel.Counter.DYNAMICS_CALLS));
    }

    @Test
    void mugGraspSameResultsLessWork() {
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        HandModel lazy = run(s, true), full = run(s, false);
        assertSameTrace(lazy, full);
        for (int k = 1; k <= 3; k++) {
            assertEquals(ClutchState.STALLED, lazy.state(k), "finger " + k + " wraps the mug");
            assertTrue(lazy.breakawayTime(k) > 2 && lazy.breakawayTime(k) < 2.5, "finger " + k + " breaks away at " + lazy.breakawayTime(k));
        }
        assertTrue(lazy.counter(HandModel.Counter.COLLISION_QUERIES) * 2 < full.counter(HandModel.Counter.COLLISION_QUERIES));
    }

    /**
     * Temporal coherence in the collision back end (SceneGeometry.coherent) changes no recorded
     * number at all — not even in the last bit — on the mug grasp, and walks the trees far less.
     */
    @Test
    void coherentCollisionChangesNoNumber() {
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        SceneGeometry on = new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K);
        SceneGeometry off = new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K).coherent(false);
        HandModel a = new HandModel(s, on, org.handsim.dynamics.HandDynamics.barrettHand()::inverseDynamics, true);
        HandModel b = new HandModel(s, off, org.handsim.dynamics.HandDynamics.barrettHand()::inverseDynamics, true);
        a.run(null);
        b.run(null);
        Recorder ra = a.recorder(), rb = b.recorder();
        assertEquals(rb.rows(), ra.rows());
        for (int row = 0; row < ra.rows(); row++) {
            for (int k = 1; k <= 3; k++) {
                for (int c = Recorder.Q; c <= Recorder.TAU3; c++) {
                    assertEquals(rb.get(k, c, row), ra.get(k, c, row), "finger " + k + " column " + c + " row " + row);
                }
                assertEquals(rb.state(k, row), ra.state(k, row));
                assertEquals(rb.contacts(k, row), ra.contacts(k, row));
                assertEquals(rb.force(k, row), ra.force(k, row), "force, finger " + k + " row " + row);
            }
        }
        for (int k = 1; k <= 3; k++) {
            assertEquals(b.breakawayTime(k), a.breakawayTime(k));
            assertEquals(b.contactCounts(k), a.contactCounts(k));
            assertEquals(b.maxContactForce(k), a.maxContactForce(k));
        }
        assertEquals(java.util.Arrays.toString(b.counters()), java.util.Arrays.toString(a.counters()), "the model's own counters");
        long walks = on.counter(SceneGeometry.Counter.TREE_WALKS), fullWalks = off.counter(SceneGeometry.Counter.TREE_WALKS);
        assertTrue(walks * 10 < fullWalks, walks + " walks with coherence, " + fullWalks + " without");
    }

    /**
     * Dynamics only when torques are asked for, and at the held pose of a BLOCKED finger, whose
     * clutch torque includes it: the events and forces are the same as with torques.
     */
    @Test
    void torquesOffSkipsTheDynamicsAndChangesNoEvent() {
        Scenario s = Scenario.load(Home.paperScenario());
        HandModel with = run(s, true), without = run(s.withTorques(false), true);
        // without torques the dynamics runs only where the clutch needs it: at the held pose of each
        // BLOCKED phase (the torque through the clutch includes gravity's share) — the closing and the re-engaging
        assertEquals(2, without.counter(HandModel.Counter.DYNAMICS_CALLS));
        assertTrue(with.counter(HandModel.Counter.DYNAMICS_CALLS) > 1000);
        assertEquals(Double.valueOf(with.breakawayTime(3)), Double.valueOf(without.breakawayTime(3)));
        assertEquals(with.maxContactForce(3), without.maxContactForce(3), 1e-9);
    }
}
