package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.handsim.TestPaths;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The README's embedding example ({@link EmbeddedExample}) in a child JVM on the current
 * display: another program's frame holds {@link HandSimPanel}, its step listener keeps a label
 * up to date, and the view shows the hand. Also checks the program leaves without JOGL's
 * X11Util lines.
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class EmbeddedExampleTest {
    @Test
    void anotherSwingProgramEmbedsTheSimulator() throws Exception {
        GuiWindowTest.needDisplay();
        Path dir = Files.createTempDirectory("handsim-embedded");
        Path shot = dir.resolve("embedded.png");
        ProcessBuilder pb = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss16m",
            "-Dhandsim.home=" + TestPaths.root(), "-cp", System.getProperty("java.class.path"), EmbeddedExample.class.getName(),
            TestPaths.root().resolve("scenarios/paper-breakaway.json").toString(), "--screenshot", shot.toString());
        pb.environment().put("DISPLAY", GuiWindowTest.display());
        String xauth = GuiWindowTest.xauthority();
        if (xauth != null) pb.environment().put("XAUTHORITY", xauth);
        Path log = dir.resolve("log.txt");
        pb.redirectErrorStream(true).redirectOutput(log.toFile());
        Process p = pb.start();
        if (!p.waitFor(5, TimeUnit.MINUTES)) {
            p.destroyForcibly();
            fail("the example did not finish: " + Files.readString(log));
        }
        String out = Files.readString(log);
        System.out.println(out);
        assertEquals(0, p.exitValue(), out);
        // the step listener saw the model at 2.5 s, after finger 3's breakaway, with contact force
        assertTrue(out.matches("(?s).*embedded: t = 2\\.500 s, finger 3 (BROKEN|STALLED), [0-9.]+ N.*"), out);
        assertFalse(out.contains("X11Util"), "no X11Util lines at exit:\n" + out);
        BufferedImage img = ImageIO.read(shot.toFile());
        double scene = GuiWindowTest.fraction(img, new Rectangle(0, 0, img.getWidth(), img.getHeight()),
            (x, y) -> GuiWindowTest.differs(img.getRGB(x, y), SceneView.BACKGROUND_RGB, 30));
        assertTrue(scene > 0.05, "the frame shows the hand and the buttons: " + scene);
        List<String> readme = Files.readAllLines(TestPaths.root().resolve("README.md"));
        assertTrue(readme.stream().anyMatch(l -> l.contains("HandSimPanel sim = HandSimPanel.create(")),
            "the README shows the example's code");
        VrmlTesting.deleteTree(dir);
    }
}
