package org.handsim.testing;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Keeps what tests print off the console: a passing run shows only the build's own lines and
 * the count. While the tests run, {@code System.out} and {@code System.err} go to a buffer;
 * a test that fails has what it printed shown on the real standard error, under its name; and
 * everything every test printed is kept, one file per test class, in the folder named by the
 * system property {@code handsim.testOutput} (build.gradle: {@code build/test-results/test-output/}),
 * for a look after the run (the window tests' logs, screenshot folders).
 *
 * <p>Tests that expect an error capture the command's streams themselves
 * ({@code CliTesting.run}); this catches the rest: diagnostics printed for a failing run,
 * child JVM logs, the window's log lines. Registered through {@code META-INF/services}.
 */
public final class QuietTests implements TestExecutionListener {
    private PrintStream realOut, realErr;
    private final ByteArrayOutputStream buffer = new ByteArrayOutputStream();
    private int testStart;       // where the running test's output begins in the buffer
    private String currentClass;

    @Override
    public void testPlanExecutionStarted(TestPlan plan) {
        realOut = System.out;
        realErr = System.err;
        PrintStream capture = new PrintStream(buffer, true, StandardCharsets.UTF_8);
        System.setOut(capture);
        System.setErr(capture);
    }

    @Override
    public void executionStarted(TestIdentifier id) {
        String cls = className(id);
        if (cls != null && !cls.contains("$") && !cls.equals(currentClass)) {
            flushClass();
            currentClass = cls;
        }
        if (id.isTest()) {
            synchronized (buffer) {
                testStart = buffer.size();
            }
        }
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        if (!id.isTest() || result.getStatus() == TestExecutionResult.Status.SUCCESSFUL || realErr == null) return;
        byte[] all;
        synchronized (buffer) {
            all = buffer.toByteArray();
        }
        if (all.length > testStart) {
            realErr.println("---- output of " + id.getDisplayName() + " (" + currentClass + ") ----");
            realErr.write(all, testStart, all.length - testStart);
            realErr.println("----");
            realErr.flush();
        }
    }

    @Override
    public void testPlanExecutionFinished(TestPlan plan) {
        flushClass();
        if (realOut != null) {
            System.setOut(realOut);
            System.setErr(realErr);
        }
    }

    /** Writes the finished class's output to its file and empties the buffer. */
    private void flushClass() {
        byte[] all;
        synchronized (buffer) {
            all = buffer.toByteArray();
            buffer.reset();
            testStart = 0;
        }
        String dir = System.getProperty("handsim.testOutput");
        if (currentClass == null || all.length == 0 || dir == null) return;
        try {
            Path d = Files.createDirectories(Path.of(dir));
            Files.write(d.resolve(currentClass + ".txt"), all, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING);
        } catch (IOException e) {
            realErr.println("test output of " + currentClass + " not kept: " + e.getMessage());
        }
    }

    private static String className(TestIdentifier id) {
        return id.getSource().filter(s -> s instanceof ClassSource).map(s -> ((ClassSource) s).getClassName()).orElse(null);
    }
}
