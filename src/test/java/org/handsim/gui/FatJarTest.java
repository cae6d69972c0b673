package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarFile;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The one runnable jar ({@code gradle fatJar}, built before the tests): what is in it, and that
 * {@code java -jar handsim-VERSION-all.jar run --out DIR} writes the paper's experiment from an
 * empty folder on a machine without a display — the jar carries the models and scenarios — and
 * that the window opens from it (the JOGL natives come out of the jar) and closes cleanly.
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class FatJarTest {
    static Path jar() {
        String p = System.getProperty("handsim.fatJar");
        assertNotNull(p, "the build passes handsim.fatJar");
        Path j = Path.of(p);
        assertTrue(Files.isRegularFile(j), "gradle test builds " + j + " first (task fatJar)");
        return j;
    }

    record Out(int code, String log) {}

    private static final java.util.concurrent.atomic.AtomicInteger LOGS = new java.util.concurrent.atomic.AtomicInteger();

    static Out java(Path dir, boolean display, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
            "-Djava.io.tmpdir=" + dir.resolve("tmp"), "-jar", jar().toString()));
        Collections.addAll(cmd, args);
        Files.createDirectories(dir.resolve("tmp"));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
        pb.environment().remove("DISPLAY");
        pb.environment().remove("HANDSIM_SHARED");
        pb.environment().put("XDG_CACHE_HOME", dir.resolve("cache").toAbsolutePath().toString());   // the models' copy stays in the test's folder
        if (display) {
            pb.environment().put("DISPLAY", GuiWindowTest.display());
            String xauth = GuiWindowTest.xauthority();
            if (xauth != null) pb.environment().put("XAUTHORITY", xauth);
        }
        Path log = dir.resolve("log-" + (args.length == 0 ? "none" : args[0]) + "-" + LOGS.incrementAndGet() + ".txt");
        pb.redirectOutput(log.toFile());
        Process p = pb.start();
        if (!p.waitFor(5, TimeUnit.MINUTES)) {
            p.destroyForcibly();
            fail("java -jar did not finish: " + Files.readString(log));
        }
        return new Out(p.exitValue(), Files.readString(log));
    }

    @Test
    void theJarHoldsTheProgramTheNativesAndTheModelsAndNoSignatures() throws Exception {
        try (JarFile j = new JarFile(jar().toFile())) {
            assertEquals("org.handsim.cli.JarMain", j.getManifest().getMainAttributes().getValue("Main-Class"));
            List<String> names = new ArrayList<>();
            j.stream().forEach(e -> names.add(e.getName()));
            for (String must : List.of("org/handsim/cli/HandSim.class", "org/handsim/hand/barretthand.json",
                "natives/linux-amd64/libgluegen_rt.so", "natives/linux-amd64/libjogl_desktop.so", "natives/linux-amd64/libnativewindow_x11.so",
                "jogamp/nativetag/common/linux/amd64/TAG.class", "jogamp/nativetag/opengl/linux/amd64/TAG.class",
                "org/jogamp/java3d/Canvas3D.class", "org/jfree/chart/JFreeChart.class", "picocli/CommandLine.class",
                "META-INF/services/org.jogamp.java3d.GeometryService", "handsim-home/vrml/hand/palm.wrl",
                "handsim-home/scenarios/paper-breakaway.json", "handsim-home/vrml/objects/cube.wrl")) {
                assertTrue(names.contains(must), must + " is in the jar");
            }
            for (String n : names) {
                assertFalse(n.matches("META-INF/[^/]+\\.(SF|DSA|RSA|EC)"), "a signature file would make the merged jar invalid: " + n);
                assertFalse(n.endsWith("module-info.class"), n);
            }
            assertEquals(names.size(), new java.util.HashSet<>(names).size(), "no duplicate entries");
        }
    }

    @Test
    @SuppressWarnings("unchecked")
    void javaJarRunWritesThePapersExperimentFromAnEmptyFolderWithoutADisplay() throws Exception {
        Path dir = Files.createTempDirectory("handsim-fatjar");
        Out o = java(dir, false, "run", "--out", "paper");
        assertEquals(0, o.code(), o.log());
        assertTrue(o.log().contains("finger 3: breakaway at t = 1.8000 s, tau32 = 1.260 N*m"), o.log());
        for (String f : List.of("trace.csv", "summary.json", "fig7_finger3.png", "fig8_finger3.svg")) {
            assertTrue(Files.size(dir.resolve("paper").resolve(f)) > 0, f);
        }
        Map<String, Object> s = (Map<String, Object>) Json.parse("summary.json", Files.readString(dir.resolve("paper/summary.json")));
        Map<String, Object> f3 = ((List<Map<String, Object>>) s.get("fingers")).get(2);
        assertEquals(1.8, (Double) f3.get("breakaway_time_s"), 1e-4, "the paper's 1.80 s");
        // without arguments and without a display: one message, exit 2
        Out none = java(dir, false);
        assertEquals(2, none.code(), none.log());
        assertTrue(none.log().startsWith("handsim: no display for the window;"), none.log());
        String jar = Path.of(System.getProperty("handsim.fatJar")).getFileName().toString();
        assertTrue(none.log().contains("  java -jar " + jar + " run --out out/paper"), "names the jar it is: " + none.log());
        // a relative path outside a checkout: where it looked, and where the jar's own models are
        Out missing = java(dir, false, "plan", "vrml/objects/mug.wrl", "--trials", "1");
        assertEquals(3, missing.code(), missing.log());
        assertTrue(missing.log().contains("vrml/objects/mug.wrl: no such file (looked in " + dir.toRealPath()), missing.log());
        // where the models are: unpacked from the jar, or (the test's folder lies inside the build's checkout) the checkout's
        assertTrue(missing.log().matches("(?s).*(the models and scenarios of the jar are unpacked in|HandSim's models and scenarios are in)"
            + " \\S+: \\S+/vrml/objects/mug\\.wrl\\).*"), missing.log());
        VrmlTesting.deleteTree(dir);
    }

    /**
     * A cache and a temporary folder the models cannot be unpacked into (here below a file, which
     * even root cannot write into): the error that follows — no scenario — says why, naming the
     * failed unpack and both folders.
     */
    @Test
    void aFailedUnpackIsNamedInTheError() throws Exception {
        Path dir = Files.createTempDirectory(Path.of("/tmp"), "handsim-fatjar");   // outside the checkout: the jar must unpack
        try {
            Path file = Files.writeString(dir.resolve("file"), "");
            List<String> cmd = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.io.tmpdir=" + file.resolve("tmp"), "-jar", jar().toString(), "run", "--out", "paper");
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
            pb.environment().remove("DISPLAY");
            pb.environment().put("XDG_CACHE_HOME", file.resolve("cache").toString());
            Process p = pb.start();
            String log = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            assertTrue(p.waitFor(2, TimeUnit.MINUTES));
            assertEquals(3, p.exitValue(), log);
            assertTrue(log.startsWith("HandSim's models and scenarios (vrml/hand/*.wrl, scenarios/) were not found: "), log);
            assertTrue(log.contains("set -Dhandsim.home=DIR"), log);
            assertTrue(log.contains("(the models and scenarios of " + jar().getFileName() + " could not be unpacked: "), log);
            assertTrue(log.trim().endsWith("(the cache " + file.resolve("cache/handsim") + " and the temporary folder " + file.resolve("tmp")
                + " must be writable))"), log);
            assertEquals(1, log.trim().split("\n").length, log);
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    /**
     * Three first runs of the jar at once (an empty cache): each runs, and afterwards the cache
     * holds one verified copy of the models and the temporary folder nothing of them.
     */
    @Test
    @org.junit.jupiter.api.Tag("slow")
    void concurrentFirstRunsLeaveOneCopyOfTheModels() throws Exception {
        // outside the checkout (the build's temporary folder is inside it, where the jar would find vrml/ and not unpack)
        Path dir = Files.createTempDirectory(Path.of("/tmp"), "handsim-fatjar");
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(3);
        try {
            List<java.util.concurrent.Future<Out>> runs = new ArrayList<>();
            for (int i = 0; i < 3; i++) {
                String out = "o" + i;
                runs.add(pool.submit(() -> java(dir, false, "run", "--dt", "0.01", "--no-charts", "--out", out)));
            }
            for (int i = 0; i < 3; i++) {
                Out o = runs.get(i).get();
                assertEquals(0, o.code(), o.log());
                assertTrue(Files.isRegularFile(dir.resolve("o" + i).resolve("summary.json")));
            }
            try (var s = Files.list(dir.resolve("cache/handsim"))) {
                List<String> left = new ArrayList<>();
                // the cache folder also holds the tessellated meshes (scenario.MeshCache): only the models' copies count here
                s.map(p -> p.getFileName().toString()).filter(n -> !n.equals("meshes")).forEach(left::add);
                assertEquals(1, left.size(), "one copy, no unpacking folder: " + left);
                assertTrue(left.get(0).startsWith("home-"), left.toString());
            }
            try (var s = Files.list(dir.resolve("tmp"))) {
                assertEquals(0, s.filter(p -> p.getFileName().toString().startsWith("handsim-home")).count(), "nothing in the temporary folder");
            }
        } finally {
            pool.shutdownNow();
            VrmlTesting.deleteTree(dir);
        }
    }

    @Test
    void theWindowOpensFromTheJarAndClosesCleanly() throws Exception {
        GuiWindowTest.needDisplay();
        Path dir = Files.createTempDirectory("handsim-fatjar");
        Files.writeString(dir.resolve("s.txt"), "press Objects\nimport vrml/objects/cube.wrl\nplay 0.3\nassert-contacts 0\n");
        Out o = java(dir, true, "gui", "--script", "s.txt");
        assertEquals(0, o.code(), o.log());
        assertTrue(o.log().contains("gui: done, 0 uncaught exceptions"), o.log());
        assertFalse(o.log().contains("X11Util"), "no X11Util lines at exit:\n" + o.log());
        VrmlTesting.deleteTree(dir);
    }
}
