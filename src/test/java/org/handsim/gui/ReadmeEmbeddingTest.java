package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.scenario.Home;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The README's embedding snippet as a user has it: copied whole (imports included) into a file
 * in a folder outside the checkout, compiled with HandSim's installed jars alone, and run there
 * with no {@code handsim.home} — the models come from {@code handsim.jar}. And without a jar that
 * has them, the one message naming the property.
 */
@Tag("slow")   // child JVMs, a window: ./test --all
class ReadmeEmbeddingTest {
    /** A folder outside the checkout (the tests' own temporary folder is inside it). */
    static Path outside() throws Exception {
        Path base = Path.of(System.getenv().getOrDefault("TMPDIR", "/tmp"));
        Path d = Files.createTempDirectory(base, "handsim-embedding-");
        assertFalse(d.toAbsolutePath().normalize().startsWith(TestPaths.root().toAbsolutePath().normalize()), d.toString());
        return d;
    }

    static String snippet() throws Exception {
        List<String> readme = Files.readAllLines(TestPaths.root().resolve("README.md"));
        int start = readme.indexOf("public class MyGraspExperiment {");
        while (start > 0 && !readme.get(start).equals("```java")) start--;
        int end = start + 1;
        while (!readme.get(end).equals("```")) end++;
        return String.join("\n", readme.subList(start + 1, end)) + "\n";
    }

    @Test
    void theSnippetCompilesAndRunsFromAFolderOutsideTheCheckout() throws Exception {
        GuiWindowTest.needDisplay();
        Path lib = TestPaths.root().resolve("build/install/handsim/lib");
        assertTrue(Files.isRegularFile(lib.resolve("handsim.jar")), "build/install/handsim/lib/handsim.jar missing: ./test --all builds it (gradle installDist)");
        Path dir = outside();
        try {
            Files.writeString(dir.resolve("MyGraspExperiment.java"), snippet());
            String java = Path.of(System.getProperty("java.home"), "bin").toString();
            Process c = new ProcessBuilder(java + "/javac", "-cp", lib + "/*", "MyGraspExperiment.java")
                .directory(dir.toFile()).redirectErrorStream(true).start();
            String compiled = new String(c.getInputStream().readAllBytes());
            assertTrue(c.waitFor(3, TimeUnit.MINUTES));
            assertEquals(0, c.exitValue(), "the README's snippet compiles as written:\n" + compiled);
            ProcessBuilder pb = new ProcessBuilder(java + "/java", "-Xss16m", "-cp", lib + "/*:.", "MyGraspExperiment").directory(dir.toFile());
            pb.environment().put("XDG_CACHE_HOME", dir.resolve("cache").toString());   // the models unpack here, not in the user's cache
            pb.environment().put("DISPLAY", GuiWindowTest.display());
            String xauth = GuiWindowTest.xauthority();
            if (xauth != null) pb.environment().put("XAUTHORITY", xauth);
            Path log = dir.resolve("log.txt");
            pb.redirectErrorStream(true).redirectOutput(log.toFile());
            Process p = pb.start();
            // a window program runs until closed: alive after 20 s with nothing on its streams is a success
            boolean ended = p.waitFor(20, TimeUnit.SECONDS);
            String out = Files.readString(log);
            if (!ended) {
                p.destroy();
                p.waitFor(20, TimeUnit.SECONDS);
                if (p.isAlive()) p.destroyForcibly();
            }
            assertFalse(ended, "the program stopped by itself (exit " + (ended ? p.exitValue() : 0) + "):\n" + out);
            assertFalse(out.contains("Exception") || out.contains("no such file"), out);
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    /** With loose classes and no checkout around: the message that names handsim.home, exit 3. */
    @Test
    void withoutModelsTheErrorNamesTheProperty() throws Exception {
        Path dir = outside();
        try {
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            Process p = new ProcessBuilder(java, "-Dj3d.rend=noop", "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                "org.handsim.cli.HandSim", "run", "--out", dir.resolve("out").toString()).directory(dir.toFile()).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes());
            assertTrue(p.waitFor(3, TimeUnit.MINUTES));
            assertTrue(out.contains(Home.NOT_FOUND) || out.contains("-Dhandsim.home=DIR"), out);
            assertTrue(p.exitValue() == 3 || p.exitValue() == 2, "exit " + p.exitValue() + ": " + out);
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
