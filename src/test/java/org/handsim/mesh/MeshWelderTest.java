package org.handsim.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Welding coincident vertices: a box made of six separate faces becomes a closed mesh. */
class MeshWelderTest {
    /** A unit cube as six separate quads (24 vertices, 12 triangles), outward. */
    static TriangleMesh looseCube(double jitter) {
        int[][] quads = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
        double[] v = new double[72];
        int[] t = new int[36];
        java.util.Random r = new java.util.Random(345);
        for (int f = 0; f < 6; f++) {
            for (int k = 0; k < 4; k++) {
                int c = quads[f][k], o = 3 * (4 * f + k);
                v[o] = (c & 1) + jitter * (r.nextDouble() - 0.5);
                v[o + 1] = ((c >> 1) & 1) + jitter * (r.nextDouble() - 0.5);
                v[o + 2] = ((c >> 2) & 1) + jitter * (r.nextDouble() - 0.5);
            }
            int b = 4 * f;
            int[] tri = {b, b + 1, b + 2, b, b + 2, b + 3};
            System.arraycopy(tri, 0, t, 6 * f, 6);
        }
        return new TriangleMesh("cube", v, t);
    }

    @Test
    void exactWeldClosesTheCube() {
        TriangleMesh loose = looseCube(0);
        assertFalse(loose.isClosed());
        MeshWelder w = new MeshWelder();
        TriangleMesh m = w.weld(loose, 0);
        assertEquals(8, m.vertexCount());
        assertTrue(m.isClosed());
        assertEquals(1.0, m.signedVolume(), 1e-15);
        assertEquals(0, w.lastCollapsed());
    }

    @Test
    void toleranceDecidesWhatMerges() {
        TriangleMesh jittered = looseCube(1e-7);
        assertEquals(8, new MeshWelder().weld(jittered, 1e-6).vertexCount());
        assertEquals(24, new MeshWelder().weld(jittered, 1e-9).vertexCount());
        assertEquals(Math.sqrt(3), looseCube(0).diagonal(), 1e-15, "the unit cube's diagonal");
        assertEquals(1e-9 * Math.sqrt(3), MeshWelder.defaultTolerance(looseCube(0)), 1e-24);
        assertEquals(24, new MeshWelder().weld(jittered).vertexCount(), "default 1e-9 x diagonal keeps 1e-7 jitter apart");
    }

    @Test
    void collapsedTrianglesAreRemoved() {
        TriangleMesh m = new TriangleMesh("sliver", new double[] {0, 0, 0, 1, 0, 0, 1e-12, 0, 0, 0, 1, 0}, new int[] {0, 1, 2, 0, 2, 3, 0, 1, 3});
        MeshWelder w = new MeshWelder();
        TriangleMesh out = w.weld(m, 1e-9);
        assertEquals(3, out.vertexCount());
        assertEquals(1, out.triangleCount());
        assertEquals(2, w.lastCollapsed());
    }

    @Test
    void negativeZeroEqualsZero() {
        TriangleMesh m = new TriangleMesh("z", new double[] {0, 0, 0, -0.0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 2, 3, 1, 2, 3});
        assertEquals(3, new MeshWelder().weld(m, 0).vertexCount());
    }
}
