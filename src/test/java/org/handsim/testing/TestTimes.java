package org.handsim.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Writes, after every test run, the wall time and the CPU time each test class took to the CSV
 * named by the system property {@code handsim.testTimes} (build.gradle sets it to
 * {@code build/test-results/test-times.csv}; {@code tools/test-profile} prints it sorted).
 *
 * <p>The JUnit XML reports give wall times only, and on a loaded machine wall time says little
 * about what a test costs. The classes run one after another in one JVM, so the growth of this
 * process's CPU time (every thread: the test's, the JIT's, the collector's) and of its reaped
 * children's (the child JVMs of the end-to-end tests, counted when they exit) between a class's
 * start and end is that class's cost. Read from {@code /proc/self/stat}; elsewhere only the wall
 * time is written. Registered through {@code META-INF/services}, so nothing changes in the tests.
 */
public final class TestTimes implements TestExecutionListener {
    /** Clock ticks per second of /proc's CPU times (USER_HZ: 100 on every Linux we run on). */
    static final double TICKS_PER_S = 100.0;

    private record Mark(long wallNanos, long[] cpuTicks) {}

    private final Map<String, Mark> started = new HashMap<>();
    private final List<String> rows = new ArrayList<>();

    @Override
    public void executionStarted(TestIdentifier id) {
        String cls = className(id);
        if (cls != null) started.put(id.getUniqueId(), new Mark(System.nanoTime(), cpuTicks()));
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        String cls = className(id);
        Mark m = cls == null ? null : started.remove(id.getUniqueId());
        if (m == null) return;
        double wall = (System.nanoTime() - m.wallNanos()) / 1e9;
        long[] now = cpuTicks();
        String self = "", children = "";
        if (now != null && m.cpuTicks() != null) {
            self = String.format(Locale.ROOT, "%.2f", (now[0] - m.cpuTicks()[0]) / TICKS_PER_S);
            children = String.format(Locale.ROOT, "%.2f", (now[1] - m.cpuTicks()[1]) / TICKS_PER_S);
        }
        rows.add(String.format(Locale.ROOT, "%s,%.2f,%s,%s,%s", cls, wall, self, children,
            result.getStatus().name().toLowerCase(Locale.ROOT)));
    }

    @Override
    public void testPlanExecutionFinished(TestPlan plan) {
        String out = System.getProperty("handsim.testTimes");
        if (out == null || rows.isEmpty()) return;
        StringBuilder sb = new StringBuilder("class,wall_s,cpu_s,children_cpu_s,status\n");
        rows.forEach(r -> sb.append(r).append('\n'));
        try {
            Path p = Path.of(out);
            if (p.getParent() != null) Files.createDirectories(p.getParent());
            Files.write(p, sb.toString().getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            System.err.println("test times not written to " + out + ": " + e.getMessage());
        }
    }

    /** The test class a container stands for, or null for methods and engines. */
    private static String className(TestIdentifier id) {
        if (!id.isContainer()) return null;
        return id.getSource().filter(s -> s instanceof ClassSource)
            .map(s -> ((ClassSource) s).getClassName()).orElse(null);
    }

    /** {self user+system, reaped children's user+system} in clock ticks, or null off Linux. */
    static long[] cpuTicks() {
        try {
            String stat = Files.readString(Path.of("/proc/self/stat"));
            // the command name (field 2) may hold spaces: count fields after its closing ')'
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).trim().split("\\s+");
            // fields 14..17 of proc(5) (utime, stime, cutime, cstime) are f[11..14] here
            return new long[] {Long.parseLong(f[11]) + Long.parseLong(f[12]),
                Long.parseLong(f[13]) + Long.parseLong(f[14])};
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }
}
