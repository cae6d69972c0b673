package org.handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.apache.spark.SparkConf;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.JavaSparkContext;
import org.handsim.cli.HandSim;
import org.handsim.plan.IndexedJob;
import org.handsim.plan.LocalEngine;
import org.handsim.plan.PlanJob;
import org.handsim.plan.PlanSpec;
import org.handsim.plan.TrialEngine;
import org.handsim.plan.TrialResult;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The Spark engine gives the local engine's table: embedded ({@code local[2]}), with a task that
 * fails on its first attempt and is retried ({@code local[2,2]}), and on a one-machine
 * standalone cluster started by {@code tools/spark-cluster}; and {@code handsim plan|sweep
 * --engine spark} write the same files as {@code --engine local}.
 */
class SparkEngineTest {
    static final Path ROOT = Path.of(System.getProperty("handsim.root", "..")).toAbsolutePath().normalize();
    static final Path MUG = ROOT.resolve("vrml/objects/mug.wrl");
    static final int WALL = 17;

    static PlanSpec spec(int n) {
        return PlanSpec.forTarget(MUG, n, 21, 0.5, 8);
    }

    static List<String> local(PlanSpec s) throws Exception {
        List<String> rows = new ArrayList<>();
        new LocalEngine().run(new PlanJob(s), s.trials(), new TrialEngine.Settings(1, null, "t"), r -> rows.add(r.csvRow()));
        return withoutTiming(rows);
    }

    static List<String> withoutTiming(List<String> lines) {
        List<String> out = new ArrayList<>();
        for (String l : lines) {
            String[] f = l.split(",", -1);
            if (f.length > WALL && !l.startsWith("trial,")) f[WALL] = "";
            out.add(String.join(",", f));
        }
        return out;
    }

    @Test
    @Tag("slow")   // a Spark context starts: about 10 s; ./test --all (CI)
    void embeddedLocal2GivesTheLocalTable() throws Exception {
        PlanSpec s = spec(10);
        List<String> rows = new ArrayList<>();
        new SparkEngine().run(new PlanJob(s), 10, new TrialEngine.Settings(2, "local[2]", "test"), r -> rows.add(r.csvRow()));
        assertEquals(local(s), withoutTiming(rows));
    }

    static final AtomicInteger FIRST_ATTEMPT_FAILURES = new AtomicInteger();

    /** Fails trial 5's task on its first attempt (after trial 4 of the same chunk has run). */
    static final class FailOnce implements IndexedJob<TrialResult> {
        private static final long serialVersionUID = 1L;
        final PlanJob job;

        FailOnce(PlanJob job) { this.job = job; }

        @Override
        public TrialResult run(int index) {
            if (index == 5 && TaskContext.get().attemptNumber() == 0) {
                FIRST_ATTEMPT_FAILURES.incrementAndGet();
                throw new IllegalStateException("injected executor failure at trial 5");
            }
            return job.run(index);
        }
    }

    @Test
    @Tag("slow")   // a task killed and retried: seconds of Spark: ./test --all (CI)
    void aRetriedTaskIsCountedOnce() throws Exception {
        PlanSpec s = spec(12);
        FIRST_ATTEMPT_FAILURES.set(0);
        SparkConf conf = SparkEngine.conf(new TrialEngine.Settings(2, "local[2,2]", "retry test"));   // 2 attempts per task
        List<String> rows = new ArrayList<>();
        List<Integer> indices = new ArrayList<>();
        try (JavaSparkContext sc = new JavaSparkContext(conf)) {
            sc.setLogLevel("OFF");   // the injected failure is expected: no stack trace in the test output
            int dropped = SparkEngine.runOn(sc, new FailOnce(new PlanJob(s)), 12, r -> {
                rows.add(r.csvRow());
                indices.add(r.index());
            });
            assertEquals(0, dropped);
        }
        assertEquals(1, FIRST_ATTEMPT_FAILURES.get(), "the first attempt failed once and was retried");
        for (int i = 0; i < 12; i++) assertEquals(i, (int) indices.get(i));
        assertEquals(local(s), withoutTiming(rows));
    }

    /** Chunks in any order, with a duplicate: every result once, in order. */
    @Test
    void chunksAreReorderedAndDuplicatesDropped() {
        List<Integer> got = new ArrayList<>();
        ChunkOrder<Integer> o = new ChunkOrder<>(4, 3, got::add);
        o.offer(chunk(2, 3));
        o.offer(chunk(0, 3));
        assertEquals(List.of(0, 1, 2), got);
        assertEquals(1, o.held());
        o.offer(chunk(0, 3));        // a retried task's second copy
        o.offer(chunk(3, 3));
        o.offer(chunk(2, 3));
        o.offer(chunk(1, 3));
        assertTrue(o.complete());
        assertEquals(List.of(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11), got);
        assertEquals(2, o.dropped());
    }

