package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Random;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * Ear clipping of concave, non-planar and degenerate faces: exactly n−2 triangles, the face's
 * area preserved, every triangle inside the face and with the face's orientation. Random
 * star-shaped polygons use a fixed seed (docs/STYLE.md, item 12).
 */
class FaceTriangulatorTest {
    private static final double TOL = 1e-9;
    /**
     * Only a guard against a hang (an ear-clipping loop that never ends): the work is bounded by
     * counting, O(n²) per face; how fast it runs is not a unit-test matter.
     */
    private static final Duration HANG_GUARD = Duration.ofSeconds(60);

    /** Triangulates a planar polygon given in the z = 0 plane (x, y pairs); returns triangles as vertex numbers. */
    private static int[] triangulate(double[] xy) {
        int n = xy.length / 2;
        float[] pts = new float[3 * n];
        int[] idx = new int[n];
        for (int i = 0; i < n; i++) {
            pts[3 * i] = (float) xy[2 * i];
            pts[3 * i + 1] = (float) xy[2 * i + 1];
            idx[i] = i;
        }
        FaceTriangulator t = new FaceTriangulator();
        t.triangulateAll(pts, idx);
        int[] out = new int[3 * t.count];
        for (int k = 0; k < out.length; k++) out[k] = idx[t.tri[k]];
        return out;
    }

