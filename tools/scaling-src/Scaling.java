import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordedThread;
import jdk.jfr.consumer.RecordingFile;

/**
 * How {@code handsim plan} scales with its threads, measured from outside: runs
 * {@code bin/handsim plan TARGET --trials N --threads T} of a bundle (or checkout) at T = 1, 2,
 * 4 … cores, each as its own process under a Flight Recording, and prints a Markdown table — the
 * rate (plan.json's trials_per_s), the speed-up over one thread, the efficiency, the GC share
 * (the recording's GC pauses over the plan's wall time), the allocation per trial (what the
 * plan-worker threads allocated, over the trials), the CPU the JIT compilers and the workers
 * used (Linux, from /proc), the contended monitor enters in the workers — and checks that every
 * plan.csv is the one-thread table but for its wall_s column.
 *
 * <p>Run by {@code tools/scaling} and by a bundle's {@code bin/scaling}; needs a JRE with the
 * jdk.jfr module (the bundle's has it). Exit 0 when the tables are identical, 1 otherwise, 2 for
 * bad options.
 */
public final class Scaling {
    private Scaling() {}

    public static void main(String[] args) throws Exception {
        Map<String, String> o = options(args);
        Path home = Path.of(o.getOrDefault("--home", System.getProperty("handsim.home", "."))).toAbsolutePath().normalize();
        Path launcher = home.resolve("bin/handsim");
        if (!Files.isRegularFile(launcher)) launcher = home.resolve("handsim");
        if (!Files.isRegularFile(launcher)) usage("no bin/handsim or handsim under " + home);
        int cores = Runtime.getRuntime().availableProcessors();
        int trials = positive(o.getOrDefault("--trials", "8000"), "--trials");
        int repeat = positive(o.getOrDefault("--repeat", "1"), "--repeat");
        String target = o.getOrDefault("--target", "vrml/objects/mug.wrl");
        String seed = o.getOrDefault("--seed", "1");
        List<Integer> threads = new ArrayList<>();
        if (o.containsKey("--threads")) {
            for (String t : o.get("--threads").split(",")) threads.add(positive(t.trim(), "--threads"));
        } else {
            for (int t = 1; t < cores; t *= 2) threads.add(t);
            threads.add(cores);
        }
        List<String> jits = Arrays.asList(o.getOrDefault("--jit", "auto").split(","));
        for (String j : jits) if (!List.of("auto", "c1", "c2").contains(j)) usage("--jit must be auto, c1 or c2 (comma-separated), got " + j);
        Path work = o.containsKey("--work") ? Path.of(o.get("--work")) : Files.createTempDirectory("handsim-scaling");
        boolean keep = o.containsKey("--work") || o.containsKey("--keep");

        System.out.println("CPU: " + cpuModel() + "; " + cores + " cores present; load average before: " + loadAverage());
        System.out.println("Each row's command, run from " + home + " with a Flight Recording added by HANDSIM_JAVA_OPTS:");
        System.out.println();
        System.out.println("| command | threads | trials/s | speed-up | efficiency | wall s | GC share | alloc/trial | JIT CPU s | worker CPU/trial | contended locks | load | table |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|");
        boolean allSame = true;
        try {
            for (String jit : jits) {
                List<String> reference = null;
                double base = Double.NaN;
                for (int t : threads) {
                    for (int r = 0; r < repeat; r++) {
                        Path out = work.resolve(jit + "-t" + t + "-r" + r);
                        Row row = run(home, launcher, target, trials, seed, t, jit, out);
                        List<String> table = withoutWall(out.resolve("plan.csv"));
                        String same;
                        if (reference == null) {
                            reference = table;
                            same = "reference";
                        } else if (reference.equals(table)) {
                            same = "identical";
                        } else {
                            same = "DIFFERS";
                            allSame = false;
                        }
                        if (t == threads.get(0) && r == 0) base = row.rate / t;
                        double speedup = row.rate / base;
                        String command = "`HANDSIM_JIT=" + jit + " " + home.relativize(launcher) + " plan " + target + " --trials " + trials
                            + " --seed " + seed + " --threads " + t + "`";
                        System.out.printf(Locale.ROOT, "| %s | %d | %.1f | %.2f | %.0f %% | %.2f | %.2f %% | %.0f kB | %s | %s | %s | %s | %s |%n",
                            command, t, row.rate, speedup, 100 * speedup / t, row.wall, 100 * row.gcPauseS / row.wall,
                            row.workerAllocBytes / trials / 1e3, row.jitCpuS < 0 ? "n/a" : String.format(Locale.ROOT, "%.1f", row.jitCpuS),
                            row.workerCpuS < 0 ? "n/a" : String.format(Locale.ROOT, "%.2f ms", 1e3 * row.workerCpuS / trials),
                            row.contended + (row.contendedLoading > 0 ? " (+" + row.contendedLoading + " class loading)" : ""),
                            row.load, same);
                        if (!keep) deleteTree(out);
                    }
                }
            }
        } finally {
            if (!keep) deleteTree(work);
        }
        System.out.println();
        System.out.println(allSame ? "plan.csv identical at every thread count (wall_s aside)" : "plan.csv DIFFERS between thread counts");
        System.out.println("load average after: " + loadAverage());
        System.exit(allSame ? 0 : 1);
    }

