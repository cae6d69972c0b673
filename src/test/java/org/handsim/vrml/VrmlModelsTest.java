package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.mesh.MeshWelder;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.text.Json;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The project's own models in {@code vrml/} through the public path, against the figures in
 * {@code vrml/models.json} (computed exactly by the generator from the written coordinates).
 * The loader keeps VRML's single-precision floats, so figures agree to ~1e-7 relative
 * (coordinates to ~1e-8 m), the tolerance used here.
 */
class VrmlModelsTest {
    /** Relative tolerance for float-stored coordinates (area, volume). */
    private static final double FLOAT_REL = 1e-6;
    /** Absolute tolerance for coordinates, m. */
    private static final double FLOAT_M = 1e-7;

    @SuppressWarnings("unchecked")
    @TestFactory
    List<DynamicTest> everyModelMatchesModelsJson() throws IOException {
        Path dir = TestPaths.root().resolve("vrml");
        Path json = dir.resolve("models.json");
        assertTrue(Files.isRegularFile(json), "vrml/models.json is part of the repository: " + json);
        Map<String, Object> files = (Map<String, Object>) ((Map<String, Object>) Json.parse(json.toString(),
            new String(Files.readAllBytes(json), StandardCharsets.UTF_8))).get("files");
        List<DynamicTest> tests = new ArrayList<>();
        for (Map.Entry<String, Object> e : files.entrySet()) {
            Map<String, Object> f = (Map<String, Object>) e.getValue();
            tests.add(DynamicTest.dynamicTest(e.getKey(), () -> {
                VrmlScene s = new VrmlLoader().load(dir.resolve(e.getKey()));
                assertTrue(s.warnings().isEmpty(), s.warnings().toString());
                TessellationWalk.Result r = new TessellationWalk().run(s.getSceneGroup());
                TriangleMesh m = r.merged();
                assertEquals(((Double) f.get("shapes")).intValue(), r.shapes, "shapes");
                assertEquals(((Double) f.get("triangles")).intValue(), m.triangleCount(), "triangles");
                assertEquals(0, r.degenerate, "degenerate");
                assertEquals(((Double) f.get("vertices")).intValue(), m.vertexCount(), "vertices (each file's points all used)");
                Double area = (Double) (f.containsKey("area_m2") ? f.get("area_m2") : f.get("area_m2_sum"));
                assertEquals(area, m.area(), area * FLOAT_REL, "area");
                TriangleMesh welded = new MeshWelder().weld(m);
                assertTrue(welded.isClosed(), "closed");
                if (f.containsKey("volume_m3")) {
                    double v = (Double) f.get("volume_m3");
                    assertEquals(v, welded.signedVolume(), v * FLOAT_REL, "volume");
                }
                List<List<Double>> b = (List<List<Double>>) f.get("bounds");
                double[][] mb = m.bounds();
                for (int i = 0; i < 2; i++) {
                    for (int k = 0; k < 3; k++) assertEquals(b.get(i).get(k), mb[i][k], FLOAT_M, "bounds[" + i + "][" + k + "]");
                }
                if (f.containsKey("analytic")) {
                    Map<String, Object> a = (Map<String, Object>) f.get("analytic");
                    double rel = m.area() / (Double) a.get("area_m2") - 1;
                    assertEquals((Double) f.get("area_rel_error"), rel, FLOAT_REL, "area error against the ideal shape");
                }
            }));
        }
        return tests;
    }
}
