package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.mesh.StlWriter;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;
import org.handsim.scenario.UnitRule;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * {@link ObjectPlacer}: units guessed from the size, an object that would start inside the hand
 * is moved out along the palm axis until the simulator finds no contact at t = 0, and no further
 * than one step beyond that.
 */
class ObjectPlacerTest {
    static Path mugInMillimetres(Path dir) throws Exception {
        TriangleMesh mug = SceneMeshes.mesh(TestPaths.root().resolve("vrml/objects/mug.wrl"), 24, 1.0);
        Path f = dir.resolve("mug_mm.stl");
        try (OutputStream o = Files.newOutputStream(f)) {
            StlWriter.writeBinary(o, mug, 1000);
        }
        return f;
    }

    @Test
    void unitsFromTheSize() throws Exception {
        Path dir = Files.createTempDirectory("handsim-placer");
        Path stl = mugInMillimetres(dir);
        assertEquals(Scenario.Units.MM, UnitRule.bySize(SceneMeshes.mesh(stl, 24, 1.0)));
        assertEquals(Scenario.Units.M, UnitRule.bySize(SceneMeshes.mesh(TestPaths.root().resolve("vrml/objects/mug.wrl"), 24, 1.0)));
        VrmlTesting.deleteTree(dir);
    }

    @Test
    void aMugThatWouldStartInsideTheHandIsMovedOutUntilClear() throws Exception {
        Path dir = Files.createTempDirectory("handsim-placer");
        Path stl = mugInMillimetres(dir);
        // the mug grasp's hand, fingers part closed: the mug on the palm would be inside the fingers
        Scenario s = Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json"));
        for (int m = 0; m < 3; m++) s = s.withMotor(m, new org.handsim.trajectory.Hold(6000, 0));
        // where an import used to land: the previous object's pose (the cube's), in the mug's units
        Scenario inside = s.withObject(s.object().withPose(new double[] {0, 0, 0.12}, new double[3]).withScale(1, Scenario.Units.MM));
        inside = inside.withObject(new Scenario.ObjectPlacement(stl, inside.object().worldFromObject(), 1, 24, Scenario.Units.MM, null));
        assertFalse(ObjectPlacer.clear(inside), "the test needs a start in contact");

        ObjectPlacer.Placed p = ObjectPlacer.place(s, stl, 24, 1, Scenario.Units.MM);
        assertTrue(p.clear());
        assertTrue(p.steps() > 0, "the mug had to be moved out: " + p.steps());
        Scenario placed = s.withObject(p.placement());
        HandModel model = Simulation.model(placed, false);
        assertEquals(java.util.List.of(), model.startWarnings());
        for (int k = 1; k <= 3; k++) assertEquals(0, model.contacts(k).size());
        // one step less would still touch: the placement is the first clear one
        double[] pos = p.placement().position();
        double step = Math.max(0.005, 0.05 * SceneMeshes.mesh(stl, 24, 0.001).diagonal());
        Scenario closer = s.withObject(p.placement().withPose(new double[] {pos[0], pos[1], pos[2] - step}, p.placement().rotation()));
        assertFalse(ObjectPlacer.clear(closer));
        // on the palm axis (palm = world here): the bounding-box centre at x = y = 0
        TriangleMesh placedMesh = SceneMeshes.mesh(stl, 24, 0.001);
        double[][] b = placedMesh.bounds();
        assertEquals(0, pos[0] + 0.5 * (b[0][0] + b[1][0]), 1e-12);
        assertEquals(0, pos[1] + 0.5 * (b[0][1] + b[1][1]), 1e-12);
        assertTrue(pos[2] + b[0][2] >= ObjectPlacer.palmTop() + ObjectPlacer.GAP_M - 1e-12, "above the palm");
        VrmlTesting.deleteTree(dir);
    }
}