    /** One plan's figures. */
    static final class Row {
        double rate, wall, gcPauseS, workerAllocBytes, jitCpuS = -1, workerCpuS = -1;
        int contended, contendedLoading;
        String load;
    }

    static Row run(Path home, Path launcher, String target, int trials, String seed, int threads, String jit, Path out)
            throws IOException, InterruptedException {
        Files.createDirectories(out);
        Path jfr = out.resolve("plan.jfr"), jfc = out.resolve("scaling.jfc");
        Files.writeString(jfc, SETTINGS);
        ProcessBuilder pb = new ProcessBuilder(launcher.toString(), "plan", target, "--trials", Integer.toString(trials),
            "--threads", Integer.toString(threads), "--seed", seed, "--out", out.toString());
        pb.directory(home.toFile());
        pb.redirectErrorStream(true);
        pb.redirectOutput(out.resolve("plan.log").toFile());
        String opts = System.getenv().getOrDefault("HANDSIM_JAVA_OPTS", "");
        pb.environment().put("HANDSIM_JAVA_OPTS", (opts + " -XX:StartFlightRecording=filename=" + jfr + ",settings=" + jfc).trim());
        pb.environment().put("HANDSIM_JIT", jit);
        Row row = new Row();
        Process p = pb.start();
        Map<String, Double> threadCpu = new HashMap<>();
        while (!p.waitFor(50, java.util.concurrent.TimeUnit.MILLISECONDS)) sampleCpu(p.toHandle(), threadCpu);
        Map<String, Double> cpu = new HashMap<>();
        for (Map.Entry<String, Double> e : threadCpu.entrySet()) cpu.merge(e.getKey().substring(0, e.getKey().indexOf('/')), e.getValue(), Double::sum);
        if (p.exitValue() != 0) {
            throw new IllegalStateException("plan with " + threads + " threads failed (exit " + p.exitValue() + "): "
                + String.join("\n", Files.readAllLines(out.resolve("plan.log"))));
        }
        row.load = loadAverage();
        String json = Files.readString(out.resolve("plan.json"));
        row.rate = number(json, "trials_per_s");
        row.wall = number(json, "wall_time_s");
        if (!cpu.isEmpty()) {
            row.jitCpuS = cpu.getOrDefault("jit", 0.0);
            row.workerCpuS = cpu.getOrDefault("plan-worker", 0.0);
        }
        Map<Long, Double> allocated = new HashMap<>();
        for (RecordedEvent e : RecordingFile.readAllEvents(jfr)) {
            switch (e.getEventType().getName()) {
                case "jdk.GarbageCollection" -> row.gcPauseS += e.getDuration("sumOfPauses").toNanos() / 1e9;
                case "jdk.ThreadAllocationStatistics" -> {
                    RecordedThread th = e.getThread("thread");
                    if (th != null && "plan-worker".equals(th.getJavaName())) allocated.merge(th.getJavaThreadId(), (double) e.getLong("allocated"), Math::max);
                }
                case "jdk.JavaMonitorEnter" -> {
                    RecordedThread th = e.getThread();
                    if (th == null || !"plan-worker".equals(th.getJavaName())) break;
                    if (classLoading(e)) row.contendedLoading++; else row.contended++;
                }
                default -> { }
            }
        }
        row.workerAllocBytes = allocated.values().stream().mapToDouble(Double::doubleValue).sum();
        return row;
    }

    /**
     * A contended enter of class loading or initialisation (the first trials', once per class):
     * a class's initialisation lock is an int[], the class loader's lock per class name a bare
     * Object (taken by the VM as it resolves a class, so often with no loader frame on the stack);
     * HandSim's trial path locks neither.
     */
    private static boolean classLoading(RecordedEvent e) {
        String monitor = e.getClass("monitorClass") != null ? e.getClass("monitorClass").getName() : "";
        if (monitor.equals("[I") || monitor.equals("int[]") || monitor.equals("java.lang.Object")) return true;
        if (e.getStackTrace() == null) return false;
        for (RecordedFrame f : e.getStackTrace().getFrames()) {
            String t = f.getMethod().getType().getName();
            if (t.equals("java.lang.ClassLoader") || t.startsWith("jdk.internal.loader.")) return true;
        }
        return false;
    }

