package org.handsim.cli;

import static org.handsim.cli.CliTesting.run;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.text.JsonObject;
import org.junit.jupiter.api.Test;

/** `handsim swing`: the files it promises, the energy guard's stop, bad arguments. */
class SwingCommandTest {
    private static List<String> names(Path dir) throws Exception {
        List<String> out = new ArrayList<>();
        try (var s = Files.list(dir)) {
            s.forEach(p -> out.add(p.getFileName().toString()));
        }
        return out;
    }

    @Test
    void theDefaultRk4RunWritesBothFilesAndConservesEnergy() throws Exception {
        Path out = Files.createTempDirectory("handsim-swing").resolve("a/b");
        CliTesting.Run r = run("swing", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("finger 1, rk4, dt = 0.001 s: 1000 steps over 1 s"), r.out());
        List<String> csv = Files.readAllLines(out.resolve("swing.csv"));
        assertEquals("t_s,q1_rad,q2_rad,q3_rad,qd1_rad_s,qd2_rad_s,qd3_rad_s,energy_J", csv.get(0));
        assertEquals(1 + 1001, csv.size(), "header, the start, then 1000 steps");
        assertTrue(csv.get(1).startsWith("0,0,0,0,0,0,0,-0.0170216"), csv.get(1));
        assertTrue(csv.get(1001).startsWith("1,"), csv.get(1001));
        String text = Files.readString(out.resolve("swing.json"));
        JsonObject j = JsonObject.parse("swing.json", text);
        assertEquals(SwingCommand.JSON_KEYS, new ArrayList<>(j.keys()), "exactly these keys, in this order");
        assertEquals(List.of("finger", "integrator", "dt_s", "steps", "duration_s", "energy_initial_J", "energy_final_J",
            "energy_drift_rel", "wall_time_s"), SwingCommand.JSON_KEYS);
        assertEquals(1, j.integer("finger"));
        assertEquals("rk4", j.string("integrator"));
        assertEquals(1000, j.integer("steps"));
        double e0 = j.number("energy_initial_J"), e1 = j.number("energy_final_J");
        assertEquals(-0.0170216, e0, 1e-7);
        double drift = j.number("energy_drift_rel");
        // relative to the energy that moves: max(|E(0)|, the largest kinetic energy of the run)
        org.handsim.dynamics.ChainDynamics d = org.handsim.dynamics.HandDynamics.barrettHand().finger(1);
        double scale = Math.abs(e0);
        for (String row : csv.subList(1, csv.size())) {
            String[] v = row.split(",");
            double[] q = {Double.parseDouble(v[1]), Double.parseDouble(v[2]), Double.parseDouble(v[3])};
            double[] qd = {Double.parseDouble(v[4]), Double.parseDouble(v[5]), Double.parseDouble(v[6])};
            scale = Math.max(scale, d.kineticEnergy(q, qd));
        }
        assertTrue(scale > 2 * Math.abs(e0), "the finger swings: largest kinetic energy " + scale);
        assertEquals(Math.abs(e1 - e0) / scale, drift, 1e-12 * drift);
        assertTrue(drift < 1e-6, "drift " + drift);
        String[] last = csv.get(1001).split(",");
        assertEquals(e1, Double.parseDouble(last[7]));
        assertEquals(List.of("swing.csv", "swing.json"), names(out).stream().sorted().toList(), "no temporary files");
    }

