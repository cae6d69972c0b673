package org.handsim.cli;

import java.awt.GraphicsEnvironment;
import java.io.PrintWriter;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * Entry point of the {@code handsim} command. Sub-commands are registered in
 * {@link #SUBCOMMANDS}; each has {@code --help}.
 */
@Command(name = "handsim", mixinStandardHelpOptions = true, version = "HandSim 0.1.0",
    description = "Simulator of the BarrettHand grasping objects from VRML97 files "
        + "(Corrales, Jara, Torres: kinematics, dynamics, breakaway clutch, contact).",
    subcommandsRepeatable = false)
public final class HandSim implements Runnable {

    /** Every sub-command, in the order `handsim --help` lists them. */
    static final List<Class<?>> SUBCOMMANDS = List.of(
        FkCommand.class,
        IkCommand.class,
        MeshCommand.class,
        IdCommand.class,
        CollideCommand.class,
        RunCommand.class,
        SweepCommand.class,
        GuiCommand.class,
        TradeoffCommand.class,
        SwingCommand.class,
        QualityCommand.class,
        GraspCommand.class,
        PlanCommand.class
        // sub-commands register here, one line each
    );

    @Override
    public void run() {
        CommandLine.usage(this, System.out);
    }

    /** Runs the command line and returns the exit code (does not call System.exit). */
    public static int execute(String... args) {
        return execute(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    /** Runs the command line with the given streams and returns the exit code. */
    public static int execute(PrintWriter out, PrintWriter err, String... args) {
        prepareHeadless();
        CommandLine cl = new CommandLine(new HandSim());
        for (Class<?> c : SUBCOMMANDS) cl.addSubcommand(c);
        cl.setOut(out);
        cl.setErr(err);
        cl.setParameterExceptionHandler((ex, a) -> {
            err.println("handsim: " + ex.getMessage());
            err.println("Try '" + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help'.");
            return CliError.USAGE;
        });
        cl.setExecutionExceptionHandler((ex, line, parsed) -> {
            if (ex instanceof CliError) {
                err.println(ex.getMessage());
                return ((CliError) ex).exitCode();
            }
            err.println("handsim: internal error: " + ex);
            ex.printStackTrace(err);
            return 1;
        });
        int code = cl.execute(args);
        out.flush();
        err.flush();
        return code;
    }

    /**
     * Java3D's VirtualUniverse throws HeadlessException without a display unless the no-op
     * renderer is chosen before the first Java3D class loads (DESIGN.md, "Headless").
     */
    static void prepareHeadless() {
        if (System.getProperty("j3d.rend") == null
            && (GraphicsEnvironment.isHeadless() || System.getenv("DISPLAY") == null)) {
            System.setProperty("j3d.rend", "noop");
            System.setProperty("java.awt.headless", "true");
        }
    }

    public static void main(String[] args) {
        System.exit(execute(args));
    }
}