    /**
     * CPU seconds of each thread of a running process and its descendants (Linux /proc), keyed
     * "group/tid" (group: jit, plan-worker or other); a thread that ended keeps its last value.
     */
    private static void sampleCpu(ProcessHandle ph, Map<String, Double> last) {
        List<ProcessHandle> procs = new ArrayList<>();
        procs.add(ph);
        ph.descendants().forEach(procs::add);   // the launcher execs java, but a wrapper may fork it

        for (ProcessHandle h : procs) {
            Path tasks = Path.of("/proc", Long.toString(h.pid()), "task");
            if (!Files.isDirectory(tasks)) continue;
            try (Stream<Path> s = Files.list(tasks)) {
                for (Path t : (Iterable<Path>) s::iterator) {
                    try {
                        String st = Files.readString(t.resolve("stat"));
                        String name = st.substring(st.indexOf('(') + 1, st.lastIndexOf(')'));
                        String[] f = st.substring(st.lastIndexOf(')') + 2).split(" ");
                        double sec = (Long.parseLong(f[11]) + Long.parseLong(f[12])) / 100.0;   // USER_HZ
                        String g = name.startsWith("C1 Compiler") || name.startsWith("C2 Compiler") ? "jit"
                            : name.equals("plan-worker") ? "plan-worker" : "other";
                        last.put(g + "/" + h.pid() + "." + t.getFileName(), sec);
                    } catch (IOException | RuntimeException gone) {
                        // the thread ended between the listing and the read
                    }
                }
            } catch (IOException | UncheckedIOException gone) {
                // the process ended
            }
        }
    }

    /** plan.csv's lines without the wall_s column. */
    static List<String> withoutWall(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv, StandardCharsets.UTF_8);
        int wall = Arrays.asList(lines.get(0).split(",", -1)).indexOf("wall_s");
        List<String> out = new ArrayList<>(lines.size());
        for (String l : lines) {
            List<String> f = new ArrayList<>(Arrays.asList(l.split(",", -1)));
            if (wall >= 0 && wall < f.size()) f.remove(wall);
            out.add(String.join(",", f));
        }
        return out;
    }

    static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\"\\s*:\\s*([-0-9.eE+]+)").matcher(json);
        if (!m.find()) throw new IllegalStateException("plan.json has no " + key);
        return Double.parseDouble(m.group(1));
    }

    static String cpuModel() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (l.startsWith("model name")) return l.substring(l.indexOf(':') + 1).trim();
            }
        } catch (IOException | RuntimeException e) {
            // not Linux
        }
        return System.getProperty("os.arch");
    }

    static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (IOException | RuntimeException e) {
            return "n/a";
        }
    }

    private static Map<String, String> options(String[] args) {
        Map<String, String> o = new LinkedHashMap<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--keep")) {
                o.put(a, "");
            } else if (List.of("--home", "--trials", "--threads", "--repeat", "--target", "--seed", "--jit", "--work").contains(a)) {
                if (i + 1 >= args.length) usage(a + " needs a value");
                o.put(a, args[++i]);
            } else if (a.equals("--help") || a.equals("-h")) {
                System.out.println(USAGE);
                System.exit(0);
            } else {
                usage("unknown option " + a);
            }
        }
        return o;
    }

    private static int positive(String s, String option) {
        try {
            int v = Integer.parseInt(s);
            if (v >= 1) return v;
        } catch (NumberFormatException e) {
            // below
        }
        usage(option + " must be an integer >= 1, got '" + s + "'");
        return 0;
    }

    private static void usage(String message) {
        System.err.println("scaling: " + message);
        System.err.println(USAGE);
        System.exit(2);
    }

    static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) Files.deleteIfExists(p);
        }
    }

    static final String USAGE = String.join("\n",
        "usage: scaling [--trials N] [--threads 1,2,4] [--jit auto,c1,c2] [--repeat R] [--target FILE] [--seed S] [--work DIR | --keep]",
        "  --trials   trials of each plan (default 8000: enough that start-up is not what is measured)",
        "  --threads  thread counts (default 1, 2, 4 ... and the cores present)",
        "  --jit      the launcher's compiler choice per row (HANDSIM_JIT): auto (its policy), c1, c2",
        "  --repeat   runs per thread count",
        "  --work     keep each run's folder (plan.csv, plan.jfr, plan.log) in DIR");

    /** The recording: GC pauses, per-thread allocation every 100 ms, every contended monitor enter. */
    static final String SETTINGS = """
        <?xml version="1.0" encoding="UTF-8"?>
        <configuration version="2.0" label="handsim scaling">
          <event name="jdk.GarbageCollection"><setting name="enabled">true</setting><setting name="threshold">0 ms</setting></event>
          <event name="jdk.ThreadAllocationStatistics"><setting name="enabled">true</setting><setting name="period">100 ms</setting></event>
          <event name="jdk.JavaMonitorEnter"><setting name="enabled">true</setting><setting name="stackTrace">true</setting><setting name="threshold">0 ms</setting></event>
        </configuration>
        """;
}
