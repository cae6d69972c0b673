package org.handsim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** How the quick suite's classes are dealt to its JVMs, and where the weights of the next run are kept. */
class ForkedLauncherTest {
    /**
     * Longest first to the least loaded JVM: 7, 5, 4, 3 and 3 s go to {7, 3} and {5, 4, 3} (10 and
     * 12 s). A class without a time weighs the known ones' median (the upper one: 5 s of 3, 4, 5, 7).
     */
    @Test
    void longestFirstToTheLeastLoaded() {
        Map<String, Double> t = Map.of("a", 7.0, "b", 5.0, "c", 4.0, "d", 3.0, "e", 3.0);
        assertEquals(List.of(List.of("a", "d"), List.of("b", "c", "e")), ForkedLauncher.deal(List.of("a", "b", "c", "d", "e"), t, 2));
        // x weighs 5 s, after b (ties in name order): a | b, x | a, c | b, x, d
        assertEquals(List.of(List.of("a", "c"), List.of("b", "d", "x")), ForkedLauncher.deal(List.of("a", "b", "c", "d", "x"),
            Map.of("a", 7.0, "b", 5.0, "c", 4.0, "d", 3.0), 2));
        assertEquals(List.of(List.of("a", "b")), ForkedLauncher.deal(List.of("b", "a"), Map.of(), 1));
    }

    @Test
    void theQuickRunsCopyBesideTheTimes() {
        assertEquals(Path.of("build/test-results/test-times.quick.csv"), ForkedLauncher.quickTimes(Path.of("build/test-results/test-times.csv")));
        assertEquals(Path.of("/tmp/times.quick"), ForkedLauncher.quickTimes(Path.of("/tmp/times")));
    }
}
