package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.clutch.ClutchState;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/**
 * A trial's scenario is made directly from the template parsed once
 * ({@link TrialRunner#trialScenario}); it must be the scenario {@code best/NN.json}'s text
 * gives — the text {@link TrialRunner#scenarioJson} writes, parsed — in every number it runs
 * with ({@link Scenario#toJson}, which writes them all), and run the same grasp to the last bit.
 */
class TrialScenarioTest {
    /** The trial's scenario both ways, as the JSON of everything each runs with. */
    static String[] bothWays(TrialRunner r, PlanSpec spec, int i) {
        TrialParameters p = r.parameters(i);
        TrialResult res = r.run(i);
        assertTrue(res.ok(), res.error());
        Scenario direct = r.trialScenario(p, res.palmPosition(), res.palmRotation());
        Scenario parsed = Scenario.parse(Path.of(spec.templateFile()),
            r.scenarioJson(p, res.standoff(), res.palmPosition(), res.palmRotation(), spec.name() + "-trial" + i, false, null));
        Path dir = Path.of(spec.templateFile()).getParent();
        return new String[] {JsonWriter.write(direct.toJson(dir)), JsonWriter.write(parsed.toJson(dir))};
    }

    @Test
    void mugTrialsAreTheScenariosTheirTextGives() {
        PlanSpec spec = PlanTesting.mugPlan(200, 5);
        TrialRunner r = new TrialRunner(spec);
        for (int i = 0; i < 200; i += 7) {
            String[] s = bothWays(r, spec, i);
            assertEquals(s[1], s[0], "trial " + i);
        }
        // run through to the grasp from each, as the runner does: the same numbers to the last bit
        for (int i : new int[] {3, 25, 140}) {
            TrialParameters p = r.parameters(i);
            TrialResult res = r.run(i);
            Scenario direct = r.trialScenario(p, res.palmPosition(), res.palmRotation());
            Scenario parsed = Scenario.parse(Path.of(spec.templateFile()),
                r.scenarioJson(p, res.standoff(), res.palmPosition(), res.palmRotation(), "t", false, null));
            GraspAssessment a = closed(direct, spec), b = closed(parsed, spec);
            assertEquals(b.quality().epsilon(), a.quality().epsilon());
            assertEquals(b.holdMinN(), a.holdMinN());
            assertEquals(b.contacts().size(), a.contacts().size());
            assertEquals(res.epsilon(), a.quality().epsilon(), "the runner's row, trial " + i);
            assertEquals(res.holdMinN(), a.holdMinN());
        }
    }

    /** Each motor's set-points along the run (a line's depend on the spread; its segment's JSON does not show that). */
    static String samples(Scenario s) {
        StringBuilder b = new StringBuilder();
        double[] out = new double[3];
        for (int m = 0; m < 4; m++) {
            for (double t = 0; t <= s.duration(); t += 0.05) {
                s.motor(m).sample(t, out);
                b.append(' ').append(out[0]).append('/').append(out[1]).append('/').append(out[2]);
            }
        }
        return b.toString();
    }

    static GraspAssessment closed(Scenario s, PlanSpec spec) {
        HandModel m = Simulation.model(s, false);
        while (m.running() && !(m.state(1) == ClutchState.STALLED && m.state(2) == ClutchState.STALLED && m.state(3) == ClutchState.STALLED)) {
            m.step();
        }
        return GraspAssessment.of(m.graspInput(), spec.mu(), spec.edges());
    }

    /**
     * A scenario template whose spread motor moves (the trial holds it at its own spread instead),
     * with a fingertip line (its path depends on the spread: made again at each trial's) and no
     * duration_s (the longest motor's, the spread's segments gone): each trial both ways alike,
     * or both refused with the same message.
     */
    @Test
    void aTemplateWithASpreadMotorAndAFingertipLine() throws Exception {
        Path dir = Files.createTempDirectory("trial-scenario");
        try {
            @SuppressWarnings("unchecked")
            Map<String, Object> t = (Map<String, Object>) Json.parse("mug-grasp.json",
                Files.readString(TestPaths.root().resolve("scenarios/mug-grasp.json")));
            @SuppressWarnings("unchecked")
            Map<String, Object> o = (Map<String, Object>) t.get("object");
            o.put("file", TestPaths.root().resolve("vrml/objects/mug.wrl").toAbsolutePath().toString());
            @SuppressWarnings("unchecked")
            Map<String, Object> motors = (Map<String, Object>) t.get("motors");
            motors.put("M4", List.of(Map.of("type", "trapezoid", "to", 3000.0, "v_max", 300.0, "a_max", 1000.0)));   // 10 s: the longest
            motors.put("M1", List.of(Map.of("type", "trapezoid", "to", 6000.0, "v_max", 5000.0, "a_max", 25000.0),
                Map.of("type", "line", "target_m", List.of(0.09, 0.0, 0.06), "duration_s", 1.0)));
            t.put("dt_s", 0.05);
            Path file = dir.resolve("template.json");
            Files.writeString(file, JsonWriter.pretty(t));
            assertEquals(10.0, Scenario.load(file).duration(), 0.5, "the spread's segments are the longest");
            PlanSpec spec = PlanSpec.forTarget(file, 40, 9, 0.5, 8);
            TrialRunner r = new TrialRunner(spec);
            int same = 0, refused = 0;
            // each trial finds its fingertip line's reachable points twice (about 0.2 s): the
            // quick run takes the first quarter of the trials
            for (int i = 0; i < TestEffort.cases(40); i++) {
                TrialParameters p = r.parameters(i);
                double[] pos = {0.01 * i, 0, 0}, rot = {0, 0.02 * i, 0};
                String a, b;
                try {
                    Scenario d = r.trialScenario(p, pos, rot);
                    assertTrue(d.duration() < 9, "without the spread's segments the duration is the fingers' (" + d.duration() + " s)");
                    a = JsonWriter.write(d.toJson(dir)) + samples(d);
                } catch (RuntimeException e) {
                    a = "refused: " + e.getMessage();
                }
                try {
                    Scenario q = Scenario.parse(file, r.scenarioJson(p, 0.005, pos, rot, spec.name() + "-trial" + i, false, null));
                    b = JsonWriter.write(q.toJson(dir)) + samples(q);
                } catch (RuntimeException e) {
                    b = "refused: " + e.getMessage();
                }
                assertEquals(b, a, "trial " + i);
                if (a.startsWith("refused")) refused++; else same++;
            }
            System.out.println(same + " trials alike, " + refused + " refused alike");
            assertTrue(same > 0, "some trials run");
            assertFalse(same == 0 && refused == 0);
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }
}
