package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim run} with a free object draws {@code object_motion.png/.svg}: the object's
 * displacement and rotation relative to the palm against time, from the trace's
 * {@code obj_disp_m} and {@code obj_rot_deg}; a fixed object's run does not.
 */
class ObjectMotionChartTest {
    static final double G = 9.81;

    /**
     * The mug of mug-lift.json free from the start for 15 ms, the palm still and the fingers only
     * starting to close: it falls freely (it lands on the palm 3 mm below after about 25 ms, and
     * contacts start within the 1 mm margin), so the trace's displacement relative to the palm at
     * 15 ms is ½g t² = 1.104 mm (the step is exact for a constant force), and the chart names the
     * release.
     */
    @Test
    void aFreeObjectsRunChartsItsMotionInTheHand() throws Exception {
        Path dir = Files.createTempDirectory("object-motion");
        try {
            Path scenario = MugLiftVariant.write(dir, "falling.json", MugLiftVariant.read("falling-mug", 0.015, 0.0));
            Path out = dir.resolve("out");
            CliTesting.Run r = CliTesting.run("run", scenario.toString(), "--out", out.toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().contains("object_motion.png/.svg"), r.out());
            List<String> trace = Files.readAllLines(out.resolve("trace.csv"));
            List<String> header = List.of(trace.get(0).split(","));
            String[] last = trace.get(trace.size() - 1).split(",");
            assertEquals(0.015, Double.parseDouble(last[0]), 1e-12);
            assertEquals(0.5 * G * 0.015 * 0.015, Double.parseDouble(last[header.indexOf("obj_disp_m")]), 1e-9, "displacement at 15 ms");
            assertEquals(0, Double.parseDouble(last[header.indexOf("obj_rot_deg")]), 1e-9, "no rotation in free fall");
            String svg = Files.readString(out.resolve("object_motion.svg"));
            assertTrue(svg.contains("released at 0.000 s") && svg.contains("displacement of the centre of mass, relative to the palm"), "object_motion.svg");
            assertTrue(Files.size(out.resolve("object_motion.png")) > 1000);
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }

    /** A fixed object's run draws no object chart. */
    @Test
    void aFixedObjectsRunDoesNotChartAnObject() throws Exception {
        Path dir = Files.createTempDirectory("object-motion-fixed");
        try {
            CliTesting.Run r = CliTesting.run("run", "--out", dir.resolve("out").toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(!Files.exists(dir.resolve("out/object_motion.png")) && !r.out().contains("object_motion"), r.out());
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
