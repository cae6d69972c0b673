package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.hand.HandDescription;
import org.handsim.model.HandModel;
import org.handsim.model.Simulation;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * The hand's parameters in a scenario ({@code hand.parameters}): each checked with its range,
 * the derived ones following (DESIGN.md decision 1), the run breaking away where they say, and
 * the summary recording the values used.
 */
class HandParametersTest {
    static final Path PAPER = TestPaths.root().resolve("scenarios/paper-breakaway.json");

    /** The paper's scenario with {@code hand.parameters} set to {@code parameters} (JSON text). */
    @SuppressWarnings("unchecked")
    static Scenario paperWith(String parameters) {
        Map<String, Object> j = (Map<String, Object>) Json.parse("paper", Scenario.readText(PAPER));
        Map<String, Object> hand = j.get("hand") instanceof Map ? (Map<String, Object>) j.get("hand") : new java.util.LinkedHashMap<>();
        hand.put("parameters", Json.parse("parameters", parameters));
        j.put("hand", hand);
        return Scenario.parse(PAPER, JsonWriter.write(j));
    }

    @Test
    void eachParameterIsCheckedWithItsRangeNamingTheField() {
        String[][] bad = {
            {"{\"tau_break_Nm\": 9}", "field hand.parameters.tau_break_Nm: must be in [0.05, 5] N*m"},
            {"{\"tau_break_Nm\": 0.9, \"k_clutch_Nm_per_rad\": 5, \"windup_deg\": 10}", "field hand.parameters.k_clutch_Nm_per_rad: give the clutch stiffness or the wind-up angle"},
            {"{\"windup_deg\": 0}", "field hand.parameters.windup_deg: must be in [0.1, 90] degrees"},
            {"{\"theta3_limits_deg\": [40, 10]}", "field hand.parameters.theta3_limits_deg: the lower limit must be below the upper"},
            {"{\"motor_v_max_counts_s\": 3000}", "field motors.M3[0].v_max: is above the hand's motor speed limit 3000 counts/s"},
            {"{\"theta2_limits_deg\": [0, 120]}", "field motors.M3[0].to: must be in [0, 15000] counts, got 17500"},
            {"{\"friction\": 11}", "field hand.parameters.friction: must be in [0, 10]"},
            {"{\"tau_brake_Nm\": 1}", "tau_brake_Nm"},
        };
        for (String[] b : bad) {
            ScenarioException e = assertThrows(ScenarioException.class, () -> paperWith(b[0]), b[0]);
            assertTrue(e.getMessage().contains(b[1]), b[0] + " -> " + e.getMessage());
        }
    }

    /**
     * τ_break alone keeps the wind-up angle (10°, the hand file's 1.26 / 7.2192 rad) and the
     * stiffness follows: 0.9 / (1.26 / 7.2192) = 5.1566 N·m/rad; a stiffness instead sets the
     * wind-up: 0.9 / 7.2192 rad = 7.143°. (The inner joint's upper limit sets the finger's count
     * range by eq (3): 120° × 125 = 15 000 counts, which refuses the paper's 17 500: above.)
     */
    @Test
    void theDerivedParametersFollowAsDesignSays() {
        HandDescription file = HandDescription.barrettHand();
        HandDescription h = paperWith("{\"tau_break_Nm\": 0.9}").hand();
        assertEquals(0.9, h.tauBreak());
        assertEquals(0.9 * file.kClutch() / file.tauBreak(), h.kClutch(), 1e-12);
        assertEquals(10.0, Math.toDegrees(h.tauBreak() / h.kClutch()), 1e-3);
        HandDescription k = paperWith("{\"tau_break_Nm\": 0.9, \"k_clutch_Nm_per_rad\": 7.2192}").hand();
        assertEquals(7.2192, k.kClutch());
        assertEquals(Math.toDegrees(0.9 / 7.2192), (Double) k.parametersJson().get("windup_deg"), 1e-12);
        HandDescription w = paperWith("{\"windup_deg\": 5}").hand();
        assertEquals(1.26 / Math.toRadians(5), w.kClutch(), 1e-12);
        assertEquals(0.3, paperWith("{\"friction\": 0.3}").friction(), "the fingers' friction on the object");
        assertEquals(HandDescription.barrettHand(), Scenario.load(PAPER).hand(), "no parameters: the hand file's");
    }

