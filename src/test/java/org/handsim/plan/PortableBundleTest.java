package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.handsim.cli.CliTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The portable bundle of {@code tools/scaling bundle} (a jlinked JRE, the fat jar, the models):
 * unpacked into an empty folder, it runs a plan with a PATH that holds no {@code java} (only
 * bash, env and nproc) and no JAVA_HOME — what a user finds on a many-core machine without Java
 * — and that plan's table is the one {@code handsim plan} gives here, row for row but for the
 * wall_s column; its {@code bin/scaling} measures 1 and 2 threads and finds their tables identical.
 */
@Tag("slow")
class PortableBundleTest {
    @Test
    void theBundleRunsAPlanWhereNoJavaIsInstalled() throws Exception {
        Path root = Path.of(System.getProperty("handsim.root"));
        String jar = System.getProperty("handsim.fatJar");
        assertNotNull(jar, "the build passes handsim.fatJar");
        assertTrue(Files.isRegularFile(Path.of(jar)), "gradle test builds " + jar + " first (task fatJar)");
        Path work = Files.createTempDirectory("bundle-test");
        try {
            // build it with the JDK running the tests (jlink, jdeps, javac)
            Path built = work.resolve("built");
            Path jdk = Path.of(System.getProperty("java.home"));
            Out b = run(root, Map.of("JAVA_HOME", jdk.toString(), "PATH", System.getenv("PATH")), 20,
                root.resolve("tools/scaling").toString(), "bundle", "--jar", jar, "--out", built.toString());
            assertEquals(0, b.code, b.log);
            Path tgz;
            try (Stream<Path> s = Files.list(built)) {
                tgz = s.filter(p -> p.getFileName().toString().endsWith(".tar.gz")).findFirst().orElseThrow();
            }
            // unpack into an empty folder, away from the checkout and the build
            Path empty = work.resolve("elsewhere");
            Files.createDirectories(empty);
            Out x = run(empty, Map.of("PATH", System.getenv("PATH")), 5, "tar", "xzf", tgz.toString());
            assertEquals(0, x.code, x.log);
            Path home;
            try (Stream<Path> s = Files.list(empty)) {
                home = s.filter(Files::isDirectory).findFirst().orElseThrow();
            }
            // a PATH with bash, env and nproc and nothing else: no java to find
            Path bin = work.resolve("path");
            Files.createDirectories(bin);
            for (String tool : new String[] {"bash", "env", "nproc"}) {
                for (String dir : System.getenv("PATH").split(":")) {
                    Path t = Path.of(dir, tool);
                    if (Files.isExecutable(t)) {
                        Files.createSymbolicLink(bin.resolve(tool), t.toRealPath());
                        break;
                    }
                }
            }
            Map<String, String> noJava = Map.of("PATH", bin.toString(), "HOME", work.toString());
            Out which = run(home, noJava, 1, bin.resolve("bash").toString(), "-c", "command -v java || echo none");
            assertEquals("none", which.log.trim(), "the test's PATH must hold no java");
            Path out = work.resolve("plan");
            Out plan = run(home, noJava, 10, "bin/handsim", "plan", "vrml/objects/mug.wrl", "--trials", "24", "--threads", "2",
                "--seed", "3", "--out", out.toString());
            assertEquals(0, plan.code, plan.log);
            assertTrue(plan.log.contains("24 trials (0 failed)"), plan.log);
            // the same plan here, in this JVM: the same table
            Path here = work.resolve("here");
            CliTesting.Run r = CliTesting.run("plan", root.resolve("vrml/objects/mug.wrl").toString(), "--trials", "24", "--threads", "1",
                "--seed", "3", "--out", here.toString());
            assertEquals(0, r.code(), r.err());
            List<String> a = PlanTesting.withoutTiming(Files.readAllLines(out.resolve("plan.csv")));
            List<String> e = PlanTesting.withoutTiming(Files.readAllLines(here.resolve("plan.csv")));
            assertEquals(25, a.size());
            assertEquals(e, a, "the bundle's table is the checkout's");
            // and its measuring tool, on two small plans
            Out sc = run(home, noJava, 15, "bin/scaling", "--trials", "16", "--threads", "1,2");
            assertEquals(0, sc.code, sc.log);
            assertTrue(sc.log.contains("plan.csv identical at every thread count"), sc.log);
            assertTrue(sc.log.contains("--threads 2` | 2 |"), sc.log);
            assertFalse(sc.log.contains("DIFFERS"), sc.log);
        } finally {
            PlanTesting.deleteTree(work);
        }
    }

    record Out(int code, String log) {}

    static Out run(Path dir, Map<String, String> env, int minutes, String... cmd) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
        pb.environment().clear();
        pb.environment().putAll(env);
        Path log = Files.createTempFile("bundle-test", ".log");
        try {
            pb.redirectOutput(log.toFile());
            Process p = pb.start();
            if (!p.waitFor(minutes, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                fail(Arrays.toString(cmd) + " did not finish in " + minutes + " min: " + Files.readString(log));
            }
            return new Out(p.exitValue(), Files.readString(log));
        } finally {
            Files.deleteIfExists(log);
        }
    }
}
