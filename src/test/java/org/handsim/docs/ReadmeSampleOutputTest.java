package org.handsim.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * The README's sample output of {@code ./handsim run} is what the command prints, line for line:
 * every line it prints is shown, in its order, with the same numbers; only the wall time and the
 * speeds it gives (which vary from run to run) and the output folder are left out of the
 * comparison.
 */
class ReadmeSampleOutputTest {
    @Test
    void theRunSampleIsWhatRunPrints() throws Exception {
        List<String> readme = Files.readAllLines(TestPaths.root().resolve("README.md"));
        int at = readme.indexOf("and writes `trace.csv`, `summary.json` and the paper's Fig. 7 and Fig. 8 (PNG and SVG):");
        assertTrue(at > 0, "the sentence after the sample");
        int end = at - 1;
        while (!readme.get(end).equals("```")) end--;
        int start = end - 1;
        while (!readme.get(start).equals("```")) start--;
        List<String> shown = new ArrayList<>(readme.subList(start + 1, end));
        Path dir = Files.createTempDirectory("readme-run");
        try {
            Path out = dir.resolve("paper-breakaway");
            CliTesting.Run r = CliTesting.run("run", "--out", out.toString());
            assertEquals(0, r.code(), r.err());
            List<String> printed = new ArrayList<>(List.of(r.out().replace("\r", "").split("\n")));
            assertEquals(shown.size(), printed.size(), "the README shows every line run prints:\n" + r.out());
            for (int i = 0; i < shown.size(); i++) {
                assertEquals(normalise(shown.get(i)).replace("out/paper-breakaway/", "DIR/"),
                    normalise(printed.get(i)).replace(out + "/", "DIR/"), "line " + (i + 1));
            }
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    /** The wall time and the speeds, which vary, as placeholders. */
    private static String normalise(String line) {
        return line.replaceAll(", [0-9.]+ s wall \\([0-9]+ steps/s, [0-9]+x real time\\)", ", T s wall (S steps/s, Rx real time)");
    }
}
