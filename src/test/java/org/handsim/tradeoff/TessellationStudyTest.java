package org.handsim.tradeoff;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.handsim.chart.StudyTable;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/** Chart 2: the plate contacts against their analytic answers, and the quick run's table. */
class TessellationStudyTest {
    /** The quick run: every row finite, the curved shapes' errors fall with divisions, the cube exact, defaults marked. */
    @Test
    void quickRunErrorsFallAsDivisionsGrow() {
        StudyTable t = new TessellationStudy().run(true, null);
        assertEquals(List.of("sphere centre", "sphere normal", "cylinder centre", "cylinder normal", "cube centre", "cube normal"), t.series());
        for (String s : t.series()) {
            List<StudyTable.Row> rows = t.rows(s);
            int defaults = 0;
            for (StudyTable.Row r : rows) {
                for (double v : r.values()) assertTrue(Double.isFinite(v), s + " " + r.setting() + ": " + java.util.Arrays.toString(r.values()));
                assertEquals(0.0, t.value(r, "missed"), s + " " + r.setting() + " missed the plate");
                assertTrue(t.value(r, "query_s") > 0);
                if (r.isDefault()) defaults++;
            }
            assertEquals(1, defaults, s + ": one default");
            for (int i = 1; i < rows.size(); i++) {
                double prev = t.value(rows.get(i - 1), "error"), cur = t.value(rows.get(i), "error");
                if (s.startsWith("cube")) {
                    assertEquals(0.0, cur, s + ": flat faces are exact at every subdivision");
                } else {
                    assertTrue(cur < prev, s + ": error " + cur + " at " + rows.get(i).setting() + " not below " + prev + " at " + rows.get(i - 1).setting());
                    double mean = s.endsWith("centre") ? t.value(rows.get(i), "centre_error_rel_mean") : t.value(rows.get(i), "normal_error_rad_mean");
                    double prevMean = s.endsWith("centre") ? t.value(rows.get(i - 1), "centre_error_rel_mean") : t.value(rows.get(i - 1), "normal_error_rad_mean");
                    assertTrue(mean < prevMean, s + ": mean error does not fall at " + rows.get(i).setting());
                }
            }
        }
        // the defaults: the scenario's divisions (24) and the object file's cube (1 square per face)
        for (StudyTable.Row r : t.rows()) {
            assertEquals(r.series().startsWith("cube") ? "1".equals(r.setting()) : "24".equals(r.setting()), r.isDefault(), r.series() + " " + r.setting());
        }
    }

    /**
     * The analytic references: at a fine resolution the measured contact converges on them
     * (sphere and cylinder within 0.1 % of the radius and 1° at 256 divisions), which a wrong
     * pose or a wrong analytic centre could not do; the cube is exact already at n = 1.
     */
    @Test
    void contactsConvergeOnTheAnalyticOnes() {
        TessellationStudy st = new TessellationStudy();
        for (TessellationStudy.Shape s : new TessellationStudy.Shape[] {TessellationStudy.Shape.SPHERE, TessellationStudy.Shape.CYLINDER}) {
            TessellationStudy.Measure m = st.measure(s, 256, false, true);
            assertEquals(0, m.missed());
            assertTrue(m.centreWorst() / s.radius < 1e-3, s + " centre " + m.centreWorst());
            assertTrue(m.normalWorst() < Math.toRadians(1), s + " normal " + m.normalWorst());
        }
        TessellationStudy.Measure cube = st.measure(TessellationStudy.Shape.CUBE, 1, false, true);
        assertTrue(cube.centreWorst() < 1e-15 && cube.normalWorst() < 1e-12, cube.toString());
    }

    /** The cube written as an IndexedFaceSet: 12 n² triangles, closed, area 6 a², volume a³, outward. */
    @Test
    void cubeTextIsASubdividedClosedCube() {
        for (int n : new int[] {1, 3, 8}) {
            TriangleMesh m = TessellationStudy.Shape.CUBE.mesh(n);
            assertEquals(12 * n * n, m.triangleCount());
            assertEquals(6 * 0.06 * 0.06, m.area(), 1e-9);
            assertEquals(0.06 * 0.06 * 0.06, m.signedVolume(), 1e-10);
            double[][] b = m.bounds();
            assertEquals(-0.03, b[0][2], 1e-9);
            assertEquals(0.03, b[1][0], 1e-9);
        }
    }
}
