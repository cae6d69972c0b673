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
            + "residual1_Nm,residual2_Nm,residual3_Nm"), "the new columns at the end, the old ones where they were");
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
        // the unmoved mug: no warning, an empty list
        CliTesting.Run ok = CliTesting.run("run", Home.scenarios().resolve("mug-grasp.json").toString(), "--no-charts",
            "--out", dir.resolve("ok").toString());
        assertEquals(0, ok.code(), ok.err());
        assertFalse(ok.err().contains("warning"), ok.err());
        assertTrue(Files.readString(dir.resolve("ok").resolve("summary.json")).contains("\"warnings\": []"));
    }

    /**
     * A state with no static equilibrium is said once per finger and stretch, not per step: the
     * README screenshot's scene (the millimetre mug placed clear on the palm axis, every finger
     * closing until its outer link stalls on the rim before any breakaway) without friction, where
     * no push along the normals carries the stalled outer joints' torques with the inner joints'
     * reactions within their worms' limit (DESIGN.md, "Which torques the contacts carry"). The
     * trace's residual columns show it, summary.json has the run's largest per finger, and each
     * finger's warning (standard error and summary.json) names it and the stretch's times.
     */
    @Test
    void aRunWithoutStaticEquilibriumWarnsOncePerFingerAndStretch() throws Exception {
        Path dir = Files.createTempDirectory("handsim-run");
        org.handsim.scenario.Scenario s = org.handsim.scenario.Scenario.load(Home.paperScenario());
        org.handsim.model.ObjectPlacer.Placed p = org.handsim.model.ObjectPlacer.place(s, Home.dir().resolve("vrml/objects/mug_mm.stl"),
            org.handsim.scenario.Scenario.DEFAULT_DIVISIONS, 1, org.handsim.scenario.Scenario.Units.MM);
        s = s.withObject(p.placement()).withFriction(0).withDuration(2.4);
        for (int m = 0; m < 3; m++) s = s.withMotor(m, new org.handsim.trajectory.Trapezoid(0, 17500, 5000, 25000));
        Path file = dir.resolve("stalled.json");
        Files.writeString(file, org.handsim.text.JsonWriter.pretty(s.toJson(dir)));
        CliTesting.Run r = CliTesting.run("run", file.toString(), "--no-charts", "--out", dir.resolve("out").toString());
        assertEquals(0, r.code(), r.err());
        String summary = Files.readString(dir.resolve("out").resolve("summary.json"));
        List<String> trace = Files.readAllLines(dir.resolve("out").resolve("trace.csv"));
        String[] header = trace.get(0).split(",");
        for (int k = 1; k <= 3; k++) {
            String prefix = "finger " + k + ": the contact forces cannot carry its joint torques from t = ";
            int at = r.err().indexOf("handsim: warning: " + prefix);
            assertTrue(at >= 0, r.err());
            assertEquals(at, r.err().lastIndexOf("handsim: warning: " + prefix), "once per finger: " + r.err());
            assertTrue(summary.contains("\"" + prefix), summary);
            int col = java.util.Arrays.asList(header).indexOf("residual" + k + "_Nm");
            double largest = 0;
            for (String line : trace.subList(1, trace.size())) largest = Math.max(largest, Double.parseDouble(line.split(",")[col]));
            assertTrue(largest > 0.05, "finger " + k + ": the trace shows the residual: " + largest);
            assertTrue(summary.replaceAll("\\s", "").contains("\"torque_residual_Nm\":" + org.handsim.text.Decimal.format(largest)),
                "summary.json has the trace's largest residual " + largest);
        }
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
