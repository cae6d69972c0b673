package org.handsim.testing;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Runs the JUnit console launcher's arguments in several JVMs at once, each on a share of the
 * test classes, so that the quick suite uses every core: JUnit 5.2 (what the Gradle 4.4 plugin
 * runs) has no parallel execution of its own, and running classes side by side in one JVM would
 * mix what they print and the process-wide CPU times {@link TestTimes} reads. Each test class
 * runs whole in one JVM, so a class's tests still share what they share; classes that share
 * files or servers must keep them apart (they do: each takes its own temporary folder).
 *
 * <p>The number of JVMs is {@code -Dhandsim.testForks} (build.gradle sets it for the quick
 * {@code ./test}, at most the number of cores); with 1 this is the console launcher itself. Classes
 * are dealt longest first to the least loaded JVM (LPT), by the wall times of the last run
 * ({@code handsim.testTimes}, or the copy the last run in several JVMs kept of it, which a run of
 * a few classes does not overwrite; a class it lacks counts as the median). Each JVM writes its XML
 * report to {@code <reports-dir>/fork-K/} and its times to {@code <testTimes>.K}, which are then
 * joined into the one file {@code tools/test-profile} reads.
 */
public final class ForkedLauncher {
    private ForkedLauncher() {}

    private static final String CONSOLE = "org.junit.platform.console.ConsoleLauncher";

    public static void main(String[] args) throws Exception {
        int forks = Math.min(Integer.getInteger("handsim.testForks", 1), Runtime.getRuntime().availableProcessors());
        List<String> rest = new ArrayList<>();
        List<Path> scanned = new ArrayList<>();
        List<Pattern> include = new ArrayList<>();
        Path reports = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if ((a.equals("--scan-class-path") || a.equals("--scan-classpath")) && i + 1 < args.length) {
                for (String p : args[++i].split(java.io.File.pathSeparator)) scanned.add(Path.of(p));
                continue;
            }
            if (a.equals("--reports-dir") && i + 1 < args.length) {
                reports = Path.of(args[++i]);
                continue;
            }
            if ((a.equals("-n") || a.equals("--include-classname")) && i + 1 < args.length) {
                include.add(Pattern.compile(args[i + 1]));
            }
            rest.add(a);
        }
        if (forks < 2 || scanned.isEmpty() || reports == null) {
            Class.forName(CONSOLE).getMethod("main", String[].class).invoke(null, (Object) args);
            return;
        }
        List<String> classes = testClasses(scanned, include);
        List<List<String>> shares = deal(classes, lastTimes(), forks);
        String times = System.getProperty("handsim.testTimes");
        List<String> jvm = new ArrayList<>();
        for (String o : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (!o.startsWith("-Dhandsim.testTimes=") && !o.startsWith("-Dhandsim.testForks=")) jvm.add(o);
        }
        List<Process> running = new ArrayList<>();
        long start = System.nanoTime();
        List<java.util.concurrent.CompletableFuture<Long>> ended = new ArrayList<>();
        for (int k = 0; k < shares.size(); k++) {
            List<String> cmd = new ArrayList<>();
            cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
            cmd.addAll(jvm);
            if (times != null) cmd.add("-Dhandsim.testTimes=" + times + "." + k);
            cmd.add("-cp");
            cmd.add(System.getProperty("java.class.path"));
            cmd.add(CONSOLE);
            cmd.addAll(rest);
            // what the scan would have put on the class path
            cmd.add("--class-path");
            cmd.add(String.join(java.io.File.pathSeparator, scanned.stream().map(Path::toString).toList()));
            cmd.add("--reports-dir");
            cmd.add(reports.resolve("fork-" + k).toString());
            for (String c : shares.get(k)) {
                cmd.add("--select-class");
                cmd.add(c);
            }
            Process p = new ProcessBuilder(cmd).inheritIO().start();
            running.add(p);
            ended.add(p.onExit().thenApply(x -> System.nanoTime()));
        }
        int status = 0;
        for (Process p : running) {
            int code = p.waitFor();
            if (status == 0) status = code;
        }
        if (times != null) {
            joinTimes(Path.of(times), shares.size());
            // the weights of the next quick run: a run of a few classes (-Ptests, one JVM) rewrites
            // the times file, and would leave every other class at the median
            Path all = Path.of(times);
            if (Files.isRegularFile(all)) Files.copy(all, quickTimes(all), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        // the balance of the shares and what they cost: an idle JVM while the other runs on is wall time lost
        StringBuilder walls = new StringBuilder();
        for (java.util.concurrent.CompletableFuture<Long> e : ended) {
            walls.append(walls.length() == 0 ? "" : " and ").append(String.format(java.util.Locale.ROOT, "%.0f", (e.get() - start) / 1e9));
        }
        double cpu = childrenCpuSeconds();
        System.out.println("test JVMs: " + shares.size() + " side by side, " + walls + " s wall"
            + (Double.isNaN(cpu) ? "" : String.format(java.util.Locale.ROOT, ", %.0f s CPU (their child processes included)", cpu)));
        System.exit(status);
    }

    /** The processor seconds of this JVM's reaped child processes (user + system), or NaN off Linux. */
    static double childrenCpuSeconds() {
        long[] ticks = TestTimes.cpuTicks();
        return ticks == null ? Double.NaN : ticks[1] / TestTimes.TICKS_PER_S;
    }

    /** The classes (not nested ones) under the scanned folders whose names one of the include patterns matches. */
    static List<String> testClasses(List<Path> scanned, List<Pattern> include) throws IOException {
        TreeSet<String> out = new TreeSet<>();
        for (Path root : scanned) {
            if (!Files.isDirectory(root)) continue;
            try (Stream<Path> st = Files.walk(root)) {
                for (Path p : (Iterable<Path>) st::iterator) {
                    String rel = root.relativize(p).toString();
                    if (!rel.endsWith(".class") || rel.contains("$")) continue;
                    String name = rel.substring(0, rel.length() - ".class".length()).replace(p.getFileSystem().getSeparator(), ".");
                    if (include.isEmpty() || include.stream().anyMatch(x -> x.matcher(name).matches())) out.add(name);
                }
            }
        }
        return new ArrayList<>(out);
    }

    /** Where a run in several JVMs keeps a copy of its times: {@code test-times.csv} -> {@code test-times.quick.csv}. */
    static Path quickTimes(Path times) {
        String name = times.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return times.resolveSibling(dot < 0 ? name + ".quick" : name.substring(0, dot) + ".quick" + name.substring(dot));
    }

    /** Each class's wall time in the last run in several JVMs, or else in the last run, from {@code handsim.testTimes}. */
    static Map<String, Double> lastTimes() {
        Map<String, Double> m = new HashMap<>();
        String times = System.getProperty("handsim.testTimes");
        if (times == null) return m;
        Path file = Files.isRegularFile(quickTimes(Path.of(times))) ? quickTimes(Path.of(times)) : Path.of(times);
        if (!Files.isRegularFile(file)) return m;
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            for (String l : lines.subList(Math.min(1, lines.size()), lines.size())) {
                String[] f = l.split(",");
                if (f.length < 2) continue;
                // a nested class's time is inside its outer class's
                if (!f[0].contains("$")) m.merge(f[0], Double.parseDouble(f[1]), Double::sum);
            }
        } catch (IOException | RuntimeException e) {
            m.clear();   // no usable times: every class weighs the same
        }
        return m;
    }

