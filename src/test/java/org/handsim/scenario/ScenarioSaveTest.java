package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.model.HandModel;
import org.handsim.model.Simulation;
import org.handsim.trajectory.CartesianLine;
import org.handsim.trajectory.Quintic;
import org.handsim.trajectory.Sequence;
import org.handsim.trajectory.Trapezoid;
import org.handsim.text.JsonWriter;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * {@link Scenario#toJson}: a scenario written and read back simulates the same steps to the last
 * digit (the whole trace.csv text is compared), for the committed scenarios and for one built the
 * way the window builds them (trajectories from mid-run counts, a fingertip line, a moved object
 * in millimetres, gravity).
 */
class ScenarioSaveTest {
    static String trace(Scenario s, Path dir, String name) throws Exception {
        HandModel m = Simulation.model(s, true);
        m.run(null);
        Path f = dir.resolve(name);
        m.recorder().writeCsv(f);
        return Files.readString(f);
    }

    static Scenario roundTrip(Scenario s, Path dir) throws Exception {
        Path f = dir.resolve("saved.json");
        Files.writeString(f, JsonWriter.pretty(s.toJson(dir)));
        return Scenario.load(f);
    }

    @Test
    void committedScenariosReadBackToTheSameTrace() throws Exception {
        Path dir = Files.createTempDirectory("handsim-save").toRealPath();
        for (String name : new String[] {"paper-breakaway.json", "mug-grasp.json"}) {
            Scenario s = Scenario.load(TestPaths.root().resolve("scenarios").resolve(name));
            Scenario back = roundTrip(s, dir);
            assertEquals(s.duration(), back.duration());
            assertEquals(trace(s, dir, "a.csv"), trace(back, dir, "b.csv"), name);
        }
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void aWindowBuiltScenarioReadsBackToTheSameTrace() throws Exception {
        Path dir = Files.createTempDirectory("handsim-save").toRealPath();
        Scenario s = Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json"));
        // as the Path Planning panel does: from counts reached mid-run, to the end plus 0.5 s
        double q1 = 1234.5678901, q2 = 4321.0987, q3 = 7215.3333333, q4 = 250.125;
        s = s.withMotor(3, new Trapezoid(q4, 800.5, 1000, 5000));
        s = s.withMotor(0, new CartesianLine(1, q1, q4, new double[] {0.12, 0.01, 0.10}, 1.3));
        s = s.withMotor(1, new Quintic(q2, 9000.25, 1.7));
        s = s.withMotor(2, new Sequence(java.util.List.of(new Trapezoid(q3, 17500, 4244.294, 21221.471),
            new org.handsim.trajectory.Hold(17500, 0.3), new Quintic(17500, 0, 1.1))));
        s = s.withDuration(3.1234567);
        s = s.withGravity(new double[] {0.1, -9.7, 1.3});
        Scenario.ObjectPlacement p = s.object();
        Path cube = TestPaths.root().resolve("vrml/objects/cube.wrl");
        s = s.withObject(Scenario.ObjectPlacement.of(cube, new double[] {0.001 * 3, 0.0408479, 0.1449231},
            new double[] {-2.5307271, 0.0100001, -0.0000003}, 1000, p.divisions(), Scenario.Units.MM));
        Scenario back = roundTrip(s, dir);
        Map<String, Object> json = back.toJson(dir);
        assertEquals(JsonWriter.pretty(s.toJson(dir)), JsonWriter.pretty(json), "written twice, the same text");
        assertEquals(Scenario.Units.MM, back.object().units());
        assertEquals(1000.0, back.object().scale());
        assertArrayEquals(s.object().worldFromObject().toArray(), back.object().worldFromObject().toArray());
        String a = trace(s, dir, "a.csv"), b = trace(back, dir, "b.csv");
        assertEquals(a, b);
        assertTrue(a.lines().count() > 3000, "the run is long enough to mean something: " + a.lines().count() + " rows");
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void unitsAreValidatedAndScaleTheMesh() {
        String base = "{\"name\":\"u\",\"dt_s\":0.001,\"duration_s\":0.01,\"object\":{\"file\":\"vrml/objects/cube.wrl\",\"units\":\"%s\",\"scale\":%s}}";
        Path f = TestPaths.root().resolve("u.json");
        ScenarioException e = org.junit.jupiter.api.Assertions.assertThrows(ScenarioException.class,
            () -> Scenario.parse(f, String.format(base, "inch", "1")));
        assertTrue(e.getMessage().contains("field object.units: must be auto, mm, cm or m, got \"inch\""), e.getMessage());
        Scenario mm = Scenario.parse(f, String.format(base, "mm", "1000"));
        Scenario m = Scenario.parse(f, String.format(base, "m", "1"));
        assertEquals(1.0, mm.object().meshScale());
        assertEquals(Scenario.Units.M, m.object().units());
        assertEquals(SceneMeshes.mesh(m.object().file(), 24, m.object().meshScale()).area(),
            SceneMeshes.mesh(mm.object().file(), 24, mm.object().meshScale()).area());
    }
}
