package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.scenario.Home;
import org.handsim.trace.Recorder;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.junit.jupiter.api.Test;

/** `handsim run` and `handsim sweep`: the files they promise, and their failures. */
class RunCommandsTest {
    @Test
    void runWritesTheContractFiles() throws Exception {
        Path out = Files.createTempDirectory("handsim-run");
        CliTesting.Run r = CliTesting.run("run", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("finger 3: breakaway at t = 1.800"), r.out());
        List<String> trace = Files.readAllLines(out.resolve("trace.csv"));
        assertEquals(Recorder.header(), trace.get(0));
        assertTrue(trace.get(0).startsWith("t_s,qM1_counts,theta11_rad,theta12_rad,theta13_rad,dtheta12_rad_s,dtheta13_rad_s,"
            + "ddtheta12_rad_s2,ddtheta13_rad_s2,tau12_Nm,tau13_Nm,state1,contacts1,force1_N,qM2_counts"));
        assertTrue(trace.get(0).endsWith("state3,contacts3,force3_N,qM4_counts,clutch1_Nm,clutch2_Nm,clutch3_Nm,"
            + "residual1_Nm,residual2_Nm,residual3_Nm,carried11_Nm,carried12_Nm,carried13_Nm,carried21_Nm,carried22_Nm,"
            + "carried23_Nm,carried32_Nm,carried33_Nm,tau11_Nm,tau21_Nm,tau31_Nm"), "the new columns at the end, the old ones where they were");
        assertEquals(1 + 8948, trace.size(), "header, t = 0, then 8947 steps");
        String summary = Files.readString(out.resolve("summary.json"));
        for (String key : new String[] {"\"scenario\"", "\"sim_time_s\"", "\"steps\"", "\"dt_s\"", "\"wall_time_s\"", "\"steps_per_s\"",
            "\"breakaway_time_s\"", "\"breakaway_torque_Nm\"", "\"breakaway_force_N\"", "\"final_joints_rad\"", "\"max_contact_force_N\"",
            "\"torque_residual_Nm\""}) {
            assertTrue(summary.contains(key), key);
        }
        for (String f : new String[] {"fig7_finger3.png", "fig7_finger3.svg", "fig8_finger3.png", "fig8_finger3.svg"}) {
            assertTrue(Files.size(out.resolve(f)) > 10_000, f);
        }
        try (var s = Files.list(out)) {
            assertFalse(s.anyMatch(p -> p.getFileName().toString().endsWith(".partial")), "no temporary files left");
        }
    }

    /** The mug lowered by 5 mm: it starts inside the fingers' first links, and the run says so. */
    @Test
    void aFingerStartingInsideTheObjectIsWarnedAbout() throws Exception {
        Path dir = Files.createTempDirectory("handsim-run");
        Path moved = dir.resolve("mug-moved.json");
        String text = Files.readString(Home.scenarios().resolve("mug-grasp.json"))
            .replace("../vrml/objects/mug.wrl", Home.dir().resolve("vrml/objects/mug.wrl").toString().replace("\\", "/"));
        assertTrue(text.contains("\"position_m\": [\n      0,\n      0,\n      0.125"), "the mug's position as the test expects it");
        text = text.replace("\"position_m\": [\n      0,\n      0,\n      0.125", "\"position_m\": [\n      0,\n      0,\n      0.12");
        Files.writeString(moved, text);
        CliTesting.Run r = CliTesting.run("run", moved.toString(), "--no-charts", "--out", dir.resolve("out").toString());
        assertEquals(0, r.code(), r.err());
        for (int k = 1; k <= 3; k++) {
            assertTrue(r.err().contains("handsim: warning: finger " + k + " starts in contact with the object"), r.err());
        }
        String summary = Files.readString(dir.resolve("out").resolve("summary.json"));
        assertTrue(summary.contains("\"warnings\": [\"finger 1 starts in contact"), summary);
        // the unmoved mug: no such warning (those of forces above Barrett's rating remain)
        CliTesting.Run ok = CliTesting.run("run", Home.scenarios().resolve("mug-grasp.json").toString(), "--no-charts",
            "--out", dir.resolve("ok").toString());
        assertEquals(0, ok.code(), ok.err());
        assertFalse(ok.err().contains("starts in contact"), ok.err());
        assertFalse(Files.readString(dir.resolve("ok").resolve("summary.json")).contains("starts in contact"));
    }

