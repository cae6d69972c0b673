package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.cli.ChildJvm;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim gui} with a script, on the current display, while Java3D's master control
 * thread dies after the first frame ({@link Java3dThreadDeath}): Java3D's other threads and
 * {@code SimpleUniverse.cleanup()} then wait for it for ever, as they did for the
 * rendering-attributes thread that a NullPointerException ended. The run still ends, within
 * {@value #LIMIT_S} s (its window closing gives up after {@link GuiLauncher#CLOSE_TIMEOUT_MS}, and
 * a script action whose event dispatch thread Java3D blocked after {@link ScriptRunner#EDT_TIMEOUT_MS}),
 * with exit code 1 and the uncaught exception counted (whether the thread dies while the script
 * plays or while the window closes). Closing the window with
 * {@code invokeAndWait} never returned here: the JVM stayed until it was killed.
 */
@Tag("slow")   // a child JVM with a window: ./test --all
class DeadJava3dThreadTest {
    /** The hang guard: start-up under load, the script (an action's limit at most), closing's limit and the exit's grace, with room. */
    static final long LIMIT_S = 180;

    @Test
    void aRunWhoseJava3dThreadDiesStillEndsWithExitCode1() throws Exception {
        GuiWindowTest.needDisplay();
        Path dir = Files.createTempDirectory("handsim-dead-j3d");
        try {
            Path script = dir.resolve("script.txt");
            Files.writeString(script, String.join("\n", "press Dynamics", "speed max", "play end", "log grasp", ""));
            GuiWindowTest.Child c = GuiWindowTest.runOnDisplay(dir, LIMIT_S, "handsim gui after a Java3D thread died",
                Java3dThreadDeath.class.getName(), "J3D-MasterControl",
                "gui", TestPaths.root().resolve("scenarios/mug-grasp.json").toString(), "--script", script.toString());
            String out = c.log();
            Assumptions.assumeFalse(out.contains("death: this JDK cannot stop a thread"), "Thread.stop is gone from this JDK (20 and later)");
            assertTrue(out.contains("death: stopped J3D-MasterControl"), out);
            assertTrue(out.contains("handsim gui: uncaught exception on thread J3D-MasterControl-1: java.lang.ThreadDeath"), out);
            assertTrue(out.contains("gui: failed (exit code 1), 1 uncaught exceptions"), out);
            assertEquals(1, c.code(), out);
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
