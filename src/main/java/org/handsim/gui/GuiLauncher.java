package org.handsim.gui;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.handsim.scenario.Scenario;

/**
 * Opens the window and, in scripted mode, drives it and closes it: the part of
 * {@code handsim gui} below the command line.
 *
 * <p>Interactive: the window stays until the user closes it (exit code 0; 1 when it then does
 * not close in time). Scripted (a script,
 * {@code --screenshot} or {@code --measure-fps}): waits for the first rendered frame, runs the
 * script, takes the screenshot, measures, closes the window and returns the exit code: 0 when
 * everything worked and no exception reached the event dispatch thread or any other thread's
 * top (they are recorded by an {@link ErrorLog}); otherwise the code of the failure.
 *
 * <p>Both modes print {@code gui: first frame after N ms} — the time from the JVM's start
 * (i.e. from typing {@code handsim gui}, launcher excluded) to the first frame Java3D swapped.
 * Leaving goes through {@link X11Exit}: no native abort when the X server goes away, no X11Util
 * lines at the JVM's exit. Leaving is bounded: a window that does not close within
 * {@link #CLOSE_TIMEOUT_MS} (Java3D's threads stuck) is left behind with a line on the error
 * stream, the run fails (exit code 1 unless it had failed already), and the JVM ends with that
 * code within {@link #EXIT_GRACE_MS} more.
 */
public final class GuiLauncher {
    private GuiLauncher() {}

    /** How long to wait for the first rendered frame. */
    static final long FIRST_FRAME_TIMEOUT_MS = 120_000;
    /**
     * How long closing the window may take (and the event dispatch thread may take to run what
     * is queued before it), ms: a few hundred ms when all is well, seconds on a loaded machine.
     */
    static final long CLOSE_TIMEOUT_MS = 10_000;
    /**
     * How long the JVM may take to exit once the window could not be closed, ms, before it is
     * halted with the same exit code ({@link #haltAfter}).
     */
    static final long EXIT_GRACE_MS = 10_000;

    /**
     * What to do.
     *
     * @param scenario   the scenario to open
     * @param script     actions to run, or null
     * @param scriptDir  folder for the script's relative file names, or null
     * @param screenshot PNG to save at the end, or null
     * @param measureFps seconds of continuous rendering to measure at the end, or null
     * @param speed      simulation speed (0 = as fast as possible), or null for real time
     * @param object     a VRML97 file to import before the script, or null
     */
    public record Options(Scenario scenario, Script script, Path scriptDir, Path screenshot, Double measureFps, Double speed, Path object) {
        boolean scripted() { return script != null || screenshot != null || measureFps != null; }
    }

    /** Runs the window; returns the exit code. Not on the event dispatch thread. */
    public static int run(Options o, PrintWriter out, PrintWriter err) throws InterruptedException {
        long start = System.nanoTime();
        ErrorLog errors = new ErrorLog().install();
        AtomicReference<HandSimWindow> ref = new AtomicReference<>();
        // before the first window, so that a lost X server never meets JOGL's fatal handler
        if (!X11Exit.prepare() && X11Exit.lastProblem() != null) err.println("handsim gui: " + X11Exit.lastProblem());
        try {
            MeshSource.Model[] hand = HandSimPanel.loadHand();   // off the EDT (MeshSource)
            ScriptRunner.edt(() -> {
                HandSimWindow w = new HandSimWindow(o.scenario(), hand, !o.scripted());
                if (o.speed() != null) w.setSpeed(o.speed());
                errors.onError(m -> SwingUtilities.invokeLater(() -> w.status(m, true)));
                w.show();
                ref.set(w);
                return null;
            });
        } catch (Exception e) {
            err.println("handsim gui: cannot open the window: " + e);
            e.printStackTrace(err);
            return 1;
        }
        HandSimWindow w = ref.get();
        long deadline = System.currentTimeMillis() + FIRST_FRAME_TIMEOUT_MS;
        while (w.view().framesRendered() == 0 && System.currentTimeMillis() < deadline) Thread.sleep(5);
        // in case prepare() could not (JOGL initialised by Java3D only now): a lost X server should end the program, not abort the JVM
        if (!X11Exit.restoreIoErrorHandler()) err.println("handsim gui: " + X11Exit.lastProblem());
        if (w.view().framesRendered() == 0) {
            err.println("handsim gui: no frame was rendered within " + FIRST_FRAME_TIMEOUT_MS / 1000 + " s (OpenGL not working?)");
            if (o.scripted()) {
                if (!close(w::dispose, CLOSE_TIMEOUT_MS, err)) haltAfter(1, EXIT_GRACE_MS);
                return 1;
            }
        } else {
            out.println(String.format(Locale.ROOT, "gui: first frame after %d ms (from the JVM's start; %d ms after the command began; epoch ms %d)",
                w.view().firstFrameMillisSinceJvmStart(), (System.nanoTime() - start) / 1_000_000, w.view().firstFrameEpochMillis()));
            out.flush();
        }
        ScriptRunner runner = new ScriptRunner(w, out, o.scriptDir());
        if (!o.scripted()) {
            if (o.object() != null) {
                try {
                    runner.importObject(o.object().toAbsolutePath());
                } catch (Exception e) {
                    err.println("handsim gui: --object " + o.object() + ": " + ScriptRunner.message(e));
                }
            }
            w.awaitClosing();
            if (!w.awaitClosed(CLOSE_TIMEOUT_MS)) {
                err.println("handsim gui: " + notClosed(CLOSE_TIMEOUT_MS));
                err.flush();
                haltAfter(1, EXIT_GRACE_MS);
                return 1;
            }
            closeDisplays(err);
            return 0;
        }
        int code = 0;
        // the model moves only while the script plays or waits (SimulationRunner.hold)
        w.runner().hold(true);
        try {
            if (o.object() != null) runner.importObject(o.object().toAbsolutePath());
            if (o.script() != null) runner.run(o.script());
            if (o.screenshot() != null) runner.screenshot(o.screenshot().toAbsolutePath());
            if (o.measureFps() != null) runner.measureFps(o.measureFps());
        } catch (ScriptRunner.ScriptFailure f) {
            err.println("handsim gui: " + f.getMessage());
            code = f.exitCode();
        } catch (Exception e) {
            err.println("handsim gui: " + e);
            e.printStackTrace(err);
            code = 1;
        }
        // let queued events run so that their exceptions are counted
        if (!onEdtWithin(() -> { }, CLOSE_TIMEOUT_MS)) {
            err.println("handsim gui: the event dispatch thread did not answer within " + CLOSE_TIMEOUT_MS / 1000 + " s");
            if (code == 0) code = 1;
        }
        // closed before the count: an exception while closing counts, and so does a window that does not close
        boolean closed = close(w::dispose, CLOSE_TIMEOUT_MS, err);
        if (!closed && code == 0) code = 1;
        List<String> uncaught = errors.entries();
        if (!uncaught.isEmpty()) {
            for (String e : uncaught) err.println("handsim gui: " + e);
            if (code == 0) code = 1;
        }
        out.println("gui: " + (code == 0 ? "done" : "failed (exit code " + code + ")") + ", " + uncaught.size() + " uncaught exceptions");
        out.flush();
        if (closed) {
            closeDisplays(err);
        } else {
            haltAfter(code, EXIT_GRACE_MS);
        }
        return code;
    }

