package org.handsim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.handsim.TestPaths;
import org.junit.jupiter.api.Test;

/**
 * Served means identical: every short command's example in the README ("The resident server")
 * is run twice in the same folder — once by a client with {@code HANDSIM_SERVER=0} (its own
 * JVM), once handed to a server — and the two give the same exit code, the same standard output
 * and error and the same files, byte for byte, but for what is a measured time (wall times and
 * rates, a load time) and the clip ids JFreeSVG makes of the clock in any JVM.
 */
class ServedAsInProcessTest {
    /** The README's examples: the {@code ./handsim} lines of the block after the line naming this test. */
    static List<String[]> examples() throws Exception {
        List<String> lines = Files.readAllLines(TestPaths.root().resolve("README.md"), StandardCharsets.UTF_8);
        int at = 0;
        while (at < lines.size() && !lines.get(at).contains("ServedAsInProcessTest")) at++;
        while (at < lines.size() && !lines.get(at).startsWith("```")) at++;
        List<String[]> out = new ArrayList<>();
        for (int i = at + 1; i < lines.size() && !lines.get(i).startsWith("```"); i++) {
            String l = lines.get(i).replaceAll("#.*", "").trim();
            if (l.startsWith("./handsim ")) out.add(l.substring("./handsim ".length()).trim().split("\\s+"));
        }
        return out;
    }

    /** Keys and columns that are measured times or rates, which differ between any two runs. */
    static final List<String> TIMING = List.of("load_ms", "wall_time_s", "steps_per_s", "realtime_factor", "setup_time_s", "load_s",
        "run_s", "trace_s", "charts_s", "trials_per_s", "wall_s", "time_us_median", "build_ms");

    /** A number. */
    private static final String NUM = "(-?[0-9][0-9.eE+-]*)";

    /** Where the commands write measured times (each group a time or rate), and the clip ids JFreeSVG makes of the clock. */
    private static final Pattern[] TIMES = {
        Pattern.compile("\"(?:" + String.join("|", TIMING) + ")\":\\s*" + NUM),
        Pattern.compile(NUM + " s wall \\(" + NUM + " steps/s, " + NUM + "x real time\\)"),
        Pattern.compile(NUM + " s wall, " + NUM + " trials/s"),
        Pattern.compile(" in " + NUM + " s wall;"),
        Pattern.compile("threads? in " + NUM + " s"),
        Pattern.compile("(?m)^\\[[0-9]+/[0-9]+\\] .* \\(" + NUM + " s\\)$"),
        Pattern.compile("_" + NUM + "clip-"),
    };

    /**
     * A progress report without a terminal (one line every few seconds: how many depends on the
     * machine's speed), labelled with the command alone ({@code handsim swing: 97% (1.1 s)}) or
     * with what it runs ({@code handsim run paper: 50% (1.0 s)}).
     */
    private static final Pattern PROGRESS = Pattern.compile("(?m)^handsim [a-z]+(?: [^\\n]*)?: [0-9]+% \\([0-9.]+ s\\)\\n?");

    /** The text with every measured time replaced by N, and without progress reports. */
    static String masked(String text) {
        text = PROGRESS.matcher(text).replaceAll("");
        for (Pattern p : TIMES) {
            java.util.regex.Matcher m = p.matcher(text);
            StringBuilder sb = new StringBuilder();
            int last = 0;
            while (m.find()) {
                for (int g = 1; g <= m.groupCount(); g++) {
                    sb.append(text, last, m.start(g)).append('N');
                    last = m.end(g);
                }
            }
            text = sb.append(text.substring(last)).toString();
        }
        return text;
    }