    /**
     * Forces above Barrett's rating (2 kg per finger, 19.61 N at the tip) are said once per finger,
     * link or joint and stretch, not per step, on standard error and in summary.json: the paper's
     * run, whose inner contact carries 20.09 N from the breakaway until the finger opens (the
     * paper's own breakaway force, just above the rating), whose outer contact carries up to
     * 24.60 N while the finger is stalled, and whose joints 32 (the worm's reaction, 2.634 N·m
     * over 0.126 m) and 33 (the stall torque, 1.26 N·m over 0.056 m) load the fingertip's
     * equivalent of 20.91 N and 22.50 N.
     */
    @Test
    @SuppressWarnings("unchecked")
    void forcesAboveTheRatingAreWarnedOncePerStretch() throws Exception {
        Path dir = Files.createTempDirectory("handsim-run");
        CliTesting.Run r = CliTesting.run("run", "--no-charts", "--out", dir.toString());
        assertEquals(0, r.code(), r.err());
        Map<String, Object> summary = (Map<String, Object>) Json.parse("summary", Files.readString(dir.resolve("summary.json")));
        List<Object> warnings = (List<Object>) summary.get("warnings");
        String[] expected = {
            "finger 3: a contact force on link 2 above Barrett's rating of 19.61 N (2 kg per finger) from t = ",
            "finger 3: a contact force on link 3 above Barrett's rating of 19.61 N (2 kg per finger) from t = ",
            "finger 3: the torque of joint 32 as a force at the fingertip above Barrett's rating of 19.61 N",
            "finger 3: the torque of joint 33 as a force at the fingertip above Barrett's rating of 19.61 N"};
        String[] largest = {"up to 20.09 N at t = 1.801 s", "up to 24.60 N", "up to 20.91 N (2.634 N*m over its 0.1260 m lever to the tip)",
            "up to 22.50 N (1.260 N*m over its 0.05600 m lever to the tip)"};
        for (int i = 0; i < expected.length; i++) {
            String prefix = "handsim: warning: " + expected[i];
            int at = r.err().indexOf(prefix);
            assertTrue(at >= 0, expected[i] + " in " + r.err());
            assertEquals(at, r.err().lastIndexOf(prefix), "once: " + r.err());
            int end = r.err().indexOf('\n', at);
            String line = r.err().substring(at, end < 0 ? r.err().length() : end).strip();
            assertTrue(line.contains(largest[i]), line);
            assertTrue(warnings.contains(line.substring("handsim: warning: ".length())), "summary.json has it: " + warnings);
        }
        assertEquals(expected.length, warnings.size(), warnings.toString());
    }

    /**
     * One clutch criterion (DESIGN.md decision 1): the paper's experiment with gravity along the
     * palm's −z, which loads joint 32, so the torque through the clutch is τ_dyn,32 (gravity's
     * share, C) plus the springs'. No row of trace.csv has clutch3_Nm above τ_break = 1.26 N·m,
     * summary.json's breakaway torque is τ_break, and the breakaway count is where the springs
     * carry τ_break − C: q_break = q_contact + (1.26 − C)/(k_clutch · rad per count), with C read
     * from the trace (τ32 less the springs' k_clutch·(q − q_contact) in a BLOCKED row) — earlier
     * than without gravity, where the springs carry all of 1.26.
     */
    @Test
    @SuppressWarnings("unchecked")
    void withGravityOnJoint32TheClutchNeverTransmitsMoreThanTauBreak() throws Exception {
        Path dir = Files.createTempDirectory("handsim-run");
        Path paper = Home.paperScenario();
        Map<String, Object> s = (Map<String, Object>) Json.parse(paper.toString(), Files.readString(paper));
        s.put("gravity_m_s2", List.of(0, 0, -9.81));
        ((Map<String, Object>) s.get("object")).put("file", Home.dir().resolve("vrml/objects/cube.wrl").toString());
        Path file = Files.writeString(dir.resolve("gravity.json"), JsonWriter.pretty(s));
        CliTesting.Run r = CliTesting.run("run", file.toString(), "--no-charts", "--out", dir.resolve("out").toString());
        assertEquals(0, r.code(), r.err());
        List<String> trace = Files.readAllLines(dir.resolve("out").resolve("trace.csv"));
        List<String> h = List.of(trace.get(0).split(","));
        int clutch = h.indexOf("clutch3_Nm"), tau = h.indexOf("tau32_Nm"), state = h.indexOf("state3"), q = h.indexOf("qM3_counts");
        Map<String, Object> summary = (Map<String, Object>) Json.parse("summary", Files.readString(dir.resolve("out").resolve("summary.json")));
        Map<String, Object> f3 = ((List<Map<String, Object>>) summary.get("fingers")).get(2);
        double qc = ((Number) f3.get("contact_counts")).doubleValue(), qb = ((Number) f3.get("breakaway_counts")).doubleValue();
        double perCount = org.handsim.hand.HandDescription.barrettHand().kClutch() * Math.PI / 180 / 125;
        double largest = 0, gravityShare = Double.NaN;
        for (String line : trace.subList(1, trace.size())) {
            String[] c = line.split(",");
            largest = Math.max(largest, Double.parseDouble(c[clutch]));
            if (c[state].equals("BLOCKED") && Double.isNaN(gravityShare)) {
                gravityShare = Double.parseDouble(c[tau]) - perCount * (Double.parseDouble(c[q]) - qc);
                assertEquals(Double.parseDouble(c[tau]), Double.parseDouble(c[clutch]), 1e-12, "BLOCKED: the clutch carries τ32");
            }
        }
        assertTrue(gravityShare > 0.01, "gravity loads joint 32: " + gravityShare);
        assertTrue(largest <= 1.26 + 1e-9, "no row above τ_break: " + largest);
        assertTrue(largest > 1.25, "the clutch reaches τ_break: " + largest);
        assertEquals(1.26, ((Number) f3.get("breakaway_torque_Nm")).doubleValue());
        assertEquals(qc + (1.26 - gravityShare) / perCount, qb, 1e-6, "the springs carry τ_break less gravity's share");
        assertEquals(1.80, ((Number) f3.get("breakaway_time_s")).doubleValue(), 0.02);
        assertTrue(((Number) f3.get("torque_residual_Nm")).doubleValue() <= 1e-9);
    }

