package org.handsim.gui;

import static org.handsim.gui.GuiWindowTest.needDisplay;
import static org.handsim.gui.GuiWindowTest.runGui;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The window shows the state of the run (end to end, child JVMs on the current display, as
 * {@link GuiWindowTest}). The reference is {@code handsim run}'s trace.csv of the same scenario:
 * <ul>
 *   <li>a misspelt {@code press} lists the buttons on screen;</li>
 *   <li>after {@code play T} (a run that pauses at T), a step and a reset, the Kinematics
 *       panel ({@code log kinematics}) shows for each finger the trace's motor counts (±1) and
 *       joint angles (±0.01°) at the time shown — in the paper's scenario (finger 3 broken away:
 *       θ32 and θ33 no longer the coupled angles of the counts), the mug grasp, and the mug
 *       imported from an STL in millimetres with all three fingers closing (the README's
 *       screenshot scene, whose scenario the window saves and {@code handsim run} replays);</li>
 *   <li>the same script run three times logs the same readouts — Grasp box, Dynamics table,
 *       events, Kinematics panel, charts — and its screenshots show the same tool panel, pixel
 *       for pixel; the Grasp box is of the state shown (its time, and the table's contacts).</li>
 * </ul>
 */
@Tag("slow")
class GuiStateTest {
    static final Pattern KINEMATICS = Pattern.compile(
        "gui: kinematics: finger (\\d): M(\\d) (-?\\d+) counts, θ\\d1 (-?[0-9.]+)°, θ\\d2 (-?[0-9.]+)°, θ\\d3 (-?[0-9.]+)°");

    @Test
    void theKinematicsPanelShowsThePapersRunAfterAPauseAStepAndAReset() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-gui-state").toRealPath();
        Path paper = TestPaths.root().resolve("scenarios/paper-breakaway.json");
        Path script = dir.resolve("kinematics.txt");
        Files.writeString(script, String.join("\n",
            "expect-error no button 'Kinematic' (buttons on screen: ",
            "press Kinematic",
            "press Kinematics",
            "speed max",
            "play 2.5",
            "log kinematics",
            "play 4",
            "menu run.step",
            "log state",
            "log kinematics",
            "menu run.reset",
            "log kinematics",
            "play end",
            "log kinematics",
            ""));
        GuiWindowTest.Child c = runGui(dir, paper.toString(), "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        assertTrue(c.log().contains("gui: state: t = 4.0010 s"), "one step after 4 s:\n" + c.log());
        // a misspelt button: the buttons on screen are listed, by label and, where it differs, by name
        Matcher miss = Pattern.compile("gui: expected error: .*no button 'Kinematic' \\(buttons on screen: (.*)\\)").matcher(c.log());
        assertTrue(miss.find(), c.log());
        for (String b : new String[] {"Kinematics", "Path Planning", "Dynamics", "Objects", "Play", "Pause", "Step", "Reset",
            "Use as start pose (fk.apply)", "Solve (ik.solve)"}) {
            assertTrue(List.of(miss.group(1).split(", ")).contains(b), b + " in: " + miss.group(1));
        }
        Trace trace = trace(dir, paper);
        List<String[]> shown = kinematics(c.log());
        assertEquals(12, shown.size(), c.log());
        String[] times = {"2.5", "4.001", "0", "8.947"};
        for (int i = 0; i < shown.size(); i++) assertShowsTrace(trace, times[i / 3], shown.get(i));
        // finger 3 broke away before 2.5 s: its angles are not the coupled ones of its counts (θ32 = q/125)
        String[] f3 = shown.get(2);
        assertTrue(Math.abs(Double.parseDouble(f3[4]) - Double.parseDouble(f3[2]) / 125) > 5, "finger 3 at 2.5 s: " + String.join(" ", f3));
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void theKinematicsPanelShowsEachFingerOfTheMugGrasp() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-gui-state").toRealPath();
        Path mug = TestPaths.root().resolve("scenarios/mug-grasp.json");
        Path script = dir.resolve("mug.txt");
        Files.writeString(script, "speed max\nplay 2.4\nlog kinematics\n");
        GuiWindowTest.Child c = runGui(dir, mug.toString(), "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        Trace trace = trace(dir, mug);
        List<String[]> shown = kinematics(c.log());
        assertEquals(3, shown.size(), c.log());
        for (String[] f : shown) assertShowsTrace(trace, "2.4", f);
        VrmlTesting.deleteTree(dir);
    }

    /**
     * The README's screenshot scene (docs/gui-screenshot.txt: the STL mug in millimetres, three
     * fingers on trapezoids, t = 2.4 s) three times: one readout, the trace's state, settled.
     */
    @Test
    void theStlMugSceneGivesOneTrueReadoutInThreeRuns() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-gui-state").toRealPath();
        Path saved = dir.resolve("stl-mug.json");
        List<String> logs = new ArrayList<>();
        List<BufferedImage> shots = new ArrayList<>();
        Rectangle panel = null;
        for (int run = 1; run <= 3; run++) {
            Path shot = dir.resolve("shot" + run + ".png");
            Path script = dir.resolve("stl" + run + ".txt");
            Files.writeString(script, String.join("\n",
                "press Objects",
                "import " + TestPaths.root().resolve("vrml/objects/mug_mm.stl"),
                "press Path Planning",
                "press path.M1.add",
                "press path.M2.add",
                "set path.M3.1.vmax 5000",
                "set path.M3.1.amax 25000",
                "press path.M3.3.remove",
                "press path.M3.2.remove",
                "set path.duration 4.2",
                "speed max",
                "press path.run",
                "play 2.4",
                "press Dynamics",
                "screenshot " + shot,
                "log grasp",
                "log dynamics",
                "log events",
                "log charts",
                "log kinematics",
                run == 1 ? "save-scenario " + saved : "",
                ""));
            GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
            assertEquals(0, c.code(), c.log());
            logs.add(readouts(c.log()));
            shots.add(ImageIO.read(shot.toFile()));
            Rectangle[] r = regions(c.log(), shot);
            if (panel == null) panel = r[3];
            assertEquals(panel, r[3], "the same layout");
            if (run == 1) {
                // the Grasp box is of the state shown: its time, and the table's contacts
                Matcher g = Pattern.compile("gui: grasp: .* (\\d+) contacts? as at t = ([0-9.]+) s").matcher(c.log());
                assertTrue(g.find(), c.log());
                assertEquals("2.4000", g.group(2), "evaluated at the time shown");
                int table = 0;
                Matcher d = Pattern.compile("gui: dynamics: finger=\\d .*contacts=(\\d+)").matcher(c.log());
                while (d.find()) table += Integer.parseInt(d.group(1));
                assertEquals(table, Integer.parseInt(g.group(1)), "the Grasp box and the table count the same contacts:\n" + c.log());
                assertTrue(table >= 3, "all three fingers touch the mug: " + table);
                // each finger's line is the trace's, and the three differ
                Trace trace = trace(dir, saved);
                List<String[]> shown = kinematics(c.log());
                assertEquals(3, shown.size(), c.log());
                for (String[] f : shown) assertShowsTrace(trace, "2.4", f);
                assertTrue(!shown.get(0)[4].equals(shown.get(2)[4]) || !shown.get(0)[5].equals(shown.get(2)[5]),
                    "fingers 1 and 3 do not show one pose: " + String.join(" ", shown.get(0)) + " / " + String.join(" ", shown.get(2)));
            }
        }
        assertEquals(logs.get(0), logs.get(1), "runs 1 and 2 log the same readouts");
        assertEquals(logs.get(0), logs.get(2), "runs 1 and 3 log the same readouts");
        for (int run = 2; run <= 3; run++) {
            int differ = 0;
            for (int y = panel.y; y < panel.y + panel.height; y++) {
                for (int x = panel.x; x < panel.x + panel.width; x++) if (shots.get(0).getRGB(x, y) != shots.get(run - 1).getRGB(x, y)) differ++;
            }
            assertEquals(0, differ, "pixels of the Dynamics panel (table, Grasp box, events) that differ between screenshots 1 and " + run);
        }
        VrmlTesting.deleteTree(dir);
    }

    /** The lines of a log that say what the window shows (not the timings). */
    static String readouts(String log) {
        StringBuilder sb = new StringBuilder();
        for (String l : log.split("\\R")) {
            if (l.matches("gui: (grasp|dynamics|event|charts|kinematics): .*")) sb.append(l).append('\n');
        }
        return sb.toString();
    }

    /** The view, charts, status and tool-panel regions printed for a screenshot. */
    static Rectangle[] regions(String log, Path shot) {
        Rectangle[] three = GuiWindowTest.regions(log, shot);
        Matcher m = Pattern.compile("gui: screenshot " + Pattern.quote(shot.toString()) + " .* panel=(\\d+),(\\d+),(\\d+),(\\d+)").matcher(log);
        assertTrue(m.find(), log);
        return new Rectangle[] {three[0], three[1], three[2],
            new Rectangle(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)), Integer.parseInt(m.group(3)), Integer.parseInt(m.group(4)))};
    }

    /** Each {@code log kinematics} line: {finger, motor, counts, θk1, θk2, θk3} as text. */
    static List<String[]> kinematics(String log) {
        List<String[]> out = new ArrayList<>();
        Matcher m = KINEMATICS.matcher(log);
        while (m.find()) {
            assertEquals(m.group(1), m.group(2), "finger k shows motor Mk: " + m.group());
            out.add(new String[] {m.group(1), m.group(2), m.group(3), m.group(4), m.group(5), m.group(6)});
        }
        return out;
    }

    /** trace.csv: its header, and each row by its time as written, as numbers (states as NaN). */
    record Trace(List<String> header, Map<String, double[]> rows) {
        double at(String t, String column) {
            double[] row = rows.get(t);
            assertNotNull(row, "trace.csv has a row at t = " + t);
            int i = header.indexOf(column);
            assertTrue(i >= 0, "trace.csv has a column " + column);
            return row[i];
        }
    }

    /** trace.csv of {@code handsim run SCENARIO}. */
    static Trace trace(Path dir, Path scenario) throws Exception {
        Path out = dir.resolve("run-" + scenario.getFileName());
        CliTesting.Run r = CliTesting.run("run", scenario.toString(), "--out", out.toString(), "--no-charts");
        assertEquals(0, r.code(), r.err());
        List<String> lines = Files.readAllLines(out.resolve("trace.csv"));
        Map<String, double[]> rows = new HashMap<>();
        for (String l : lines.subList(1, lines.size())) {
            String[] cells = l.split(",");
            double[] v = new double[cells.length];
            for (int i = 0; i < cells.length; i++) v[i] = cells[i].matches("-?[0-9.e+-]+") ? Double.parseDouble(cells[i]) : Double.NaN;
            rows.put(cells[0], v);
        }
        return new Trace(List.of(lines.get(0).split(",")), rows);
    }

    /** A {@code log kinematics} line equals the trace's row at time {@code t}: counts ±1, angles ±0.01°. */
    static void assertShowsTrace(Trace trace, String t, String[] shown) {
        int k = Integer.parseInt(shown[0]);
        String what = "finger " + k + " at t = " + t + " shows " + String.join(" ", shown);
        assertEquals(trace.at(t, "qM" + k + "_counts"), Double.parseDouble(shown[2]), 1.0, what + " (counts)");
        for (int j = 1; j <= 3; j++) {
            assertEquals(Math.toDegrees(trace.at(t, "theta" + k + j + "_rad")), Double.parseDouble(shown[2 + j]), 0.01, what + " (θ" + k + j + ")");
        }
    }
}
