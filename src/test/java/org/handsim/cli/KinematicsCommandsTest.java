package org.handsim.cli;

import static org.handsim.cli.CliTesting.run;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.handsim.cli.CliTesting.Run;
import org.junit.jupiter.api.Test;

class KinematicsCommandsTest {
    @Test
    void fkPrintsTheContractJson() {
        Run r = run("fk", "--finger", "3", "--joints", "0,1.5275,0.6981317007977318");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("{\"finger\":3,\"frame\":\"base\",\"joints\":[0,1.5275,0.6981317007977318],\"origins\":[[0,0,0],[0.05,0,0],["), r.out());
        assertTrue(r.out().contains("\"fingertip\":["), r.out());
    }

    /** The JSON object a command printed. */
    @SuppressWarnings("unchecked")
    private static java.util.Map<String, Object> json(Run r) {
        assertEquals(0, r.code(), r.err());
        return (java.util.Map<String, Object>) org.handsim.text.Json.parse("stdout", r.out());
    }

    /** A JSON array of numbers. */
    @SuppressWarnings("unchecked")
    private static double[] doubles(Object o) {
        List<Object> l = (List<Object>) o;
        double[] v = new double[l.size()];
        for (int i = 0; i < v.length; i++) v[i] = ((Number) l.get(i)).doubleValue();
        return v;
    }

    /** Counts go through the transmission, paper eqs (1)-(4): θ21 = (2/35)·q_M4 °, θ22 = q_M2/125 °, θ23 = q_M2/375 °. */
    @Test
    void fkFromCountsMatchesJoints() {
        java.util.Map<String, Object> byCounts = json(run("fk", "--finger", "2", "--counts", "17500,3150"));
        double[] j = doubles(byCounts.get("joints"));
        double[] paper = {Math.toRadians(2.0 / 35 * 3150), Math.toRadians(17500 / 125.0), Math.toRadians(17500 / 375.0)};
        for (int i = 0; i < 3; i++) assertEquals(paper[i], j[i], 1e-12, "joint " + (i + 1));
        java.util.Map<String, Object> byJoints = json(run("fk", "--finger", "2", "--joints", j[0] + "," + j[1] + "," + j[2]));
        assertEquals(byJoints.get("origins"), byCounts.get("origins"));
    }

    /** ik's joints put the fingertip on the target by forward kinematics (the fk command, DH). */
    @Test
    void ikRoundTripThroughTheCommand() {
        double[] target = {0.05, -0.09, 0.08};
        java.util.Map<String, Object> ik = json(run("ik", "--finger", "1", "--target", "0.05,-0.09,0.08"));
        assertEquals(Boolean.TRUE, ik.get("reachable"));
        assertTrue(((Number) ik.get("error_m")).doubleValue() < 1e-12, ik.toString());
        double[] j = doubles(ik.get("joints"));
        double[] tip = doubles(json(run("fk", "--finger", "1", "--joints", j[0] + "," + j[1] + "," + j[2])).get("fingertip"));
        assertArrayEquals(target, tip, 1e-12);
        assertArrayEquals(target, doubles(ik.get("fingertip")), 1e-12);
    }

    /** {@code --frame palm}: fk's points and ik's target in {P}, through the finger's base placement. */
    @Test
    void frameOptionPutsPointsInThePalmFrame() {
        double[] joints = {0.2, 0.5, 0.3};
        java.util.Map<String, Object> b = json(run("fk", "--finger", "2", "--joints", "0.2,0.5,0.3"));
        java.util.Map<String, Object> p = json(run("fk", "--finger", "2", "--joints", "0.2,0.5,0.3", "--frame", "palm"));
        assertEquals("palm", p.get("frame"));
        double[] tipBase = org.handsim.kinematics.FingerKinematics.of(2).fingertip(joints);
        double[] want = org.handsim.kinematics.FingerKinematics.of(2).baseInPalm().apply(tipBase);
        assertArrayEquals(tipBase, doubles(b.get("fingertip")), 1e-15);
        assertArrayEquals(want, doubles(p.get("fingertip")), 1e-15);
        // ik takes that palm-frame point as a palm-frame target, and answers in that frame
        java.util.Map<String, Object> ik = json(run("ik", "--finger", "2", "--target", want[0] + "," + want[1] + "," + want[2], "--frame", "palm"));
        assertEquals(Boolean.TRUE, ik.get("reachable"));
        assertArrayEquals(want, doubles(ik.get("fingertip")), 1e-12);

        for (Run r : new Run[] {run("fk", "--finger", "1", "--joints", "0,0,0", "--frame", "world"),
            run("ik", "--finger", "1", "--target", "0,0,0", "--frame", "world")}) {
            assertEquals(2, r.code(), r.err());
            assertEquals("handsim: --frame must be base or palm, got 'world'", r.err());
        }
    }

    @Test
    void badArgumentsExitTwoWithOneLineNamingThem() {
        Run r = run("fk", "--finger", "4", "--joints", "0,0,0");
        assertEquals(2, r.code());
        assertEquals("handsim: --finger must be 1, 2 or 3, got 4", r.err());
        r = run("ik", "--finger", "1", "--target", "0.1,abc,0");
        assertEquals(2, r.code());
        assertEquals("handsim: --target: 'abc' is not a number", r.err());
        r = run("fk", "--finger", "3", "--joints", "0.2,0,0");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("t1 must be 0"), r.err());
        r = run("fk", "--finger", "1", "--counts", "20000");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("20000"), r.err());
        r = run("fk", "--bogus");
        assertEquals(2, r.code());
        assertTrue(r.err().startsWith("handsim: Unknown option: '--bogus'"), r.err());
    }

    @Test
    void everySubcommandHasHelp() {
        for (Class<?> c : CliTesting.COMMANDS) {
            String name = c.getAnnotation(picocli.CommandLine.Command.class).name();
            Run r = run(name, "--help");
            assertEquals(0, r.code(), name);
            assertTrue(r.out().startsWith("Usage: handsim " + name), r.out());
        }
    }

    @Test
    void bulkFkAndIk() throws Exception {
        Path dir = Files.createTempDirectory("handsim-fk");
        Path in = dir.resolve("in.csv"), out = dir.resolve("out.csv");
        Files.writeString(in, "finger,t1,t2,t3\n1,0,0,0\n3,0,1,0.5\n\n2,0.3,0.2,0.1\n");
        Run r = run("fk", "--input", in.toString(), "--output", out.toString());
        assertEquals(0, r.code(), r.err());
        List<String> lines = Files.readAllLines(out);
        assertEquals("finger,t1,t2,t3,o0x,o0y,o0z,o1x,o1y,o1z,o2x,o2y,o2z,o3x,o3y,o3z", lines.get(0), "the README's header");
        assertEquals(4, lines.size());
        assertTrue(lines.get(1).startsWith("1,0,0,0,0,0,0,0.05,"), lines.get(1));

        Path ikIn = dir.resolve("ik.csv"), ikOut = dir.resolve("ik-out.csv");
        Files.writeString(ikIn, "finger,x,y,z\n3,0.15405713827444156,0,0.04740851014402606\n3,1,0,0\n");
        r = run("ik", "--input", ikIn.toString(), "--output", ikOut.toString());
        assertEquals(0, r.code(), r.err());
        lines = Files.readAllLines(ikOut);
        assertEquals("finger,x,y,z,reachable,t1,t2,t3,error_m", lines.get(0));
        assertTrue(lines.get(1).startsWith("3,0.15405713827444156,0,0.04740851014402606,true,0,"), lines.get(1));
        assertTrue(lines.get(2).startsWith("3,1,0,0,false,"), lines.get(2));
    }

    @Test
    void badRowStopsWithItsLineNumberAndLeavesNothing() throws Exception {
        Path dir = Files.createTempDirectory("handsim-fk");
        Path in = dir.resolve("in.csv"), out = dir.resolve("out.csv");
        Files.writeString(in, "finger,t1,t2,t3\n1,0,0,0\n2,0,x,0\n");
        Run r = run("fk", "--input", in.toString(), "--output", out.toString());
        assertEquals(2, r.code());
        assertEquals("handsim: " + in + ":3: column t2 = 'x' is not a number", r.err());
        assertFalse(Files.exists(out));
        try (var s = Files.list(dir)) {
            assertEquals(1, s.count(), "no temporary file left behind");
        }
        Files.writeString(in, "finger,a,b,c\n1,0,0,0\n");
        r = run("fk", "--input", in.toString(), "--output", out.toString());
        assertEquals(2, r.code());
        assertTrue(r.err().contains(":1: header must be exactly 'finger,t1,t2,t3'"), r.err());
    }
}
