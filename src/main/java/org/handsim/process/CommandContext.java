package org.handsim.process;

/**
 * What a command may ask about the invocation it runs for, when one JVM runs many commands one
 * after another (the resident server, {@code org.handsim.server.Server}): whether it has been
 * cancelled (its client got SIGINT or SIGTERM, or went away), whether its standard streams are a
 * terminal (the client's, not the server's), and which command of the JVM this is (so caches
 * of what files said check the files again once per command).
 *
 * <p>In a JVM that runs one command and exits — every command without the server — nothing is
 * ever cancelled here (SIGINT and SIGTERM stop the JVM: {@link ExitCleanup}), the terminal is
 * the process's own and the generation stays 0.
 *
 * <p><b>Cancellation points.</b> A cancelled command stops at the next progress report
 * ({@code cli.ProgressBar}), at the next named point of its work ({@link Phase#reach}) outside a
 * publication, and before it begins a temporary file or a publication ({@link ExitCleanup#stopping()});
 * what it leaves is then removed by its normal close path, as on any error. A publication that
 * has begun is completed, as SIGTERM does to a single command's JVM.
 *
 * <p>Thread rules: the server calls {@link #begin} and {@link #end} around each command (one at a
 * time) and {@link #cancel} from any thread; the command's threads read.
 */
public final class CommandContext {
    private static volatile boolean cancelled;
    private static volatile Boolean console;
    private static volatile long generation;
    private static volatile String inDoubt;

    private CommandContext() {}

    /** Thrown at a cancellation point of a cancelled command; the command unwinds as on any error. */
    public static final class Cancelled extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Cancelled() {
            super("the command was stopped", null, false, false);
        }
    }

    /** Whether the running command has been cancelled. */
    public static boolean cancelled() {
        return cancelled;
    }

    /** A cancellation point: throws {@link Cancelled} if the running command has been cancelled. */
    public static void checkCancelled() {
        if (cancelled) throw new Cancelled();
    }

    /** Whether the command's standard input and output are a terminal ({@code System.console() != null} of its process). */
    public static boolean console() {
        Boolean c = console;
        return c != null ? c : System.console() != null;
    }

    /**
     * The number of the command this JVM runs (0 until a server begins one): a cache entry made
     * from a file and checked against the file in this generation need not be checked again.
     */
    public static long generation() {
        return generation;
    }

    /** The server: a new command begins, its client's terminal is {@code clientConsole}. */
    public static synchronized void begin(boolean clientConsole) {
        generation++;
        cancelled = false;
        inDoubt = null;
        console = clientConsole;
    }

    /**
     * The command failed in a way that may have left the JVM unfit for the next one (out of
     * memory, a stack overflow, an internal error): a server then ends rather than serve on. A
     * failure the command reported as such (a bad input, a full disk: exit 1 or any other code)
     * leaves nothing in doubt.
     */
    public static void markInDoubt(String why) {
        inDoubt = why;
    }

    /** Why the last command left the JVM in doubt, or null. */
    public static String inDoubt() {
        return inDoubt;
    }

    /** The server: the running command is to stop at its next cancellation point. */
    public static void cancel() {
        cancelled = true;
    }

    /** The server: the command has ended (nothing is cancelled until the next begins). */
    public static synchronized void end() {
        cancelled = false;
        console = null;
    }
}
