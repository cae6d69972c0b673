package org.handsim.model;

import java.nio.file.Path;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;

/**
 * Where a newly imported object goes: on the palm axis in front of the palm, clear of
 * the hand, at a sensible size.
 *
 * <h2>Units</h2>
 * A file's unit of length is not written in it: chosen, or judged from its size by
 * {@link UnitRule}, the rule every command uses.
 *
 * <h2>Placement</h2>
 * The object keeps its own axes aligned with the palm's; its bounding-box centre is put on the
 * palm's z axis (the palm normal, the direction the fingers close towards), its lowest point
 * {@value #GAP_M} m above the palm's surface. Then it is moved out along that axis, a step of
 * 5 mm or 5 % of its size at a time, until no link of the hand, at the scenario's start
 * counts, touches it — tested with the simulator's own collision (a {@link HandModel} built for
 * the candidate scene: the start-in-contact test of {@link HandModel#startsInContact()}), so what
 * the placement calls clear is what the simulation will find clear.
 */
public final class ObjectPlacer {
    private ObjectPlacer() {}

    /** Clearance between the palm's surface and the object's lowest point, m. */
    public static final double GAP_M = 0.005;
    /** Most steps out along the palm axis before giving up. */
    static final int MAX_STEPS = 400;

    /**
     * A placement found.
     *
     * @param placement where the object goes
     * @param steps     steps moved out along the palm axis to clear the hand (0: clear at once)
     * @param clear     false when no clear place was found within {@link #MAX_STEPS} steps (the
     *                  placement is then the last one tried; the window warns)
     */
    public record Placed(Scenario.ObjectPlacement placement, int steps, boolean clear) {}

    /** The height of the palm's surface in the palm frame, m (the top of {@code vrml/hand/palm.wrl}). */
    public static double palmTop() {
        return SceneMeshes.mesh(SceneMeshes.palmFile(), SceneMeshes.LINK_DIVISIONS, 1.0).bounds()[1][2];
    }

    /**
     * Places an object in scenario {@code s}'s scene (see the class comment).
     *
     * @param file      the object's file (VRML, OBJ, STL)
     * @param divisions VRML primitives' divisions
     * @param scale     the scale after the units
     * @param units     the file's unit
     * @throws ScenarioException if the file cannot be loaded
     */
    public static Placed place(Scenario s, Path file, int divisions, double scale, Scenario.Units units) {
        double ms = units.metres() * scale;
        TriangleMesh mesh = SceneMeshes.mesh(file, divisions, ms);
        double[][] b = mesh.bounds();
        double cx = 0.5 * (b[0][0] + b[1][0]), cy = 0.5 * (b[0][1] + b[1][1]);
        double size = mesh.diagonal();
        double step = Math.max(0.005, 0.05 * size);
        RigidTransform wp = s.worldFromPalm();
        double[] rotation = wp.rotationVector();
        double z = palmTop() + GAP_M - b[0][2];
        Scenario.ObjectPlacement p = null;
        for (int i = 0; i <= MAX_STEPS; i++) {
            double[] position = wp.apply(new double[] {-cx, -cy, z + i * step});
            p = Scenario.ObjectPlacement.of(file, position, rotation, scale, divisions, units);
            if (clear(s.withObject(p))) return new Placed(p, i, true);
        }
        return new Placed(p, MAX_STEPS, false);
    }

    /** True if no link touches the object at the scenario's start (the simulator's own test). */
    public static boolean clear(Scenario s) {
        return !Simulation.model(s.withTorques(false), false).startsInContact();
    }
}
