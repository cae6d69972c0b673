package org.handsim.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The numbers every picture of the README and docs/ displays — written beside it by
 * {@code tools/docs-pictures} as {@code <picture>.numbers.json} — are what the current build
 * computes. The pictures themselves are remade by that script (slow: a 500-trial plan, the
 * tradeoff studies, window screenshots); this test recomputes their numbers the fast way: the
 * charts through the same commands in this JVM (their SVG's texts, as the script reads them),
 * the window screenshots by replaying the scene each saved ({@code *.scenario.json}) without a
 * window and comparing every value its log lines show at the precision shown. A picture left
 * stale after a change of the physics (docs/plan/best-grasp.png once showed 0.00 N on fingers 1
 * and 2 where the grasp has 23.50 and 28.49 N) fails here.
 */
class DocsPicturesTest {
    private static final Path DOCS = TestPaths.root().resolve("docs");

    @SuppressWarnings("unchecked")
    private static List<String> committed(String picture) throws IOException {
        Path png = TestPaths.root().resolve(picture);
        Path f = png.resolveSibling(png.getFileName().toString().replaceFirst("\\.png$", ".numbers.json"));
        assertTrue(Files.isRegularFile(f), "no " + f + ": run tools/docs-pictures");
        Map<String, Object> j = (Map<String, Object>) Json.parse(f.toString(), Files.readString(f));
        assertEquals(picture, j.get("picture"));
        return (List<String>) j.get("numbers");
    }

    /** The texts of an SVG that hold a digit, in document order (tools/docs-pictures' rule). */
    static List<String> svgNumbers(Path svg) throws IOException {
        List<String> out = new ArrayList<>();
        Matcher m = Pattern.compile("<text[^>]*>(.*?)</text>", Pattern.DOTALL).matcher(Files.readString(svg));
        while (m.find()) {
            String t = unescape(m.group(1));
            if (t.matches("(?s).*[0-9].*")) out.add(t);
        }
        return out;
    }

    private static String unescape(String s) {
        Matcher m = Pattern.compile("&#(x?)([0-9a-fA-F]+);").matcher(s);
        StringBuilder sb = new StringBuilder();
        while (m.find()) m.appendReplacement(sb, Matcher.quoteReplacement(new String(Character.toChars(Integer.parseInt(m.group(2), m.group(1).isEmpty() ? 10 : 16)))));
        m.appendTail(sb);
        return sb.toString().replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&apos;", "'").replace("&#39;", "'").replace("&amp;", "&");
    }

    @Test
    void thePapersFiguresShowWhatTheRunComputes() throws Exception {
        Path dir = Files.createTempDirectory("docs-paper");
        try {
            CliTesting.Run r = CliTesting.run("run", "--out", dir.toString());
            assertEquals(0, r.code(), r.err());
            assertEquals(committed("docs/paper-fig7.png"), svgNumbers(dir.resolve("fig7_finger3.svg")), "docs/paper-fig7.png");
            assertEquals(committed("docs/paper-fig8.png"), svgNumbers(dir.resolve("fig8_finger3.svg")), "docs/paper-fig8.png");
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    @Test
    void theMugGraspChartShowsWhatTheGraspCommandComputes() throws Exception {
        Path dir = Files.createTempDirectory("docs-grasp");
        try {
            CliTesting.Run r = CliTesting.run("grasp", TestPaths.root().resolve("scenarios/mug-grasp.json").toString(), "--chart",
                dir.resolve("mug-grasp").toString());
            assertEquals(0, r.code(), r.err());
            assertEquals(committed("docs/grasp/mug-grasp.png"), svgNumbers(dir.resolve("mug-grasp.svg")), "docs/grasp/mug-grasp.png");
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    /** EmbeddedExample's label at t = 2.5 s: time, finger 3's clutch and its contact force. */
    @Test
    void theEmbeddedExampleShowsThePapersStateAt2point5Seconds() throws Exception {
        HandModel m = Simulation.model(Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json")), false);
        while (m.time() < 2.5 - 1e-9) m.step();
        String label = String.format(Locale.ROOT, "t = %.3f s, finger 3 %s, %.1f N", m.time(), m.state(3), m.snapshot().fingers()[2].forceSum());
        assertEquals(committed("docs/embedded.png"), List.of(label));
    }

    @Test
    void theWindowScreenshotShowsItsScenesState() throws Exception {
        checkWindow("docs/gui.png", DOCS.resolve("gui.scenario.json"));
    }

    @Test
    void theBestGraspPictureShowsItsScenesState() throws Exception {
        checkWindow("docs/plan/best-grasp.png", DOCS.resolve("plan/best-grasp.scenario.json"));
    }

    /**
     * The lift in the window (docs/lift/mug-lift-window.png): the time shown and every figure of
     * the Dynamics panel's Free object box against the mug lift replayed without a window to
     * that time — trace.csv's object columns ({@link HandModel#objectNow}), the largest
     * displacement and rotation and the release, slip and drop times, each at the precision shown.
     */
    @Test
    @Tag("slow")   // 5 300 steps of the lift, 1 300 of them free: ./test --all
    void theLiftPictureShowsTheMugsStateAtItsTime() throws Exception {
        String picture = "docs/lift/mug-lift-window.png";
        List<String> lines = committed(picture);
        Matcher t = Pattern.compile("t = ([0-9.]+) s").matcher(only(lines, "state: "));
        assertTrue(t.find(), lines.toString());
        double time = Double.parseDouble(t.group(1));
        HandModel m = Simulation.model(Scenario.load(TestPaths.root().resolve("scenarios/mug-lift.json")), false);
        while (m.running() && m.time() < time - 1e-9) m.step();
        assertShown(t.group(1), m.time(), picture + " time");
        Map<String, Double> model = new LinkedHashMap<>();
        double[] now = m.objectNow();
        for (int c = 0; c < now.length; c++) model.put(org.handsim.trace.Recorder.OBJECT_COLUMNS[c], now[c]);
        model.put("max_displacement_m", m.objectMaxDisplacement());
        model.put("max_rotation_deg", m.objectMaxRotation());
        model.put("released_at_s", m.objectReleasedAt());
        model.put("slipped_at_s", m.objectSlippedAt());
        model.put("dropped_at_s", m.objectDroppedAt());
        int compared = 0;
        for (String l : lines) {
            if (!l.startsWith("object: ") || l.startsWith("object: status=")) continue;
            String[] kv = l.substring("object: ".length()).split("=", 2);
            Double v = model.get(kv[0]);
            assertTrue(v != null, picture + ": " + l);
            if (kv[1].equals("–")) assertTrue(Double.isNaN(v), picture + ": " + l + " but the model has " + v);
            else assertShown(kv[1], v, picture + ": " + l);
            compared++;
        }
        assertEquals(model.size(), compared, "every figure of the Free object box: " + lines);
        assertTrue(m.objectReleased() && only(lines, "object: status=").contains("free since t = 4.7000 s"), lines.toString());
    }

    /**
     * The window's log lines of a screenshot (state, Dynamics table, live grasp) against the
     * same scene replayed without a window to the time shown.
     */
    private static void checkWindow(String picture, Path scenario) throws Exception {
        List<String> lines = committed(picture);
        Matcher t = Pattern.compile("t = ([0-9.]+) s").matcher(only(lines, "state: "));
        assertTrue(t.find(), lines.toString());
        double time = Double.parseDouble(t.group(1));
        Scenario s = Scenario.load(scenario);
        HandModel m = Simulation.model(s, false);
        while (m.running() && m.time() < time - 1e-9) m.step();
        assertShown(t.group(1), m.time(), picture + " time");
        int fingers = 0;
        for (String l : lines) {
            if (!l.startsWith("dynamics: ")) continue;
            Map<String, String> f = fields(l);
            int k = Integer.parseInt(f.get("finger"));
            fingers++;
            String where = picture + ", finger " + k + ": " + l;
            assertEquals(f.get("clutch"), m.state(k).name(), where);
            assertEquals(Integer.parseInt(f.get("contacts")), m.contacts(k).size(), where);
            assertShown(f.get("force_N"), m.snapshot().fingers()[k - 1].forceSum(), where);
            double[] tau = m.torques(k);
            for (int j = 1; j <= 3; j++) {
                if (f.containsKey("tau" + j + "_Nm")) assertShown(f.get("tau" + j + "_Nm"), tau[j - 1], where + " (tau" + j + ")");
            }
            String b = f.get("breakaway_s");
            if (b != null && b.matches("[0-9.]+")) assertShown(b, m.breakawayTime(k), where);
            else assertTrue(Double.isNaN(m.breakawayTime(k)), where);
        }
        assertEquals(3, fingers, "the Dynamics table's three fingers: " + lines);
        String g = only(lines, "grasp: ");
        Map<String, String> gf = fields(g);
        GraspAssessment ga = GraspAssessment.of(m.graspInput(), s.friction(), s.coneEdges());
        assertEquals(gf.get("force_closure"), ga.quality().forceClosure() ? "yes" : "no", g);
        assertShown(gf.get("epsilon"), ga.quality().epsilon(), g);
        assertShown(gf.get("volume"), ga.quality().volume(), g);
        assertShown(gf.get("hold_min"), ga.holdMinN(), g);
        Matcher c = Pattern.compile("(\\d+) contacts?").matcher(g);
        assertTrue(c.find(), g);
        int contacts = 0;
        for (int k = 1; k <= 3; k++) contacts += m.contacts(k).size();
        assertEquals(Integer.parseInt(c.group(1)), contacts, g);
        Matcher st = Pattern.compile("finger (\\d) ([A-Z]+)").matcher(only(lines, "state: "));
        int said = 0;
        while (st.find()) {
            assertEquals(st.group(2), m.state(Integer.parseInt(st.group(1))).name(), only(lines, "state: "));
            said++;
        }
        assertEquals(3, said, only(lines, "state: "));
    }

    private static String only(List<String> lines, String prefix) {
        List<String> hit = new ArrayList<>();
        for (String l : lines) if (l.startsWith(prefix)) hit.add(l);
        assertEquals(1, hit.size(), "one '" + prefix + "' line in " + lines);
        return hit.get(0);
    }

    /** The {@code key=value} fields of a log line. */
    private static Map<String, String> fields(String line) {
        Map<String, String> f = new LinkedHashMap<>();
        Matcher m = Pattern.compile("([A-Za-z_0-9]+)=(\\S+)").matcher(line);
        while (m.find()) f.put(m.group(1), m.group(2));
        return f;
    }

    /** {@code value} written with as many decimals as {@code shown} has is {@code shown}. */
    static void assertShown(String shown, double value, String where) {
        assertTrue(shown != null, "not shown: " + where);
        int dot = shown.indexOf('.');
        int decimals = dot < 0 ? 0 : shown.length() - dot - 1;
        String mine = String.format(Locale.ROOT, "%." + decimals + "f", value);
        if (mine.matches("-0(\\.0*)?")) mine = mine.substring(1);
        assertEquals(shown, mine, where);
    }

    /**
     * The plan's two charts: 500 trials (about 15 s on two cores), so only in ./test --all.
     * Their numbers: the plan's summary line (without its timing), its force-closure count and
     * best ε, and every number the two SVGs show.
     */
    @Test
    @Tag("slow")
    @SuppressWarnings("unchecked")
    void thePlanChartsShowWhatThePlanComputes() throws Exception {
        Path dir = Files.createTempDirectory("docs-plan");
        try {
            CliTesting.Run r = CliTesting.run("plan", TestPaths.root().resolve("vrml/objects/mug.wrl").toString(), "--trials", "500", "--seed", "1",
                "--out", dir.toString());
            assertEquals(0, r.code(), r.err());
            Map<String, Object> summary = (Map<String, Object>) Json.parse("plan.json", Files.readString(dir.resolve("plan.json")));
            List<String> said = List.of(r.out().split("\n")[0].replaceFirst(";\\s*[0-9.]+ s wall.*$", ""),
                String.format(Locale.ROOT, "force_closure %d, best_epsilon %.4f", ((Number) summary.get("force_closure")).intValue(),
                    ((Number) summary.get("best_epsilon")).doubleValue()));
            for (String name : new String[] {"epsilon-histogram", "epsilon-directions"}) {
                List<String> now = new ArrayList<>(said);
                now.addAll(svgNumbers(dir.resolve(name + ".svg")));
                assertEquals(committed("docs/plan/" + name + ".png"), now, name);
            }
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
