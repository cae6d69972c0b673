package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Results are never lost to a machine without usable fonts or display. Each command runs in a child JVM
 * whose font library cannot load, as on a compute node without libharfbuzz: the JDK's
 * {@code sun.font.FontManagerNativeLibrary} (which loads libfontmanager.so) is replaced through
 * {@code --patch-module} by one that throws the {@link UnsatisfiedLinkError} such a node gives.
 * Every table and summary must still be written, with one warning naming the cause and the
 * remedy, exit 0, and {@code charts_missing} in the JSON.
 */
@Tag("slow")
class NoFontsTest {
    static final String CAUSE = "libfontmanager.so: libharfbuzz.so.0: cannot open shared object file: No such file or directory";
    static Path work;
    static List<String> noFonts;

    @BeforeAll
    static void brokenFontLibrary() throws Exception {
        work = Files.createTempDirectory("handsim-nofonts");
        Path src = work.resolve("patch-src/sun/font/FontManagerNativeLibrary.java");
        Files.createDirectories(src.getParent());
        Files.writeString(src, "package sun.font;\n"
            + "public class FontManagerNativeLibrary {\n"
            + "    static { if (true) throw new UnsatisfiedLinkError(\"" + CAUSE + "\"); }\n"
            + "    public static void load() {}\n"
            + "}\n");
        Path classes = work.resolve("patch");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int rc = javac.run(null, null, null, "--patch-module", "java.desktop=" + work.resolve("patch-src"), "-d", classes.toString(), src.toString());
        assertEquals(0, rc, "compiling the broken font library");
        noFonts = List.of("--patch-module", "java.desktop=" + classes);
    }

    @AfterAll
    static void clean() throws Exception {
        ChildJvm.deleteTree(work);
    }

    /** The one warning: the cause and the remedy on one line, nothing else about the charts. */
    static void oneWarning(String err) {
        List<String> lines = err.lines().filter(l -> l.contains("charts not drawn")).toList();
        assertEquals(1, lines.size(), err);
        String w = lines.get(0);
        assertTrue(w.startsWith("handsim: warning: charts not drawn (UnsatisfiedLinkError: " + CAUSE + ")"), w);
        assertTrue(w.contains("apt-get install") && w.contains("fonts-dejavu-core"), w);
        assertFalse(err.contains("internal error"), err);
        assertFalse(err.contains("\tat "), "no stack trace: " + err);
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> json(Path file) throws Exception {
        return (Map<String, Object>) Json.parse(file.toString(), Files.readString(file));
    }

    static void noCharts(Path dir) throws Exception {
        try (var s = Files.walk(dir)) {
            assertFalse(s.anyMatch(p -> p.toString().endsWith(".png") || p.toString().endsWith(".svg") || p.toString().endsWith(".partial")),
                "no chart files, no temporary files");
        }
    }

    @Test
    void runWritesTraceAndSummary() throws Exception {
        Path out = work.resolve("run");
        ChildJvm.Result r = ChildJvm.run(work, "512m", noFonts, 5, "run", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        oneWarning(r.err());
        assertEquals(1 + 8948, Files.readAllLines(out.resolve("trace.csv")).size());
        Map<String, Object> s = json(out.resolve("summary.json"));
        assertEquals("UnsatisfiedLinkError: " + CAUSE, s.get("charts_missing"));
        assertTrue(s.containsKey("phase_times") && s.containsKey("grasp") && s.containsKey("fingers"), s.keySet().toString());
        assertTrue(r.out().contains("breakaway at t = 1.8000 s"), r.out());
        assertTrue(r.out().contains("wrote " + out + "/{trace.csv, summary.json}"), r.out());
        noCharts(out);
    }

    @Test
    void planWritesItsTables() throws Exception {
        Path out = work.resolve("plan");
        ChildJvm.Result r = ChildJvm.run(work, "512m", noFonts, 5, "plan", TestPaths.root().resolve("vrml/objects/cube.wrl").toString(),
            "--trials", "12", "--threads", "1", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        oneWarning(r.err());
        assertEquals(1 + 12, Files.readAllLines(out.resolve("plan.csv")).size());
        Map<String, Object> p = json(out.resolve("plan.json"));
        assertEquals("UnsatisfiedLinkError: " + CAUSE, p.get("charts_missing"));
        assertEquals(12L, ((Number) p.get("trials")).longValue());
        assertTrue(Files.isRegularFile(out.resolve("best/01.json")));
        noCharts(out);
    }

    @Test
    void tradeoffWritesItsTables() throws Exception {
        Path out = work.resolve("tradeoff");
        ChildJvm.Result r = ChildJvm.run(work, "1g", noFonts, 10, "tradeoff", "--quick", "--only", "1", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        oneWarning(r.err());
        Map<String, Object> t = json(out.resolve("tradeoff.json"));
        assertEquals("UnsatisfiedLinkError: " + CAUSE, t.get("charts_missing"));
        try (var s = Files.list(out)) {
            assertEquals(1, s.filter(f -> f.toString().endsWith(".csv")).count());
        }
        noCharts(out);
    }

    /**
     * A display that cannot be used (DISPLAY names a server that does not exist) and no
     * headless option on the command line, as on a login node with a stale DISPLAY: run loads
     * its VRML files through Java3D (the mesh cache off) and draws its charts all the same, since
     * every command but gui runs headless.
     */
    @Test
    void runIgnoresAnUnusableDisplay() throws Exception {
        Path out = work.resolve("display");
        List<String> cmd = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss16m", "-Xmx512m",
            "-Dhandsim.cache=off", "-Djava.io.tmpdir=" + work, "-Dhandsim.home=" + TestPaths.root(), "-cp", System.getProperty("java.class.path"),
            HandSim.class.getName(), "run", "--out", out.toString());
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(work.toFile()).redirectErrorStream(true).redirectOutput(work.resolve("display.log").toFile());
        pb.environment().put("DISPLAY", "127.0.0.1:4711");
        pb.environment().remove("XAUTHORITY");
        Process p = pb.start();
        assertTrue(p.waitFor(5, java.util.concurrent.TimeUnit.MINUTES), "finished");
        String log = Files.readString(work.resolve("display.log"));
        assertEquals(0, p.exitValue(), log);
        for (String f : new String[] {"trace.csv", "summary.json", "fig7_finger3.png", "fig7_finger3.svg", "fig8_finger3.png", "fig8_finger3.svg"}) {
            assertTrue(Files.size(out.resolve(f)) > 1000, f + ": " + log);
        }
        // no warning but the paper's forces above Barrett's rating (RunCommandsTest)
        assertFalse(log.lines().anyMatch(l -> l.contains("warning") && !l.contains("above Barrett's rating")), log);
    }

    @Test
    void sweepNeedsNoFonts() throws Exception {
        Path sweep = work.resolve("sweep.json");
        Files.writeString(sweep, "{\"name\": \"nofonts\", \"base\": \"" + TestPaths.root().resolve("scenarios/paper-breakaway.json").toString().replace("\\", "/")
            + "\", \"runs\": [{\"label\": \"a\", \"set\": {}}, {\"label\": \"b\", \"set\": {\"dt_s\": 0.002}}]}");
        Path out = work.resolve("sweep");
        ChildJvm.Result r = ChildJvm.run(work, "512m", noFonts, 5, "sweep", sweep.toString(), "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        assertFalse(r.err().contains("warning"), r.err());
        assertEquals(3, Files.readAllLines(out.resolve("summary.csv")).size());
    }
}
