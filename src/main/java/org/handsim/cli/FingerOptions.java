package org.handsim.cli;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * The options {@code fk}, {@code ik} and {@code id} share (a picocli mixin): the finger of a
 * single question, or a CSV file of questions in and their answers out.
 */
final class FingerOptions {
    @Option(names = "--finger", paramLabel = "K", description = "finger 1, 2 or 3")
    Integer finger;

    @Option(names = "--input", paramLabel = "IN.csv", description = "bulk input (the header is given above)")
    Path input;

    @Option(names = "--output", paramLabel = "OUT.csv", description = "bulk output (written only if every row succeeds)")
    Path output;

    /** Whether the command works on a CSV file rather than one question. */
    boolean bulk() {
        return input != null || output != null;
    }
}
