package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
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
            GuiWindowTest.Child c = GuiWindowTest.runOnDisplay(dir, GuiWindowTest.TIMEOUT_MIN * 60, "the view's stress run",
                SceneViewStress.class.getName(), String.valueOf(POSES), "200000");
            String out = c.log();
            assertTrue(out.contains("stress: " + POSES + " poses shown, 0 exceptions on Java3D threads, 0 of 4 geometry arrays written while live"), out);
            assertEquals(0, c.code(), out);
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