    /** A CSV table with the cells of its timing columns ({@link #TIMING}) replaced by N. */
    static String maskedCsv(String text) {
        String[] lines = text.split("\n", -1);
        List<String> header = List.of(lines[0].split(",", -1));
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < lines.length; i++) {
            String[] cells = lines[i].split(",", -1);
            for (int c = 0; i > 0 && c < cells.length && c < header.size(); c++) if (TIMING.contains(header.get(c))) cells[c] = "N";
            sb.append(String.join(",", cells)).append(i + 1 < lines.length ? "\n" : "");
        }
        return sb.toString();
    }

    @Test
    void everyShortCommandsExampleGivesTheSameBytesServedAndInProcess() throws Exception {
        List<String[]> examples = examples();
        Set<String> commands = new TreeSet<>();
        for (String[] e : examples) commands.add(e[0]);
        assertEquals(new TreeSet<>(Client.SERVED), commands, "one example at least of each short command");
        // 23 JVMs (a server, and a client each way per example) that each run a second or two: C1
        // alone and the serial collector, as ./handsim runs `run`, cost a third less processor time
        // than C2's compilations of code then run for a moment; results do not depend on the compiler
        try (ServerTest.Setup s = new ServerTest.Setup("same", "-Dhandsim.server.warmup=0", "-Dhandsim.timing.warmupCapSeconds=0.05",
                "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC")) {
            for (String d : List.of("scenarios", "vrml")) Files.createSymbolicLink(s.work.resolve(d), TestPaths.root().resolve(d));
            s.server();
            for (String[] args : examples) {
                String what = String.join(" ", args);
                Map<String, byte[]> before = files(s.work);
                ServerTest.Ran ref = s.run(true, args);
                Map<String, byte[]> refFiles = made(before, files(s.work), s.work);
                ServerTest.Ran served = s.run(false, args);
                Map<String, byte[]> servedFiles = made(before, files(s.work), s.work);
                assertEquals("served", served.how(), what);
                assertEquals(ref.code(), served.code(), what + ": " + served.err());
                assertEquals(masked(ref.out()), masked(served.out()), what + ": standard output");
                assertEquals(masked(ref.err()), masked(served.err()), what + ": standard error");
                assertEquals(refFiles.keySet(), servedFiles.keySet(), what + ": the files written");
                for (String f : refFiles.keySet()) {
                    byte[] a = refFiles.get(f), b = servedFiles.get(f);
                    boolean text = f.endsWith(".json") || f.endsWith(".svg") || f.endsWith(".obj");
                    if (f.endsWith(".csv")) {
                        assertEquals(maskedCsv(new String(a, StandardCharsets.UTF_8)), maskedCsv(new String(b, StandardCharsets.UTF_8)), what + ": " + f);
                    } else if (text) {
                        assertEquals(masked(new String(a, StandardCharsets.UTF_8)), masked(new String(b, StandardCharsets.UTF_8)), what + ": " + f);
                    } else {
                        assertTrue(Arrays.equals(a, b), what + ": " + f + " differs");
                    }
                }
            }
        }
    }

    /** Progress lines go, both labels; other lines on standard error stay. */
    @Test
    void maskingDropsProgressReportsOnly() {
        assertEquals("wrote out/swing\n", masked("handsim swing: 97% (1.1 s)\nhandsim swing: 100% (1.3 s)\nwrote out/swing\n"));
        assertEquals("", masked("handsim run paper-breakaway: 50% (1.0 s)\n"));
        assertEquals("handsim swing: the duration must be positive\n", masked("handsim swing: the duration must be positive\n"));
    }

    /** Every regular file under {@code dir} by relative path, links not followed. */
    static Map<String, byte[]> files(Path dir) throws Exception {
        Map<String, byte[]> m = new TreeMap<>();
        try (Stream<Path> st = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) st::iterator) {
                if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) m.put(dir.relativize(p).toString(), Files.readAllBytes(p));
            }
        }
        return m;
    }

    /** What a command made or changed (against {@code before}), which is then deleted, so the next run starts from the same folder. */
    static Map<String, byte[]> made(Map<String, byte[]> before, Map<String, byte[]> after, Path dir) throws Exception {
        Map<String, byte[]> m = new TreeMap<>();
        for (Map.Entry<String, byte[]> e : after.entrySet()) {
            if (before.containsKey(e.getKey()) && Arrays.equals(before.get(e.getKey()), e.getValue())) continue;
            m.put(e.getKey(), e.getValue());
        }
        for (String f : m.keySet()) Files.delete(dir.resolve(f));
        try (Stream<Path> st = Files.walk(dir)) {   // folders left empty by the deletion, deepest first
            List<Path> folders = new ArrayList<>();
            st.filter(p -> !p.equals(dir) && Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)).forEach(folders::add);
            folders.sort(java.util.Comparator.reverseOrder());
            for (Path p : folders) {
                try (Stream<Path> in = Files.list(p)) {
                    if (in.findAny().isEmpty()) Files.delete(p);
                }
            }
        }
        return m;
    }
}
