package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Every invalid number is caught where it enters, with the field or option and the value named,
 * exit 2 (an option, a CSV row) or 3 (a file's field), one line, no stack trace — where before
 * they gave ArrayIndexOutOfBounds (a rotation of 1e300), "reach must be >= 0, got NaN" (scale
 * 1e300), "no triangles" (scale 1e-300), results identical to the default (gravity -1e308),
 * "refusing to write a non-finite number as JSON" (ik, id, swing), "tolerance must be finite"
 * (mesh --scale 1e200), "needs 9223372036854775807 steps" blaming duration_s (dt 1e-300), or
 * nothing at all (run --dt 1e-9 started an 8.9e9-step run). Also: byte-order marks accepted in
 * JSON, non-UTF-8 input named by line and byte, {@code 0d} not a number.
 */
class InvalidNumbersTest {
    static Path dir;
    static final Path PAPER = TestPaths.root().resolve("scenarios/paper-breakaway.json");
    static final Path CUBE = TestPaths.root().resolve("vrml/objects/cube.wrl");

    @BeforeAll
    static void folder() throws Exception {
        dir = Files.createTempDirectory("handsim-numbers");
    }

    @AfterAll
    static void clean() throws Exception {
        ChildJvm.deleteTree(dir);
    }

    /** The paper's scenario (object by absolute path) changed by {@code edit}, written as {@code name}. */
    @SuppressWarnings("unchecked")
    static Path scenario(String name, Consumer<Map<String, Object>> edit) throws Exception {
        Map<String, Object> s = (Map<String, Object>) Json.parse(PAPER.toString(), Files.readString(PAPER));
        ((Map<String, Object>) s.get("object")).put("file", CUBE.toString());
        edit.accept(s);
        return Files.writeString(dir.resolve(name), JsonWriter.pretty(s));
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> object(Map<String, Object> s) {
        return (Map<String, Object>) s.get("object");
    }

    /** Exit code {@code code}, one line that contains every {@code parts}, no trace, nothing written. */
    static void refused(int code, CliTesting.Run r, String... parts) {
        assertEquals(code, r.code(), r.err());
        assertFalse(r.err().contains("\n") || r.err().contains("Exception") || r.err().contains("\tat "), r.err());
        for (String p : parts) assertTrue(r.err().contains(p), "'" + p + "' in: " + r.err());
        assertTrue(r.out().isEmpty(), r.out());
    }

    static CliTesting.Run run(Path scenario, String... more) {
        String[] args = new String[3 + more.length];
        args[0] = "run";
        args[1] = scenario.toString();
        args[2] = "--no-charts";
        System.arraycopy(more, 0, args, 3, more.length);
        String[] all = java.util.Arrays.copyOf(args, args.length + 2);
        all[args.length] = "--out";
        all[args.length + 1] = dir.resolve("out").toString();
        return CliTesting.run(all);
    }

    @Test
    void rotationsScalesGravityAndFrictionOutOfRangeNameTheField() throws Exception {
        refused(3, run(scenario("orot.json", s -> object(s).put("rotation_rad", List.of(1e300, 0.0, 0.0)))),
            "field object.rotation_rad[0]: must be within +-1000 rad", "got 1e+300");
        refused(3, run(scenario("hrot.json", s -> s.put("hand", Map.of("rotation_rad", List.of(0.0, -1e300, 0.0))))),
            "field hand.rotation_rad[1]: must be within +-1000 rad", "got -1e+300");
        refused(3, run(scenario("hpos.json", s -> s.put("hand", Map.of("position_m", List.of(0.0, 0.0, 1e7))))),
            "field hand.position_m[2]: must be within +-1e6 m, got 10000000");
        refused(3, run(scenario("big.json", s -> object(s).put("scale", 1e300))), "field object.scale: must be in [1e-6, 1e6], got 1e+300");
        refused(3, run(scenario("tiny.json", s -> object(s).put("scale", 1e-300))), "field object.scale: must be in [1e-6, 1e6], got 1e-300");
        refused(3, run(scenario("g.json", s -> s.put("gravity_m_s2", List.of(0.0, 0.0, -1e308)))),
            "field gravity_m_s2[2]: -1e+308 is beyond +-100 m/s^2");
        refused(3, run(scenario("mu.json", s -> object(s).put("friction", 1e308))), "field object.friction: must be in [0, 10]", "got 1e+308");
        // grasp on that scenario failed every evaluation with "degenerate initial simplex (a bug)"
        refused(3, CliTesting.run("grasp", dir.resolve("mu.json").toString()), "field object.friction: must be in [0, 10]");
        // the edges of the range are accepted: a run of 0.05 s with them
        CliTesting.Run ok = run(scenario("edges.json", s -> {
            s.put("gravity_m_s2", List.of(0.0, 0.0, -100.0));
            s.put("duration_s", 0.05);
            object(s).put("friction", 10.0);
            object(s).put("rotation_rad", List.of(1000.0, 0.0, 0.0));
        }));
        assertEquals(0, ok.code(), ok.err());
    }

    @Test
    void commandLineNumbersOutOfRangeNameTheOption() {
        refused(2, CliTesting.run("collide", CUBE.toString(), CUBE.toString(), "--pose-b", "0,0,0,1e300,0,0"),
            "--pose-b: rotation[0] must be within +-1000 rad", "got 1e+300");
        refused(2, CliTesting.run("ik", "--finger", "1", "--target", "1e300,0,0"), "--target: 1e+300 is beyond +-1000000 m");
        refused(2, CliTesting.run("id", "--finger", "1", "--q", "0,0,0", "--qd", "1e300,0,0", "--qdd", "0,0,0", "--gravity", "0,0,-9.81"),
            "--qd: 1e+300 is beyond +-1000 rad/s");
        refused(2, CliTesting.run("swing", "--qd", "1e150,0,0"), "--qd: 1e+150 is beyond +-1000 rad/s");
        refused(2, CliTesting.run("swing", "--gravity", "0,0,-1e300"), "--gravity: -1e+300 is beyond +-100 m/s^2");
        refused(2, CliTesting.run("mesh", CUBE.toString(), "--scale", "1e200"), "--scale must be in [1e-6, 1e6], got 1e+200");
        refused(2, CliTesting.run("fk", "--finger", "1", "--joints", "1e300,0,0"), "--joints: 1e+300 is beyond +-1000 rad");
        refused(2, CliTesting.run("plan", CUBE.toString(), "--trials", "2147483647"), "--trials must be in [1, 1000000]", "got 2147483647");
        refused(2, CliTesting.run("plan", CUBE.toString(), "--friction", "1e308"), "--friction must be in [0, 10]", "got 1e+308");
        refused(2, CliTesting.run("run", "--dt", "0d"), "'0d' is not a number");
        refused(2, CliTesting.run("quality", CUBE.toString(), "--radius", "1f"), "--radius: '1f' is not a number");
        refused(2, CliTesting.run("plan", CUBE.toString(), "--threads", "-5"), "--threads must be in [1, 1024], got -5");
    }

    @Test
    void bulkRowsOutOfRangeNameTheirLine() throws Exception {
        Path in = Files.writeString(dir.resolve("ik.csv"), "finger,x,y,z\n1,0.1,0,0\n1,1e300,0,0\n");
        refused(2, CliTesting.run("ik", "--input", in.toString(), "--output", dir.resolve("ik-out.csv").toString()),
            in + ":3: column x = 1e+300 is beyond +-1000000 m");
        Path id = Files.writeString(dir.resolve("id.csv"), "finger,q1,q2,q3,qd1,qd2,qd3,qdd1,qdd2,qdd3,gx,gy,gz\n"
            + "1,0,0,0,0,1e300,0,0,0,0,0,0,-9.81\n");
        refused(2, CliTesting.run("id", "--input", id.toString(), "--output", dir.resolve("id-out.csv").toString()),
            id + ":2: column qd2 = 1e+300 is beyond +-1000 rad/s");
        Path zero = Files.writeString(dir.resolve("d.csv"), "finger,x,y,z\n1,0d,0,0\n");
        refused(2, CliTesting.run("ik", "--input", zero.toString(), "--output", dir.resolve("z-out.csv").toString()),
            zero + ":2: column x = '0d' is not a number");
        assertFalse(Files.exists(dir.resolve("ik-out.csv")) || Files.exists(dir.resolve("id-out.csv")));
    }

    /** A huge duration or a tiny dt: the count as people read it, the field or option that causes it. */
    @Test
    void theStepLimitHoldsWhateverSetTheStep() throws Exception {
        refused(2, run(PAPER, "--dt", "1e-9"),
            "--dt 1e-9: needs 8.95 billion steps (8.946365572224732 s at 1e-9 s a step), more than the limit of 10 million");
        refused(2, run(PAPER, "--dt", "1e-300"), "--dt 1e-300: needs 8.95e+300 steps");
        refused(3, run(scenario("dur.json", s -> s.put("duration_s", 1e300))), "field duration_s: needs 1e+303 steps (1e+300 s at 0.001 s a step)");
        refused(2, CliTesting.run("swing", "--dt", "1e-300"), "--dt 1e-300 for --duration 1 s needs 1e+300 steps, more than the limit of 10 million");
        refused(3, run(scenario("dt.json", s -> s.put("dt_s", 1e-300))), "field dt_s: needs 8.95e+300 steps");
        for (String r : new String[] {run(PAPER, "--dt", "1e-9").err(), run(scenario("dur2.json", s -> s.put("duration_s", 1e300))).err()}) {
            assertFalse(r.contains("9223372036854775807"), r);
        }
        // just inside: 10 million steps are accepted (not run here: the check is before the run)
        assertEquals(null, org.handsim.scenario.Scenario.stepsProblem(10_000, 0.001));
        assertTrue(org.handsim.scenario.Scenario.stepsProblem(10_000.001, 0.001).startsWith("needs 10 million steps"));
    }

    @Test
    void byteOrderMarksAndNonUtf8() throws Exception {
        byte[] paper = Files.readString(scenario("plain.json", s -> s.put("duration_s", 0.01))).getBytes(StandardCharsets.UTF_8);
        byte[] bom = new byte[paper.length + 3];
        bom[0] = (byte) 0xef;
        bom[1] = (byte) 0xbb;
        bom[2] = (byte) 0xbf;
        System.arraycopy(paper, 0, bom, 3, paper.length);
        Path withBom = Files.write(dir.resolve("bom.json"), bom);
        assertEquals(0, run(withBom).code(), run(withBom).err());
        Path sweep = Files.write(dir.resolve("bom-sweep.json"),
            ("\uFEFF{\"name\": \"bom\", \"scenarios\": [\"" + withBom + "\"], \"threads\": 1}").getBytes(StandardCharsets.UTF_8));
        CliTesting.Run s = CliTesting.run("sweep", sweep.toString(), "--out", dir.resolve("sw").toString());
        assertEquals(0, s.code(), s.err());
        byte[] latin = new String(paper, StandardCharsets.UTF_8).replace("\"name\": \"paper-breakaway\"", "\"name\": \"caf\u00e9\"")
            .getBytes(StandardCharsets.ISO_8859_1);
        Path bad = Files.write(dir.resolve("latin1.json"), latin);
        refused(3, run(bad), bad + ":2:", ": not UTF-8: byte 0xe9 at offset ");
        Path csv = Files.write(dir.resolve("latin1.csv"), "x,y,z,nx,ny,nz\n0,0,0,1,0,0\n0,0,0\u00ff,1,0,0\n".getBytes(StandardCharsets.ISO_8859_1));
        refused(3, CliTesting.run("quality", csv.toString()), csv + ":3:6: not UTF-8: byte 0xff at offset 32");
    }

    /** A normal of (1e-300, 0, 0) is a direction (its square underflows): the cube's faces give the same ε as unit normals. */
    @Test
    void aTinyNormalIsNormalisedNotCalledZero() throws Exception {
        String rows = "x,y,z,nx,ny,nz\n0.03,0,0,-1,0,0\n-0.03,0,0,1,0,0\n0,0.03,0,0,-1,0\n0,-0.03,0,0,1,0\n0,0,0.03,0,0,-1\n0,0,-0.03,0,0,1\n";
        Path unit = Files.writeString(dir.resolve("unit.csv"), rows);
        Path tiny = Files.writeString(dir.resolve("tiny.csv"), rows.replace(",-1,0,0", ",-1e-300,0,0").replace(",0,0,1\n", ",0,0,1e-300\n"));
        CliTesting.Run a = CliTesting.run("quality", unit.toString(), "--radius", "0.052", "--edges", "4");
        CliTesting.Run b = CliTesting.run("quality", tiny.toString(), "--radius", "0.052", "--edges", "4");
        assertEquals(0, b.code(), b.err());
        assertTrue(b.out().contains("\"epsilon\":0.1665433468816228"), b.out());
        assertEquals(a.out().replaceAll("\"time_us_median\":[0-9.e+-]+", ""), b.out().replaceAll("\"time_us_median\":[0-9.e+-]+", ""));
        Path zero = Files.writeString(dir.resolve("zero.csv"), "x,y,z,nx,ny,nz\n0,0,0,0,0,0\n");
        refused(2, CliTesting.run("quality", zero.toString()), zero + ":2: the normal (0, 0, 0) must be a finite non-zero vector");
    }

    /** A sweep's threads as --threads; its rows never show Java class names. */
    @Test
    void sweepThreadsAndRowErrors() throws Exception {
        Path neg = Files.writeString(dir.resolve("neg.json"), "{\"name\": \"n\", \"scenarios\": [\"" + PAPER + "\"], \"threads\": -3}");
        refused(3, CliTesting.run("sweep", neg.toString()), "field threads: must be in [0, 1024] (0: all cores), got -3");
        Path base = scenario("base.json", s -> s.put("duration_s", 0.01));
        Path rows = Files.writeString(dir.resolve("rows.json"), "{\"name\": \"rows\", \"base\": \"" + base + "\", \"threads\": 1, \"runs\": ["
            + "{\"label\": \"index\", \"set\": {\"motors.M3[x].v_max\": 1}},"
            + "{\"label\": \"rotation\", \"set\": {\"object.rotation_rad\": [1e300, 0, 0]}},"
            + "{\"label\": \"shadow\", \"set\": {\"object.file\": \"" + dir.resolve("secret.txt") + "\"}}]}");
        Files.writeString(dir.resolve("secret.txt"), "root:*:20228:0:99999:7:::\n");
        CliTesting.Run r = CliTesting.run("sweep", rows.toString(), "--out", dir.resolve("rows").toString());
        assertEquals(1, r.code(), r.err());
        String table = Files.readString(dir.resolve("rows").resolve("summary.csv"));
        assertFalse(table.contains("java.lang") || table.contains("Exception") || table.contains("$"), table);
        assertTrue(table.contains("override \"\"motors.M3[x].v_max\"\": bad index in 'M3[x]'"), table);
        assertTrue(table.contains("field object.rotation_rad[0]: must be within +-1000 rad"), table);
        assertTrue(table.contains("secret.txt:1:1: not a VRML97 file") && !table.contains("root:"), table);
    }

    /** An STL with 3e38 coordinates: planning it hung; its coordinates are now refused where the mesh is loaded. */
    @Test
    void aMeshBeyondAMillionMetresIsRefused() throws Exception {
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(134).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        b.position(80);
        b.putInt(1);
        for (float f : new float[] {0, 0, 1, 0, 0, 0, 3e38f, 0, 0, 0, 3e38f, 0}) b.putFloat(f);
        Path stl = Files.write(dir.resolve("huge.stl"), b.array());
        for (String[] cmd : new String[][] {{"plan", stl.toString(), "--trials", "1", "--out", dir.resolve("p").toString()}, {"mesh", stl.toString()},
            {"collide", stl.toString(), CUBE.toString()}}) {
            refused(3, CliTesting.run(cmd), stl + ":1:1: coordinates reach 3.0000000054977558e+38 m from the file's origin (after units and scale),"
                + " more than the limit of 1e6 m");
        }
    }

    /** A result that is not finite is stopped before the JSON with the field named: exit 4. */
    @Test
    void nonFiniteResultsAreNamedBeforeTheJson() {
        JsonWriter.NonFiniteException e = org.junit.jupiter.api.Assertions.assertThrows(JsonWriter.NonFiniteException.class,
            () -> JsonWriter.write(Map.of("fingers", List.of(Map.of("x", 1.0), Map.of("tau", new double[] {0, Double.NaN})))));
        assertEquals("fingers[1].tau[1]", e.path());
        assertEquals("the result fingers[1].tau[1] is NaN, not a finite number", e.getMessage());
        java.io.StringWriter err = new java.io.StringWriter();
        assertEquals(4, HandSim.failure(new java.io.PrintWriter(err), e));
        assertEquals("handsim: the result fingers[1].tau[1] is NaN, not a finite number: an input is beyond the range the computation can"
            + " represent; nothing was written", err.toString().trim());
    }
}
