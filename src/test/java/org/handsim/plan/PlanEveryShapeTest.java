package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The planner grasps every shape of docs/plan-shapes/README.md: {@code handsim plan SHAPE
 * --trials 300 --seed 1} reaches force closure in at least 10 % of the trials on each (spheres of
 * 40, 60 and 100 mm, a box, a torus, a cylinder, a cone, the mug, two YCB meshes). The figures
 * are in docs/BENCHMARKS.md ("Planning any shape").
 */
@Tag("slow")   // ten 300-trial plans: ./test --all
class PlanEveryShapeTest {
    static final String[] SHAPES = {"docs/plan-shapes/sphere40.obj", "docs/plan-shapes/sphere60.obj", "docs/plan-shapes/sphere100.obj",
        "docs/plan-shapes/box40x40x120.obj", "vrml/objects/ring.wrl", "vrml/objects/cylinder.wrl", "vrml/objects/cone.wrl",
        "vrml/objects/mug.wrl", "docs/plan-shapes/ycb-006-mustard-bottle.obj", "docs/plan-shapes/ycb-011-banana.obj"};

    @Test
    void everyShapeReachesForceClosureInATenthOfItsTrials() throws Exception {
        Path dir = Files.createTempDirectory("plan-shapes");
        try {
            StringBuilder rates = new StringBuilder();
            for (String shape : SHAPES) {
                Path out = dir.resolve(Path.of(shape).getFileName().toString());
                CliTesting.Run r = CliTesting.run("plan", TestPaths.root().resolve(shape).toString(), "--trials", "300", "--seed", "1",
                    "--out", out.toString());
                assertEquals(0, r.code(), shape + ": " + r.err());
                @SuppressWarnings("unchecked")
                java.util.Map<String, Object> plan = (java.util.Map<String, Object>) Json.parse("plan.json", Files.readString(out.resolve("plan.json")));
                long fc = ((Number) plan.get("force_closure")).longValue();
                rates.append(shape).append(": ").append(fc).append(" of 300\n");
                assertTrue(fc >= 30, shape + ": " + fc + " of 300 trials in force closure\n" + rates);
                assertTrue(Files.isRegularFile(out.resolve("best/01.json")), shape + ": a best grasp");
            }
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