    @Test
    void badScenarioIsALoadErrorNamingTheField() throws Exception {
        Path dir = Files.createTempDirectory("handsim-run");
        Path bad = dir.resolve("bad.json");
        Files.writeString(bad, Files.readString(Home.paperScenario()).replace("\"dt_s\": 0.001", "\"dt_s\": -1")
            .replace("../vrml/objects/cube.wrl", Home.dir().resolve("vrml/objects/cube.wrl").toString().replace("\\", "/")));
        CliTesting.Run r = CliTesting.run("run", bad.toString(), "--out", dir.resolve("out").toString());
        assertEquals(3, r.code());
        assertTrue(r.err().contains("field dt_s: must be > 0"), r.err());
        assertFalse(Files.exists(dir.resolve("out")));
    }

    @Test
    void sweepRunsInParallelAndReportsAFailedRunWithoutStoppingTheOthers() throws Exception {
        Path dir = Files.createTempDirectory("handsim-sweep");
        Path base = dir.resolve("base.json");
        Files.writeString(base, Files.readString(Home.paperScenario())
            .replace("../vrml/objects/cube.wrl", Home.dir().resolve("vrml/objects/cube.wrl").toString().replace("\\", "/")));
        Path sweep = dir.resolve("sweep.json");
        Files.writeString(sweep, "{\"name\":\"t\",\"base\":\"base.json\",\"runs\":["
            + "{\"label\":\"as is\",\"set\":{}},"
            + "{\"label\":\"no cube\",\"set\":{\"object\":null,\"duration_s\":2.0}},"
            + "{\"label\":\"broken\",\"set\":{\"dt_s\":-1}}]}");
        CliTesting.Run r = CliTesting.run("sweep", sweep.toString(), "--out", dir.resolve("out").toString(), "--threads", "2");
        assertEquals(1, r.code(), r.err());
        List<String> rows = Files.readAllLines(dir.resolve("out").resolve("summary.csv"));
        assertEquals("run,scenario,status,sim_time_s,steps,wall_time_s,final_state1,breakaway1_s,breakaway_force1_N,max_force1_N,"
            + "final_state2,breakaway2_s,breakaway_force2_N,max_force2_N,final_state3,breakaway3_s,breakaway_force3_N,max_force3_N,error,"
            + "force_closure,epsilon,volume,hold_min_N",
            rows.get(0), "the README's header");
        assertEquals(4, rows.size());
        assertTrue(rows.get(1).startsWith("as is,paper-breakaway,ok,"), rows.get(1));
        assertTrue(rows.get(1).contains(",1.800"), rows.get(1));
        assertTrue(rows.get(2).startsWith("no cube,paper-breakaway,ok,"), rows.get(2));
        assertTrue(rows.get(3).startsWith("broken,,failed,") && rows.get(3).contains("dt_s"), rows.get(3));
        String csvSplit = ",(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)"; // commas outside quotes
        for (String row : rows) assertEquals(SweepCommand.HEADER.split(",", -1).length, row.split(csvSplit, -1).length, row);
    }
}
