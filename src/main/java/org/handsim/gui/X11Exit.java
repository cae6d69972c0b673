package org.handsim.gui;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.util.List;

/**
 * Leaving the window cleanly on X11, around two habits of JOGL 2.6's
 * {@code jogamp.nativewindow.x11.X11Util} (checked in its sources, {@code Xmisc.c} and
 * {@code X11Util.java}):
 * <ol>
 *   <li>At its initialisation it installs a process-wide X I/O error handler that, when any X
 *       connection breaks — AWT's too, when the X server goes away or {@code xvfb-run} ends —
 *       prints "Nativewindow X11 IOError" and calls the JVM's {@code FatalError}: an abort with
 *       a core file, exit code 134. {@link #restoreIoErrorHandler()} calls its
 *       {@code shutdown0()}, which puts back the handler that was there before (AWT's): on a lost
 *       server AWT prints one line ("X connection to :0 broken") and the process exits.
 *       {@link #prepare()} does it before the first window, so that JOGL's handler is never in
 *       place while a window is open.</li>
 *   <li>At JVM shutdown it prints three "X11Util" lines when an X display connection is still
 *       open — Java3D's renderer leaves the one of its canvas open after
 *       {@code SimpleUniverse.cleanup()}, and JOGL's shared context keeps its own until the hook.
 *       {@link #closeDisplays()} releases both once the window and Java3D are gone (and
 *       Java3D's renderer has stopped using its connection).</li>
 * </ol>
 * Both reach JOGL's internal class by reflection (it is on the class path, not in a named
 * module); if JOGL changes, they do nothing and say why on request ({@link #lastProblem()}).
 * Not for embedding programs that keep using JOGL afterwards.
 */
public final class X11Exit {
    private X11Exit() {}

    private static final String X11_UTIL = "jogamp.nativewindow.x11.X11Util";
    /** How long {@link #closeDisplays()} waits for Java3D's threads to be idle, ms. */
    static final long IDLE_WAIT_MS = 5_000;
    private static volatile String problem;
    private static boolean restored;

    /**
     * Initialises JOGL now ({@code GLProfile.initSingleton()}, which JOGL asks programs to call
     * before any other X11 call) and at once puts back the X I/O error handler it replaced
     * ({@link #restoreIoErrorHandler()}): from here on a lost X server ends the program (AWT's or
     * Xlib's handler: a line, exit 1) and never aborts the JVM — not even while the first window
     * is being opened, which under a loaded machine takes seconds. Call it before the first
     * window (off the event dispatch thread). Does nothing without a display or off X11.
     */
    public static boolean prepare() {
        if (java.awt.GraphicsEnvironment.isHeadless()) return false;
        try {
            com.jogamp.opengl.GLProfile.initSingleton();
            if (!com.jogamp.nativewindow.NativeWindowFactory.TYPE_X11.equals(com.jogamp.nativewindow.NativeWindowFactory.getNativeWindowType(true))) {
                return false;
            }
        } catch (RuntimeException | LinkageError e) {
            problem = "cannot initialise JOGL: " + e;
            return false;
        }
        return restoreIoErrorHandler();
    }

    /**
     * Puts the X I/O error handler that was there before JOGL's initialisation (AWT's, or Xlib's
     * default) back in place of JOGL's fatal one. Once: a second {@code shutdown0()} would put
     * Xlib's default in place of whatever the first restored.
     */
    public static synchronized boolean restoreIoErrorHandler() {
        if (restored) return true;
        try {
            Class<?> c = Class.forName(X11_UTIL);
            Method m = c.getDeclaredMethod("shutdown0");
            m.setAccessible(true);
            m.invoke(null);
            restored = true;
            return true;
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            problem = "cannot restore the X I/O error handler: " + e;
            return false;
        }
    }

    /**
     * Releases JOGL's resources ({@code GLProfile.shutdown()}: its shared OpenGL context and the X
     * display connections it keeps for it), then closes the X display connection Java3D's
     * renderer opened for the canvas and left open, so nothing is left for JOGL's shutdown hook
     * to complain about. Call it when the window is disposed and nothing renders any more; JOGL
     * is unusable afterwards. Returns the display connections still open after it.
     */
    public static int closeDisplays() {
        awaitJava3dIdle();
        try {
            com.jogamp.opengl.GLProfile.shutdown();
        } catch (RuntimeException | LinkageError e) {
            problem = "GLProfile.shutdown failed: " + e;
        }
        try {
            Class<?> c = Class.forName(X11_UTIL);
            Field f = c.getDeclaredField("openDisplayList");
            f.setAccessible(true);
            Object lock = globalLock(c);
            List<?> open;
            synchronized (lock != null ? lock : c) {
                open = new java.util.ArrayList<>((List<?>) f.get(null));
            }
            // what is left is the connection Java3D's renderer opened for the canvas, unused now
            Method close = c.getMethod("closeDisplay", long.class);
            for (Object d : open) close.invoke(null, (Long) d.getClass().getMethod("getHandle").invoke(d));
            synchronized (lock != null ? lock : c) {
                return ((List<?>) f.get(null)).size();
            }
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            problem = "cannot close the X display connections: " + e;
            return -1;
        }
    }

    /**
     * Waits (at most {@link #IDLE_WAIT_MS}) until every Java3D thread has ended or waits for work,
     * twice in a row 20 ms apart: {@code SimpleUniverse.cleanup()} returns before its renderer
     * has released the canvas's OpenGL context, and a display connection closed under a thread
     * that still uses it breaks that thread's next X call.
     */
    private static void awaitJava3dIdle() {
        long deadline = System.currentTimeMillis() + IDLE_WAIT_MS;
        int quiet = 0;
        while (quiet < 2 && System.currentTimeMillis() < deadline) {
            boolean busy = false;
            for (Thread t : Thread.getAllStackTraces().keySet()) {
                Thread.State st = t.getState();
                if (t.getName().startsWith("J3D-") && t.isAlive() && st != Thread.State.WAITING && st != Thread.State.TIMED_WAITING) busy = true;
            }
            quiet = busy ? 0 : quiet + 1;
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private static Object globalLock(Class<?> c) {
        try {
            Field l = c.getDeclaredField("globalLock");
            l.setAccessible(true);
            return l.get(null);
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
    }

    /** What went wrong in the last call that did nothing, or null. */
    public static String lastProblem() { return problem; }
}
