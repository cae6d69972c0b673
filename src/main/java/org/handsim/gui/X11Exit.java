package org.handsim.gui;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.util.List;

/**
 * Leaving the window cleanly on X11 (issue 14), around two habits of JOGL 2.6's
 * {@code jogamp.nativewindow.x11.X11Util} (checked in its sources, {@code Xmisc.c} and
 * {@code X11Util.java}):
 * <ol>
 *   <li>At its initialisation it installs a process-wide X I/O error handler that, when any X
 *       connection breaks — AWT's too, when the X server goes away or {@code xvfb-run} ends —
 *       prints "Nativewindow X11 IOError" and calls the JVM's {@code FatalError}: an abort with
 *       a core file, exit code 134. {@link #restoreIoErrorHandler()} calls its
 *       {@code shutdown0()}, which puts back the handler that was there before (AWT's): on a lost
 *       server AWT prints one line ("X connection to :0 broken") and the process exits.</li>
 *   <li>At JVM shutdown it prints three "X11Util" lines when an X display connection is still
 *       open — Java3D's renderer leaves the one of its canvas open after
 *       {@code SimpleUniverse.cleanup()}, and JOGL's shared context keeps its own until the hook.
 *       {@link #closeDisplays()} releases both once the window and Java3D are gone.</li>
 * </ol>
 * Both reach JOGL's internal class by reflection (it is on the class path, not in a named
 * module); if JOGL changes, they do nothing and say why on request ({@link #lastProblem()}).
 * Not for embedding programs that keep using JOGL afterwards.
 */
public final class X11Exit {
    private X11Exit() {}

    private static final String X11_UTIL = "jogamp.nativewindow.x11.X11Util";
    private static volatile String problem;

    /** Puts AWT's X I/O error handler back in place of JOGL's fatal one (after JOGL's initialisation). */
    public static boolean restoreIoErrorHandler() {
        try {
            Class<?> c = Class.forName(X11_UTIL);
            Method m = c.getDeclaredMethod("shutdown0");
            m.setAccessible(true);
            m.invoke(null);
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
