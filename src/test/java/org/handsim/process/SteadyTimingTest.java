package org.handsim.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link SteadyTiming}: the warm-up rules and the batches (what is timed, never how fast). */
class SteadyTimingTest {
    @Test
    void warmsUpByTimeAndCountThenTimesTheBatches() {
        long[] calls = {0};
        // the commands' cap (the test JVM lowers the default one: handsim.timing.warmupCapSeconds)
        SteadyTiming.Result r = SteadyTiming.median(() -> ++calls[0], 7, SteadyTiming.WARMUP_CAP_SECONDS);
        assertTrue(r.warmupCalls() >= SteadyTiming.WARMUP_CALLS, "at least 10 000 warm-up calls: " + r.warmupCalls());
        assertTrue(r.warmupSeconds() >= SteadyTiming.WARMUP_SECONDS, "at least 0.5 s of warm-up: " + r.warmupSeconds());
        if (java.lang.management.ManagementFactory.getCompilationMXBean().isCompilationTimeMonitoringSupported()) {
            assertTrue(r.warmupSeconds() >= SteadyTiming.WARMUP_SECONDS + SteadyTiming.JIT_QUIET_SECONDS,
                "then at least 0.25 s with the JIT idle: " + r.warmupSeconds());
        }
        assertEquals(7, r.samples());
        assertEquals(r.warmupCalls() + r.timedCalls(), calls[0], "every call is warm-up or timed");
        assertTrue(r.timedCalls() % 7 == 0 && r.timedCalls() >= 7, "equal batches: " + r.timedCalls());
        assertTrue(r.medianSeconds() > 0 && r.medianMicros() == r.medianSeconds() * 1e6);
        assertThrows(IllegalArgumentException.class, () -> SteadyTiming.median(() -> 1, 0));
    }

    /** The suite's JVM caps the commands' warm-up (timings are not what tests check); a bad value keeps the default. */
    @Test
    void theWarmUpCapCanBeLoweredBySystemProperty() {
        String before = System.getProperty("handsim.timing.warmupCapSeconds");
        try {
            System.setProperty("handsim.timing.warmupCapSeconds", "0.05");
            assertEquals(0.05, SteadyTiming.warmupCap());
            System.setProperty("handsim.timing.warmupCapSeconds", "nonsense");
            assertEquals(SteadyTiming.WARMUP_CAP_SECONDS, SteadyTiming.warmupCap());
            System.setProperty("handsim.timing.warmupCapSeconds", "100");
            assertEquals(SteadyTiming.WARMUP_CAP_SECONDS, SteadyTiming.warmupCap(), "never above the commands' cap");
            System.clearProperty("handsim.timing.warmupCapSeconds");
            assertEquals(SteadyTiming.WARMUP_CAP_SECONDS, SteadyTiming.warmupCap());
        } finally {
            if (before != null) System.setProperty("handsim.timing.warmupCapSeconds", before);
            else System.clearProperty("handsim.timing.warmupCapSeconds");
        }
    }

    /** A slow operation: 10 000 calls would take 20 s, the warm-up stops at its cap (here 0.05 s); batches of one call. */
    @Test
    void aSlowOperationIsWarmedUpOnlyUpToTheCap() {
        SteadyTiming.Result r = SteadyTiming.median(() -> {
            long end = System.nanoTime() + 2_000_000;
            long n = 0;
            while (System.nanoTime() < end) n++;
            return n;
        }, 3, 0.05);
        assertTrue(r.warmupCalls() < 1000, "capped long before 10 000 calls: " + r.warmupCalls());
        assertTrue(r.warmupSeconds() >= 0.05, "warms up until the cap: " + r.warmupSeconds());
        assertEquals(3, r.timedCalls(), "a call longer than a batch is a batch of one");
        assertTrue(r.medianSeconds() >= 0.002, "at least the busy-wait: " + r.medianSeconds());
    }
}
