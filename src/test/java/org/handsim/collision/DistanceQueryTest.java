package org.handsim.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/**
 * {@link DistanceQuery} against FCL's distance query (python-fcl 0.7.0.11, OBBRSS models; the
 * reference file is written by tools/fcl/distance_reference.py) on the collision bench's pairs,
 * and against the all-pairs minimum of {@link TriangleDistance} at seeded poses.
 */
class DistanceQueryTest {
    static final Path BENCH = org.handsim.TestPaths.shared().resolve("bench-meshes");

    /** Every row of fcl-distances.csv: the same distance to 1e-9 m, with every k. */
    @Test
    void agreesWithFclOnTheBenchPairs() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isDirectory(BENCH), "../shared/bench-meshes not present");
        Map<String, TriangleMesh> meshes = new HashMap<>();
        int rows = 0;
        double worst = 0;
        try (BufferedReader r = new BufferedReader(new InputStreamReader(
            DistanceQueryTest.class.getResourceAsStream("fcl-distances.csv"), StandardCharsets.UTF_8))) {
            r.readLine();
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                String[] f = splitCsv(line);
                TriangleMesh a = meshes.computeIfAbsent(f[1], n -> TestMeshes.vrml(BENCH.resolve(n)));
                TriangleMesh b = meshes.computeIfAbsent(f[2], n -> TestMeshes.vrml(BENCH.resolve(n)));
                String[] p = f[3].split(",");
                double[] pose = RigidTransform.fromPose(d(p[0]), d(p[1]), d(p[2]), d(p[3]), d(p[4]), d(p[5])).toArray();
                double want = d(f[4]);
                for (int k : Kdop.SUPPORTED_K) {
                    DistanceQuery q = new DistanceQuery();
                    double got = q.distance(KdopTree.build(a, k), KdopTree.build(b, k), pose, 0);
                    assertEquals(want, got, 1e-9, f[0] + " " + f[1] + " k=" + k);
                    worst = Math.max(worst, Math.abs(want - got));
                    if (want > 0) {
                        double[] x = q.pointA(), y = q.pointB();
                        double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
                        assertEquals(got, Math.sqrt(dx * dx + dy * dy + dz * dz), 1e-12, "closest points " + f[0]);
                    }
                }
                rows++;
            }
        }
        assertEquals(20, rows);
        System.out.println("largest difference from FCL's distance: " + worst + " m");
    }

    /** The tree's answer equals the smallest distance over all triangle pairs, at seeded poses near, touching and apart. */
    @Test
    void equalsTheAllPairsMinimum() {
        SplittableRandom rnd = new SplittableRandom(31);
        TriangleMesh a = TestMeshes.icosphere(2, 1), b = TestMeshes.box(0.6, 0.4, 0.3, 2);
        KdopTree ta = KdopTree.build(a, 18), tb = KdopTree.build(b, 18);
        TriangleDistance td = new TriangleDistance();
        DistanceQuery q = new DistanceQuery();
        int cases = TestEffort.cases(40);
        for (int n = 0; n < cases; n++) {
            double[] dir = {rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5};
            double l = Math.sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]), r = 1.2 + rnd.nextDouble() * 0.8;
            double[] pose = RigidTransform.fromPose(r * dir[0] / l, r * dir[1] / l, r * dir[2] / l, rnd.nextDouble() - 0.5,
                rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5).toArray();
            double[] vb = new double[b.vertices().length];
            KdopTree.transformPoints(pose, b.vertices(), vb, b.vertexCount());
            double want = Double.POSITIVE_INFINITY;
            int[] t1 = a.triangles(), t2 = b.triangles();
            for (int i = 0; i < t1.length; i += 3) {
                for (int j = 0; j < t2.length; j += 3) {
                    want = Math.min(want, td.triangles(a.vertices(), 3 * t1[i], 3 * t1[i + 1], 3 * t1[i + 2], vb, 3 * t2[j], 3 * t2[j + 1], 3 * t2[j + 2]));
                }
            }
            assertEquals(want, q.distance(ta, tb, pose, 0), 1e-12, "case " + n);
        }
    }

    /** Triangle pairs against a fine sampling of both triangles: never above it, and within the sampling's resolution of it. */
    @Test
    void triangleDistanceIsTheSmallestOverTheTriangles() {
        SplittableRandom rnd = new SplittableRandom(5);
        TriangleDistance td = new TriangleDistance();
        int cases = TestEffort.cases(200);
        for (int n = 0; n < cases; n++) {
            double[] va = new double[9], vb = new double[9];
            for (int i = 0; i < 9; i++) {
                va[i] = rnd.nextDouble();
                vb[i] = rnd.nextDouble() + (i % 3 == 0 ? 0.6 : 0);
            }
            double d = td.triangles(va, 0, 3, 6, vb, 0, 3, 6);
            int s = 24;
            double sampled = Double.POSITIVE_INFINITY;
            double[] p = new double[3], q = new double[3];
            for (int i = 0; i <= s; i++) {
                for (int j = 0; i + j <= s; j++) {
                    point(va, i / (double) s, j / (double) s, p);
                    for (int k = 0; k <= s; k++) {
                        for (int l = 0; k + l <= s; l++) {
                            point(vb, k / (double) s, l / (double) s, q);
                            sampled = Math.min(sampled, Math.sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2])));
                        }
                    }
                }
            }
            assertTrue(d <= sampled + 1e-12, "case " + n + ": " + d + " above the sampled " + sampled);
            assertTrue(sampled - d < 0.1, "case " + n + ": " + d + " far below the sampled " + sampled);
        }
    }

    private static void point(double[] v, double u, double w, double[] out) {
        for (int c = 0; c < 3; c++) out[c] = v[c] + u * (v[3 + c] - v[c]) + w * (v[6 + c] - v[c]);
    }

    private static double d(String s) { return Double.parseDouble(s.trim()); }

    private static String[] splitCsv(String line) {
        java.util.List<String> out = new java.util.ArrayList<>();
        StringBuilder cur = new StringBuilder();
        boolean q = false;
        for (char c : line.toCharArray()) {
            if (c == '"') q = !q;
            else if (c == ',' && !q) { out.add(cur.toString()); cur.setLength(0); }
            else cur.append(c);
        }
        out.add(cur.toString());
        return out.toArray(new String[0]);
    }
}
