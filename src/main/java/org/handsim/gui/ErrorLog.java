package org.handsim.gui;

import java.util.ArrayList;
import java.util.List;

/**
 * Records exceptions nobody caught — on the event dispatch thread above all, where Swing would
 * otherwise print them and carry on — so a scripted run can fail with a non-zero exit code and
 * a test can see what went wrong. {@link #install()} makes it the JVM's default uncaught
 * exception handler; the window also shows the latest one in its status bar. Thread-safe.
 */
public final class ErrorLog implements Thread.UncaughtExceptionHandler {
    private final List<String> entries = new ArrayList<>();
    private volatile java.util.function.Consumer<String> listener;

    /** Installs this log as the default handler for every thread (the EDT included). */
    public ErrorLog install() {
        Thread.setDefaultUncaughtExceptionHandler(this);
        return this;
    }

    /** Called with each new entry (e.g. to show it in the status bar); may be null. */
    public void onError(java.util.function.Consumer<String> l) { listener = l; }

    @Override
    public void uncaughtException(Thread t, Throwable e) {
        String entry = "uncaught exception on thread " + t.getName() + ": " + e;
        synchronized (entries) {
            entries.add(entry);
        }
        System.err.println("handsim gui: " + entry);
        e.printStackTrace();
        java.util.function.Consumer<String> l = listener;
        if (l != null) {
            try {
                l.accept(entry);
            } catch (RuntimeException ignored) {
                // the listener must not hide the original error
            }
        }
    }

    /** @return the entries so far */
    public List<String> entries() {
        synchronized (entries) {
            return new ArrayList<>(entries);
        }
    }
}
