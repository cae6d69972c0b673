package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;

/**
 * Runs {@code handsim ARGS} in a child JVM with a given heap limit and reports its exit code,
 * what it printed, and its peak resident memory (VmHWM of /proc/self/status, read by the child
 * just before it exits): the tests of bounded memory.
 */
public final class ChildJvm {
    /** Exit code, standard output, standard error (without the VmHWM line) and peak resident memory in bytes (-1 if unknown). */
    public record Result(int code, String out, String err, long peakBytes) {}

    private ChildJvm() {}

    /** The child's main: {@link HandSim#execute}, then its peak resident memory as the last line on standard error. */
    public static void main(String[] args) {
        org.handsim.testing.PhaseWatch.installIfAsked();
        int code = HandSim.execute(args);
        System.err.println("VmHWM " + peakResidentBytes());
        System.exit(code);
    }

    /** Peak resident set of this process in bytes (Linux), -1 elsewhere. */
    static long peakResidentBytes() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (l.startsWith("VmHWM:")) return Long.parseLong(l.replaceAll("[^0-9]", "")) * 1024;
            }
        } catch (IOException | RuntimeException e) {
            return -1;
        }
        return -1;
    }

    /** A child JVM started by {@link #start}: the process and the files its standard output and error go to. */
    public record Started(Process process, Path out, Path err) {
        /** What the child has written on standard error so far. */
        public String errText() throws IOException {
            return Files.readString(err, StandardCharsets.UTF_8);
        }
    }

    /**
     * Starts {@code handsim args} in a child JVM with {@code -Xmx<heap>} and the given system
     * properties ({@code name=value}) in {@code dir}, its output going to files in {@code dir};
     * the caller waits for it, or stops it, and deletes the files.
     */
    public static Started start(Path dir, String heap, List<String> properties, String... args) throws IOException {
        List<String> cmd = command(dir, heap, List.of(), args);
        int at = cmd.indexOf("-cp");
        for (String p : properties) cmd.add(at, "-D" + p);
        Path out = Files.createTempFile(dir, "child", ".out"), err = Files.createTempFile(dir, "child", ".err");
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        return new Started(p, out, err);
    }

    private static List<String> command(Path dir, String heap, List<String> jvmOptions, String... args) {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(jvmOptions);
        cmd.add("-Xss16m");
        cmd.add("-Xmx" + heap);
        cmd.add("-Djava.awt.headless=true");
        cmd.add("-Dj3d.rend=noop");
        cmd.add("-Djava.io.tmpdir=" + dir.toAbsolutePath());   // its log files, if any, stay in the test's folder
        cmd.add("-Dhandsim.home=" + TestPaths.root());
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add(ChildJvm.class.getName());
        cmd.addAll(List.of(args));
        return cmd;
    }

    /** Runs {@code handsim args} in a child JVM with {@code -Xmx<heap>} in {@code dir}. */
    public static Result run(Path dir, String heap, long timeoutMinutes, String... args) throws Exception {
        return run(dir, heap, List.of(), timeoutMinutes, args);
    }

    /** As {@link #run(Path, String, long, String...)} with more options for the child JVM (before its main class). */
    public static Result run(Path dir, String heap, List<String> jvmOptions, long timeoutMinutes, String... args) throws Exception {
        List<String> cmd = command(dir, heap, jvmOptions, args);
        Path out = Files.createTempFile(dir, "child", ".out"), err = Files.createTempFile(dir, "child", ".err");
        try {
            Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            if (!p.waitFor(timeoutMinutes, TimeUnit.MINUTES)) {
                p.destroyForcibly().waitFor();
                fail("handsim " + String.join(" ", args) + " did not finish within " + timeoutMinutes + " minutes: " + Files.readString(err));
            }
            String e = Files.readString(err, StandardCharsets.UTF_8).trim();
            long peak = -1;
            int at = e.lastIndexOf("VmHWM ");
            if (at >= 0) {
                peak = Long.parseLong(e.substring(at + 6).trim());
                e = e.substring(0, at).trim();
            }
            return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8).trim(), e, peak);
        } finally {
            Files.deleteIfExists(out);
            Files.deleteIfExists(err);
        }
    }

    /** Deletes a folder and everything in it. */
    public static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (var s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s.sorted(java.util.Comparator.reverseOrder())::iterator) Files.deleteIfExists(p);
        }
    }
}
