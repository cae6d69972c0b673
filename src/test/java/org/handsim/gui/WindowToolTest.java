package org.handsim.gui;

import static org.handsim.gui.GuiWindowTest.differs;
import static org.handsim.gui.GuiWindowTest.fraction;
import static org.handsim.gui.GuiWindowTest.needDisplay;
import static org.handsim.gui.GuiWindowTest.regions;
import static org.handsim.gui.GuiWindowTest.runGui;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.OutputStream;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.mesh.ObjWriter;
import org.handsim.mesh.StlWriter;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.SceneMeshes;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The window as a daily tool, end to end in a child JVM on the current
 * display (see {@link GuiWindowTest} for how the display reaches the tests):
 * <ul>
 *   <li>an STL and an OBJ model that would start inside the hand are placed clear of it (no
 *       contacts at t = 0) and framed (the object's pixels in the view, away from its edges);</li>
 *   <li>a scenario saved from the window runs in {@code handsim run} to the window's trace, to
 *       the last digit, and the window's exported trace equals {@code handsim run}'s trace.csv;</li>
 *   <li>at 1024 × 768 the charts and the status bar are on screen (pixels);</li>
 *   <li>the shortcuts act (Space, →, R through real key events; menu items); the Kinematics
 *       preview shows the contacts a pose would have;</li>
 *   <li>charts span the run, series hide from the View menu; camera actions; expected errors
 *       and field names in scripts.</li>
 * </ul>
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class WindowToolTest {
    /** The mug in millimetres, as a binary STL (GraspIt!'s unit: "auto" must find it). */
    static Path mugStl(Path dir) throws Exception {
        TriangleMesh mug = SceneMeshes.mesh(TestPaths.root().resolve("vrml/objects/mug.wrl"), 24, 1.0);
        Path f = dir.resolve("mug_mm.stl");
        try (OutputStream o = Files.newOutputStream(f)) {
            StlWriter.writeBinary(o, mug, 1000);
        }
        return f;
    }

    /** A cylinder 0.11 m across as OBJ in metres: wider than the gap between the fingers. */
    static Path wideObj(Path dir) throws Exception {
        TriangleMesh cyl = SceneMeshes.mesh(TestPaths.root().resolve("vrml/objects/cylinder.wrl"), 24, 2.2);
        Path f = dir.resolve("wide.obj");
        StringWriter w = new StringWriter();
        ObjWriter.write(w, List.of(cyl));
        Files.writeString(f, w.toString());
        return f;
    }

    /** Pixels of the objects' default colour (red-orange, lit): red well above green and blue. */
    static boolean objectRed(int rgb) {
        int r = (rgb >> 16) & 255, g = (rgb >> 8) & 255, b = rgb & 255;
        return r > g + 60 && r > b + 60;
    }

    /** The bounding box of the object's pixels in the view region, or null. */
    static Rectangle objectBox(BufferedImage img, Rectangle view) {
        int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = -1, y1 = -1;
        for (int y = view.y; y < view.y + view.height; y++) {
            for (int x = view.x; x < view.x + view.width; x++) {
                if (objectRed(img.getRGB(x, y))) {
                    x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
                }
            }
        }
        return x1 < 0 ? null : new Rectangle(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
    }

    @Test
    void objAndStlThatWouldStartInsideTheHandArePlacedClearAndFramed() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-window-test");
        Path stl = mugStl(dir), obj = wideObj(dir);
        Path a = dir.resolve("stl.png"), b = dir.resolve("obj.png"), none = dir.resolve("none.png");
        Path dark = dir.resolve("black.png"), darkNone = dir.resolve("black-hidden.png");
        Path black = dir.resolve("black.wrl");
        Files.writeString(black, "#VRML V2.0 utf8\nShape { appearance Appearance { material Material { diffuseColor 0 0 0 } }\n"
            + " geometry Box { size 0.08 0.08 0.08 } }\n");
        Path script = dir.resolve("import.txt");
        Files.writeString(script, String.join("\n",
            "# fingers part closed: an object where the cube was would start inside them",
            "press Path Planning",
            "press path.M1.add",
            "set path.M1.1.to 6000",
            "press path.M2.add",
            "set path.M2.1.to 6000",
            "set path.M3.1.to 6000",
            "press path.M3.3.remove",
            "press path.M3.2.remove",
            "speed max",
            "press path.run",
            "play end",
            "press Kinematics",
            "press Use as start pose",
            "press Objects",
            "import " + stl,
            "assert-contacts 0",
            "assert-status units mm by its size",
            "log events",
            "screenshot " + a,
            "import " + obj,
            "assert-contacts 0",
            "screenshot " + b,
            "show object off",
            "screenshot " + none,
            "show object on",
            "import " + black,
            "assert-contacts 0",
            "screenshot " + dark,
            "show object off",
            "screenshot " + darkNone,
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        assertTrue(c.log().contains("gui: contacts: 0"), c.log());
        assertFalse(c.log().contains("starts in contact"), "no start-in-contact warning:\n" + c.log());
        assertTrue(c.log().contains("units mm by its size"), "the STL's millimetres found:\n" + c.log());
        for (Path shot : List.of(a, b)) {
            Rectangle view = regions(c.log(), shot)[0];
            BufferedImage img = ImageIO.read(shot.toFile());
            Rectangle box = objectBox(img, view);
            double share = fraction(img, view, (x, y) -> objectRed(img.getRGB(x, y)));
            System.out.printf("%s: object pixels %.1f%% of the view, box %s in %s%n", shot.getFileName(), 100 * share, box, view);
            assertTrue(share > 0.01, "the object is in the view: " + share);
            // framed: the whole object inside the view, not cut by its edges
            assertTrue(box.x > view.x + 2 && box.y > view.y + 2 && box.x + box.width < view.x + view.width - 2
                && box.y + box.height < view.y + view.height - 2, "the object is framed: " + box + " in " + view);
        }
        BufferedImage n = ImageIO.read(none.toFile());
        assertTrue(fraction(n, regions(c.log(), none)[0], (x, y) -> objectRed(n.getRGB(x, y))) < 0.001, "hidden, the red pixels go");
        // a black model shows against the background: where it is, the view differs by more than 200
        // (of 765) from the view without it; on the old background (0x2A313B, 150 from black) it did not
        BufferedImage k = ImageIO.read(dark.toFile()), kn = ImageIO.read(darkNone.toFile());
        Rectangle view = regions(c.log(), dark)[0];
        double blackShows = fraction(k, view, (x, y) -> differs(k.getRGB(x, y), kn.getRGB(x, y), 200));
        System.out.printf("black model: %.1f%% of the view differ by more than 200 from the view without it%n", 100 * blackShows);
        assertTrue(blackShows > 0.01, "a black model is visible: " + blackShows);
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void aSavedScenarioRunsToTheWindowsTraceAndTheExportIsRunsTraceCsv() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-window-test").toRealPath();
        Path stl = mugStl(dir);
        Path exported = dir.resolve("window-trace.csv"), saved = dir.resolve("saved/window.json");
        Path script = dir.resolve("save.txt");
        // finger 2's fingertip to (0.03, 0.05, 0.19) m in the palm frame, written in its base frame {k0} as a scenario holds it
        double[] k0 = org.handsim.kinematics.FingerKinematics.of(2).baseInPalm().inverse().apply(new double[] {0.03, 0.05, 0.19});
        String target = org.handsim.text.Decimal.format(k0[0]) + "," + org.handsim.text.Decimal.format(k0[1]) + ","
            + org.handsim.text.Decimal.format(k0[2]);
        Files.writeString(script, String.join("\n",
            "press Objects",
            "import " + stl,
            "press Dynamics",
            "set dyn.gravity -z",
            "press Apply gravity",
            "press Path Planning",
            "press path.M1.add",
            "set path.M1.1.type quintic",
            "set path.M1.1.to 12345.5",
            "set path.M1.1.duration 1.7",
            "press path.M2.add",
            "set path.M2.1.type line",
            "set path.M2.1.target " + target,
            "set path.M2.1.duration 1.1",
            "press path.M4.add",
            "set path.M4.1.to 600",
            "speed max",
            "press path.run",
            "play end",
            "export-traces " + exported,
            "save-scenario " + saved,
            "log charts",
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        CliTesting.Run r = CliTesting.run("run", saved.toString(), "--out", dir.resolve("out").toString(), "--no-charts");
        assertEquals(0, r.code(), r.err());
        String run = Files.readString(dir.resolve("out/trace.csv")), window = Files.readString(exported);
        assertTrue(run.lines().count() > 1000, "a real run: " + run.lines().count() + " rows");
        assertEquals(run.lines().findFirst().get(), window.lines().findFirst().get(), "the trace.csv header");
        assertEquals(run, window, "handsim run on the saved scenario reproduces the window's trace to the last digit");
        // the charts span the run's duration
        Matcher m = Pattern.compile("gui: charts: time axis 0\\.000\\.\\.([0-9.]+) s").matcher(c.log());
        assertTrue(m.find(), c.log());
        String last = run.lines().reduce((x, y) -> y).get();
        double end = Double.parseDouble(last.substring(0, last.indexOf(',')));
        assertEquals(end, Double.parseDouble(m.group(1)), 0.0015, "the time axis ends at the run's end");
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void at1024x768TheChartsAndTheStatusBarAreOnScreen() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-window-test");
        Path shot = dir.resolve("small.png");
        Path script = dir.resolve("small.txt");
        Files.writeString(script, String.join("\n",
            "resize 1024 768",
            "speed max",
            "play end",
            "assert-runstate finished",
            "screenshot " + shot,
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        assertTrue(c.log().contains("gui: window 1024x768"), c.log());
        Rectangle[] r = regions(c.log(), shot);
        BufferedImage img = ImageIO.read(shot.toFile());
        assertEquals(1024, img.getWidth());
        assertEquals(768, img.getHeight());
        Rectangle view = r[0], charts = r[1], status = r[2];
        for (Rectangle x : r) assertTrue(new Rectangle(0, 0, 1024, 768).contains(x), x + " inside the window");
        assertTrue(view.width >= 250 && view.height >= 300, "the 3D view " + view);
        assertTrue(charts.width >= 250 && charts.height >= 300, "the charts " + charts);
        int red = 0;
        for (int y = charts.y; y < charts.y + charts.height; y++) {
            for (int x = charts.x; x < charts.x + charts.width; x++) if (!differs(img.getRGB(x, y), TraceCharts.FINGER_RGB[2], 60)) red++;
        }
        assertTrue(red >= GuiWindowTest.MIN_TRACE_PIXELS, "finger 3's traces in the charts: " + red);
        double text = fraction(img, status, (x, y) -> {
            int v = img.getRGB(x, y);
            return ((v >> 16) & 255) + ((v >> 8) & 255) + (v & 255) < 3 * 110;
        });
        assertTrue(text > 0.01, "the status bar shows text: " + text);
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void shortcutsMenusAndCameraAct() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-window-test");
        Path shown = dir.resolve("three.png"), hidden = dir.resolve("hidden.png");
        Path script = dir.resolve("keys.txt");
        Files.writeString(script, String.join("\n",
            "# the Kinematics preview collides as the simulation does: finger 3 into the paper's cube",
            "press Kinematics",
            "set fk3.counts 6500",
            "assert-contacts 2",
            "assert-status finger 3 touches the object (2 contacts)",
            "set fk3.counts 3000",
            "assert-contacts 0",
            "speed 0.25",
            "key SPACE",
            "assert-runstate running",
            "wait 400",
            "key SPACE",
            "assert-runstate paused",
            "key R",
            "assert-runstate reset",
            "assert-time 0",
            "key RIGHT",
            "assert-time 0.001",
            "key RIGHT",
            "assert-time 0.002",
            "menu run.reset",
            "assert-time 0",
            "menu run.toggle",
            "assert-runstate running",
            "wait 200",   // a scripted model moves only while the script plays or waits
            "menu run.toggle",
            "assert-runstate paused",
            "speed max",
            "play end",
            "assert-runstate finished",
            "screenshot " + shown,
            "menu view.series.finger3",
            "log charts",
            "screenshot " + hidden,
            "camera top",
            "camera front",
            "key H",
            "key F",
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        assertTrue(c.log().contains("gui: charts: time axis 0.000..8.947 s"), "the paper's run ends at 8.947 s, as handsim run says:\n" + c.log());
        assertTrue(c.log().contains("fingers shown 1,2\n"), c.log());
        // camera: from the top the eye is above the palm (z), from the front in front of it (x); the palm frame is the world here
        Matcher top = Pattern.compile("gui: camera top: eye at \\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\\) m").matcher(c.log());
        Matcher front = Pattern.compile("gui: camera front: eye at \\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\\) m").matcher(c.log());
        assertTrue(top.find() && front.find(), c.log());
        assertTrue(Double.parseDouble(top.group(3)) > 0.4 && Math.abs(Double.parseDouble(top.group(1))) < 0.05, top.group());
        assertTrue(Double.parseDouble(front.group(1)) > 0.4 && Math.abs(Double.parseDouble(front.group(2))) < 0.05, front.group());
        // hiding finger 3's series takes its colour out of the charts
        Rectangle charts = regions(c.log(), shown)[1];
        BufferedImage a = ImageIO.read(shown.toFile()), b = ImageIO.read(hidden.toFile());
        double before = fraction(a, charts, (x, y) -> !differs(a.getRGB(x, y), TraceCharts.FINGER_RGB[2], 60));
        double after = fraction(b, charts, (x, y) -> !differs(b.getRGB(x, y), TraceCharts.FINGER_RGB[2], 60));
        System.out.printf("finger 3's colour in the charts: %.3f%% shown, %.3f%% hidden%n", 100 * before, 100 * after);
        assertTrue(before > 0.005 && after < 0.1 * before, before + " -> " + after);
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void scriptsExpectErrorsAndNameTheFields() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-window-test");
        Path bad = dir.resolve("truncated.stl");
        byte[] truncated = new byte[104];   // the header announces 1 triangle (50 bytes): 20 of them are there
        java.nio.ByteBuffer.wrap(truncated).order(java.nio.ByteOrder.LITTLE_ENDIAN).putInt(80, 1);
        Files.write(bad, truncated);
        Path shot = dir.resolve("error.png");
        Path script = dir.resolve("errors.txt");
        Files.writeString(script, String.join("\n",
            "press Kinematics",
            "expect-error no field 'fk9.counts' (fields on screen: speed, fk1.slider, fk1.counts",
            "set fk9.counts 100",
            "press Objects",
            "expect-error truncated.stl: byte 104: the file ends inside triangle 1 of the 1",
            "import " + bad,
            "assert-status cannot load",
            "screenshot " + shot,
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        assertTrue(c.log().contains("gui: expected error: no field 'fk9.counts' (fields on screen: speed, fk1.slider, fk1.counts, fk1.theta2"), c.log());
        assertTrue(c.log().contains("gui: expected error: " + bad + ": byte 104: the file ends inside triangle 1 of the 1"), c.log());
        assertTrue(c.log().contains("gui: status: cannot load " + bad), c.log());
        assertTrue(Files.size(shot) > 0);

        // an action expected to fail that works fails the script
        Files.writeString(script, "expect-error nothing\npress Kinematics\n");
        c = runGui(dir, "--script", script.toString());
        assertEquals(1, c.code(), c.log());
        assertTrue(c.log().contains("errors.txt:2: press Kinematics: expected an error containing 'nothing', but the action succeeded"), c.log());
        VrmlTesting.deleteTree(dir);
    }
}
