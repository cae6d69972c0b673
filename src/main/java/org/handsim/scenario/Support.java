package org.handsim.scenario;

import java.nio.file.Path;
import org.handsim.files.InputFile;
import org.handsim.math.RigidTransform;
import org.handsim.text.JsonObject;

/**
 * A static body the free object may rest on (scenario field {@code "supports"}, DESIGN.md
 * decision 7): a box centred on its frame ({@code box_m}: edge lengths x, y, z) or a mesh file
 * (relative to the scenario; coordinates in metres), placed in the world by
 * {@code position_m} and {@code rotation_rad}. It never moves.
 *
 * @param boxM      edge lengths, m (3 values), or null for a mesh
 * @param file      the mesh file, or null for a box
 * @param pose      position (m) then rotation vector (rad), world
 */
public record Support(double[] boxM, Path file, double[] pose) {
    /** @return world ← support */
    public RigidTransform worldFromSupport() {
        return RigidTransform.fromPose(pose[0], pose[1], pose[2], pose[3], pose[4], pose[5]);
    }

    /** Support i of the scenario's {@code supports}, refused naming its field when it is neither one box nor one readable file. */
    static Support parse(JsonObject s, Path scenarioDir, java.util.function.Function<JsonObject, double[]> pose) {
        s.allowOnly("box_m", "file", "position_m", "rotation_rad");
        boolean box = s.has("box_m"), mesh = s.has("file");
        if (box == mesh) throw s.error(box ? "file" : "box_m", box ? "give box_m or file, not both" : "missing: give box_m (edge lengths) or file (a mesh)");
        double[] edges = null;
        Path f = null;
        if (box) {
            edges = s.numbers("box_m", 3);
            for (int i = 0; i < 3; i++) {
                if (!(edges[i] > 0)) throw s.error("box_m[" + i + "]", "must be > 0, got " + org.handsim.text.Decimal.format(edges[i]));
            }
        } else {
            f = scenarioDir.resolve(s.string("file")).normalize();
            String why = InputFile.problem(f);
            if (why != null) throw s.error("file", why + ": " + f);
        }
        return new Support(edges, f, pose.apply(s));
    }

    /** This support as {@link #parse} reads it, its file relative to {@code dir} when it can be. */
    java.util.Map<String, Object> toJson(Path dir) {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        if (boxM != null) {
            m.put("box_m", boxM.clone());
        } else {
            m.put("file", Scenario.fileName(dir, file));
        }
        m.put("position_m", java.util.Arrays.copyOfRange(pose, 0, 3));
        m.put("rotation_rad", java.util.Arrays.copyOfRange(pose, 3, 6));
        return m;
    }
}