    /** {@link X11Exit#closeDisplays}, saying on {@code err} why when it cannot. */
    private static void closeDisplays(PrintWriter err) {
        if (X11Exit.closeDisplays() < 0) err.println("handsim gui: " + X11Exit.lastProblem());
    }

    /**
     * Runs {@code dispose} (closing the window: Java3D's {@code SimpleUniverse.cleanup()} among
     * it) on the event dispatch thread and waits for it at most {@code timeoutMs}. Returns false,
     * having said so on {@code err}, when it did not finish in time: a Java3D thread that died
     * leaves the others waiting for it for ever, and the cleanup with them (the event dispatch
     * thread stays blocked; the caller leaves without it, {@link #haltAfter}). An exception from
     * {@code dispose} is reported on {@code err}; the window counts as closed.
     */
    static boolean close(Runnable dispose, long timeoutMs, PrintWriter err) throws InterruptedException {
        boolean done = onEdtWithin(() -> {
            try {
                dispose.run();
            } catch (RuntimeException e) {
                err.println("handsim gui: closing the window: " + e);
            }
        }, timeoutMs);
        if (!done) err.println("handsim gui: " + notClosed(timeoutMs));
        err.flush();
        return done;
    }

    /** A time limit in seconds as the messages give it: 0.3, 10, 60. */
    static String seconds(long ms) {
        return java.math.BigDecimal.valueOf(ms, 3).stripTrailingZeros().toPlainString();
    }

    private static String notClosed(long timeoutMs) {
        return "the window did not close within " + seconds(timeoutMs) + " s (Java3D's threads no longer answer): leaving without it";
    }

    /**
     * Runs {@code r} on the event dispatch thread (at once when called on it) and waits at most
     * {@code timeoutMs} for it to finish; true when it did. Unlike {@code invokeAndWait}, a
     * blocked event dispatch thread never blocks the caller for longer.
     */
    static boolean onEdtWithin(Runnable r, long timeoutMs) throws InterruptedException {
        if (SwingUtilities.isEventDispatchThread()) {
            r.run();
            return true;
        }
        CountDownLatch done = new CountDownLatch(1);
        SwingUtilities.invokeLater(() -> {
            try {
                r.run();
            } finally {
                done.countDown();
            }
        });
        return done.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    /**
     * Halts the JVM with {@code code} after {@code ms} unless it has ended by then (a daemon
     * thread): called when the window could not be closed, before returning the exit code to the
     * command line, whose {@code System.exit} runs JOGL's shutdown hook, which can wait for a
     * thread that Java3D left blocked. {@code handsim gui}'s exit code is kept either way.
     */
    static void haltAfter(int code, long ms) {
        Thread t = new Thread(() -> {
            try {
                Thread.sleep(ms);
            } catch (InterruptedException e) {
                return;
            }
            System.out.flush();
            System.err.flush();
            Runtime.getRuntime().halt(code);
        }, "handsim-gui-exit-guard");
        t.setDaemon(true);
        t.start();
    }
}
