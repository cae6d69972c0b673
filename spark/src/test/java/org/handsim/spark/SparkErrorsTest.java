package org.handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim plan --engine spark} as a user runs it (a child JVM started as ./handsim starts
 * it): Spark says that it is starting and where it logs, then the plan's progress, and nothing of
 * Spark's own logging reaches the terminal (it is in the named file). A bad master with Spark on
 * the class path is still refused before Spark starts; an unreachable one within 15 s with its
 * URL and the reason.
 */
@Tag("slow")
class SparkErrorsTest {
    /** Exit code, standard output, standard error of {@code handsim ARGS} in a child JVM with Spark's JVM options. */
    record Run(int code, String out, String err, double seconds) {}

    static Run handsim(Path dir, String... args) throws Exception {
        Path lib = Path.of(System.getProperty("handsim.sparkLib"));
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xss16m");
        cmd.add("-Xmx1g");
        cmd.addAll(Files.readAllLines(lib.resolve("jvm-opens.txt")));
        cmd.add("-Djava.io.tmpdir=" + dir);
        cmd.add("-Dhandsim.home=" + SparkEngineTest.ROOT);
        cmd.add("-cp");
        cmd.add(lib + "/*");
        cmd.add("org.handsim.cli.HandSim");
        cmd.addAll(List.of(args));
        Path out = dir.resolve("child.out"), err = dir.resolve("child.err");
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        assertTrue(p.waitFor(5, TimeUnit.MINUTES), "handsim " + String.join(" ", args) + " finished");
        return new Run(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8).trim(), Files.readString(err, StandardCharsets.UTF_8).trim(),
            (System.nanoTime() - t0) / 1e9);
    }

    @Test
    void sparkSaysItIsStartingThenItsProgressAndLogsToAFile() throws Exception {
        Path dir = Files.createTempDirectory("spark-log");
        try {
            Run r = handsim(dir, "plan", SparkEngineTest.MUG.toString(), "--trials", "8", "--engine", "spark", "--master", "local[2]",
                "--out", dir.resolve("plan").toString());
            assertEquals(0, r.code(), r.err());
            String[] lines = r.err().split("\n");
            Matcher m = Pattern.compile("handsim plan mug: starting Spark \\(master local\\[2\\]; Spark's log: (.*spark-[0-9]+\\.log)\\);"
                + " progress follows once the first tasks finish").matcher(lines[1]);
            assertTrue(lines[0].startsWith("handsim plan: mug.wrl: units "), lines[0]);
            assertTrue(m.matches(), lines[1]);
            for (int i = 2; i < lines.length; i++) assertTrue(lines[i].matches("handsim plan mug: [0-9]+% \\([0-9.]+ s\\)"), "only progress: " + lines[i]);
            assertTrue(lines[lines.length - 1].startsWith("handsim plan mug: 100% "), r.err());
            Path log = Path.of(m.group(1));
            assertTrue(log.startsWith(dir.resolve("handsim-logs")), log.toString());
            String spark = Files.readString(log);
            assertTrue(spark.contains("SparkContext: Running Spark version"), spark);
            assertFalse(r.err().contains("INFO") || r.err().contains("WARN") || r.err().contains("spark:"), r.err());
        } finally {
            SparkEngineTest.deleteTree(dir);
        }
    }

    @Test
    void aBadOrUnreachableMasterIsOneLine() throws Exception {
        Path dir = Files.createTempDirectory("spark-master");
        try {
            Run bad = handsim(dir, "plan", SparkEngineTest.MUG.toString(), "--engine", "spark", "--master", "local[-1]");
            assertEquals(2, bad.code(), bad.err());
            assertTrue(bad.err().startsWith("handsim: --master 'local[-1]' is not a Spark master: use local, local[N]"), bad.err());
            assertFalse(bad.err().contains("\n"), bad.err());
            int port;
            try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
                port = s.getLocalPort();
            }
            Run gone = handsim(dir, "sweep", SparkEngineTest.ROOT.resolve("scenarios/sweeps/cube-offsets.json").toString(), "--engine", "spark",
                "--master", "spark://127.0.0.1:" + port);
            assertEquals(2, gone.code(), gone.err());
            assertEquals("handsim: --master spark://127.0.0.1:" + port + ": cannot connect (127.0.0.1:" + port + ": Connection refused);"
                + " is the cluster running? (tools/spark-cluster start prints its URL)", gone.err());
            assertTrue(gone.seconds() < 15, gone.seconds() + " s");
        } finally {
            SparkEngineTest.deleteTree(dir);
        }
    }
}
