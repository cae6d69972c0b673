package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.model.HandModel;
import org.handsim.model.LinkContacts;
import org.handsim.scenario.Scenario;
import org.handsim.model.SimulationException;
import org.handsim.model.TorqueModel;
import org.junit.jupiter.api.Test;

/** The simulation thread without a window: commands, pacing to a target time, trace rows, errors. */
class SimulationRunnerTest {
    static Scenario closing() {
        return Scenario.parse(Path.of("runner.json"), "{\"name\":\"runner\",\"dt_s\":0.001,\"duration_s\":2.0,"
            + "\"motors\":{\"M3\":[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000}]}}");
    }

    static SimulationRunner.State await(SimulationRunner r) throws InterruptedException {
        r.sync();
        long deadline = System.currentTimeMillis() + 60_000;
        while (r.latest().playing() && System.currentTimeMillis() < deadline) Thread.sleep(5);
        return r.latest();
    }

    @Test
    void playsToATargetTimeAndRecordsEveryTraceRow() throws Exception {
        try (SimulationRunner r = new SimulationRunner()) {
            r.load(closing());
            r.setSpeed(0);
            r.playUntil(0.5);
            SimulationRunner.State s = await(r);
            assertNull(s.error());
            assertEquals(0.5, s.time(), 1e-9);
            assertFalse(s.finished());
            List<double[]> rows = new ArrayList<>();
            r.drainTrace(rows::add);
            assertEquals(101, rows.size(), "t = 0, 0.005, ..., 0.5");
            assertEquals(0.5, rows.get(100)[1], 1e-9);
            double q = s.snapshot().fingers()[2].motorCounts();
            assertEquals(Math.toDegrees(s.snapshot().fingers()[2].joints()[1]), rows.get(100)[2 + 14], 1e-9, "θ32 in degrees");
            assertTrue(q > 0, "finger 3 moved");

            r.play();
            s = await(r);
            assertTrue(s.finished());
            assertEquals(2.0, s.time(), 1e-9);

            long gen = s.generation();
            r.reset();
            r.step();
            r.sync();
            s = r.latest();
            assertEquals(gen + 1, s.generation());
            assertEquals(0.001, s.time(), 1e-12);
            assertFalse(s.playing());
        }
    }

    @Test
    void realTimePacingFollowsTheWallClock() throws Exception {
        try (SimulationRunner r = new SimulationRunner()) {
            r.load(closing());
            r.setSpeed(1);
            long t0 = System.nanoTime();
            r.playUntil(0.3);
            SimulationRunner.State s = await(r);
            double wall = (System.nanoTime() - t0) / 1e9;
            assertEquals(0.3, s.time(), 1e-9);
            assertTrue(wall >= 0.28, "0.3 simulated seconds at real time took only " + wall + " s");
        }
    }

    @Test
    void aSimulationExceptionStopsTheRunAndIsReported() throws Exception {
        LinkContacts failing = new LinkContacts() {
            @Override
            public int collide(int finger, int link, double[] worldFromLink, org.handsim.model.ContactSet out) {
                if (worldFromLink[11] > 0.16) throw new SimulationException("test: link above 0.16 m");
                return 0;
            }
        };
        try (SimulationRunner r = new SimulationRunner(s -> new HandModel(s, failing, TorqueModel.NONE, false))) {
            r.load(closing());
            r.setSpeed(0);
            r.play();
            SimulationRunner.State s = await(r);
            assertNotNull(s.error());
            assertTrue(s.error().contains("test: link above 0.16 m"), s.error());
            assertFalse(s.playing());
            assertTrue(s.time() > 0 && s.time() < 2.0, "stopped part way: " + s.time());
        }
    }
}
