package org.handsim.testing;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.process.CommandContext;
import org.handsim.process.Phase;

/**
 * The tests' watcher of a command's named points ({@link Phase}), set in the child JVMs of the
 * tests that stop a command at each point: with the system property {@code handsim.phases} set,
 * each point prints {@code handsim-phase NAME} on standard error, and the point named by
 * {@code handsim.phases.pause} waits there until the file named by {@code handsim.phases.resume}
 * exists (forever without it, or until the command is cancelled).
 */
public final class PhaseWatch {
    private PhaseWatch() {}

    /** Sets the watcher if {@code handsim.phases} asks for it. */
    public static void installIfAsked() {
        if (System.getProperty("handsim.phases") == null) return;
        String pause = System.getProperty("handsim.phases.pause"), resume = System.getProperty("handsim.phases.resume");
        Phase.watch(name -> {
            System.err.println("handsim-phase " + name);
            System.err.flush();
            if (!name.equals(pause)) return;
            try {
                while ((resume == null || !Files.exists(Path.of(resume))) && !CommandContext.cancelled()) Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
    }
}
