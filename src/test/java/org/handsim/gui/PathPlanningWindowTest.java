package org.handsim.gui;

import static org.handsim.gui.GuiWindowTest.needDisplay;
import static org.handsim.gui.GuiWindowTest.runGui;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The Path Planning panel shows every segment of every motor as the scenario file holds it, and
 * what it edits is what runs and what Save scenario writes: the window under a script (a child
 * JVM on the test display, as {@link GuiWindowTest}).
 */
@Tag("slow")   // a child JVM with the window: ./test --all (CI) runs it, the quick ./test does not
class PathPlanningWindowTest {
    /**
     * The paper's scenario opened: the panel lists M3's three segments with the file's numbers
     * (trapezoid to 17 500 at v_max 4244.294 and a_max 21221.471, the 0.3 s hold, the return to
     * 0; not one trapezoid of 5000 and 25000) and no segment for M1, M2, M4, read from the file's
     * JSON here, not from the classes the panel uses. Then segments are edited, added and
     * removed: the panel shows what the saved file holds, the saved file holds the edits, and
     * {@code handsim run} on it reproduces the window's trace to the last digit.
     */
    @Test
    void thePanelListsTheScenariosSegmentsAndWhatItEditsRunsAndIsSaved() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-path-panel").toRealPath();
        Path paper = TestPaths.root().resolve("scenarios/paper-breakaway.json");
        Path opened = dir.resolve("opened.json"), edited = dir.resolve("edited.json"), exported = dir.resolve("window-trace.csv");
        Path script = dir.resolve("path.txt");
        Files.writeString(script, String.join("\n",
            "press Path Planning",
            "log path",
            "save-scenario " + opened,
            "set path.M3.1.vmax 4000",
            "set path.M3.2.duration 0.5",
            "press path.M3.3.remove",
            "press path.M3.add",
            "set path.M3.3.type quintic",
            "set path.M3.3.to 2000",
            "set path.M3.3.duration 1.25",
            "press path.M1.add",
            "set path.M1.1.to 9000",
            "set path.M1.1.vmax 3000",
            "press path.M1.add",
            "set path.M1.2.type hold",
            "set path.M1.2.duration 0.2",
            "set path.M4.start 100",
            "set path.M3.1.vmax -1",
            "expect-error M3 segment 1 v_max: must be > 0, got -1",
            "press path.apply",
            "set path.M3.1.vmax 4000",
            "press path.apply",
            "log path",
            "save-scenario " + edited,
            "speed max",
            "press path.run",
            "play end",
            "export-traces " + exported,
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        List<List<String>> logs = pathLogs(c.log());
        assertEquals(2, logs.size(), c.log());

        // as opened: the file's segments, its numbers written as the file writes them
        List<String> file = expected(paper);
        assertEquals(file, logs.get(0).subList(0, 4), "the panel shows the paper's file");
        assertEquals("M3: start 0; trapezoid to=17500 v_max=4244.294 a_max=21221.471; hold duration_s=0.3; "
            + "trapezoid to=0 v_max=4244.294 a_max=21221.471", logs.get(0).get(2));
        assertEquals("M1: start 0", logs.get(0).get(0));
        assertEquals("duration_s=longest", logs.get(0).get(4), "the paper gives no duration: the longest motor's");
        assertEquals(file, expected(opened), "Save scenario writes the segments shown");

        // edited: shown, saved and run alike
        assertEquals(List.of(
            "M1: start 0; trapezoid to=9000 v_max=3000 a_max=25000; hold duration_s=0.2",
            "M2: start 0",
            "M3: start 0; trapezoid to=17500 v_max=4000 a_max=21221.471; hold duration_s=0.5; quintic to=2000 duration_s=1.25",
            "M4: start 100",
            "duration_s=longest"), logs.get(1));
        assertEquals(logs.get(1).subList(0, 4), expected(edited), "Save scenario writes the segments shown");
        @SuppressWarnings("unchecked")
        Map<String, Object> saved = (Map<String, Object>) Json.parse(edited.toString(), Files.readString(edited));
        // M3: 17500 / 4000 + 4000 / 21221.471 s, 0.5 s, 1.25 s
        double m3 = 17500 / 4000.0 + 4000 / 21221.471 + 0.5 + 1.25;
        assertEquals(m3, ((Number) saved.get("duration_s")).doubleValue(), 1e-9, "the longest motor's end");
        CliTesting.Run r = CliTesting.run("run", edited.toString(), "--out", dir.resolve("out").toString(), "--no-charts");
        assertEquals(0, r.code(), r.err());
        assertEquals(Files.readString(dir.resolve("out/trace.csv")), Files.readString(exported),
            "handsim run on the saved scenario reproduces the window's run to the last digit");
        VrmlTesting.deleteTree(dir);
    }

    /** The {@code gui: path: } blocks of the log, one list of five lines per {@code log path}. */
    static List<List<String>> pathLogs(String log) {
        List<List<String>> out = new ArrayList<>();
        List<String> block = null;
        for (String l : log.split("\\R")) {
            if (!l.startsWith("gui: path: ")) {
                block = null;
                continue;
            }
            if (block == null) {
                block = new ArrayList<>();
                out.add(block);
            }
            block.add(l.substring("gui: path: ".length()));
        }
        return out;
    }

    /**
     * The panel's motor lines for a scenario file, made from its JSON: per motor its start count
     * and each segment's type and fields in the file's order, numbers as the file writes them.
     */
    @SuppressWarnings("unchecked")
    static List<String> expected(Path scenario) throws Exception {
        String text = Files.readString(scenario);
        Map<String, Object> j = (Map<String, Object>) Json.parse(scenario.toString(), text);
        Map<String, Object> start = (Map<String, Object>) j.getOrDefault("start_counts", Map.of());
        Map<String, Object> motors = (Map<String, Object>) j.getOrDefault("motors", Map.of());
        List<String> out = new ArrayList<>();
        for (int m = 1; m <= 4; m++) {
            String key = "M" + m;
            StringBuilder sb = new StringBuilder(key).append(": start ").append(numberText(text, start.getOrDefault(key, 0.0)));
            for (Object o : (List<Object>) motors.getOrDefault(key, List.of())) {
                Map<String, Object> seg = new LinkedHashMap<>((Map<String, Object>) o);
                sb.append("; ").append(seg.remove("type"));
                for (Map.Entry<String, Object> e : seg.entrySet()) sb.append(' ').append(e.getKey()).append('=').append(numberText(text, e.getValue()));
            }
            out.add(sb.toString());
        }
        return out;
    }

    /** A number of the file as its text writes it (17500, not 17500.0): the shortest text that reads back as it. */
    private static String numberText(String file, Object v) {
        if (v instanceof List) {
            StringBuilder sb = new StringBuilder();
            for (Object x : (List<?>) v) sb.append(sb.length() == 0 ? "" : ",").append(numberText(file, x));
            return sb.toString();
        }
        double d = ((Number) v).doubleValue();
        String s = d == Math.rint(d) && Math.abs(d) < 1e15 ? String.valueOf((long) d) : String.valueOf(d);
        Matcher m = Pattern.compile("(?<![0-9.])" + Pattern.quote(s) + "(?![0-9])").matcher(file);
        assertTrue(m.find() || !(v instanceof Double), s + " is written so in " + file.substring(0, Math.min(80, file.length())));
        return s;
    }
}
