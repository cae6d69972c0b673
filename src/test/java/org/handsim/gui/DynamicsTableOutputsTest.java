package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.model.HandModel;
import org.handsim.model.Simulation;
import org.handsim.scenario.Scenario;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * Every number the Dynamics table shows is in {@code handsim run}'s output: each column named by
 * {@link DynamicsPanel#OUTPUT} is a column of trace.csv (or, for the breakaway time, a field of
 * summary.json), and the table's text for a state of the run is that column's value of the same
 * step, formatted as the table formats it. The mug grasp moves all three fingers and every finger
 * breaks away; with the hand on its side (gravity along the palm's -x, as in the paper's
 * experiment) gravity loads the spread joints too, so τk1 is not 0.
 */
class DynamicsTableOutputsTest {
    @Test
    void everyNumberOfTheDynamicsTableIsAColumnOfTheRunsOutput() throws Exception {
        Path dir = Files.createTempDirectory("handsim-dynamics-outputs").toRealPath();
        try {
            Path file = dir.resolve("mug-on-its-side.json");
            Scenario mug = Scenario.load(TestPaths.root().resolve("scenarios/mug-grasp.json")).withGravity(new double[] {-9.81, 0, 0});
            Files.writeString(file, JsonWriter.pretty(mug.toJson(dir)));
            Path out = dir.resolve("out");
            CliTesting.Run r = CliTesting.run("run", file.toString(), "--out", out.toString(), "--no-charts");
            assertEquals(0, r.code(), r.err());
            List<String> trace = Files.readAllLines(out.resolve("trace.csv"));
            List<String> header = Arrays.asList(trace.get(0).split(","));
            @SuppressWarnings("unchecked")
            List<Map<String, Object>> summary = (List<Map<String, Object>>) ((Map<String, Object>) Json.parse("summary.json",
                Files.readString(out.resolve("summary.json")))).get("fingers");

            Scenario s = Scenario.load(file);
            HandModel m = Simulation.model(s, false);
            Object[] row = new Object[DynamicsPanel.OUTPUT.length];
            int compared = 0, spreadTorques = 0;
            while (true) {
                if (m.stepIndex() % 97 == 0 || !m.running()) {
                    String[] csv = trace.get(1 + (int) m.stepIndex()).split(",");
                    assertEquals(Double.parseDouble(csv[0]), m.time(), "the same step");
                    for (int k = 1; k <= 3; k++) {
                        DynamicsPanel.row(k, m.snapshot().fingers()[k - 1], m.breakawayTime(k), row);
                        assertEquals(k, row[0]);
                        for (int c = 1; c < row.length; c++) {
                            String column = String.format(DynamicsPanel.OUTPUT[c], k);
                            String shown = String.valueOf(row[c]);
                            if (column.startsWith("summary.json ")) {
                                Object b = summary.get(k - 1).get("breakaway_time_s");
                                double t = m.breakawayTime(k);
                                assertEquals(Double.isNaN(t) ? "–" : Widgets.fmt(((Number) b).doubleValue(), 4), shown,
                                    "finger " + k + " breakaway at t = " + m.time());
                                continue;
                            }
                            int col = header.indexOf(column);
                            assertTrue(col > 0, column + " is a trace.csv column: " + header);
                            String value = csv[col];
                            String expected = c == 1 || c == 5 ? value : Widgets.fmt(Double.parseDouble(value), c == 6 ? 2 : 3);
                            assertEquals(expected, shown, "finger " + k + " " + column + " at t = " + m.time());
                            if (c == 2 && !shown.equals("0.000")) spreadTorques++;
                        }
                    }
                    compared++;
                }
                if (!m.running()) break;
                m.step();
            }
            assertTrue(compared > 40, "states compared: " + compared);
            assertTrue(spreadTorques > 20, "the spread joints carry torques the table shows: " + spreadTorques);
            for (int k = 1; k <= 3; k++) {
                assertNotNull(summary.get(k - 1).get("breakaway_time_s"), "finger " + k + " breaks away, so the breakaway column is compared");
            }
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
