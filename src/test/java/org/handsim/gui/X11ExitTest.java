package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The X server going away under an open window (issue 14): the program ends without JOGL's
 * native abort ("FATAL ERROR in native method: Nativewindow X11 IOError", exit 134, an hs_err
 * file). The test starts an X server of its own (Xvfb, which {@code ./test} installs), opens
 * {@code handsim gui} on it, waits for the first frame and kills the server.
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class X11ExitTest {
    @Test
    void losingTheXServerEndsTheProgramWithoutANativeAbort() throws Exception {
        GuiWindowTest.needDisplay();   // a machine that runs the window tests has Xvfb
        Path xvfbBin = null;
        for (String d : System.getenv().getOrDefault("PATH", "/usr/bin").split(":")) {
            if (Files.isExecutable(Path.of(d, "Xvfb"))) xvfbBin = Path.of(d, "Xvfb");
        }
        Assumptions.assumeTrue(xvfbBin != null, "no Xvfb on the PATH");
        Path dir = Files.createTempDirectory("handsim-x11-exit");
        Process xvfb = new ProcessBuilder(xvfbBin.toString(), "-displayfd", "1", "-screen", "0", "1024x768x24", "-nolisten", "tcp")
            .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        Process gui = null;
        try {
            String display;
            try (BufferedReader r = new BufferedReader(new InputStreamReader(xvfb.getInputStream(), StandardCharsets.US_ASCII))) {
                display = ":" + r.readLine().trim();
            }
            Path log = dir.resolve("gui.log");
            ProcessBuilder pb = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss16m",
                "-Dhandsim.home=" + TestPaths.root(), "-cp", System.getProperty("java.class.path"), "org.handsim.cli.HandSim", "gui")
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
            pb.environment().put("DISPLAY", display);
            pb.environment().remove("XAUTHORITY");
            gui = pb.start();
            long deadline = System.currentTimeMillis() + 120_000;
            while (!Files.readString(log).contains("gui: first frame") && System.currentTimeMillis() < deadline && gui.isAlive()) Thread.sleep(100);
            assertTrue(Files.readString(log).contains("gui: first frame"), "the window opened:\n" + Files.readString(log));
            Thread.sleep(500);
            xvfb.destroy();   // the X server goes away
            if (!gui.waitFor(60, TimeUnit.SECONDS)) fail("handsim gui still running 60 s after its X server went away");
            String out = Files.readString(log);
            System.out.println("exit " + gui.exitValue() + "; log:\n" + out);
            assertNotEquals(134, gui.exitValue(), "not a native abort:\n" + out);
            assertFalse(out.contains("FATAL ERROR"), out);
            try (var files = Files.list(dir)) {
                List<Path> crash = files.filter(f -> f.getFileName().toString().startsWith("hs_err")).toList();
                assertTrue(crash.isEmpty(), "no JVM crash report: " + crash);
            }
        } finally {
            if (gui != null) gui.destroyForcibly();
            xvfb.destroyForcibly();
            VrmlTesting.deleteTree(dir);
        }
    }
}
