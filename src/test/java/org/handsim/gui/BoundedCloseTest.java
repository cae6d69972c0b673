package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.swing.SwingUtilities;
import org.handsim.cli.ChildJvm;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim gui} leaves in bounded time when Java3D's threads are stuck: closing the window
 * ({@link GuiLauncher#close}) gives up after its time limit when the event dispatch thread is
 * blocked, and says so; and a JVM whose shutdown hook never returns still ends, with the run's
 * exit code ({@link GuiLauncher#haltAfter}; a child JVM, {@link StuckWindowExit}). Needs no
 * display: the event dispatch thread runs headless.
 */
class BoundedCloseTest {
    /** Blocks the event dispatch thread (once it is blocked, returns) until the latch returned is counted down. */
    private static CountDownLatch blockTheEventDispatchThread() throws InterruptedException {
        CountDownLatch inside = new CountDownLatch(1), release = new CountDownLatch(1);
        SwingUtilities.invokeLater(() -> {
            inside.countDown();
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        assertTrue(inside.await(60, TimeUnit.SECONDS));
        return release;
    }

    @Test
    void aScriptActionGivesUpWhenTheEventDispatchThreadIsBlockedAndSaysSo() throws Exception {
        CountDownLatch release = blockTheEventDispatchThread();
        AtomicBoolean ran = new AtomicBoolean();
        long t0 = System.nanoTime();
        String message = null;
        boolean ranThen = true;
        try {
            ScriptRunner.edt(() -> ran.getAndSet(true), 300);
        } catch (ScriptRunner.ScriptFailure f) {
            message = f.getMessage();
            assertEquals(1, f.exitCode());
        } finally {
            ranThen = ran.get();
            release.countDown();
        }
        assertFalse(ranThen, "the action cannot have run on a blocked thread");
        double waited = (System.nanoTime() - t0) / 1e9;
        assertEquals("the event dispatch thread did not answer within 0.3 s (Java3D's threads no longer answer?)", message);
        assertTrue(waited >= 0.29, "gave up before its limit: " + waited + " s");
        // a free event dispatch thread answers: the value, and the action's own exception as it was thrown
        assertEquals(Integer.valueOf(7), ScriptRunner.edt(() -> 7, 60_000));
        IllegalStateException thrown = new IllegalStateException("from the action");
        try {
            ScriptRunner.edt(() -> { throw thrown; }, 60_000);
            fail("the action's exception was lost");
        } catch (IllegalStateException e) {
            assertTrue(e == thrown, "the same exception: " + e);
        }
    }

    @Test
    void closingGivesUpWhenTheEventDispatchThreadIsBlockedAndSaysSo() throws Exception {
        CountDownLatch release = blockTheEventDispatchThread();
        AtomicBoolean disposed = new AtomicBoolean();
        StringWriter text = new StringWriter();
        long t0 = System.nanoTime();
        boolean closed, disposedThen;
        try {
            closed = GuiLauncher.close(() -> disposed.set(true), 300, new PrintWriter(text));
            disposedThen = disposed.get();
        } finally {
            release.countDown();
        }
        double waited = (System.nanoTime() - t0) / 1e9;
        assertFalse(closed, "the event dispatch thread was blocked");
        assertFalse(disposedThen);
        assertTrue(waited >= 0.29, "gave up before its limit: " + waited + " s");
        assertEquals("handsim gui: the window did not close within 0.3 s (Java3D's threads no longer answer): leaving without it",
            text.toString().trim());
        // once the thread is free, what was queued runs
        assertTrue(GuiLauncher.onEdtWithin(() -> { }, 60_000));
        assertTrue(disposed.get());
    }

    @Test
    void closingWaitsForTheWindowAndReportsAnExceptionFromIt() throws Exception {
        StringWriter text = new StringWriter();
        AtomicBoolean onEdt = new AtomicBoolean();
        assertTrue(GuiLauncher.close(() -> onEdt.set(SwingUtilities.isEventDispatchThread()), 60_000, new PrintWriter(text)));
        assertTrue(onEdt.get(), "the window is closed on the event dispatch thread");
        assertEquals("", text.toString());
        assertTrue(GuiLauncher.close(() -> { throw new IllegalStateException("canvas gone"); }, 60_000, new PrintWriter(text)));
        assertEquals("handsim gui: closing the window: java.lang.IllegalStateException: canvas gone", text.toString().trim());
    }

    @Test
    void aJvmWhoseShutdownHookHangsStillEndsWithTheRunsExitCode() throws Exception {
        Path dir = Files.createTempDirectory("handsim-stuck-exit");
        try {
            for (int code : new int[] {1, 0}) {
                Path log = dir.resolve("out-" + code + ".txt");
                Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                    StuckWindowExit.class.getName(), String.valueOf(code), "300", "500")
                    .redirectErrorStream(true).redirectOutput(log.toFile()).start();
                if (!p.waitFor(2, TimeUnit.MINUTES)) {
                    p.destroyForcibly();
                    fail("the child JVM did not end: " + Files.readString(log));
                }
                String out = Files.readString(log, StandardCharsets.UTF_8);
                assertEquals(code, p.exitValue(), out);
                List<String> lines = out.lines().toList();
                assertEquals(List.of(
                    "handsim gui: the window did not close within 0.3 s (Java3D's threads no longer answer): leaving without it",
                    "stuck: exit " + code,
                    "stuck: shutdown hook waits for ever"), lines, out);
            }
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
