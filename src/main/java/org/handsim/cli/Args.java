package org.handsim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.grasp.FrictionCone;
import org.handsim.hand.InputRanges;
import java.util.List;
import org.handsim.scenario.NotFound;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.UnitRule;
import org.handsim.text.Decimal;
import org.handsim.files.InputFile;
import org.handsim.files.OutputSet;
import org.handsim.text.SafeText;

/** Parsing of the comma-separated numeric arguments the sub-commands share. */
final class Args {
    private Args() {}

    /**
     * Parses {@code "a,b,c"} into exactly {@code n} finite numbers.
     *
     * @throws CliError (exit 2) naming the option and the bad value
     */
    static double[] numbers(String option, String text, int n) {
        if (text == null) throw CliError.usage("handsim: missing " + option);
        String[] parts = text.split(",", -1);
        if (parts.length != n) {
            throw CliError.usage("handsim: " + option + " needs " + n + " comma-separated numbers, got '" + SafeText.quote(text) + "'");
        }
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            try {
                out[i] = Decimal.parse(parts[i]);
            } catch (NumberFormatException e) {
                throw CliError.usage("handsim: " + option + ": '" + SafeText.quote(parts[i]) + "' is not a number");
            }
            if (!Double.isFinite(out[i])) throw CliError.usage("handsim: " + option + ": '" + SafeText.quote(parts[i]) + "' is not finite");
        }
        return out;
    }

    /**
     * Exit 3, {@code handsim: FILE: <why>}, unless {@code file} is a readable regular file
     * ({@link InputFile#problem}: a FIFO, directory or device is refused before it is opened).
     */
    static void inputFile(Path file) {
        String why = NotFound.problem(file);
        if (why != null) throw new CliError(CliError.LOAD, "handsim: " + file + ": " + why);
    }

    /**
     * {@link #numbers(String, String, int)}, each within {@code range} (exit 2 naming the option
     * and the value: {@code handsim: --qd: 1e+300 is beyond +-1000 rad/s (...)}).
     */
    static double[] numbers(String option, String text, int n, InputRanges.Range range) {
        double[] v = numbers(option, text, n);
        for (double x : v) {
            String p = range.problem(x);
            if (p != null) throw CliError.usage("handsim: " + option + ": " + p);
        }
        return v;
    }

    /** Checks {@code --frame}: true for {@code palm}, false for {@code base}. */
    static boolean palmFrame(String frame) {
        if (frame.equals("palm")) return true;
        if (frame.equals("base")) return false;
        throw CliError.usage("handsim: --frame must be base or palm, got '" + SafeText.quote(frame) + "'");
    }

    /** Checks a finger number. */
    static int finger(Integer k) {
        if (k == null) throw CliError.usage("handsim: missing --finger (1, 2 or 3)");
        if (k < 1 || k > 3) throw CliError.usage("handsim: --finger must be 1, 2 or 3, got " + k);
        return k;
    }

    /** Exit 2 naming the value unless 0 ≤ {@code --friction} ≤ 10 and 1 ≤ {@code --edges} ≤ 1024 (null: not given). */
    static void frictionAndEdges(Double friction, Integer edges) {
        if (friction != null && FrictionCone.muProblem(friction) != null) {
            throw CliError.usage("handsim: --friction " + FrictionCone.muProblem(friction));
        }
        if (edges != null && (edges < 1 || edges > 1024)) throw CliError.usage("handsim: --edges must be between 1 and 1024, got " + edges);
    }

    /**
     * {@code --units}: {@code auto} (null: judged by the file's size, {@link UnitRule}) or mm, cm, m.
     *
     * @throws CliError (exit 2) for anything else
     */
    static Scenario.Units units(String text) {
        try {
            return UnitRule.parse(text);
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: --units must be auto, mm, cm or m, got '" + SafeText.quote(text) + "'");
        }
    }

    /** The help of every {@code --units} option (the same rule everywhere: {@link UnitRule}). */
    static final String UNITS_HELP_1 = "unit of the object file's coordinates. auto";
    static final String UNITS_HELP_2 = "(default): metres up to 2 units across, else mm";
    static final String UNITS_HELP_3 = "(GraspIt!'s unit), as the window's import";

    /**
     * What the user typed for an option (its last occurrence), for error messages: "got 0" for
     * {@code --dt 0}, not the parsed double's "0.0".
     */
    static String typed(picocli.CommandLine.Model.CommandSpec spec, String option) {
        picocli.CommandLine.ParseResult r = spec.commandLine().getParseResult();
        picocli.CommandLine.Model.OptionSpec o = r == null ? null : r.matchedOption(option);
        List<String> v = o == null ? List.of() : o.stringValues();
        return v.isEmpty() ? "(none)" : SafeText.quote(v.get(v.size() - 1));
    }

    /** Formats a number for CSV output ({@link Decimal}: shortest round trip, integers plain); refuses non-finite values. */
    static String csv(double d) {
        if (!Double.isFinite(d)) throw new IllegalStateException("refusing to write non-finite value " + d);
        return Decimal.format(d);
    }

    /** Exit 2 unless an output option names something ({@code --out ''} would write into the current folder). */
    static Path outputPath(String option, Path p) {
        if (p != null && p.toString().isEmpty()) throw CliError.usage("handsim: " + option + " must name a " + (option.equals("--out") ? "folder" : "file") + ", got ''");
        return p;
    }

    /** Exit 2 unless a file output option names a file: not '', not a folder. */
    static Path outputFile(String option, Path p) {
        outputPath(option, p);
        if (p != null && Files.isDirectory(p)) throw CliError.usage("handsim: " + option + " " + p + " is a folder, not a file");
        return p;
    }

    /**
     * Opens the output set of a command in {@code dir} ({@link OutputSet}): waits for another
     * writer of the folder, saying so once on standard error; exit 2 naming {@code option} if the
     * folder cannot take the set.
     */
    static OutputSet outputSet(PrintWriter err, String option, Path dir, OutputSet.Layout layout) throws IOException {
        outputPath(option, dir);
        try {
            return OutputSet.open(dir, layout, msg -> {
                err.println("handsim: " + msg);
                err.flush();
            });
        } catch (OutputSet.Refused e) {
            throw CliError.usage("handsim: " + option + " " + dir + ": " + e.getMessage());
        } catch (java.nio.file.FileSystemException e) {
            throw cannotWrite(option, dir, e);
        }
    }

    /**
     * The single output file of {@code option} ({@link AtomicFile}); exit 2 naming the option and
     * the path when the file system will not have it there (a name too long, no permission, a
     * read-only file system).
     */
    static org.handsim.files.AtomicFile atomicOutput(String option, Path file) throws IOException {
        try {
            return new org.handsim.files.AtomicFile(file);
        } catch (java.nio.file.FileSystemException e) {
            throw cannotWrite(option, file, e);
        }
    }

    /** Exit 2: the file system refused to make {@code path} (or a folder on its way), with its reason and, for a name too long, the name's length. */
    static CliError cannotWrite(String option, Path path, java.nio.file.FileSystemException e) {
        String reason = e.getReason() != null ? e.getReason() : e.getClass().getSimpleName();
        String more = "";
        if ("File name too long".equals(reason)) {
            for (Path part : path) {
                int bytes = part.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8).length;
                if (bytes > 255) {
                    more = ": the name '" + SafeText.quote(part.toString()) + "' has " + bytes + " bytes, more than the 255 a name may have";
                    break;
                }
            }
        }
        String p = path.toString();   // the user's own path, whole unless absurdly long
        return CliError.usage("handsim: " + option + " '" + (p.length() <= 200 ? SafeText.escape(p) : SafeText.quote(p)) + "' cannot be written: "
            + reason + more);
    }

    /** Exit 2 if an output names the same file as the input (links resolved): the input would be overwritten. */
    static void notTheInput(Path input, String inputName, Path output, String option) {
        if (input == null || output == null) return;
        try {
            if (Files.exists(output) && Files.exists(input) && Files.isSameFile(input, output)) {
                throw CliError.usage("handsim: " + option + " " + output + " is the input " + inputName + " " + input + ": refusing to overwrite it");
            }
        } catch (IOException e) {
            // cannot tell: the write itself will report any problem
        }
    }
}
