package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
 * The X server going away under an open window: the program ends without JOGL's native abort
 * ("FATAL ERROR in native method: Nativewindow X11 IOError", exit 134, an hs_err file) — the
 * window of {@code handsim gui} and the README's embedding example. Each test starts an X
 * server of its own (Xvfb, which {@code ./test} installs), opens the program on it, waits for
 * the first frame and kills the server.
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class X11ExitTest {
    @Test
    void losingTheXServerEndsTheProgramWithoutANativeAbort() throws Exception {
        loseTheServerUnder("gui: first frame", 500, "org.handsim.cli.HandSim", "gui");
    }

    /**
     * The README's embedding example ({@link EmbeddedExample}): another program's frame, which
     * never called {@link X11Exit} itself — {@link HandSimPanel#create} replaces JOGL's fatal
     * handler before the first window. Without that it aborted: "FATAL ERROR in native method:
     * Nativewindow X11 IOError ... Resource temporarily unavailable", exit 134 (the errno is
     * what AWT's last non-blocking read left, not the cause).
     */
    @Test
    void losingTheXServerEndsTheEmbeddingExampleWithoutANativeAbort() throws Exception {
        loseTheServerUnder("embedded: first frame", 0, EmbeddedExample.class.getName(),
            TestPaths.root().resolve("scenarios/paper-breakaway.json").toString(), "--screenshot", "never.png");
    }

    /**
     * Starts an X server, runs {@code main} on it until {@code opened} is printed, kills the
     * server {@code afterMs} later, checks the ending: exit code 1 (the X I/O error handler
     * that AWT or Xlib put in place ends the program), no abort.
     */
    private static void loseTheServerUnder(String opened, long afterMs, String main, String... args) throws Exception {
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
            List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss16m",
                "-Xmx1g", "-Dhandsim.home=" + TestPaths.root(), "-cp", System.getProperty("java.class.path"), main));
            cmd.addAll(List.of(args));
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
            pb.environment().put("DISPLAY", display);
            pb.environment().remove("XAUTHORITY");
            gui = pb.start();
            long deadline = System.currentTimeMillis() + 120_000;
            while (!Files.readString(log).contains(opened) && System.currentTimeMillis() < deadline && gui.isAlive()) Thread.sleep(100);
            assertTrue(Files.readString(log).contains(opened), "the window opened:\n" + Files.readString(log));
            Thread.sleep(afterMs);
            xvfb.destroy();   // the X server goes away
            if (!gui.waitFor(60, TimeUnit.SECONDS)) fail(main + " still running 60 s after its X server went away");
            String out = Files.readString(log);
            System.out.println("exit " + gui.exitValue() + "; log:\n" + out);
            assertNotEquals(134, gui.exitValue(), "not a native abort:\n" + out);
            assertEquals(1, gui.exitValue(), "the lost X server ended the program:\n" + out);
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
