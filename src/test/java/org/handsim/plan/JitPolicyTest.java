package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.junit.jupiter.api.Test;

/**
 * The launcher's compiler choice for {@code plan} ({@code tools/jit-policy}, sourced by
 * {@code ./handsim} and a bundle's {@code bin/handsim}) on machines of 2 and 16 cores (a fake
 * {@code nproc}): C1 alone when trials / T &lt; 1000 + (free cores &lt; 2 ? 4000 / T : 0), else C2
 * without on-stack replacement — each case worked out by hand from that rule.
 */
class JitPolicyTest {
    static final String C1 = "-XX:TieredStopAtLevel=1", C2 = "-XX:-UseOnStackReplacement";

    static String flags(int cores, Map<String, String> env, String... args) throws Exception {
        Path dir = Files.createTempDirectory("jit-policy");
        try {
            Path nproc = dir.resolve("nproc");
            Files.writeString(nproc, "#!/bin/sh\necho " + cores + "\n");
            assertTrue(nproc.toFile().setExecutable(true));
            List<String> cmd = new ArrayList<>(List.of("bash", "-c", "source \"$0\"; handsim_jit_flags \"$@\"",
                TestPaths.root().resolve("tools/jit-policy").toString()));
            cmd.addAll(List.of(args));
            ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
            pb.environment().put("PATH", dir + ":" + System.getenv("PATH"));
            pb.environment().remove("HANDSIM_JIT");
            pb.environment().remove("HANDSIM_JAVA_OPTS");
            pb.environment().putAll(env);
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes()).trim();
            assertTrue(p.waitFor(30, TimeUnit.SECONDS));
            assertEquals(0, p.exitValue(), out);
            return out;
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    static String plan(int cores, String trials, String threads) throws Exception {
        return threads == null ? flags(cores, Map.of(), "plan", "mug.wrl", "--trials", trials)
            : flags(cores, Map.of(), "plan", "mug.wrl", "--trials", trials, "--threads", threads);
    }

    @Test
    void sixteenCores() throws Exception {
        // 16 threads, no free core: C1 below (1000 + 4000/16) · 16 = 20 000 trials
        assertEquals(C1, plan(16, "2000", null));
        assertEquals(C1, plan(16, "19999", "16"));
        assertEquals(C2, plan(16, "20000", "16"));
        // one thread, 15 free cores: C1 below 1000 trials
        assertEquals(C1, plan(16, "999", "1"));
        assertEquals(C2, plan(16, "1000", "1"));
        assertEquals(C2, plan(16, "2000", "1"));
        // 15 threads, one free core: (1000 + 4000/15 = 1266) · 15 = 18 990
        assertEquals(C1, plan(16, "18989", "15"));
        assertEquals(C2, plan(16, "18990", "15"));
        // 8 threads, 8 free cores: 8 000
        assertEquals(C1, plan(16, "7999", "8"));
        assertEquals(C2, plan(16, "8000", "8"));
    }

    @Test
    void twoCores() throws Exception {
        // 2 threads (the default): (1000 + 2000) · 2 = 6 000; one thread, one free core: 5 000
        assertEquals(C1, plan(2, "5999", null));
        assertEquals(C2, plan(2, "6000", null));
        assertEquals(C1, plan(2, "4999", "1"));
        assertEquals(C2, plan(2, "5000", "1"));
        // more threads than cores count as the cores; the default --trials is 500
        assertEquals(C1, plan(2, "5999", "8"));
        assertEquals(C1, flags(2, Map.of(), "plan", "mug.wrl"));
        assertEquals(C2, flags(2, Map.of(), "plan", "mug.wrl", "--trials=6000", "--threads=2"));
    }

    @Test
    void overridesAndOtherCommands() throws Exception {
        assertEquals(C1, flags(16, Map.of("HANDSIM_JIT", "c1"), "plan", "mug.wrl", "--trials", "100000"));
        assertEquals("", flags(16, Map.of("HANDSIM_JIT", "c2"), "plan", "mug.wrl", "--trials", "10"));
        assertEquals("", flags(16, Map.of("HANDSIM_JAVA_OPTS", "-Xmx2g -XX:TieredStopAtLevel=3"), "plan", "mug.wrl"));
        assertEquals(C1, flags(16, Map.of("HANDSIM_JAVA_OPTS", "-XX:StartFlightRecording=filename=x.jfr"), "plan", "mug.wrl"));
        assertEquals("", flags(16, Map.of(), "plan", "mug.wrl", "--engine", "spark"));
        assertEquals("", flags(16, Map.of(), "run"));
        assertEquals("", flags(16, Map.of(), "sweep", "s.json", "--trials", "10"));
        assertEquals("", flags(2, Map.of(), "plan", "mug.wrl", "--trials", "many"), "a bad --trials is the command's to report");
        String bad = flags(2, Map.of("HANDSIM_JIT", "fast"), "plan", "mug.wrl");
        assertTrue(bad.startsWith("handsim: HANDSIM_JIT must be auto, c1 or c2, got 'fast'") && bad.endsWith(C1), bad);
    }
}
