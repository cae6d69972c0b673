package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;
import org.junit.jupiter.api.Test;

/**
 * Tunnelling: a 1 mm plate in the path of a fast-closing finger at a large step.
 * With the motor at 50 000 counts/s and dt = 0.1 s the inner link turns 40° per step: the
 * whole link (about 20 mm thick) jumps over the plate, and both end poses miss it. The model
 * must catch it, and find the contact where a fine step finds it.
 */
class TunnellingTest {
    static Path plate() throws Exception {
        Path dir = Files.createTempDirectory("handsim-plate");
        Path f = dir.resolve("plate.wrl");
        // 1 mm thick (y), 40 mm (x) by 20 mm (z), centred at the origin, closed and outward
        double a = 0.02, b = 0.0005, c = 0.01;
        Files.writeString(f, "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { solid TRUE coord Coordinate { point [\n"
            + -a + " " + -b + " " + -c + ", " + a + " " + -b + " " + -c + ", " + a + " " + b + " " + -c + ", " + -a + " " + b + " " + -c + ",\n"
            + -a + " " + -b + " " + c + ", " + a + " " + -b + " " + c + ", " + a + " " + b + " " + c + ", " + -a + " " + b + " " + c + " ] }\n"
            + "coordIndex [ 0 3 2 1 -1 4 5 6 7 -1 0 1 5 4 -1 1 2 6 5 -1 2 3 7 6 -1 3 0 4 7 -1 ] } }\n");
        return f;
    }

    /**
     * Finger 3 closes in the palm's y–z plane. The plate stands across the inner link's path at
     * θ32 = 18°: its 1 mm (local y) along the direction the link moves there, the tangent
     * (−sin φ, cos φ) (a turn of φ + 90° about the palm x axis), spanning 50–70 mm from joint 32
     * radially and the finger's width across.
     */
    static Scenario scenario(Path plate, double dt) {
        double phi = Math.toRadians(18 + 2.46);
        double r = 0.06; // plate centre 60 mm from joint 32 along the link
        double y = 0.05 + r * Math.cos(phi), z = 0.084 + r * Math.sin(phi);
        String json = "{\"name\":\"plate\",\"dt_s\":" + dt + ",\"duration_s\":1.2,\"gravity_m_s2\":[-9.81,0,0],"
            + "\"object\":{\"file\":\"" + plate + "\",\"position_m\":[0," + y + "," + z + "],\"rotation_rad\":[" + (phi + Math.PI / 2) + ",0,0]},"
            + "\"motors\":{\"M3\":[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":50000,\"a_max\":1.0E7}]},\"outputs\":{\"torques\":false}}";
        return Scenario.parse(plate.getParent().resolve("plate.json"), json);
    }

    @Test
    void aThinPlateIsNeverMissed() throws Exception {
        Path plate = plate();
        HandModel fine = Simulation.model(scenario(plate, 1e-4), false);
        fine.run(null);
        assertEquals(0, fine.counter(HandModel.Counter.TUNNELLING_CAUGHT), "at 0.1 ms no substeps are needed");
        double qc = fine.contactCounts(3);
        assertTrue(qc > 500 && qc < 5000, "the inner link meets the plate: q_contact = " + qc);
        assertTrue(fine.state(3) != ClutchState.FREE);

        HandModel coarse = Simulation.model(scenario(plate, 0.1), false);
        coarse.run(null);
        assertTrue(coarse.counter(HandModel.Counter.TUNNELLING_CAUGHT) > 0, "the large step passed through the plate and was caught");
        assertTrue(coarse.counter(HandModel.Counter.SWEPT_SUBSTEPS) > 0);
        assertEquals(qc, coarse.contactCounts(3), 1e-3, "and the contact is found where the fine step finds it");
        assertTrue(coarse.state(3) != ClutchState.FREE);
    }

    @Test
    void thicknessEstimateOfThePlate() throws Exception {
        double w = SceneGeometry.minWidth(SceneMeshes.mesh(plate(), 24, 1.0));
        assertEquals(0.001, w, 1e-7);
    }
}
