package org.handsim.tradeoff;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.handsim.chart.StudyTable;
import org.handsim.model.SceneGeometry;
import org.junit.jupiter.api.Test;

/** Chart 3: k changes only the speed; the grasps really touch; the quick run's table. */
class KdopStudyTest {
    /**
     * On the hand grasping every vrml/objects model, every k and the all-pairs loop find the
     * same intersecting pairs (link by link), segments and contacts; every walk tests at least
     * as many triangle pairs as intersect and the loop tests exactly every pair.
     */
    @Test
    void everyKFindsWhatBruteForceFinds() {
        List<Path> objects = KdopStudy.objects();
        assertEquals(7, objects.size());
        for (Path f : objects) {
            KdopStudy.Grasp g = KdopStudy.grasp(f);
            KdopStudy.HandQuery brute = new KdopStudy.HandQuery(g, KdopStudy.BRUTE);
            brute.run();
            long all = 0;
            for (int i = 0; i < 9; i++) all += (long) g.links()[i].triangleCount() * g.object().triangleCount();
            assertEquals(all, brute.triangleTests(), g.name() + ": the loop tests every pair");
            assertTrue(brute.linksTouching() >= 3, g.name() + ": the grasp touches with " + brute.linksTouching() + " links");
            int contacts = brute.contacts();
            assertTrue(contacts >= 3, g.name() + " contacts " + contacts);
            for (int k : new int[] {6, 14, 18, 26}) {
                KdopStudy.HandQuery q = new KdopStudy.HandQuery(g, k);
                q.run();
                for (int i = 0; i < 9; i++) {
                    assertArrayEquals(brute.results[i].sortedPairKeys(), q.results[i].sortedPairKeys(), g.name() + " k=" + k + " link " + i);
                    assertEquals(brute.results[i].segmentCount(), q.results[i].segmentCount(), g.name() + " k=" + k + " link " + i);
                }
                assertEquals(contacts, q.contacts(), g.name() + " k=" + k);
                assertTrue(q.triangleTests() >= q.pairs(), g.name() + " k=" + k);
                assertTrue(q.triangleTests() < brute.triangleTests(), g.name() + " k=" + k + ": the tree prunes");
            }
        }
    }

    @Test
    void quickRunTable() {
        StudyTable t = new KdopStudy().run(true, null);
        assertEquals(List.of("cone", "cube", "cylinder"), t.series());
        for (String s : t.series()) {
            List<StudyTable.Row> rows = t.rows(s);
            assertEquals(5, rows.size());
            assertEquals("brute force", rows.get(4).setting());
            double pairs = t.value(rows.get(4), "pairs");
            for (StudyTable.Row r : rows) {
                for (double v : r.values()) assertTrue(Double.isFinite(v));
                assertTrue(t.value(r, "query_s") > 0);
                assertEquals(pairs, t.value(r, "pairs"), s + " " + r.setting());
                assertEquals(r.setting().equals("k=" + SceneGeometry.DEFAULT_K), r.isDefault());
                assertTrue(t.value(r, "triangle_tests") >= t.value(r, "pairs"));
            }
        }
    }
}
