package org.handsim.collision;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.handsim.mesh.TriangleMesh;

/**
 * Programmatic test meshes (closed, welded, counter-clockwise seen from outside unless said
 * otherwise): icospheres, UV spheres, subdivided boxes, flat grids, random triangle soups.
 */
public final class TestMeshes {
    private TestMeshes() {}

    /**
     * Icosphere: the icosahedron with every triangle split in four {@code level} times, new
     * vertices pushed to the sphere (20·4^level triangles), the construction of
     * the shared data folder's {@code bench-meshes/icosphere_s*.wrl} ({@link org.handsim.TestPaths#shared}).
     */
    public static TriangleMesh icosphere(int level, double radius) {
        double t = (1 + Math.sqrt(5)) / 2;
        List<double[]> v = new ArrayList<>();
        double[][] base = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
            {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (double[] p : base) v.add(unit(p));
        int[][] faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2},
            {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11},
            {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        List<int[]> f = new ArrayList<>();
        for (int[] x : faces) f.add(x);
        for (int l = 0; l < level; l++) {
            Map<Long, Integer> mid = new HashMap<>();
            List<int[]> nf = new ArrayList<>();
            for (int[] x : f) {
                int a = midpoint(v, mid, x[0], x[1]), b = midpoint(v, mid, x[1], x[2]), c = midpoint(v, mid, x[2], x[0]);
                nf.add(new int[] {x[0], a, c});
                nf.add(new int[] {x[1], b, a});
                nf.add(new int[] {x[2], c, b});
                nf.add(new int[] {a, b, c});
            }
            f = nf;
        }
        double[] verts = new double[3 * v.size()];
        for (int i = 0; i < v.size(); i++) for (int c = 0; c < 3; c++) verts[3 * i + c] = v.get(i)[c] * radius;
        int[] tris = new int[3 * f.size()];
        for (int i = 0; i < f.size(); i++) for (int c = 0; c < 3; c++) tris[3 * i + c] = f.get(i)[c];
        return new TriangleMesh("icosphere" + level, verts, tris);
    }

    private static double[] unit(double[] p) {
        double l = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return new double[] {p[0] / l, p[1] / l, p[2] / l};
    }

    private static int midpoint(List<double[]> v, Map<Long, Integer> mid, int a, int b) {
        long key = Math.min(a, b) * 1_000_000L + Math.max(a, b);
        Integer i = mid.get(key);
        if (i != null) return i;
        double[] p = v.get(a), q = v.get(b);
        v.add(unit(new double[] {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2}));
        mid.put(key, v.size() - 1);
        return v.size() - 1;
    }

    /** UV sphere: {@code segments} longitudes, segments/2 latitude bands, poles as single vertices. */
    public static TriangleMesh uvSphere(int segments, double radius) {
        int bands = segments / 2;
        List<double[]> v = new ArrayList<>();
        v.add(new double[] {0, 0, radius});
        for (int i = 1; i < bands; i++) {
            double th = Math.PI * i / bands;
            for (int j = 0; j < segments; j++) {
                double ph = 2 * Math.PI * j / segments;
                v.add(new double[] {radius * Math.sin(th) * Math.cos(ph), radius * Math.sin(th) * Math.sin(ph), radius * Math.cos(th)});
            }
        }
        v.add(new double[] {0, 0, -radius});
        int south = v.size() - 1;
        List<int[]> f = new ArrayList<>();
        for (int j = 0; j < segments; j++) f.add(new int[] {0, 1 + j, 1 + (j + 1) % segments});
        for (int i = 0; i < bands - 2; i++) {
            int r0 = 1 + i * segments, r1 = r0 + segments;
            for (int j = 0; j < segments; j++) {
                int j1 = (j + 1) % segments;
                f.add(new int[] {r0 + j, r1 + j, r1 + j1});
                f.add(new int[] {r0 + j, r1 + j1, r0 + j1});
            }
        }
        int last = 1 + (bands - 2) * segments;
        for (int j = 0; j < segments; j++) f.add(new int[] {south, last + (j + 1) % segments, last + j});
        return toMesh("uvsphere" + segments, v, f);
    }

    /**
     * Axis-aligned box with half extents (hx, hy, hz) centred at the origin, each face a
     * {@code div × div} grid of squares, two triangles each.
     */
    public static TriangleMesh box(double hx, double hy, double hz, int div) {
        List<double[]> v = new ArrayList<>();
        Map<String, Integer> index = new HashMap<>();
        List<int[]> f = new ArrayList<>();
        double[] h = {hx, hy, hz};
        for (int axis = 0; axis < 3; axis++) {
            for (int s = -1; s <= 1; s += 2) {
                int u = (axis + 1) % 3, w = (axis + 2) % 3;
                int[][] id = new int[div + 1][div + 1];
                for (int i = 0; i <= div; i++) {
                    for (int j = 0; j <= div; j++) {
                        double[] p = new double[3];
                        p[axis] = s * h[axis];
                        p[u] = -h[u] + 2 * h[u] * i / div;
                        p[w] = -h[w] + 2 * h[w] * j / div;
                        String key = p[0] + "," + p[1] + "," + p[2];
                        Integer k = index.get(key);
                        if (k == null) {
                            v.add(p);
                            k = v.size() - 1;
                            index.put(key, k);
                        }
                        id[i][j] = k;
                    }
                }
                for (int i = 0; i < div; i++) {
                    for (int j = 0; j < div; j++) {
                        int a = id[i][j], b = id[i + 1][j], c = id[i + 1][j + 1], d = id[i][j + 1];
                        // (u, w, axis) is right-handed: counter-clockwise in (u, w) faces +axis
                        if (s > 0) {
                            f.add(new int[] {a, b, c});
                            f.add(new int[] {a, c, d});
                        } else {
                            f.add(new int[] {a, c, b});
                            f.add(new int[] {a, d, c});
                        }
                    }
                }
            }
        }
        return toMesh("box", v, f);
    }

    /** A flat square grid in z = 0, [−h, h]², n × n squares, normal +z (an open surface). */
    public static TriangleMesh grid(double h, int n) {
        List<double[]> v = new ArrayList<>();
        List<int[]> f = new ArrayList<>();
        for (int i = 0; i <= n; i++) for (int j = 0; j <= n; j++) v.add(new double[] {-h + 2 * h * i / n, -h + 2 * h * j / n, 0});
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int a = i * (n + 1) + j, b = (i + 1) * (n + 1) + j, c = b + 1, d = a + 1;
                f.add(new int[] {a, b, c});
                f.add(new int[] {a, c, d});
            }
        }
        return toMesh("grid", v, f);
    }

    /**
     * n random triangles with vertices in [−s, s]³ (not welded, not closed); every 20th has
     * zero area (its third vertex the exact midpoint of the first two).
     */
    public static TriangleMesh soup(int n, double s, SplittableRandom r) {
        double[] v = new double[9 * n];
        int[] t = new int[3 * n];
        for (int i = 0; i < 9 * n; i++) v[i] = (2 * r.nextDouble() - 1) * s;
        for (int i = 0; i < n; i += 20) {
            for (int c = 0; c < 3; c++) v[9 * i + 6 + c] = (v[9 * i + c] + v[9 * i + 3 + c]) / 2;
        }
        for (int i = 0; i < 3 * n; i++) t[i] = i;
        return new TriangleMesh("soup", v, t);
    }

    /** An icosphere with each vertex moved radially by a random factor in [1 − a, 1 + a]. */
    public static TriangleMesh bumpy(int level, double radius, double a, SplittableRandom r) {
        TriangleMesh s = icosphere(level, radius);
        double[] v = s.vertices().clone();
        for (int i = 0; i < v.length; i += 3) {
            double f = 1 + a * (2 * r.nextDouble() - 1);
            v[i] *= f;
            v[i + 1] *= f;
            v[i + 2] *= f;
        }
        return new TriangleMesh("bumpy", v, s.triangles());
    }

    /** Loads a VRML97 file as one mesh (VrmlLoader + tessellation walk, transforms applied). */
    public static TriangleMesh vrml(java.nio.file.Path file) {
        org.handsim.vrml.VrmlScene scene = new org.handsim.vrml.VrmlLoader().load(file);
        return new org.handsim.mesh.TessellationWalk().name(file.getFileName().toString()).run(scene.getSceneGroup()).merged();
    }

    /** The mesh moved so its bounding box is centred at the origin and scaled so its largest side is {@code size}. */
    public static TriangleMesh fit(TriangleMesh m, double size) {
        double[][] b = m.bounds();
        double ext = Math.max(b[1][0] - b[0][0], Math.max(b[1][1] - b[0][1], b[1][2] - b[0][2]));
        double s = size / ext;
        double[] v = m.vertices().clone();
        for (int i = 0; i < v.length; i += 3) {
            for (int c = 0; c < 3; c++) v[i + c] = (v[i + c] - 0.5 * (b[0][c] + b[1][c])) * s;
        }
        return new TriangleMesh(m.name(), v, m.triangles());
    }

    private static TriangleMesh toMesh(String name, List<double[]> v, List<int[]> f) {
        double[] verts = new double[3 * v.size()];
        for (int i = 0; i < v.size(); i++) System.arraycopy(v.get(i), 0, verts, 3 * i, 3);
        int[] tris = new int[3 * f.size()];
        for (int i = 0; i < f.size(); i++) System.arraycopy(f.get(i), 0, tris, 3 * i, 3);
        return new TriangleMesh(name, verts, tris);
    }
}
