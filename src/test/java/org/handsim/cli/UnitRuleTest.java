package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.scenario.SceneMeshes;
import org.handsim.scenario.UnitRule;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * One unit rule ({@link UnitRule}) in every command: a millimetre file (vrml/objects/mug_mm.stl,
 * GraspIt!'s unit) is read in metres by {@code mesh}, {@code collide} and a scenario without
 * {@code object.units}, each with the same one-line notice; a scenario that forces it to metres
 * runs with a warning that it is far larger than the hand.
 */
class UnitRuleTest {
    private static final Path MUG_MM = TestPaths.root().resolve("vrml/objects/mug_mm.stl");
    private static final Path CUBE = TestPaths.root().resolve("vrml/objects/cube.wrl");

    @SuppressWarnings("unchecked")
    private static Map<String, Object> json(String line) {
        return (Map<String, Object>) Json.parse("stdout", line);
    }

    private static double number(Map<String, Object> j, String key) {
        return ((Number) j.get(key)).doubleValue();
    }

    @Test
    void meshReadsTheMillimetreMugInMetresAndSaysSo() {
        CliTesting.Run auto = CliTesting.run("mesh", MUG_MM.toString());
        CliTesting.Run metres = CliTesting.run("mesh", MUG_MM.toString(), "--units", "m");
        CliTesting.Run mm = CliTesting.run("mesh", MUG_MM.toString(), "--units", "mm");
        assertEquals(0, auto.code(), auto.err());
        assertEquals("handsim mesh: mug_mm.stl: units mm by its size (--units to choose)", auto.err());
        assertEquals("", mm.err(), "a chosen unit needs no notice");
        Map<String, Object> a = json(auto.out()), m = json(metres.out()), c = json(mm.out());
        assertEquals("mm", a.get("units"));
        assertEquals("m", m.get("units"));
        // lengths scale by 1e-3, areas by 1e-6, volumes by 1e-9 (the file read once in each unit)
        assertEquals(number(m, "volume_m3") * 1e-9, number(a, "volume_m3"), 1e-9 * number(a, "volume_m3"));
        assertEquals(number(m, "area_m2") * 1e-6, number(a, "area_m2"), 1e-9 * number(a, "area_m2"));
        assertEquals(c.get("volume_m3"), a.get("volume_m3"), "auto is --units mm");
        assertEquals(c.get("bounds"), a.get("bounds"));
        // the mug is 114 mm long: between 0.1 and 0.2 m, the size of a mug
        @SuppressWarnings("unchecked")
        List<List<Number>> b = (List<List<Number>>) a.get("bounds");
        assertEquals(0.114, b.get(1).get(0).doubleValue() - b.get(0).get(0).doubleValue(), 1e-6);
        // --scale alone keeps its meaning: the whole conversion to metres
        CliTesting.Run scaled = CliTesting.run("mesh", MUG_MM.toString(), "--scale", "0.001");
        assertEquals("", scaled.err());
        assertEquals(number(a, "volume_m3"), number(json(scaled.out()), "volume_m3"), 1e-12 * number(a, "volume_m3"));
    }

    @Test
    void collideJudgesEachFileByItsSize() {
        StringWriter err = new StringWriter();
        PrintWriter w = new PrintWriter(err);
        TriangleMesh mug = CollideCommand.loadMesh(MUG_MM, null, w), cube = CollideCommand.loadMesh(CUBE, null, w);
        w.flush();
        assertEquals("handsim collide: mug_mm.stl: units mm by its size (--units to choose)\n"
            + "handsim collide: cube.wrl: units m by its size (--units to choose)", err.toString().trim().replace("\r", ""));
        // the same meshes as loading each in its unit
        assertTrue(mug.sameTrianglesAs(SceneMeshes.mesh(MUG_MM, CollideCommand.VRML_DIVISIONS, 0.001)));
        assertTrue(cube.sameTrianglesAs(SceneMeshes.mesh(CUBE, CollideCommand.VRML_DIVISIONS, 1.0)));
        // the command: the cube pushed into the mug's wall touches it in millimetres, not in metres
        String pose = "0.05,0,0,0,0,0";
        CliTesting.Run auto = CliTesting.run("collide", MUG_MM.toString(), CUBE.toString(), "--pose-b", pose);
        assertEquals(0, auto.code(), auto.err());
        assertEquals(err.toString().trim().replace("\r", ""), auto.err());
        Map<String, Object> a = json(auto.out());
        assertEquals(true, a.get("intersecting"));
        @SuppressWarnings("unchecked")
        List<Map<String, Object>> patches = (List<Map<String, Object>>) a.get("patches");
        assertFalse(patches.isEmpty());
        for (Map<String, Object> p : patches) {
            // on the mug's wall (radius 40 mm) inside the cube's x range 20..80 mm
            @SuppressWarnings("unchecked")
            double x = ((List<Number>) p.get("center")).get(0).doubleValue();
            assertTrue(x > 0.02 - 1e-9 && x < 0.08 + 1e-9, "patch centre x " + x);
        }
        // read as metres, the 6 cm cube sits inside the 80 m mug's hollow: nothing touches
        TriangleMesh mugInMetres = CollideCommand.loadMesh(MUG_MM, Scenario.Units.M, w);
        CollisionResult r = new TreeQuery().collide(KdopTree.build(mugInMetres, 18), KdopTree.build(cube, 18),
            RigidTransform.fromPose(0.05, 0, 0, 0, 0, 0), new CollisionResult());
        assertFalse(r.intersecting());
    }

    @Test
    void aScenarioWithoutUnitsReadsTheMillimetreMugAtItsSize() throws IOException {
        Path dir = Files.createTempDirectory("handsim-units");
        try {
            String mug = Files.readString(TestPaths.root().resolve("scenarios/mug-grasp.json"))
                .replace("\"../vrml/objects/mug.wrl\"", JsonWriter.write(MUG_MM.toString()))
                .replace("\"units\": \"m\",", "")
                .replace("\"mug-grasp\"", "\"mug-mm\"");
            Path noUnits = Files.writeString(dir.resolve("mug-mm.json"), mug);
            Path forced = Files.writeString(dir.resolve("mug-m.json"), mug.replace("\"scale\": 1.2,", "\"scale\": 1.2, \"units\": \"m\","));
            Scenario s = Scenario.load(noUnits);
            assertEquals(Scenario.Units.MM, s.object().units());
            assertTrue(s.unitsBySize());
            assertEquals("handsim run: mug_mm.stl: units mm by its size (object.units to choose)", s.unitNotice("handsim run"));
            Scenario wrl = Scenario.load(TestPaths.root().resolve("scenarios/mug-grasp.json"));
            assertNull(wrl.unitNotice("handsim run"), "a written unit needs no notice");

            // the STL mug is mug.wrl to float rounding: the same breakaways (within a step) as the VRML mug
            HandModel mm = Simulation.model(s.withDuration(2.3), false), ref = Simulation.model(wrl.withDuration(2.3), false);
            mm.run(null);
            ref.run(null);
            for (int k = 1; k <= 3; k++) {
                assertFalse(Double.isNaN(ref.breakawayTime(k)));
                assertEquals(ref.breakawayTime(k), mm.breakawayTime(k), 2 * s.dt(), "finger " + k);
            }
            assertTrue(mm.startWarnings().isEmpty(), mm.startWarnings().toString());

            // grasp and sweep say the same (grasp at 0.1 s, one sweep run of 0.05 s)
            CliTesting.Run g = CliTesting.run("grasp", noUnits.toString(), "--at", "0.1");
            assertEquals(0, g.code(), g.err());
            assertEquals("handsim grasp: mug_mm.stl: units mm by its size (object.units to choose)", g.err());
            Path sweep = Files.writeString(dir.resolve("sweep.json"), "{\"name\": \"units\", \"base\": \"mug-m.json\", \"threads\": 1,"
                + " \"runs\": [{\"label\": \"short\", \"set\": {\"duration_s\": 0.05}}], \"scenarios\": []}");
            CliTesting.Run sw = CliTesting.run("sweep", sweep.toString(), "--out", dir.resolve("sweep").toString());
            assertEquals(0, sw.code(), sw.err());
            assertTrue(sw.err().contains("handsim: warning: short: the object mug_mm.stl is 137 m across"), sw.err());

            // forced to metres: 1000 times too large, no contact, and a warning in summary.json and on stderr
            Path out = dir.resolve("out");
            CliTesting.Run r = CliTesting.run("run", forced.toString(), "--out", out.toString(), "--no-charts", "--dt", "0.005");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.err().contains("handsim: warning: the object mug_mm.stl is 137 m across, far larger than the hand's workspace"), r.err());
            assertTrue(r.err().contains("read as metres; check object.units"), r.err());
            @SuppressWarnings("unchecked")
            Map<String, Object> summary = (Map<String, Object>) Json.parse("summary", Files.readString(out.resolve("summary.json")));
            @SuppressWarnings("unchecked")
            List<String> warnings = (List<String>) summary.get("warnings");
            assertEquals(1, warnings.size(), warnings.toString());
            assertTrue(warnings.get(0).startsWith("the object mug_mm.stl is 137 m across"), warnings.get(0));
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    @Test
    void theRuleItself() {
        assertNull(UnitRule.parse("auto"));
        assertEquals(Scenario.Units.CM, UnitRule.parse("cm"));
        // a hand's reach: palm offset + three links of Table I (25 + 50 + 70 + 55 mm = 0.2 m)
        assertEquals(0.2, UnitRule.handReach(org.handsim.hand.HandDescription.barrettHand()), 0.01);
        TriangleMesh mugM = SceneMeshes.mesh(MUG_MM, 24, 1.0), mugMm = SceneMeshes.mesh(MUG_MM, 24, 0.001);
        assertEquals(Scenario.Units.MM, UnitRule.bySize(mugM));
        assertEquals(Scenario.Units.M, UnitRule.bySize(mugMm));
        assertNotNull(UnitRule.sizeWarning(MUG_MM, mugM, Scenario.Units.M));
        assertNull(UnitRule.sizeWarning(MUG_MM, mugMm, Scenario.Units.MM));
        // in centimetres the mug is 11.4 m: still far larger than 20 reaches (4 m)
        assertNotNull(UnitRule.sizeWarning(MUG_MM, SceneMeshes.mesh(MUG_MM, 24, 0.1), Scenario.Units.CM));
    }
}