    /**
     * τ_break = 0.9 N·m with the hand file's stiffness k = 7.2192 N·m/rad: the clutch, winding
     * k·(π/180)/125 N·m per motor count once the inner link is blocked, reaches 0.9 N·m
     * (1.26 − 0.9)/(k·π/(180·125)) = 357.15 counts before it reaches 1.26; both happen while the
     * paper's trapezoid cruises at 4244.294 counts/s, so 0.08413 s earlier than the paper's
     * 1.8000 s. The inner link is held still in the same pose from contact to breakaway, so its
     * contacts carry the spring torque through the same moment arm, 62.7 mm (README: 1.26 N·m
     * over 20.09 N): the force at breakaway is 0.36 N·m / 0.0627 m = 5.74 N less.
     */
    @Test
    void aTauBreakOf09BreaksAwayAtTheTimeAndForceThatFollow() throws Exception {
        HandModel paper = Simulation.model(Scenario.load(PAPER), false);
        paper.run(null);
        Scenario s09 = paperWith("{\"tau_break_Nm\": 0.9, \"k_clutch_Nm_per_rad\": 7.2192}");
        HandModel m = Simulation.model(s09, false);
        m.run(null);
        double perCount = 7.2192 * Math.PI / 180 / 125;
        double earlierCounts = (1.26 - 0.9) / perCount;
        assertEquals(357.15, earlierCounts, 0.01);
        double earlier = earlierCounts / 4244.294;
        assertEquals(1.8000, paper.breakawayTime(3), 5e-5);
        assertEquals(1.8000 - earlier, m.breakawayTime(3), 5e-5);
        assertEquals(0.9, m.breakawayTorque(3), 1e-9);
        assertEquals(paper.breakawayForce(3) - 0.36 / 0.0627, m.breakawayForce(3), 0.02);
        assertEquals(20.09 - 0.36 / 0.0627, m.breakawayForce(3), 0.03, "14.35 N");
        // the summary shows the parameters used
        Path dir = Files.createTempDirectory("hand-params");
        try {
            Path f = dir.resolve("tau09.json");
            Files.writeString(f, JsonWriter.write(s09.toJson(dir)));
            CliTesting.Run r = CliTesting.run("run", f.toString(), "--out", dir.resolve("out").toString(), "--no-charts");
            assertEquals(0, r.code(), r.err());
            @SuppressWarnings("unchecked")
            Map<String, Object> summary = (Map<String, Object>) Json.parse("summary", Files.readString(dir.resolve("out/summary.json")));
            @SuppressWarnings("unchecked")
            Map<String, Object> hp = (Map<String, Object>) summary.get("hand_parameters");
            assertEquals(0.9, ((Number) hp.get("tau_break_Nm")).doubleValue());
            assertEquals(7.2192, ((Number) hp.get("k_clutch_Nm_per_rad")).doubleValue());
            assertEquals(Math.toDegrees(0.9 / 7.2192), ((Number) hp.get("windup_deg")).doubleValue(), 1e-12);
            assertEquals(0.5, ((Number) hp.get("friction")).doubleValue());
            // the same from the command line: --tau-break over the paper's scenario, the wind-up kept at 10 degrees
            CliTesting.Run o = CliTesting.run("run", PAPER.toString(), "--tau-break", "0.9", "--out", dir.resolve("opt").toString(), "--no-charts");
            assertEquals(0, o.code(), o.err());
            String sum = Files.readString(dir.resolve("opt/summary.json"));
            assertTrue(sum.replaceAll("\\s", "").contains("\"tau_break_Nm\":0.9"), sum);
            CliTesting.Run bad = CliTesting.run("run", PAPER.toString(), "--tau-break", "9", "--out", dir.resolve("bad").toString());
            assertEquals(2, bad.code());
            assertTrue(bad.err().startsWith("handsim: --tau-break: must be in [0.05, 5] N*m"), bad.err());
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
