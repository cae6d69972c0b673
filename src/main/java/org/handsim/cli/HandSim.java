package org.handsim.cli;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.process.CommandContext;
import org.handsim.text.Decimal;
import org.handsim.files.InputFile;
import org.handsim.text.SafeText;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;

/**
 * Entry point of the {@code handsim} command. Sub-commands are registered in
 * {@link #SUBCOMMANDS}; each has {@code --help}, and {@code handsim help CMD} shows the same.
 *
 * <p><b>Errors.</b> Every failure is one line on standard error (control and line-breaking
 * characters escaped by {@link SafeText}) and an exit code (README): a {@link CliError} with its
 * own code; an input file that is not a readable regular UTF-8 file
 * ({@link InputFile.InputFileException}), exit 3; a picocli usage error, exit 2; anything unexpected — any exception or error,
 * {@link OutOfMemoryError} and {@link StackOverflowError} included, on any thread the command
 * waited for — exit 1 with one line naming it and the path of a log file under the system's
 * temporary folder ({@code handsim-logs/}) that holds the stack trace. No command prints a
 * stack trace.
 *
 * <p><b>Help.</b> The usage width is fixed at {@value #HELP_WIDTH} columns; the synopsis is
 * wrapped between options only, never inside one ({@code [--gravity=gx,gy,gz]} stays whole);
 * the command list shows each command's first sentence whole. {@code handsim} alone prints the
 * command list on standard error and exits 2.
 */
