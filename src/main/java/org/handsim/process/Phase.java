package org.handsim.process;

import java.util.function.Consumer;
import java.util.function.DoubleConsumer;

/**
 * Named points of a command's work (opened, half-way, table written, staged, published ...):
 * each is a cancellation point of a command the resident server runs ({@link CommandContext}),
 * but for the points inside a publication that has begun ({@link #reachInPublication}), which is
 * completed whatever happens; and each is told to a watcher, if one is set ({@link #watch}: the
 * tests that stop a command at each point with SIGTERM or SIGKILL set one in their child JVMs;
 * the program never does).
 */
public final class Phase {
    private static volatile Consumer<String> watcher;

    private Phase() {}

    /**
     * Tells {@code w} of every point reached from now on, on the thread that reaches it (null: no
     * one). A watcher may block the command there until it is cancelled.
     */
    public static void watch(Consumer<String> w) {
        watcher = w;
    }

    /** Marks the point {@code name}; a cancelled command stops here. */
    public static void reach(String name) {
        reachInPublication(name);
        CommandContext.checkCancelled();
    }

    /** Marks a point inside a publication: never a cancellation point. */
    public static void reachInPublication(String name) {
        Consumer<String> w = watcher;
        if (w != null) w.accept(name);
    }

    /** {@code progress}, marking the point {@code name} the first time the fraction done reaches one half. */
    public static DoubleConsumer atHalf(String name, DoubleConsumer progress) {
        if (watcher == null) return progress;
        boolean[] reached = {false};
        return f -> {
            if (progress != null) progress.accept(f);
            if (f >= 0.5 && !reached[0]) {
                reached[0] = true;
                reach(name);
            }
        };
    }
}
