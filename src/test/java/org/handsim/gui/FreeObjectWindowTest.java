package org.handsim.gui;

import static org.handsim.gui.GuiWindowTest.needDisplay;
import static org.handsim.gui.GuiWindowTest.runGui;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.model.HandModel;
import org.handsim.model.Simulation;
import org.handsim.scenario.Scenario;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The window shows a free object moving and the Dynamics panel reports its state as
 * {@code handsim run} writes it. {@code handsim gui scenarios/mug-lift.json} (a child JVM on the
 * test display, as {@link GuiWindowTest}) plays the lift to its end and logs the Free object box
 * and the transforms its 3D scene graph holds; the same scenario is run here without a window,
 * by the model ({@link Simulation#model}) and by {@code handsim run} (its summary.json and
 * trace.csv). Then the paper's experiment (a fixed cube) is opened in the same window: no box,
 * no object state.
 */
@Tag("slow")   // a child JVM with the window: ./test --all (CI) runs it, the quick ./test does not
class FreeObjectWindowTest {
    @Test
    void theWindowMovesTheFreeMugWithTheModelAndReportsItsState() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-free-window").toRealPath();
        Path lift = TestPaths.root().resolve("scenarios/mug-lift.json");
        Path script = dir.resolve("lift.txt");
        Files.writeString(script, String.join("\n",
            "press Dynamics",
            "log object",        // t = 0: held in place where the scenario puts it
            "speed max",
            "play end",
            "log state",
            "log object",        // the end of the lift
            "open " + TestPaths.root().resolve("scenarios/paper-breakaway.json"),
            "play 0.5",
            "log object",        // a fixed object
            ""));
        GuiWindowTest.Child c = runGui(dir, lift.toString(), "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        assertTrue(c.log().contains("gui: done, 0 uncaught exceptions"), c.log());
        assertTrue(c.log().contains("gui: state: t = 6.4000 s, finished"), c.log());
        List<Map<String, String>> logs = objectLogs(c.log());
        assertEquals(3, logs.size(), c.log());
        Map<String, String> start = logs.get(0), end = logs.get(1);
        assertEquals(Map.of("fixed", ""), logs.get(2), "the paper's cube is fixed: no free object state");

        // the model without a window, to the same end
        Scenario s = Scenario.load(lift);
        HandModel m = Simulation.model(s, false);
        double[] objectStart = m.objectPose(), palmStart = m.worldFromPalm();
        while (m.running()) m.step();
        double k = s.object().meshScale();

        // the scene graph holds the model's poses: the object's (its rotation times the mesh's scale) and the palm's
        assertClose(scaled(objectStart, k), numbers(start.get("view_world_from_object")), "the object's transform at t = 0");
        assertClose(scaled(m.objectPose(), k), numbers(end.get("view_world_from_object")), "the object's transform at the end");
        assertClose(m.objectPose(), numbers(end.get("model_world_from_object")), "the window's model at the end");
        assertEquals(Double.toString(k), end.get("scale"));
        assertClose(palmStart, numbers(start.get("view_world_from_palm")), "the palm's transform at t = 0");
        assertClose(m.worldFromPalm(), numbers(end.get("view_world_from_palm")), "the palm's transform at the end");
        // and those moved: the hand's base rose 0.1 m (hand.moves) and carried the mug up with it
        assertEquals(0.1, numbers(end.get("view_world_from_palm"))[11] - palmStart[11], 1e-9, "the palm rose 10 cm");
        assertEquals(0.1, numbers(end.get("view_world_from_object"))[11] - objectStart[11], 1e-4, "the mug rose 10 cm with it");

        // the Dynamics panel's Free object box: handsim run's figures
        Path out = dir.resolve("out");
        CliTesting.Run r = CliTesting.run("run", lift.toString(), "--out", out.toString(), "--no-charts");
        assertEquals(0, r.code(), r.err());
        @SuppressWarnings("unchecked")
        Map<String, Object> summary = (Map<String, Object>) Json.parse("summary.json", Files.readString(out.resolve("summary.json")));
        double maxDisp = ((Number) summary.get("max_displacement_m")).doubleValue();
        assertTrue(maxDisp > 0 && maxDisp < 0.005, "the mug stays in the hand: " + maxDisp);
        assertEquals(Widgets.significant(maxDisp, 4), end.get("max_displacement_m"), "summary.json's max_displacement_m");
        assertEquals(Widgets.significant(((Number) summary.get("max_rotation_deg")).doubleValue(), 4), end.get("max_rotation_deg"));
        assertEquals(Widgets.fmt(((Number) summary.get("released_at_s")).doubleValue(), 4), end.get("released_at_s"));
        assertNull(summary.get("slipped_at_s"));
        assertNull(summary.get("dropped_at_s"));
        assertEquals("–", end.get("slipped_at_s"));
        assertEquals("–", end.get("dropped_at_s"));
        assertEquals("free since t = 4.7000 s, not slipped", end.get("status"));
        assertEquals("held in place (not released yet)", start.get("status"));
        assertEquals("0", start.get("obj_disp_m"));

        List<String> trace = Files.readAllLines(out.resolve("trace.csv"));
        List<String> header = Arrays.asList(trace.get(0).split(","));
        String[] last = trace.get(trace.size() - 1).split(",");
        assertEquals(6.4, Double.parseDouble(last[0]), 1e-12);
        int compared = 0;
        for (String column : org.handsim.trace.Recorder.OBJECT_COLUMNS) {
            int at = header.indexOf(column);
            assertTrue(at > 0, column + " in trace.csv");
            double v = Double.parseDouble(last[at]);
            String expected = column.equals("obj_contacts") ? Long.toString(Math.round(v))
                : column.matches("obj_[xyz]_m|obj_q[wxyz]") ? Widgets.fmt(v, 5) : Widgets.significant(v, 4);
            assertEquals(expected, end.get(column), "trace.csv's " + column + " at 6.4 s");
            compared++;
        }
        assertEquals(13, compared);
        assertNotNull(end.get("obj_contacts"));
        assertFalse(end.get("obj_contacts").equals("0"), "the hand holds the mug at the end: " + end);
        VrmlTesting.deleteTree(dir);   // kept when a check fails
    }

    /** Each {@code log object}'s lines as KEY → VALUE (the {@code scale=} at the end of a line is a key of its own). */
    private static List<Map<String, String>> objectLogs(String log) {
        List<Map<String, String>> all = new ArrayList<>();
        Map<String, String> now = null;
        String[] lines = log.split("\\R");
        for (int i = 0; i < lines.length; i++) {
            if (!lines[i].startsWith("gui: object: ")) {
                now = null;
                continue;
            }
            if (now == null) all.add(now = new LinkedHashMap<>());
            String body = lines[i].substring("gui: object: ".length());
            for (String part : body.split(" (?=scale=)")) {
                int eq = part.indexOf('=');
                if (eq < 0) now.put(part, "");
                else now.put(part.substring(0, eq), part.substring(eq + 1));
            }
        }
        return all;
    }

    private static double[] numbers(String csv) {
        assertNotNull(csv);
        return Arrays.stream(csv.split(",")).mapToDouble(Double::parseDouble).toArray();
    }

    /** A rigid pose (12 row-major values) with its rotation times {@code k}: how the view draws a mesh scaled by k. */
    private static double[] scaled(double[] pose, double k) {
        double[] a = pose.clone();
        for (int r = 0; r < 3; r++) for (int col = 0; col < 3; col++) a[4 * r + col] *= k;
        return a;
    }

    private static void assertClose(double[] expected, double[] actual, String what) {
        assertEquals(12, actual.length, what);
        for (int i = 0; i < 12; i++) assertEquals(expected[i], actual[i], 1e-9, what + ", value " + i + ": " + Arrays.toString(actual));
    }
}
