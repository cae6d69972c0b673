package org.handsim.cli;

/** A failure the command reports as one line on standard error with a given exit code. */
public final class CliError extends RuntimeException {
    private static final long serialVersionUID = 1L;
    /** Bad arguments or a bad input row. */
    public static final int USAGE = 2;
    /** An input file that cannot be loaded. */
    public static final int LOAD = 3;
    /** A run stopped by a numerical guard. */
    public static final int NUMERIC = 4;
    /** A command stopped by SIGINT (128 + 2), what the shell reports for a JVM that SIGINT stopped. */
    public static final int STOPPED = 130;

    private final int exitCode;

    public CliError(int exitCode, String message) {
        super(message);
        this.exitCode = exitCode;
    }

    public CliError(int exitCode, String message, Throwable cause) {
        super(message, cause);
        this.exitCode = exitCode;
    }

    public int exitCode() { return exitCode; }

    /** Exit 2 with "handsim: {message}". */
    public static CliError usage(String message) { return new CliError(USAGE, message); }
}