    @Test
    void finger3KeepsItsSpreadAtZero() throws Exception {
        Path out = Files.createTempDirectory("handsim-swing");
        CliTesting.Run r = run("swing", "--finger", "3", "--q", "0,0.5,0.2", "--qd", "0,1,-1", "--integrator", "dopri",
            "--duration", "0.2", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        List<String> csv = Files.readAllLines(out.resolve("swing.csv"));
        assertEquals(1 + 201, csv.size());
        for (String row : csv.subList(1, csv.size())) {
            String[] v = row.split(",");
            assertEquals("0", v[1], row);
            assertEquals("0", v[4], row);
        }
        assertTrue(JsonObject.parse("swing.json", Files.readString(out.resolve("swing.json"))).number("energy_drift_rel") < 1e-8);
    }

    /** Explicit Euler at 0.05 s from the stretched pose: stopped at step 5 (t = 0.25 s), exit 4, nothing written. */
    @Test
    void explicitEulerBlowingUpExits4AndWritesNothing() throws Exception {
        Path base = Files.createTempDirectory("handsim-swing");
        Path out = base.resolve("new/dir");
        CliTesting.Run r = run("swing", "--integrator", "euler", "--dt", "0.05", "--out", out.toString());
        assertEquals(4, r.code(), r.err());
        assertTrue(r.err().startsWith("handsim: swing stopped at step 5 (t = 0.25 s): energy 0.207"), r.err());
        assertTrue(r.err().contains("exceeds the initial -0.0170216 J by more than 50 %"), r.err());
        assertTrue(r.err().contains("explicit Euler is unstable at dt = 0.05 s; try rk4 or a smaller --dt"), r.err());
        assertTrue(r.err().endsWith("; no output written"), r.err());
        assertEquals(1, r.err().split("\n").length, "one line");
        assertEquals("", r.out());
        assertFalse(Files.exists(base.resolve("new")), "the folders made for the output are removed again");
        assertEquals(List.of(), names(base));
    }

    /** A stopped run leaves an earlier run's files exactly as they were (and adds no temporary file). */
    @Test
    void aStoppedRunLeavesAnEarlierRunsFilesUntouched() throws Exception {
        Path out = Files.createTempDirectory("handsim-swing");
        assertEquals(0, run("swing", "--duration", "0.1", "--out", out.toString()).code());
        byte[] csv = Files.readAllBytes(out.resolve("swing.csv")), json = Files.readAllBytes(out.resolve("swing.json"));
        CliTesting.Run r = run("swing", "--integrator", "euler", "--dt", "0.1", "--out", out.toString());
        assertEquals(4, r.code(), r.err());
        assertTrue(r.err().startsWith("handsim: swing stopped at step 3 (t = 0.3 s): energy"), r.err());
        assertArrayEquals(csv, Files.readAllBytes(out.resolve("swing.csv")));
        assertArrayEquals(json, Files.readAllBytes(out.resolve("swing.json")));
        assertEquals(List.of("swing.csv", "swing.json"), names(out).stream().sorted().toList());
    }

    @Test
    void badArgumentsExit2NamingTheArgument() throws Exception {
        Path out = Files.createTempDirectory("handsim-swing").resolve("never");
        String[][] cases = {
            {"--finger", "4"}, {"--finger"},
            {"--q", "1,2"}, {"--q"},
            {"--qd", "0,x,0"}, {"--qd"},
            {"--gravity", "0,0,NaN"}, {"--gravity"},
            {"--integrator", "leapfrog"}, {"--integrator"},
            {"--dt", "0"}, {"--dt"},
            {"--dt", "abc"}, {"--dt"},
            {"--duration", "-1"}, {"--duration"},
            {"--finger", "3", "--q", "0.1,0,0"}, {"--q"},
            {"--finger", "3", "--qd", "1,0,0"}, {"--qd"},
            {"--dt", "1e-6", "--duration", "3600"}, {"--duration"},
            {"--bogus"}, {"--bogus"},
        };
        for (int i = 0; i < cases.length; i += 2) {
            List<String> args = new ArrayList<>(List.of("swing", "--out", out.toString()));
            args.addAll(List.of(cases[i]));
            CliTesting.Run r = run(args.toArray(new String[0]));
            assertEquals(2, r.code(), String.join(" ", cases[i]) + ": " + r.err());
            assertTrue(r.err().startsWith("handsim: ") && r.err().contains(cases[i + 1][0]), String.join(" ", cases[i]) + ": " + r.err());
        }
        assertFalse(Files.exists(out));
    }

    @Test
    void helpDescribesTheContract() {
        CliTesting.Run r = run("swing", "--help");
        assertEquals(0, r.code(), r.err());
        for (String s : new String[] {"--finger", "--q", "--qd", "--gravity", "--integrator", "--dt", "--duration", "--out",
            "t_s,q1_rad,q2_rad,q3_rad,qd1_rad_s,qd2_rad_s,qd3_rad_s,energy_J", "exit 4"}) {
            assertTrue(r.out().contains(s), s + " in\n" + r.out());
        }
        for (String line : r.out().split("\n")) assertTrue(line.length() <= 80, "line too long: " + line);
    }
}