    private static double shoelace(double[] xy) {
        double a = 0;
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            a += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
        }
        return a / 2;
    }

    private static boolean inside(double[] xy, double px, double py) {
        boolean in = false;
        int n = xy.length / 2;
        for (int i = 0, j = n - 1; i < n; j = i++) {
            double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
            if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) in = !in;
        }
        return in;
    }

    /** n−2 triangles, area preserved, same orientation, centroids inside. */
    private static void check(String name, double[] xy) {
        // the test works with the float-rounded coordinates the triangulator sees
        for (int i = 0; i < xy.length; i++) xy[i] = (float) xy[i];
        int n = xy.length / 2;
        int[] t = triangulate(xy);
        assertEquals(3 * (n - 2), t.length, name + ": n-2 triangles");
        double total = 0, polygon = shoelace(xy);
        for (int k = 0; k < t.length; k += 3) {
            double ax = xy[2 * t[k]], ay = xy[2 * t[k] + 1], bx = xy[2 * t[k + 1]], by = xy[2 * t[k + 1] + 1];
            double cx = xy[2 * t[k + 2]], cy = xy[2 * t[k + 2] + 1];
            double a = ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2;
            assertTrue(a * Math.signum(polygon) >= -TOL * Math.abs(polygon), name + ": triangle " + k / 3 + " has the face's orientation");
            total += a;
            if (Math.abs(a) > 1e-9 * Math.abs(polygon)) {
                assertTrue(inside(xy, (ax + bx + cx) / 3, (ay + by + cy) / 3), name + ": triangle " + k / 3 + " lies inside the face");
            }
        }
        assertEquals(polygon, total, TOL * Math.abs(polygon), name + ": area preserved");
    }

    @Test
    void lShape() {
        check("L", new double[] {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2});
    }

    @Test
    void clockwiseLShape() {
        check("L reversed", new double[] {0, 2, 1, 2, 1, 1, 2, 1, 2, 0, 0, 0});
    }

    @Test
    void comb() {
        // a comb with 10 teeth: 42 vertices, many reflex corners
        double[] xy = new double[2 * 42];
        int k = 0;
        xy[k++] = 0; xy[k++] = 0;
        xy[k++] = 20; xy[k++] = 0;
        for (int i = 10; i > 0; i--) {
            double x = 2 * i;
            xy[k++] = x; xy[k++] = 5;
            xy[k++] = x - 1; xy[k++] = 5;
            xy[k++] = x - 1; xy[k++] = 1;
            xy[k++] = x - 2; xy[k++] = 1;
        }
        check("comb", java.util.Arrays.copyOf(xy, k));
    }

    @Test
    void starAndSpiral() {
        double[] star = new double[20];
        for (int i = 0; i < 10; i++) {
            double r = i % 2 == 0 ? 1 : 0.3, a = Math.PI * 2 * i / 10;
            star[2 * i] = r * Math.cos(a);
            star[2 * i + 1] = r * Math.sin(a);
        }
        check("star", star);
        int m = 60;
        double[] spiral = new double[4 * m];
        for (int i = 0; i < m; i++) {
            double a = 4 * Math.PI * i / m, r = 1 + a;
            spiral[2 * i] = r * Math.cos(a);
            spiral[2 * i + 1] = r * Math.sin(a);
            double b = 4 * Math.PI * (m - 1 - i) / m, q = 1.5 + b;
            spiral[2 * (m + i)] = q * Math.cos(b);
            spiral[2 * (m + i) + 1] = q * Math.sin(b);
        }
        check("spiral", spiral);
    }

    @Test
    void collinearAndRepeatedVertices() {
        check("collinear", new double[] {0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 2, 1, 2, 2, 0, 2});
        int[] t = triangulate(new double[] {0, 0, 1, 0, 1, 0, 1, 1, 0, 1});
        assertEquals(9, t.length, "a repeated vertex still gives n-2 triangles (one of zero area)");
    }

    @Test
    void randomStarShapedPolygons() {
        Random r = new Random(345);
        for (int p = 0; p < 200; p++) {
            int n = 4 + r.nextInt(60);
            double[] xy = new double[2 * n];
            for (int i = 0; i < n; i++) {
                double a = 2 * Math.PI * (i + 0.8 * r.nextDouble()) / n, rad = 0.2 + r.nextDouble();
                xy[2 * i] = rad * Math.cos(a);
                xy[2 * i + 1] = rad * Math.sin(a);
            }
            check("random polygon " + p, xy);
        }
    }

    @Test
    void nonPlanarQuadKeepsItsOrientation() {
        // a twisted quad: triangles must exist and face the average normal (+z)
        TriangleMesh m = VrmlTesting.mesh("Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0.2, 1 1 0, 0 1 0.2 ] }"
            + " coordIndex [ 0 1 2 3 -1 ] } }");
        assertEquals(2, m.triangleCount());
        for (int t = 0; t < 2; t++) assertTrue(m.normals()[3 * t + 2] > 0.9, "normal near +z");
    }

    @Test
    void concaveFaceMarkedConvexIsStillTriangulatedCorrectly() {
        // an L-shaped face without "convex FALSE": a fan from vertex 0 would leave the face
        TriangleMesh m = VrmlTesting.mesh("Shape { geometry IndexedFaceSet { coord Coordinate { point [ 1 1 0, 1 2 0, 0 2 0, 0 0 0, 2 0 0, 2 1 0 ] }"
            + " coordIndex [ 0 1 2 3 4 5 ] } }");
        assertEquals(4, m.triangleCount());
        assertEquals(3.0, m.area(), 1e-12);
    }

    @Test
    void hugeFaceIsFastAndCorrect() {
        int n = 100_000;
        double[] xy = new double[2 * n];
        for (int i = 0; i < n; i++) {
            xy[2 * i] = Math.cos(2 * Math.PI * i / n);
            xy[2 * i + 1] = Math.sin(2 * Math.PI * i / n);
        }
        int[] t = assertTimeoutPreemptively(HANG_GUARD, () -> triangulate(xy));
        assertEquals(3 * (n - 2), t.length);
    }

    @Test
    void selfIntersectingFacesStillGiveNMinus2TrianglesQuickly() {
        double[] pentagram = new double[10];
        for (int i = 0; i < 5; i++) {
            pentagram[2 * i] = Math.cos(4 * Math.PI * i / 5);
            pentagram[2 * i + 1] = Math.sin(4 * Math.PI * i / 5);
        }
        assertEquals(9, triangulate(pentagram).length);
        Random r = new Random(345);
        double[] scribble = new double[2 * 5000];
        for (int i = 0; i < scribble.length; i++) scribble[i] = r.nextDouble();
        int[] t = assertTimeoutPreemptively(HANG_GUARD, () -> triangulate(scribble));
        assertEquals(3 * 4998, t.length);
        VrmlScene s = VrmlTesting.load("Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 1 0, 1 0 0, 0 1 0 ] }"
            + " coordIndex [ 0 1 2 3 ] } }");
        assertTrue(s.warnings().get(0).contains("fan-triangulated although not convex"), s.warnings().toString());
    }
}
