package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.scenario.Home;
import org.junit.jupiter.api.Test;

/**
 * The battery's three internal errors, each now one clear line with the exit code {@code run}
 * gives: {@code grasp} of a scenario whose object reaches 3e38 m (exit 3, the object file's
 * words), a trapezoid with v_max = a_max = 1e308 (exit 3 naming the field, where
 * {@code BigDecimal} failed on the infinite duration), {@code --out} with a 300-character name
 * (exit 2 naming the option and the name's length, where a stack-trace file was written); and the
 * smaller ones: a newline in an output name is shown escaped, a name a single output's temporary
 * file would make too long still works, and an argument that is not UTF-8 is refused naming its
 * byte instead of becoming another name.
 */
class ClearErrorsTest {
    static String paper(Path dir) throws Exception {
        return Files.readString(Home.paperScenario()).replace("../vrml/objects/cube.wrl",
            TestPaths.root().resolve("vrml/objects/cube.wrl").toString().replace("\\", "/"));
    }

    @Test
    void anObjectReaching3e38IsExit3ForGraspAsForRun() throws Exception {
        Path dir = Files.createTempDirectory("handsim-errors");
        try {
            ByteBuffer b = ByteBuffer.allocate(84 + 50).order(ByteOrder.LITTLE_ENDIAN);
            b.position(80);
            b.putInt(1);
            for (float f : new float[] {0, 0, 0, 0, 0, 0, 3e38f, 0, 0, 0, 3e38f, 0}) b.putFloat(f);
            Path stl = Files.write(dir.resolve("far.stl"), b.array());
            Path s = Files.writeString(dir.resolve("far.json"), paper(dir).replace(TestPaths.root().resolve("vrml/objects/cube.wrl").toString()
                .replace("\\", "/"), stl.toString().replace("\\", "/")));
            CliTesting.Run run = CliTesting.run("run", s.toString(), "--out", dir.resolve("out").toString());
            CliTesting.Run grasp = CliTesting.run("grasp", s.toString());
            assertEquals(3, run.code(), run.err());
            assertEquals(run.code(), grasp.code(), grasp.err());
            assertEquals(run.err(), grasp.err());
            assertEquals(stl + ":1:1: coordinates reach 3.0000000054977558e+38 m from the file's origin (after units and scale), more than"
                + " the limit of 1e6 m", grasp.err());
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void aTrapezoidOf1e308IsRefusedNamingTheField() throws Exception {
        Path dir = Files.createTempDirectory("handsim-errors");
        try {
            Path s = Files.writeString(dir.resolve("fast.json"), paper(dir).replaceFirst("\"v_max\": 4244.294", "\"v_max\": 1e308")
                .replaceFirst("\"a_max\": 21221.471", "\"a_max\": 1e308"));
            for (String cmd : List.of("run", "grasp")) {
                CliTesting.Run r = CliTesting.run(cmd, s.toString());
                assertEquals(3, r.code(), cmd + ": " + r.err());
                assertEquals(s + ": field motors.M3[0].v_max: 1e+308 is beyond +-10000000 counts/s (the inner joint at 1 400 rad/s; the"
                    + " motors close a finger in about a second, 2e4 counts/s)", r.err());
            }
            Path a = Files.writeString(dir.resolve("accel.json"), paper(dir).replaceFirst("\"a_max\": 21221.471", "\"a_max\": 1e308"));
            CliTesting.Run r = CliTesting.run("run", a.toString());
            assertEquals(3, r.code(), r.err());
            assertTrue(r.err().startsWith(a + ": field motors.M3[0].a_max: 1e+308 is beyond +-10000000000 counts/s^2"), r.err());
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void namesTooLongForTheFileSystemAreExit2NamingTheOption() throws Exception {
        Path dir = Files.createTempDirectory("handsim-errors");
        try {
            Path out = dir.resolve("a".repeat(300));
            CliTesting.Run r = CliTesting.run("run", "--dt", "0.01", "--out", out.toString());
            assertEquals(2, r.code(), r.err());
            assertTrue(r.err().startsWith("handsim: --out '"), r.err());
            assertTrue(r.err().endsWith("' cannot be written: File name too long: the name 'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...aaaaaaaaaaaaaaaaa'"
                + " has 300 bytes, more than the 255 a name may have"), r.err());
            CleanOutputTest.assertOneLineNoStackTrace("--out", r.err());
            assertTrue(r.err().length() < 300, "the name is quoted short: " + r.err().length());
            Path in = Files.writeString(dir.resolve("fk.csv"), OutputSafetyTest.FK_IN);
            r = CliTesting.run("fk", "--input", in.toString(), "--output", dir.resolve("b".repeat(256)).toString());
            assertEquals(2, r.code(), r.err());
            assertTrue(r.err().startsWith("handsim: --output '") && r.err().endsWith(" has 256 bytes, more than the 255 a name may have"), r.err());
            // 250 bytes fit; the temporary file beside it keeps a shorter part of the name
            Path fits = dir.resolve("c".repeat(250));
            r = CliTesting.run("fk", "--input", in.toString(), "--output", fits.toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(Files.readString(fits).startsWith("finger,"), "written whole");
            List<String> left = new ArrayList<>();
            try (var st = Files.list(dir)) {
                st.forEach(p -> left.add(p.getFileName().toString()));
            }
            left.sort(null);
            assertEquals(List.of("c".repeat(250), "fk.csv"), left, "nothing else made");
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void aNewlineInAnOutputNameIsShownEscaped() throws Exception {
        Path dir = Files.createTempDirectory("handsim-errors");
        try {
            CliTesting.Run r = CliTesting.run("run", "--dt", "0.01", "--out", dir.resolve("two\nlines").toString());
            assertEquals(0, r.code(), r.err());
            String last = r.out().substring(r.out().lastIndexOf('\n') + 1);
            assertEquals("wrote " + dir + "/two\\u000alines/{trace.csv, fig7_finger3.png/.svg, fig8_finger3.png/.svg, summary.json}", last);
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** Bytes that are not UTF-8 in an argument (given raw, through the shell): refused naming the byte, nothing made. */
    @Test
    void anArgumentThatIsNotUtf8IsRefusedNamingItsByte() throws Exception {
        Path dir = Files.createTempDirectory("handsim-errors");
        try {
            List<String> cmd = new ArrayList<>(List.of("bash", "-c", "exec \"$@\" \"$(printf 'out\\377x')\"", "bash",
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Djava.awt.headless=true",
                "-Dhandsim.home=" + TestPaths.root(), "-Djava.io.tmpdir=" + dir, "-cp", System.getProperty("java.class.path"),
                HandSim.class.getName(), "run", "--dt", "0.01", "--out"));
            Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).start();
            String said = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).trim();
            assertTrue(p.waitFor(2, TimeUnit.MINUTES));
            assertEquals(2, p.exitValue(), said);
            assertEquals("handsim: the argument 'out\\udcffx' is not UTF-8 text (byte 0xff): Java would read it as another name; rename the"
                + " file, or give another name", said);
            try (var st = Files.list(dir)) {
                assertFalse(st.anyMatch(f -> f.getFileName().toString().startsWith("out")), "no folder made under another name");
            }
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
