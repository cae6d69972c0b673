package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.cli.ChildJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The 3D view under a stream of poses with contacts, normals and friction cones shown (a child
 * JVM on the current display, {@link SceneViewStress}): no exception reaches the top of a
 * Java3D thread, and none of the view's geometry arrays is ever written while it is live (no
 * data-changed message was sent for any: {@link DoubleBufferedLines} says why such writes let
 * a Java3D thread die). The second check does not depend on the race's timing.
 */
@Tag("slow")   // a child JVM with a window: ./test --all
class SceneViewLinesTest {
    static final int POSES = 4000;

    @Test
    void posesWithContactsAndConesNeverWriteLiveGeometry() throws Exception {
        GuiWindowTest.needDisplay();
        Path dir = Files.createTempDirectory("handsim-scene-lines");
        try {
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx1g", "-Dhandsim.home=" + TestPaths.root(), "-cp", System.getProperty("java.class.path"),
                SceneViewStress.class.getName(), String.valueOf(POSES), "200000"));
            ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).directory(dir.toFile());
            pb.environment().put("DISPLAY", GuiWindowTest.display());
            String xauth = GuiWindowTest.xauthority();
            if (xauth != null) pb.environment().put("XAUTHORITY", xauth);
            Path log = dir.resolve("stress.log");
            pb.redirectOutput(log.toFile());
            Process p = pb.start();
            if (!p.waitFor(GuiWindowTest.TIMEOUT_MIN, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                fail("the view's stress run did not finish; log:\n" + Files.readString(log));
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            System.out.println(out);
            assertTrue(out.contains("stress: " + POSES + " poses shown, 0 exceptions on Java3D threads, 0 of 4 geometry arrays written while live"), out);
            assertEquals(0, p.exitValue(), out);
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
