package org.handsim.process;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.DoubleConsumer;

/**
 * Named points of a command's work (loaded, half-way, table written, published ...), a hook for
 * the tests that stop a command at each of them with SIGTERM or SIGKILL. Off unless the system
 * property {@code handsim.phases} is set: then each point prints {@code handsim-phase NAME} on
 * standard error, and the point named by {@code handsim.phases.pause} waits there until the file
 * named by {@code handsim.phases.resume} exists (forever without it, or until the command is
 * cancelled).
 *
 * <p>Each point is also a cancellation point of a command run by the resident server
 * ({@link CommandContext}), but for the points inside a publication that has begun
 * ({@link #reachInPublication}), which is completed whatever happens.
 */
public final class Phase {
    private Phase() {}

    /** Marks the point {@code name} (nothing unless the tests asked for it); a cancelled command stops here. */
    public static void reach(String name) {
        reachInPublication(name);
        CommandContext.checkCancelled();
    }

    /** Marks a point inside a publication: never a cancellation point. */
    public static void reachInPublication(String name) {
        if (System.getProperty("handsim.phases") == null) return;
        System.err.println("handsim-phase " + name);
        System.err.flush();
        if (!name.equals(System.getProperty("handsim.phases.pause"))) return;
        String resume = System.getProperty("handsim.phases.resume");
        try {
            while ((resume == null || !Files.exists(Path.of(resume))) && !CommandContext.cancelled()) Thread.sleep(20);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** {@code progress}, marking the point {@code name} the first time the fraction done reaches one half. */
    public static DoubleConsumer atHalf(String name, DoubleConsumer progress) {
        if (System.getProperty("handsim.phases") == null) return progress;
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
