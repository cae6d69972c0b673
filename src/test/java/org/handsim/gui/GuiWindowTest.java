package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.handsim.TestPaths;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The window end to end, in a separate JVM on the current display —
 * the test JVM itself runs headless with Java3D's no-op renderer. The child process opens
 * {@code handsim gui} on the paper's experiment and runs a script that presses each of the
 * four buttons, imports the cube (placed clear of the hand), opens the paper's scenario again
 * (the cube where the paper has it), runs the experiment with dynamics (in real time to
 * t = 2.5 s, after the breakaway, where it logs the Dynamics panel and takes a screenshot; then
 * as fast as possible to the end), and takes a second screenshot with the hand, object and
 * contacts hidden (the empty scene). Checked:
 * <ul>
 *   <li>exit code 0 and no exception on the event dispatch thread (the program counts them and
 *       fails; the log is searched too);</li>
 *   <li>the 3D view region shows the hand: enough pixels differ from the background colour,
 *       and from the empty scene's screenshot;</li>
 *   <li>the chart region shows the traces: pixels in finger 3's trace colour;</li>
 *   <li>the breakaway appears in the Dynamics panel: at t = 2.5 s finger 3 is BROKEN or
 *       STALLED and its row has the breakaway time; the events list names the breakaway.</li>
 * </ul>
 * Without a display the test is skipped with the reason printed — or fails, when the system
 * property {@code handsim.requireDisplay} is {@code true} or the environment variable
 * {@code HANDSIM_REQUIRE_DISPLAY} is {@code 1} / {@code true} (what {@code ./test} sets when it
 * runs the suite under {@code xvfb-run}).
 *
 * <p>The display comes from the system properties {@code handsim.display} and
 * {@code handsim.xauthority} (what {@code ./test} passes for its run) or else the environment
 * ({@code DISPLAY}, {@code XAUTHORITY}), which does not always reach the test JVM as it is now:
 * Gradle 4.4's daemon on JDK 17 keeps the environment it was started with, which may name an
 * earlier {@code xvfb-run}'s display. Either of these runs the test under a virtual display:
 * <pre>
 * HANDSIM_REQUIRE_DISPLAY=1 xvfb-run -a -s '-screen 0 1280x1024x24' gradle --no-daemon test
 * xvfb-run -a -s '-screen 0 1280x1024x24' sh -c 'gradle test -Dhandsim.requireDisplay=true \
 *     -Dhandsim.display="$DISPLAY" -Dhandsim.xauthority="$XAUTHORITY"'   # build.gradle forwards them
 * </pre>
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class GuiWindowTest {
    /** Share of the 3D view's pixels that must show something other than the background. */
    static final double MIN_SCENE_FRACTION = 0.02;
    static final double MAX_EMPTY_FRACTION = 0.002;
    static final int MIN_TRACE_PIXELS = 800;
    static final long TIMEOUT_MIN = 10;

    static boolean requireDisplay() {
        String env = System.getenv("HANDSIM_REQUIRE_DISPLAY");
        return Boolean.getBoolean("handsim.requireDisplay") || "1".equals(env) || "true".equalsIgnoreCase(env);
    }

    /**
     * The X display: the system property {@code handsim.display}, else the environment's DISPLAY.
     * The property first: Gradle 4.4's daemon on JDK 17 keeps the environment it started with,
     * so under a reused daemon the environment names the display (and the cookie file) of an
     * earlier, finished {@code xvfb-run} — "Authorization required" — while {@code ./test}
     * passes this run's as properties (see the class comment).
     */
    static String display() {
        String d = System.getProperty("handsim.display");
        if (d == null || d.isEmpty()) d = System.getenv("DISPLAY");
        return d == null || d.isEmpty() ? null : d;
    }

    /** The X authority file of {@link #display()}: the property {@code handsim.xauthority}, else XAUTHORITY. */
    static String xauthority() {
        String x = System.getProperty("handsim.xauthority");
        if (x == null || x.isEmpty()) x = System.getenv("XAUTHORITY");
        return x == null || x.isEmpty() ? null : x;
    }

    static void needDisplay() {
        if (display() != null) return;
        String why = "no DISPLAY: the window test needs a display; run the tests under a virtual display, e.g. "
            + "xvfb-run -a -s '-screen 0 1280x1024x24' gradle test (./test does this)";
        if (requireDisplay()) fail(why + " [handsim.requireDisplay is set, so this is a failure]");
        System.out.println("GuiWindowTest skipped: " + why);
        Assumptions.assumeTrue(false, why);
    }

    /** Output and exit code of {@code handsim gui ARGS} in a child JVM on the current display. */
    record Child(int code, String log) {}

    static Child runGui(Path dir, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("org.handsim.cli.HandSim", "gui"));
        cmd.addAll(List.of(args));
        return runOnDisplay(dir, TIMEOUT_MIN * 60, "handsim gui", cmd.toArray(new String[0]));
    }

    /**
     * Runs {@code java MAIN ARGS} (the tests' class path, {@code handsim.home} the checkout) in
     * {@code dir} on the current display; fails, naming {@code what} and showing the output and
     * the child's threads ({@link #threadDump}), when it has not ended within {@code limitSeconds}.
     */
    static Child runOnDisplay(Path dir, long limitSeconds, String what, String... mainAndArgs) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xss16m");
        cmd.add("-Xmx1g");
        cmd.add("-Dhandsim.home=" + TestPaths.root());
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.addAll(List.of(mainAndArgs));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).directory(dir.toFile());
        pb.environment().put("DISPLAY", display());
        String xauth = xauthority();
        if (xauth != null) pb.environment().put("XAUTHORITY", xauth);
        Path logFile = dir.resolve("gui.log");
        pb.redirectOutput(logFile.toFile());
        Process p = pb.start();
        if (!p.waitFor(limitSeconds, TimeUnit.SECONDS)) {
            String threads = threadDump(p.pid(), dir);
            p.destroyForcibly();
            String limit = limitSeconds % 60 == 0 ? limitSeconds / 60 + " minutes" : limitSeconds + " s";
            fail(what + " did not finish within " + limit + "; log:\n" + Files.readString(logFile) + "\nits threads then:\n" + threads);
        }
        String log = Files.readString(logFile, StandardCharsets.UTF_8);
        System.out.println("---- " + what + " log ----\n" + log + "-------------------------");
        return new Child(p.exitValue(), log);
    }

    /** The JDK's thread dump of a JVM that did not end (where it hangs), or why there is none; 30 s at most. */
    static String threadDump(long pid, Path dir) {
        try {
            Path out = dir.resolve("threads.txt");
            Process j = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "jstack").toString(), Long.toString(pid))
                .redirectErrorStream(true).redirectOutput(out.toFile()).start();
            if (!j.waitFor(30, TimeUnit.SECONDS)) {
                j.destroyForcibly();
                return "(jstack did not answer within 30 s)";
            }
            return Files.readString(out, StandardCharsets.UTF_8);
        } catch (Exception e) {
            return "(no thread dump: " + e + ")";
        }
    }

    @Test
    void theWindowRunsThePapersExperiment() throws Exception {
        Path dir = Files.createTempDirectory("handsim-gui-test");
        needDisplay();
        Path cube = TestPaths.root().resolve("vrml/objects/cube.wrl");
        Path full = dir.resolve("window.png"), empty = dir.resolve("empty.png");
        Path script = dir.resolve("paper.txt");
        Files.writeString(script, String.join("\n",
            "press Kinematics",
            "set fk3.counts 5000",
            "set ik.z 0.5",
            "press Solve",
            "assert-status UNREACHABLE",
            "press Path Planning",
            "press Dynamics",
            "press Objects",
            "import " + cube,
            "assert-contacts 0",
            "open " + TestPaths.root().resolve("scenarios/paper-breakaway.json"),
            "press Dynamics",
            "speed 1",
            "press Run with dynamics",
            "play 2.5",
            "assert-state 3 BROKEN|STALLED",
            "log dynamics",
            "screenshot " + full,
            "speed max",
            "play end",
            "log dynamics",
            "log events",
            "log state",
            "show hand off",
            "show object off",
            "show contacts off",
            "screenshot " + empty,
            ""));
        Child c = runGui(dir, "--script", script.toString());
        System.out.println("screenshots and log in " + dir);

        // no exception on the event dispatch thread (or anywhere)
        assertEquals(0, c.code(), "exit code; log:\n" + c.log());
        assertTrue(c.log().contains("gui: done, 0 uncaught exceptions"), c.log());
        assertFalse(c.log().contains("uncaught exception on thread"), c.log());
        assertFalse(c.log().contains("\tat org.handsim."), "a stack trace from HandSim code:\n" + c.log());
        assertTrue(c.log().contains("gui: status: inverse kinematics: target UNREACHABLE"), "unreachable IK target in the status bar:\n" + c.log());

        // the breakaway in the Dynamics panel
        Matcher row = Pattern.compile("gui: dynamics: finger=3 .*clutch=(\\w+).*breakaway_s=([0-9.]+)").matcher(c.log());
        assertTrue(row.find(), "finger 3's Dynamics row with a breakaway time:\n" + c.log());
        assertTrue(row.group(1).equals("BROKEN") || row.group(1).equals("STALLED"), row.group());
        double tb = Double.parseDouble(row.group(2));
        assertTrue(tb > 0, "breakaway time " + tb);
        assertTrue(c.log().contains("gui: event: t = " + row.group(2) + " s  finger 3: BLOCKED → BROKEN, BREAKAWAY"),
            "the events list names the breakaway, at its time:\n" + c.log());

        // the screenshots
        Rectangle[] regions = regions(c.log(), full);
        BufferedImage a = ImageIO.read(full.toFile()), b = ImageIO.read(empty.toFile());
        Rectangle view = regions[0], charts = regions[1];
        int viewPixels = view.width * view.height;
        assertTrue(viewPixels > 100 * 100, "3D view region too small: " + view);
        double scene = fraction(a, view, (x, y) -> differs(a.getRGB(x, y), SceneView.BACKGROUND_RGB, 30));
        double emptyScene = fraction(b, view, (x, y) -> differs(b.getRGB(x, y), SceneView.BACKGROUND_RGB, 30));
        double changed = fraction(a, view, (x, y) -> differs(a.getRGB(x, y), b.getRGB(x, y), 30));
        System.out.printf("3D view %s: %.1f%% not background with the hand, %.2f%% without, %.1f%% changed%n",
            view, 100 * scene, 100 * emptyScene, 100 * changed);
        assertTrue(scene >= MIN_SCENE_FRACTION, "the 3D view shows too little: " + scene);
        assertTrue(emptyScene <= MAX_EMPTY_FRACTION, "the empty scene is not empty (or the background colour is wrong): " + emptyScene);
        assertTrue(changed >= MIN_SCENE_FRACTION, "hiding the hand changed too little: " + changed);

        int red = 0;
        for (int y = charts.y; y < charts.y + charts.height; y++) {
            for (int x = charts.x; x < charts.x + charts.width; x++) {
                if (!differs(a.getRGB(x, y), TraceCharts.FINGER_RGB[2], 60)) red++;
            }
        }
        System.out.println("charts " + charts + ": " + red + " pixels in finger 3's colour");
        assertTrue(red >= MIN_TRACE_PIXELS, "the charts show no traces of finger 3 (" + red + " pixels)");
        VrmlTesting.deleteTree(dir);   // kept when a check fails, for a look at the screenshots
    }

    @Test
    void aVrmlFileThatFailsToLoadIsReportedInTheWindow() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-gui-test");
        Path broken = dir.resolve("broken.wrl");
        Files.writeString(broken, "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 1 0 0] }"
            + " coordIndex [0, 1, 9, -1] } }\n");
        Path script = dir.resolve("broken.txt");
        Files.writeString(script, "press Objects\nimport " + broken + "\n");
        Child c = runGui(dir, "--script", script.toString());
        assertEquals(1, c.code(), "the failed import fails the script; log:\n" + c.log());
        // one line names both places: the script's line, then the loader's FILE:LINE:COL
        assertTrue(c.log().contains("broken.txt:2: import " + broken + ": " + broken + ":2:95: coordIndex"),
            "the script line and the loader's FILE:LINE:COL:\n" + c.log());
        assertEquals(1, c.log().split("coordIndex\\[2\\]", -1).length - 1, "the error is printed once:\n" + c.log());
        assertTrue(c.log().contains("gui: failed (exit code 1), 0 uncaught exceptions"), c.log());
        VrmlTesting.deleteTree(dir);
    }

    /** The view, chart and status bar regions the program printed for a screenshot. */
    static Rectangle[] regions(String log, Path shot) {
        Matcher m = Pattern.compile("gui: screenshot " + Pattern.quote(shot.toString())
            + " (\\d+)x(\\d+) view=(\\d+),(\\d+),(\\d+),(\\d+) charts=(\\d+),(\\d+),(\\d+),(\\d+) status=(\\d+),(\\d+),(\\d+),(\\d+)").matcher(log);
        assertTrue(m.find(), "no screenshot line for " + shot + " in:\n" + log);
        int[] v = new int[14];
        for (int i = 0; i < 14; i++) v[i] = Integer.parseInt(m.group(i + 1));
        assertTrue(new File(shot.toString()).length() > 0);
        return new Rectangle[] {new Rectangle(v[2], v[3], v[4], v[5]), new Rectangle(v[6], v[7], v[8], v[9]), new Rectangle(v[10], v[11], v[12], v[13])};
    }

    interface PixelTest { boolean at(int x, int y); }

    static double fraction(BufferedImage img, Rectangle r, PixelTest t) {
        long n = 0, hit = 0;
        for (int y = r.y; y < Math.min(img.getHeight(), r.y + r.height); y++) {
            for (int x = r.x; x < Math.min(img.getWidth(), r.x + r.width); x++) {
                n++;
                if (t.at(x, y)) hit++;
            }
        }
        return n == 0 ? 0 : hit / (double) n;
    }

    /** True if two colours differ by more than {@code tolerance} summed over R, G, B. */
    static boolean differs(int rgb1, int rgb2, int tolerance) {
        int d = Math.abs(((rgb1 >> 16) & 255) - ((rgb2 >> 16) & 255)) + Math.abs(((rgb1 >> 8) & 255) - ((rgb2 >> 8) & 255))
            + Math.abs((rgb1 & 255) - (rgb2 & 255));
        return d > tolerance;
    }
}
