package org.handsim.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.handsim.server.ServerCommand;

/** Runs the {@code handsim} command in the test's JVM and captures what it said (shared by the command tests). */
public final class CliTesting {
    private CliTesting() {}

    /**
     * Every sub-command as the launcher has them: {@link HandSim#SUBCOMMANDS} and the resident
     * server's own ({@code handsim server}), which its package adds from above.
     */
    public static final List<Class<?>> COMMANDS = all();

    private static List<Class<?>> all() {
        List<Class<?>> all = new ArrayList<>(HandSim.SUBCOMMANDS);
        all.add(ServerCommand.class);
        return List.copyOf(all);
    }

    /** Exit code, standard output and standard error (both trimmed) of one command. */
    public record Run(int code, String out, String err) {}

    /** {@link HandSim#execute} with captured streams, with every sub-command the launcher has. */
    public static Run run(String... args) {
        StringWriter o = new StringWriter(), e = new StringWriter();
        int code = HandSim.execute(new PrintWriter(o), new PrintWriter(e), List.of(ServerCommand.class), args);
        return new Run(code, o.toString().trim(), e.toString().trim());
    }
}
