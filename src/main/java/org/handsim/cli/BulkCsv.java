package org.handsim.cli;

import org.handsim.text.SafeText;
import org.handsim.scenario.NotFound;
import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import org.handsim.files.AtomicFile;
import org.handsim.files.CsvInput;
import picocli.CommandLine.Model.CommandSpec;

/**
 * The bulk form shared by {@code fk}, {@code ik} and {@code id}: read IN.csv with an exact
 * header, write OUT.csv repeating each row's input columns and adding the command's columns,
 * stop at a bad row naming its line (exit 2), and let the output appear only when every row
 * succeeded (exit 3 if IN.csv does not exist).
 */
final class BulkCsv {
    /** Computes one row's added columns (each preceded by a comma) into {@code out}. */
    @FunctionalInterface
    interface Row {
        void columns(CsvInput in, StringBuilder out);
    }

    private BulkCsv() {}

    /**
     * @param command  the sub-command's name, for messages
     * @param others   whether single-call options were also given (an error in bulk mode)
     * @param othersNames how to name those options in the error
     * @return the exit code (0)
     */
    static int run(CommandSpec spec, String command, Path input, Path output, boolean others, String othersNames,
                   String inHeader, String addedHeader, Row row) throws IOException {
        if (input == null || output == null) throw CliError.usage("handsim: bulk mode needs both --input and --output");
        if (others) throw CliError.usage("handsim: --input/--output cannot be combined with " + othersNames);
        Args.inputFile(input);
        Args.outputFile("--output", output);
        Args.notTheInput(input, "--input", output, "--output");
        int rows = 0;
        int inColumns = inHeader.split(",").length;
        try (CsvInput in = new CsvInput(input, inHeader); AtomicFile af = Args.atomicOutput("--output", output)) {
            Writer w = af.writer();
            w.write(inHeader + "," + addedHeader + "\n");
            StringBuilder sb = new StringBuilder(256);
            while (in.next()) {
                sb.setLength(0);
                for (int i = 0; i < inColumns; i++) sb.append(i == 0 ? "" : ",").append(in.text(i));
                row.columns(in, sb);
                w.append(sb).append('\n');
                rows++;
            }
            af.commit();
        } catch (CsvInput.CsvException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        }
        spec.commandLine().getErr().println("handsim " + command + ": " + rows + " rows written to " + SafeText.escape(output.toString()));
        return 0;
    }

    /** Column 0 as a finger number 1..3. */
    static int finger(CsvInput in) {
        int k = in.integer(0);
        if (k < 1 || k > 3) throw in.error("finger must be 1, 2 or 3, got " + in.text(0));
        return k;
    }
}