@Command(name = "handsim", mixinStandardHelpOptions = true, version = "HandSim 0.1.0",
    description = "Simulator of the BarrettHand grasping objects from VRML97, OBJ and STL files "
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
        HoldTestCommand.class,
        PlanCommand.class
        // sub-commands register here, one line each; the launcher adds the resident server's
        // own (handsim server), which sits above this package (execute(List, String...))
    );

    /** Columns of every help text. */
    static final int HELP_WIDTH = 80;

    @picocli.CommandLine.Spec CommandSpec spec;

    /** {@code handsim} without a command: the command list on standard error, exit 2. */
    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getErr());
        throw new CliError(CliError.USAGE, "handsim: a command is needed (see the list above; 'handsim help CMD' for one command)");
    }

    /** Runs the command line and returns the exit code (does not call System.exit). */
    public static int execute(String... args) {
        return execute(List.of(), args);
    }

    /**
     * Runs the command line with {@code more} sub-commands after {@link #SUBCOMMANDS} (the
     * launcher's {@code handsim server}, whose package sits above this one) and returns the exit
     * code.
     */
    public static int execute(List<Class<?>> more, String... args) {
        return execute(new PrintWriter(System.out, true), new PrintWriter(System.err, true), more, args);
    }

    /** Runs the command line with the given streams and returns the exit code. */
    public static int execute(PrintWriter out, PrintWriter err, String... args) {
        return execute(out, err, List.of(), args);
    }

    /** Runs the command line with the given streams and {@code more} sub-commands, and returns the exit code. */
    public static int execute(PrintWriter out, PrintWriter err, List<Class<?>> more, String... args) {
        int code;
        try {
            String bytes = ArgumentBytes.problem(args);
            if (bytes != null) {
                err.println(SafeText.line(bytes));
                err.flush();
                return CliError.USAGE;
            }
            prepareHeadless(args.length > 0 ? args[0] : null);
            CommandLine cl = commandLine(args.length > 0 ? args[0] : null, more);
            cl.setOut(out);
            cl.setErr(err);
            cl.setParameterExceptionHandler((ex, a) -> {
                err.println(SafeText.line("handsim: " + ex.getMessage()) + " (try '" + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help')");
                return CliError.USAGE;
            });
            cl.setExecutionExceptionHandler((ex, line, parsed) -> failure(err, ex));
            code = cl.execute(args);
        } catch (Throwable t) {   // errors picocli does not catch (OutOfMemoryError, StackOverflowError ...)
            code = failure(err, t);
        }
        out.flush();
        err.flush();
        return code;
    }

    /** The command line with every sub-command and the help layout. */
    static CommandLine commandLine() {
        return commandLine(null, List.of());
    }

    /**
     * The command line for arguments that start with {@code first}: when that names a
     * sub-command (by the convention {@code XxxCommand} is {@code xxx}), with that one alone —
     * picocli reads every registered command's annotations, which for all of them was a good part
     * of a short command's start-up — else, or if the convention does not hold, with every one.
     */
    static CommandLine commandLine(String first, List<Class<?>> more) {
        CommandLine cl = new CommandLine(new HandSim());
        List<Class<?>> all = new ArrayList<>(SUBCOMMANDS);
        all.addAll(more);
        Class<?> only = null;
        for (Class<?> c : all) {
            if (first != null && (first.toLowerCase(java.util.Locale.ROOT) + "command").equals(c.getSimpleName().toLowerCase(java.util.Locale.ROOT))) only = c;
        }
        if (only != null) {
            cl.addSubcommand(only);
            if (!cl.getSubcommands().containsKey(first)) return commandLine(null, more);
        } else {
            for (Class<?> c : all) cl.addSubcommand(c);
            cl.addSubcommand("help", new CommandLine.HelpCommand());   // handsim help CMD
        }
        // numbers as people write them (text.Decimal.parse): '0d', '1f', 'NaN', '0x1p3' are refused
        CommandLine.ITypeConverter<Double> number = text -> {
            try {
                return Decimal.parse(text);
            } catch (NumberFormatException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        };
        cl.registerConverter(Double.class, number);
        cl.registerConverter(Double.TYPE, number);
        cl.setUsageHelpWidth(HELP_WIDTH);
        cl.setUsageHelpAutoWidth(false);
        applySynopsis(cl);
        for (CommandLine sub : cl.getSubcommands().values()) oneParagraphDescriptions(sub.getCommandSpec());
        return cl;
    }

    /**
     * Makes each option's and parameter's description one paragraph that picocli wraps itself.
     * Written as several strings (the source's line breaks), picocli starts each at the column
     * and indents only its own wrapped overflow, so one description came out indented two ways.
     */
    private static void oneParagraphDescriptions(CommandLine.Model.CommandSpec spec) {
        for (CommandLine.Model.OptionSpec o : new ArrayList<>(spec.options())) {
            if (o.description().length < 2) continue;
            spec.remove(o);
            spec.addOption(o.toBuilder().description(String.join(" ", o.description())).build());
        }
        for (CommandLine.Model.PositionalParamSpec p : new ArrayList<>(spec.positionalParameters())) {
            if (p.description().length < 2) continue;
            spec.remove(p);
            spec.addPositional(p.toBuilder().description(String.join(" ", p.description())).build());
        }
    }

    private static void applySynopsis(CommandLine cl) {
        cl.getHelpSectionMap().put(CommandLine.Model.UsageMessageSpec.SECTION_KEY_SYNOPSIS, help -> wholeOptionSynopsis(help));
        for (CommandLine sub : cl.getSubcommands().values()) applySynopsis(sub);
    }

    /**
     * picocli's synopsis, wrapped at {@link #HELP_WIDTH} only at spaces outside brackets, so an
     * option and its parameter label ({@code [--gravity=gx,gy,gz]}) are never split.
     */
    static String wholeOptionSynopsis(CommandLine.Help help) {
        CommandLine.Model.UsageMessageSpec u = help.commandSpec().usageMessage();
        int width = u.width();
        String one;
        try {
            u.width(10_000);
            one = help.synopsis(0).trim();
        } finally {
            u.width(width);
        }
        String prefix = u.synopsisHeading().replace("%n", "");
        one = one.startsWith(prefix.trim()) ? one.substring(prefix.trim().length()).trim() : one;
        String qualified = help.commandSpec().qualifiedName();
        if (one.startsWith(qualified)) one = one.substring(qualified.length()).trim();
        List<String> tokens = new ArrayList<>();
        int depth = 0, start = 0;
        for (int i = 0; i < one.length(); i++) {
            char c = one.charAt(i);
            if (c == '[' || c == '(') depth++;
            else if (c == ']' || c == ')') depth--;
            else if (c == ' ' && depth == 0) {
                if (i > start) tokens.add(one.substring(start, i));
                start = i + 1;
            }
        }
        if (start < one.length()) tokens.add(one.substring(start));
        String name = help.commandSpec().qualifiedName();
        StringBuilder sb = new StringBuilder(name);   // the heading ("Usage: ") is its own section
        int indent = prefix.length() + name.length() + 1;
        int col = indent - 1;
        for (int i = 0; i < tokens.size(); i++) {
            String t = tokens.get(i);
            if (col + 1 + t.length() > width && col > indent) {
                sb.append(System.lineSeparator()).append(" ".repeat(indent));
                col = indent;
            } else {
                sb.append(' ');
                col++;
            }
            sb.append(t);
            col += t.length();
        }
        return sb.append(System.lineSeparator()).toString();
    }

    /**
     * One line on standard error for any failure and its exit code: a {@link CliError}'s message
     * and code; anything else exit 1, naming the error and a log file with its stack trace.
     */
    static int failure(PrintWriter err, Throwable ex) {
        java.io.StringWriter line = new java.io.StringWriter();
        int code = report(new PrintWriter(line), ex);
        String text = line.toString().stripTrailing();
        String unpack = org.handsim.scenario.Home.unpackFailure();   // the cause behind a missing model, when the jar's were not unpacked
        if (!text.isEmpty()) err.println(unpack == null ? text : text + " (" + SafeText.line(unpack) + ")");
        err.flush();
        return code;
    }

    private static int report(PrintWriter err, Throwable ex) {
        // a command the resident server was told to stop: whatever its unwinding threw, no message
        // and no log (the client exits as the signal that stopped it says, as a stopped JVM does)
        if (CommandContext.cancelled()) return CliError.STOPPED;
        Throwable t = ex;
        while ((t instanceof java.util.concurrent.ExecutionException || t instanceof java.util.concurrent.CompletionException
            || t instanceof CommandLine.ExecutionException) && t.getCause() != null) t = t.getCause();
        if (t instanceof CliError) {
            err.println(SafeText.line(t.getMessage()));
            err.flush();
            return ((CliError) t).exitCode();
        }
        if (t instanceof org.handsim.text.JsonWriter.NonFiniteException) {   // an input beyond what the computation represents
            err.println(SafeText.line("handsim: " + t.getMessage() + ": an input is beyond the range the computation can represent;"
                + " nothing was written"));
            err.flush();
            return CliError.NUMERIC;
        }
        if (t instanceof org.handsim.grasp.ConvexHull.TooLargeException) {   // a grasp wrench space beyond its documented limits
            err.println(SafeText.line("handsim: " + t.getMessage()));
            err.flush();
            return CliError.USAGE;
        }
        if (t instanceof org.handsim.files.OutputSet.Refused) {   // an output folder the set may not be written into: exit 2
            err.println(SafeText.line("handsim: " + t.getMessage()));
            err.flush();
            return CliError.USAGE;
        }
        if (t instanceof org.handsim.scenario.ScenarioException) {   // a scenario's object or model that cannot be loaded: exit 3, as run says it
            err.println(SafeText.line(t.getMessage()));
            err.flush();
            return CliError.LOAD;
        }
        if (t instanceof InputFile.InputFileException) {   // an input that is not a readable regular UTF-8 file: exit 3
            err.println(SafeText.line("handsim: " + t.getMessage()));
            err.flush();
            return CliError.LOAD;
        }
        String what;
        if (t instanceof OutOfMemoryError) {
            what = "out of memory (" + t.getMessage() + "): give Java more heap, e.g. HANDSIM_JAVA_OPTS=-Xmx8g, or make the run smaller";
        } else if (t instanceof StackOverflowError) {
            what = "stack overflow (input nested too deeply): give Java a larger stack, e.g. HANDSIM_JAVA_OPTS=-Xss64m";
        } else if (t instanceof IOException || t instanceof java.io.UncheckedIOException) {
            what = "input/output error: " + (t instanceof java.io.UncheckedIOException ? t.getCause() : t);
        } else {
            what = "internal error: " + t;
        }
        if (!(t instanceof IOException || t instanceof java.io.UncheckedIOException)) CommandContext.markInDoubt(what);
        String log = writeLog(t);
        err.println(SafeText.line("handsim: " + what) + (log != null ? " (stack trace in " + log + ")" : ""));
        err.flush();
        return 1;
    }

    /** Writes the stack trace to a new file under {@code <tmp>/handsim-logs/}; null if that fails too. */
    static String writeLog(Throwable t) {
        try {
            Path dir = Path.of(System.getProperty("java.io.tmpdir"), "handsim-logs");
            Files.createDirectories(dir);
            Path f = Files.createTempFile(dir, "handsim-", ".log");
            java.io.StringWriter sw = new java.io.StringWriter();
            t.printStackTrace(new PrintWriter(sw));
            Files.writeString(f, sw.toString());
            return f.toString();
        } catch (IOException | RuntimeException | Error e) {
            return null;
        }
    }

    /**
     * Java3D's VirtualUniverse throws HeadlessException without a display unless the no-op
     * renderer is chosen before the first Java3D class loads (DESIGN.md, "Headless"). Every
     * command but {@code gui} runs headless whether or not there is a display: none of them
     * shows anything, and with a display they could not use (DISPLAY set, the X server refusing
     * the connection) loading a VRML file died in Java3D's renderer set-up and charts in AWT's.
     * Properties set on the command line are kept.
     */
    static void prepareHeadless(String command) {
        if (!"gui".equals(command)) {
            if (System.getProperty("java.awt.headless") == null) System.setProperty("java.awt.headless", "true");
            if (System.getProperty("j3d.rend") == null) System.setProperty("j3d.rend", "noop");
            return;
        }
        prepareHeadless();
    }

    /** For the window: headless (and Java3D's no-op renderer) only when there is no display. */
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