    static SparkEngine.Chunk<Integer> chunk(int part, int size) {
        ArrayList<Integer> r = new ArrayList<>();
        for (int i = part * size; i < (part + 1) * size; i++) r.add(i);
        return new SparkEngine.Chunk<>(part, part * size, r);
    }

    /**
     * tools/spark-cluster start: a standalone master and worker (separate JVMs); the plan on it
     * gives the local table, and so does {@code plan --hold-test}'s (PlanHoldEnginesTest's three trials).
     */
    @Test
    @Tag("slow")   // a master and a worker in child JVMs: ./test --all (CI)
    void standaloneClusterGivesTheLocalTable() throws Exception {
        Path state = Files.createTempDirectory("spark-cluster");
        try {
            String url = tool("start", "--cores", "2", "--memory", "1g", "--state", state.toString()).trim();
            assertTrue(url.startsWith("spark://127.0.0.1:"), url);
            PlanSpec s = spec(8);
            List<String> rows = new ArrayList<>();
            new SparkEngine().run(new PlanJob(s), 8, new TrialEngine.Settings(2, url, "cluster test"), r -> rows.add(r.csvRow()));
            assertEquals(local(s), withoutTiming(rows));
            assertTrue(Files.list(state.resolve("work")).count() > 0, "the worker launched an executor process");
            PlanSpec hold = PlanHoldEnginesTest.spec();
            List<String> holdRows = new ArrayList<>();
            new SparkEngine().run(new PlanJob(hold), hold.trials(), new TrialEngine.Settings(2, url, "cluster hold test"), r -> holdRows.add(r.csvRow(true)));
            assertEquals(PlanHoldEnginesTest.oneThread(hold), withoutTiming(holdRows), "plan --hold-test on the standalone cluster");
        } finally {
            tool("stop", "--state", state.toString());
            assertTrue(!Files.exists(state.resolve("master.pid")) && !Files.exists(state.resolve("worker.pid")));
            deleteTree(state);
        }
    }

    static String tool(String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(ROOT.resolve("tools/spark-cluster").toString());
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        String out = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "tools/spark-cluster " + args[0] + " finished");
        assertEquals(0, p.exitValue(), "tools/spark-cluster " + String.join(" ", args));
        return out;
    }

    /** handsim plan and handsim sweep with --engine spark --master local[2] write the --engine local files. */
    @Test
    @Tag("slow")   // plan and sweep end to end on Spark: ./test --all (CI)
    void commandsWriteTheSameTables() throws Exception {
        Path dir = Files.createTempDirectory("spark-cmd");
        try {
            run("plan", MUG.toString(), "--trials", "6", "--seed", "4", "--engine", "spark", "--master", "local[2]", "--out", dir.resolve("s").toString());
            run("plan", MUG.toString(), "--trials", "6", "--seed", "4", "--threads", "1", "--out", dir.resolve("l").toString());
            assertEquals(withoutTiming(Files.readAllLines(dir.resolve("l/plan.csv"))), withoutTiming(Files.readAllLines(dir.resolve("s/plan.csv"))));
            assertEquals(Files.readString(dir.resolve("l/best/01.json")), Files.readString(dir.resolve("s/best/01.json")));
            assertTrue(Files.readString(dir.resolve("s/plan.json")).contains("\"engine\": \"spark\""));

            String sweep = ROOT.resolve("scenarios/sweeps/cube-offsets.json").toString();
            run("sweep", sweep, "--engine", "spark", "--master", "local[2]", "--out", dir.resolve("ws").toString());
            run("sweep", sweep, "--threads", "2", "--out", dir.resolve("wl").toString());
            assertEquals(withoutSweepTiming(Files.readAllLines(dir.resolve("wl/summary.csv"))),
                withoutSweepTiming(Files.readAllLines(dir.resolve("ws/summary.csv"))));
        } finally {
            deleteTree(dir);
        }
    }

    /** summary.csv without its wall_time_s column (index 5). */
    static List<String> withoutSweepTiming(List<String> lines) {
        List<String> out = new ArrayList<>();
        for (String l : lines) {
            String[] f = l.split(",", -1);
            if (f.length > 5) f[5] = "";
            out.add(String.join(",", f));
        }
        return out;
    }

    static void run(String... args) {
        StringWriter o = new StringWriter(), e = new StringWriter();
        int code = HandSim.execute(new PrintWriter(o), new PrintWriter(e), args);
        assertEquals(0, code, String.join(" ", args) + ": " + e);
    }

    static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) Files.delete(p);
        }
    }
}
