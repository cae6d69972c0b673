package org.handsim.process;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * What a command must undo if the JVM is stopped by SIGINT or SIGTERM (or {@code System.exit}
 * while it writes): one shutdown hook runs the registered actions, the latest first. An
 * {@link AtomicFile} registers the deletion of its temporary file, an {@link OutputSet} the
 * removal (or, once its publication has begun, the completion) of its private folder. After the
 * hook has started, {@link #stopping()} is true and no new temporary file is begun. SIGKILL runs
 * no hook: what it leaves has the process id in its name, and the next writer removes it.
 */
public final class ExitCleanup {
    private static final Set<Runnable> ACTIONS = new LinkedHashSet<>();
    private static boolean hooked;
    private static volatile boolean stopping;

    private ExitCleanup() {}

    /** Registers an action to run at exit (until {@link #unregister}). */
    public static synchronized void register(Runnable action) {
        if (!hooked) {
            hooked = true;
            try {
                Runtime.getRuntime().addShutdownHook(new Thread(ExitCleanup::runAll, "handsim-exit-cleanup"));
            } catch (IllegalStateException alreadyStopping) {
                stopping = true;
            }
        }
        ACTIONS.add(action);
    }

    public static synchronized void unregister(Runnable action) {
        ACTIONS.remove(action);
    }

    /**
     * Whether the JVM is shutting down (a temporary file begun now would not be cleaned up), or
     * the command is cancelled ({@link CommandContext}): no new temporary file or set is begun.
     */
    public static boolean stopping() {
        return stopping || CommandContext.cancelled();
    }

    /** The actions registered now (what {@link #runAllBut} leaves alone). */
    public static synchronized Set<Runnable> registered() {
        return new LinkedHashSet<>(ACTIONS);
    }

    /**
     * Runs and removes the registered actions that are not in {@code before}, the latest first:
     * what the JVM's exit would have done for a command that ends without its process ending
     * (the resident server). Returns how many ran.
     */
    public static int runAllBut(Set<Runnable> before) {
        List<Runnable> todo = new ArrayList<>();
        synchronized (ExitCleanup.class) {
            for (Runnable r : ACTIONS) if (!before.contains(r)) todo.add(r);
            ACTIONS.removeAll(todo);
        }
        for (int i = todo.size() - 1; i >= 0; i--) {
            try {
                todo.get(i).run();
            } catch (RuntimeException | Error e) {
                // best effort: the next action still runs
            }
        }
        return todo.size();
    }

    private static void runAll() {
        List<Runnable> todo;
        synchronized (ExitCleanup.class) {
            stopping = true;
            todo = new ArrayList<>(ACTIONS);
            ACTIONS.clear();
        }
        for (int i = todo.size() - 1; i >= 0; i--) {
            try {
                todo.get(i).run();
            } catch (RuntimeException | Error e) {
                // best effort: the next action still runs
            }
        }
    }
}
