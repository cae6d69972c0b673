package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Two commands into one folder at once, in two processes: the second says once that it waits
 * for the first (naming its process), does not touch the folder while the first runs, and the
 * folder holds the first's whole set when the first ends, then the second's whole set — never
 * the two interleaved (before the fix: a trace.csv of 38 721 lines for 44 732 steps with the
 * two runs' rows mixed, and a 603-row plan.csv beside a plan.json of 300 trials).
 */
@Tag("slow")
class ConcurrentWritersTest {
    @Test
    void twoRunsIntoOneFolder() throws Exception {
        Path dir = Files.createTempDirectory("handsim-concurrent");
        try {
            Path out = dir.resolve("out");
            both(dir, "half-run", new String[] {"run", "--dt", "0.01", "--out", out.toString()},
                new String[] {"run", "--dt", "0.005", "--out", out.toString()}, () -> wholeRun(out, 0.01));
            assertEquals(null, wholeRun(out, 0.005), "then the second's whole set");
            assertEquals(List.of(), KillAtPhaseTest.hidden(out));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void twoPlansIntoOneFolder() throws Exception {
        Path dir = Files.createTempDirectory("handsim-concurrent");
        try {
            Path out = dir.resolve("out");
            String cube = TestPaths.root().resolve("vrml/objects/cube.wrl").toString();
            both(dir, "half-trials", new String[] {"plan", cube, "--trials", "6", "--seed", "1", "--threads", "1", "--out", out.toString()},
                new String[] {"plan", cube, "--trials", "4", "--seed", "2", "--threads", "1", "--out", out.toString()}, () -> wholePlan(out, 6, 1));
            assertEquals(null, wholePlan(out, 4, 2), "then the second's whole set");
            assertEquals(List.of(), KillAtPhaseTest.hidden(out));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    interface Check {
        String problem() throws Exception;
    }

    /**
     * Starts {@code a}, paused at {@code pausePoint}, then {@code b}; checks that b waits while a
     * is paused; lets a finish and checks the folder with {@code afterA} while b, holding the
     * lock now, is paused where it starts; then lets b finish.
     */
    private static void both(Path dir, String pausePoint, String[] a, String[] b, Check afterA) throws Exception {
        Path resumeA = dir.resolve("resume-a"), resumeB = dir.resolve("resume-b");
        ChildJvm.Started first = ChildJvm.start(dir, "1g", List.of("handsim.phases=on", "handsim.phases.pause=" + pausePoint,
            "handsim.phases.resume=" + resumeA), a);
        ChildJvm.Started second = null;
        try {
            waitFor(first, "handsim-phase " + pausePoint + "\n");
            second = ChildJvm.start(dir, "1g", List.of("handsim.phases=on", "handsim.phases.pause=opened", "handsim.phases.resume=" + resumeB), b);
            waitFor(second, "is being written by another handsim (pid " + first.process().pid() + "); waiting for it");
            Thread.sleep(1000);
            assertTrue(second.process().isAlive());
            assertFalse(second.errText().contains("handsim-phase opened"), "the second does not start writing while the first runs");
            Files.createFile(resumeA);
            assertTrue(first.process().waitFor(3, TimeUnit.MINUTES));
            assertEquals(0, first.process().exitValue(), first.errText());
            waitFor(second, "handsim-phase opened\n");
            assertEquals(null, afterA.problem(), "the first's whole set when it ends");
            Files.createFile(resumeB);
            assertTrue(second.process().waitFor(3, TimeUnit.MINUTES));
            assertEquals(0, second.process().exitValue(), second.errText());
            String err = second.errText();
            assertEquals(1, err.split("waiting for it", -1).length - 1, "the second says once that it waits: " + err);
        } finally {
            for (ChildJvm.Started s : new ChildJvm.Started[] {first, second}) {
                if (s == null) continue;
                if (s.process().isAlive()) s.process().destroyForcibly().waitFor();
                Files.deleteIfExists(s.out());
                Files.deleteIfExists(s.err());
            }
        }
    }

    private static void waitFor(ChildJvm.Started child, String text) throws Exception {
        long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(3);
        while (System.nanoTime() < end) {
            if (child.errText().contains(text)) return;
            if (!child.process().isAlive()) fail("ended before saying '" + text + "': " + child.errText());
            Thread.sleep(20);
        }
        fail("did not say '" + text + "' within 3 minutes: " + child.errText());
    }

    /** The paper's run at dt: trace rows = steps + 1 of the summary, t_s increasing. */
    @SuppressWarnings("unchecked")
    static String wholeRun(Path out, double dt) throws Exception {
        Map<String, Object> s = (Map<String, Object>) Json.parse("summary.json", Files.readString(out.resolve("summary.json")));
        if (((Number) s.get("dt_s")).doubleValue() != dt) return "dt_s " + s.get("dt_s") + ", want " + dt;
        List<String> trace = Files.readAllLines(out.resolve("trace.csv"), StandardCharsets.UTF_8);
        long steps = ((Number) s.get("steps")).longValue();
        if (trace.size() != steps + 2) return trace.size() + " trace lines for " + steps + " steps";
        double last = -1;
        for (int i = 1; i < trace.size(); i++) {
            double t = Double.parseDouble(trace.get(i).substring(0, trace.get(i).indexOf(',')));
            if (!(t > last)) return "t_s not increasing at line " + (i + 1);
            last = t;
        }
        return null;
    }

    /** A plan of n trials with seed s: plan.json says so, plan.csv has n rows in trial order. */
    @SuppressWarnings("unchecked")
    static String wholePlan(Path out, int n, int seed) throws Exception {
        Map<String, Object> j = (Map<String, Object>) Json.parse("plan.json", Files.readString(out.resolve("plan.json")));
        if (((Number) j.get("trials")).intValue() != n || ((Number) j.get("seed")).intValue() != seed) return "plan.json " + j;
        List<String> rows = Files.readAllLines(out.resolve("plan.csv"), StandardCharsets.UTF_8);
        if (rows.size() != n + 1) return rows.size() + " lines for " + n + " trials";
        for (int i = 1; i <= n; i++) if (!rows.get(i).startsWith((i - 1) + ",")) return "row " + i + ": " + rows.get(i);
        return null;
    }
}
