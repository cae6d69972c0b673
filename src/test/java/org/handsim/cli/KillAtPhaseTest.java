package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.handsim.files.OutputSet;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A command stopped at any point leaves its folder with a whole set of outputs, the old one or
 * the new one, never a mixture. Each command runs in a child JVM that pauses at a named point of
 * its work ({@code org.handsim.process.Phase}) and is stopped there with SIGTERM or with SIGKILL,
 * at ten points of {@code run}, {@code plan}, {@code sweep} and {@code tradeoff}: during the
 * computation, between the files, and between the renames of the publication. The folder starts
 * with the previous run's set plus a file of the set the new run does not write (a chart of a
 * finger that no longer moves, a best grasp beyond the new count, a study not run again), which
 * the new set must not leave behind.
 *
 * <p>Afterwards the folder holds exactly the old set, byte for byte, or exactly a whole new set
 * (checked for consistency: the table's rows against the summary), and at most one hidden
 * temporary folder (none after SIGTERM). A SIGKILL in the middle of the renames leaves the
 * marker file absent and the manifest beside it; the next writer completes the publication
 * ({@link OutputSet#recover}, what every command does first), giving the new whole set.
 */
@Tag("slow")
class KillAtPhaseTest {
    /** Whether a folder holds the new run's whole set: null if so, else what is wrong. */
    interface NewSet {
        String problem(Path out, Map<String, byte[]> old) throws Exception;
    }

    record Case(String[] oldArgs, String[] newArgs, Map<String, String> planted, String marker, List<String> phases, NewSet check) {}

    @Test
    void run() throws Exception {
        exercise("run", new Case(
            new String[] {"run", "--dt", "0.01"},
            new String[] {"run", "--dt", "0.005"},
            Map.of("fig7_finger1.png", "a stale chart", "fig8_finger1.svg", "<svg/>"),
            "summary.json",
            List.of("half-run", "chart", "trace", "staged", "manifest", "old-marker-removed", "tables-published", "charts-published", "stale-removed", "published"),
            KillAtPhaseTest::wholeRun));
    }

    @Test
    void plan() throws Exception {
        exercise("plan", new Case(
            // the old set has more best/ grasps (5 with force closure) than the new one (4), so a stale file is removed
            new String[] {"plan", TestPaths.root().resolve("vrml/objects/cube.wrl").toString(), "--trials", "8", "--seed", "3", "--threads", "1"},
            new String[] {"plan", TestPaths.root().resolve("vrml/objects/cube.wrl").toString(), "--trials", "5", "--seed", "2", "--threads", "1"},
            Map.of(),
            "plan.json",
            List.of("half-trials", "table", "best", "charts", "staged", "manifest", "tables-published", "charts-published", "stale-removed", "published"),
            KillAtPhaseTest::wholePlan));
    }

    @Test
    void sweep() throws Exception {
        exercise("sweep", new Case(
            new String[] {"sweep", "SWEEP:a,b", "--threads", "1"},
            new String[] {"sweep", "SWEEP:c,d,e", "--threads", "1"},
            Map.of(),
            "summary.csv",
            List.of("opened", "first-row", "half-rows", "last-row", "table", "staged", "manifest", "old-marker-removed", "marker-published", "published"),
            KillAtPhaseTest::wholeSweep));
    }

    @Test
    void tradeoff() throws Exception {
        exercise("tradeoff", new Case(
            new String[] {"tradeoff", "--quick", "--only", "4"},
            new String[] {"tradeoff", "--quick", "--only", "4"},
            Map.of("2-tessellation.csv", "series,setting\n", "2-tessellation.png", "png", "2-tessellation.svg", "<svg/>"),
            "tradeoff.json",
            List.of("opened", "half-4-integrators", "study-4-integrators", "staged", "manifest", "old-marker-removed", "tables-published",
                "charts-published", "stale-removed", "published"),
            KillAtPhaseTest::wholeTradeoff));
    }

    private void exercise(String name, Case c) throws Exception {
        Path dir = Files.createTempDirectory("handsim-kill-" + name);
        try {
            Path out = dir.resolve("out");
            String[] oldArgs = withOut(resolveSweep(dir, c.oldArgs(), "old"), out);
            String[] newArgs = withOut(resolveSweep(dir, c.newArgs(), "new"), out);
            CliTesting.Run first = CliTesting.run(oldArgs);
            assertTrue(first.code() == 0, first.err());
            for (Map.Entry<String, String> e : c.planted().entrySet()) Files.writeString(out.resolve(e.getKey()), e.getValue());
            Map<String, byte[]> old = snapshot(out);
            assertNotNull(old.get(c.marker()), "the old set has its marker");
            assertNotNull(c.check().problem(out, old), "the checker tells the old set from a new one");
            List<String> report = new ArrayList<>();
            for (String phase : c.phases()) {
                for (boolean kill : new boolean[] {false, true}) {
                    restore(out, old);
                    String signal = kill ? "SIGKILL" : "SIGTERM";
                    ChildJvm.Started child = ChildJvm.start(dir, "1g",
                        List.of("handsim.phases=on", "handsim.phases.pause=" + phase), newArgs);
                    try {
                        waitForPhase(child, phase);
                        if (kill) child.process().destroyForcibly(); else child.process().destroy();
                        assertTrue(child.process().waitFor(2, TimeUnit.MINUTES), name + " did not stop after " + signal + " at " + phase);
                    } finally {
                        if (child.process().isAlive()) child.process().destroyForcibly().waitFor();
                        Files.deleteIfExists(child.out());
                        Files.deleteIfExists(child.err());
                    }
                    String where = name + ", " + signal + " at " + phase;
                    List<String> hidden = hidden(out);
                    assertTrue(hidden.size() <= (kill ? 1 : 0), where + ": temporary files left: " + hidden);
                    Map<String, byte[]> now = snapshot(out);
                    String state;
                    String newProblem = c.check().problem(out, old);
                    if (same(now, old)) {
                        state = "old set";
                    } else if (newProblem == null) {
                        state = "new set";
                    } else {
                        assertTrue(kill, where + ": neither the old set nor a whole new one: " + newProblem + "; files " + now.keySet());
                        assertFalse(now.containsKey(c.marker()), where + ": a mixed set must not show the marker " + c.marker() + ": " + now.keySet());
                        assertTrue(Files.isRegularFile(manifest(out)), where + ": a mixed set only while its publication's manifest is there");
                        state = "publication under way (marker absent)";
                    }
                    boolean committed = Files.isRegularFile(manifest(out));
                    OutputSet.recover(out);   // what the next command into the folder does first
                    assertEquals(List.of(), hidden(out), where + ": the next writer removes what was left");
                    if (committed) {   // the manifest was written: the publication had begun and is completed
                        assertEquals(null, c.check().problem(out, old), where + ": the next writer completes the publication");
                        state += ", publication completed by the next writer";
                    } else {
                        assertTrue(same(snapshot(out), now), where + ": the next writer changes nothing of a whole set");
                    }
                    report.add(signal + " at " + phase + ": " + state);
                }
            }
            // the next run of the command itself, after a SIGKILL, removes the leftovers and publishes a whole new set
            restore(out, old);
            ChildJvm.Started child = ChildJvm.start(dir, "1g", List.of("handsim.phases=on", "handsim.phases.pause=staged"), newArgs);
            try {
                waitForPhase(child, "staged");
                child.process().destroyForcibly().waitFor();
            } finally {
                Files.deleteIfExists(child.out());
                Files.deleteIfExists(child.err());
            }
            assertEquals(List.of(OutputSet.WORK), hidden(out), "SIGKILL before the publication leaves the work folder");
            assertTrue(same(snapshot(out), old), "and the old set");
            CliTesting.Run next = CliTesting.run(newArgs);
            assertTrue(next.code() == 0, next.err());
            assertEquals(List.of(), hidden(out));
            assertEquals(null, c.check().problem(out, old));
            System.out.println(name + ":\n  " + String.join("\n  ", report));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    private static String[] withOut(String[] args, Path out) {
        String[] a = Arrays.copyOf(args, args.length + 2);
        a[args.length] = "--out";
        a[args.length + 1] = out.toString();
        return a;
    }

    /** {@code SWEEP:l1,l2} becomes a sweep file of the paper's experiment at dt 0.01 s, one run per label. */
    private static String[] resolveSweep(Path dir, String[] args, String name) throws Exception {
        String[] a = args.clone();
        for (int i = 0; i < a.length; i++) {
            if (!a[i].startsWith("SWEEP:")) continue;
            StringBuilder runs = new StringBuilder();
            for (String label : a[i].substring(6).split(",")) {
                if (runs.length() > 0) runs.append(',');
                runs.append("{\"label\": \"").append(label).append("\", \"set\": {\"dt_s\": 0.01}}");
            }
            Path f = dir.resolve(name + "-sweep.json");
            Files.writeString(f, "{\"name\": \"s\", \"base\": \"" + TestPaths.root().resolve("scenarios/paper-breakaway.json")
                + "\", \"runs\": [" + runs + "]}");
            a[i] = f.toString();
        }
        return a;
    }

    private static void waitForPhase(ChildJvm.Started child, String phase) throws Exception {
        long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(3);
        while (System.nanoTime() < end) {
            String err = child.errText();
            if (err.contains("handsim-phase " + phase + "\n")) return;
            if (!child.process().isAlive()) fail("the command ended before the point " + phase + ": " + err);
            Thread.sleep(20);
        }
        fail("the point " + phase + " was not reached within 3 minutes: " + child.errText());
    }

    /** Every file under the folder but the hidden ones, by relative path. */
    static Map<String, byte[]> snapshot(Path out) throws Exception {
        Map<String, byte[]> m = new TreeMap<>();
        if (!Files.isDirectory(out)) return m;
        try (Stream<Path> s = Files.walk(out)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String rel = out.relativize(p).toString();
                if (rel.isEmpty() || rel.startsWith(".") || rel.contains("/.") || !Files.isRegularFile(p)) continue;
                m.put(rel, Files.readAllBytes(p));
            }
        }
        return m;
    }

    static boolean same(Map<String, byte[]> a, Map<String, byte[]> b) {
        if (!a.keySet().equals(b.keySet())) return false;
        for (String k : a.keySet()) if (!Arrays.equals(a.get(k), b.get(k))) return false;
        return true;
    }

    private static void restore(Path out, Map<String, byte[]> set) throws Exception {
        ChildJvm.deleteTree(out);
        for (Map.Entry<String, byte[]> e : set.entrySet()) {
            Path p = out.resolve(e.getKey());
            Files.createDirectories(p.getParent());
            Files.write(p, e.getValue());
        }
    }

    /** Hidden names anywhere under the folder (temporary files and folders). */
    static List<String> hidden(Path out) throws Exception {
        List<String> h = new ArrayList<>();
        if (!Files.isDirectory(out)) return h;
        try (Stream<Path> s = Files.walk(out, 2)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String rel = out.relativize(p).toString();
                if (rel.startsWith(".") && !rel.contains("/") || rel.contains("/.") && !rel.startsWith(".")) h.add(rel);
            }
        }
        return h;
    }

    private static Path manifest(Path out) throws Exception {
        if (!Files.isDirectory(out.resolve(OutputSet.WORK))) return out.resolve("none");
        try (Stream<Path> s = Files.walk(out.resolve(OutputSet.WORK))) {
            return s.filter(p -> p.getFileName().toString().equals(".publish")).findFirst().orElse(out.resolve("none"));
        }
    }

    private static List<String> lines(byte[] b) {
        return List.of(new String(b, StandardCharsets.UTF_8).split("\n"));
    }

    private static boolean sameBytes(Map<String, byte[]> now, Map<String, byte[]> old, String name) {
        return now.containsKey(name) && old.containsKey(name) && Arrays.equals(now.get(name), old.get(name));
    }

    /** The paper's run at dt = 0.005 s: trace rows = steps + 1 of the summary, finger 3's charts only, none of the old files. */
    @SuppressWarnings("unchecked")
    static String wholeRun(Path out, Map<String, byte[]> old) throws Exception {
        Map<String, byte[]> now = snapshot(out);
        List<String> want = List.of("fig7_finger3.png", "fig7_finger3.svg", "fig8_finger3.png", "fig8_finger3.svg", "summary.json", "trace.csv");
        if (!new ArrayList<>(now.keySet()).equals(want)) return "files " + now.keySet();
        Map<String, Object> s = (Map<String, Object>) Json.parse("summary.json", new String(now.get("summary.json"), StandardCharsets.UTF_8));
        if (((Number) s.get("dt_s")).doubleValue() != 0.005) return "dt_s " + s.get("dt_s");
        long steps = ((Number) s.get("steps")).longValue();
        List<String> trace = lines(now.get("trace.csv"));
        if (trace.size() != steps + 2) return trace.size() + " trace lines for " + steps + " steps";
        for (String f : List.of("trace.csv", "fig7_finger3.svg", "fig8_finger3.svg")) if (sameBytes(now, old, f)) return f + " is the old one";
        return null;
    }

    /** Plan of 5 trials, seed 2: plan.json, plan.csv's rows in trial order, best/ of the successful trials only, both charts. */
    @SuppressWarnings("unchecked")
    static String wholePlan(Path out, Map<String, byte[]> old) throws Exception {
        Map<String, byte[]> now = snapshot(out);
        if (!now.containsKey("plan.json") || !now.containsKey("plan.csv")) return "files " + now.keySet();
        Map<String, Object> j = (Map<String, Object>) Json.parse("plan.json", new String(now.get("plan.json"), StandardCharsets.UTF_8));
        if (((Number) j.get("trials")).intValue() != 5 || ((Number) j.get("seed")).intValue() != 2) return "plan.json " + j;
        List<String> rows = lines(now.get("plan.csv"));
        if (rows.size() != 6) return rows.size() + " lines in plan.csv";
        int closure = List.of(rows.get(0).split(",")).indexOf("force_closure");
        int ok = 0;   // best/ holds only the grasps with force closure
        for (int i = 1; i < rows.size(); i++) {
            if (!rows.get(i).startsWith((i - 1) + ",")) return "row " + i + ": " + rows.get(i);
            String[] cells = rows.get(i).split(",", -1);
            if (cells[1].equals("ok") && cells[closure].equals("true")) ok++;
        }
        List<String> want = new ArrayList<>();
        for (int i = 1; i <= Math.min(10, ok); i++) want.add(String.format("best/%02d.json", i));
        for (String c : List.of("epsilon-directions.png", "epsilon-directions.svg", "epsilon-histogram.png", "epsilon-histogram.svg", "plan.csv", "plan.json")) {
            want.add(c);
        }
        want.sort(null);
        if (!new ArrayList<>(now.keySet()).equals(want)) return "files " + now.keySet() + ", want " + want;
        for (String f : List.of("plan.csv", "best/01.json", "epsilon-histogram.svg")) if (sameBytes(now, old, f)) return f + " is the old one";
        return null;
    }

    /** The sweep of runs c, d, e: summary.csv with those three rows in order, all ok. */
    static String wholeSweep(Path out, Map<String, byte[]> old) throws Exception {
        Map<String, byte[]> now = snapshot(out);
        if (!new ArrayList<>(now.keySet()).equals(List.of("summary.csv"))) return "files " + now.keySet();
        List<String> rows = lines(now.get("summary.csv"));
        if (rows.size() != 4 || !rows.get(0).equals(SweepCommand.HEADER)) return rows.size() + " lines";
        for (int i = 0; i < 3; i++) if (!rows.get(i + 1).startsWith("cde".charAt(i) + ",paper-breakaway,ok,")) return "row " + rows.get(i + 1);
        return null;
    }

    /** The quick study 4 alone: its three files and tradeoff.json naming it with the CSV's row count; the old study 2 files gone. */
    @SuppressWarnings("unchecked")
    static String wholeTradeoff(Path out, Map<String, byte[]> old) throws Exception {
        Map<String, byte[]> now = snapshot(out);
        if (!new ArrayList<>(now.keySet()).equals(List.of("4-integrators.csv", "4-integrators.png", "4-integrators.svg", "tradeoff.json"))) {
            return "files " + now.keySet();
        }
        if (sameBytes(now, old, "tradeoff.json") || sameBytes(now, old, "4-integrators.csv")) return "an old file";
        Map<String, Object> j = (Map<String, Object>) Json.parse("tradeoff.json", new String(now.get("tradeoff.json"), StandardCharsets.UTF_8));
        Map<String, Object> studies = (Map<String, Object>) j.get("studies");
        if (!studies.keySet().equals(java.util.Set.of("4-integrators"))) return "studies " + studies.keySet();
        int rows = ((Number) ((Map<String, Object>) studies.get("4-integrators")).get("rows")).intValue();
        if (lines(now.get("4-integrators.csv")).size() != rows + 1) return "csv lines against rows " + rows;
        return null;
    }
}