    /** The classes dealt to {@code forks} shares, longest first to the least loaded one. */
    static List<List<String>> deal(List<String> classes, Map<String, Double> times, int forks) {
        List<Double> known = new ArrayList<>();
        for (String c : classes) if (times.containsKey(c)) known.add(times.get(c));
        known.sort(null);
        double median = known.isEmpty() ? 1 : known.get(known.size() / 2);
        List<String> order = new ArrayList<>(classes);
        order.sort((a, b) -> {
            int byTime = Double.compare(times.getOrDefault(b, median), times.getOrDefault(a, median));
            return byTime != 0 ? byTime : a.compareTo(b);
        });
        List<List<String>> shares = new ArrayList<>();
        double[] load = new double[forks];
        for (int k = 0; k < forks; k++) shares.add(new ArrayList<>());
        for (String c : order) {
            int least = 0;
            for (int k = 1; k < forks; k++) if (load[k] < load[least]) least = k;
            shares.get(least).add(c);
            load[least] += times.getOrDefault(c, median);
        }
        shares.removeIf(List::isEmpty);
        for (List<String> s : shares) s.sort(null);
        return shares;
    }

    /** The shares' time files joined into one (one header), the shares' files removed. */
    static void joinTimes(Path out, int forks) throws IOException {
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < forks; k++) {
            Path part = Path.of(out + "." + k);
            if (!Files.isRegularFile(part)) continue;
            List<String> lines = Files.readAllLines(part, StandardCharsets.UTF_8);
            for (int i = sb.length() == 0 ? 0 : 1; i < lines.size(); i++) sb.append(lines.get(i)).append('\n');
            Files.delete(part);
        }
        if (sb.length() > 0) Files.write(out, sb.toString().getBytes(StandardCharsets.UTF_8));
    }
}
