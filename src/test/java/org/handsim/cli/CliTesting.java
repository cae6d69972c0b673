package org.handsim.cli;

import java.io.PrintWriter;
import java.io.StringWriter;

/** Runs the {@code handsim} command in the test's JVM and captures what it said (shared by the command tests). */
public final class CliTesting {
    private CliTesting() {}

    /** Exit code, standard output and standard error (both trimmed) of one command. */
    public record Run(int code, String out, String err) {}

    /** {@link HandSim#execute} with captured streams. */
    public static Run run(String... args) {
        StringWriter o = new StringWriter(), e = new StringWriter();
        int code = HandSim.execute(new PrintWriter(o), new PrintWriter(e), args);
        return new Run(code, o.toString().trim(), e.toString().trim());
    }
}
