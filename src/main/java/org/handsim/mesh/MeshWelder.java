package org.handsim.mesh;

import java.util.Arrays;

/**
 * Merges coincident vertices of a triangle mesh, so that shapes built from separate pieces
 * (six Box faces, a cylinder's caps and side, parts of a CAD model) share their vertices and
 * a closed surface is recognised as closed ({@link TriangleMesh#isClosed()} compares vertex
 * indices).
 *
 * <h2>Algorithm</h2>
 * Vertices within {@code tol} of each other (Euclidean) are merged into the first one met.
 * Space is cut into cubic cells of side 2·tol; a vertex can only be within tol of a vertex in
 * its own cell or, on each axis, the neighbouring cell on the side it is nearer to, so eight
 * cells are searched per vertex: O(n) expected time with a hash table of cells on primitive
 * arrays. With {@code tol = 0} only bit-identical positions merge (−0 equals +0).
 *
 * <p>Triangles that lose an edge in the merge (two corners welded together) have zero area and
 * are removed; {@link #lastCollapsed()} tells how many.
 */
public final class MeshWelder {
    private int collapsed;

    /** Triangles removed by the last {@link #weld} because two of their corners merged. */
    public int lastCollapsed() {
        return collapsed;
    }

    /**
     * The default tolerance for a mesh: 1e-9 times its bounding-box diagonal (a few units in the
     * last place of float input after transforms; far below any modelled feature).
     */
    public static double defaultTolerance(TriangleMesh m) {
        return 1e-9 * m.diagonal();
    }

    /** Welds with {@link #defaultTolerance}. */
    public TriangleMesh weld(TriangleMesh m) {
        return weld(m, defaultTolerance(m));
    }

    /**
     * @param tol merge distance in the mesh's units (≥ 0)
     * @return a new mesh with merged vertices and without collapsed triangles
     */
    public TriangleMesh weld(TriangleMesh m, double tol) {
        if (!(tol >= 0) || !Double.isFinite(tol)) throw new IllegalArgumentException("tolerance must be finite and >= 0, got " + tol);
        double[] v = m.vertices();
        int n = m.vertexCount();
        int[] rep = new int[n];
        double[] out = new double[3 * n];
        int kept = 0;
        Table table = new Table(n);
        double cell = 2 * tol;
        double tol2 = tol * tol;
        int[] nextInCell = new int[n];
        for (int i = 0; i < n; i++) {
            double x = v[3 * i] + 0.0, y = v[3 * i + 1] + 0.0, z = v[3 * i + 2] + 0.0;
            int found = -1;
            if (tol == 0) {
                int h = table.find(Double.doubleToLongBits(x), Double.doubleToLongBits(y), Double.doubleToLongBits(z), false);
                if (h >= 0) found = table.head[h];
            } else {
                long ix = (long) Math.floor(x / cell), iy = (long) Math.floor(y / cell), iz = (long) Math.floor(z / cell);
                long ox = x / cell - ix < 0.5 ? -1 : 1, oy = y / cell - iy < 0.5 ? -1 : 1, oz = z / cell - iz < 0.5 ? -1 : 1;
                search:
                for (int k = 0; k < 8; k++) {
                    int h = table.find(ix + ((k & 1) != 0 ? ox : 0), iy + ((k & 2) != 0 ? oy : 0), iz + ((k & 4) != 0 ? oz : 0), false);
                    if (h < 0) continue;
                    for (int r = table.head[h]; r >= 0; r = nextInCell[r]) {
                        double ex = out[3 * r] - x, ey = out[3 * r + 1] - y, ez = out[3 * r + 2] - z;
                        if (ex * ex + ey * ey + ez * ez <= tol2) {
                            found = r;
                            break search;
                        }
                    }
                }
            }
            if (found >= 0) {
                rep[i] = found;
                continue;
            }
            int h = tol == 0
                ? table.find(Double.doubleToLongBits(x), Double.doubleToLongBits(y), Double.doubleToLongBits(z), true)
                : table.find((long) Math.floor(x / cell), (long) Math.floor(y / cell), (long) Math.floor(z / cell), true);
            out[3 * kept] = x; out[3 * kept + 1] = y; out[3 * kept + 2] = z;
            nextInCell[kept] = table.head[h];
            table.head[h] = kept;
            rep[i] = kept++;
        }
        int[] t = m.triangles();
        int[] nt = new int[t.length];
        int k = 0;
        collapsed = 0;
        for (int i = 0; i < t.length; i += 3) {
            int a = rep[t[i]], b = rep[t[i + 1]], c = rep[t[i + 2]];
            if (a == b || b == c || a == c) {
                collapsed++;
                continue;
            }
            nt[k++] = a; nt[k++] = b; nt[k++] = c;
        }
        return new TriangleMesh(m.name(), Arrays.copyOf(out, 3 * kept), Arrays.copyOf(nt, k));
    }

    /** Open-addressing hash table of cells (three long keys) on primitive arrays. */
    private static final class Table {
        final long[] kx, ky, kz;
        final int[] head;
        final boolean[] used;
        final int mask;

        Table(int n) {
            int cap = Integer.highestOneBit(Math.max(4, 2 * n) - 1) << 1;
            kx = new long[cap];
            ky = new long[cap];
            kz = new long[cap];
            head = new int[cap];
            used = new boolean[cap];
            mask = cap - 1;
        }

        /** Slot of cell (x, y, z); -1 if absent and !insert. */
        int find(long x, long y, long z, boolean insert) {
            long h = x * 0x9E3779B97F4A7C15L + y * 0xC2B2AE3D27D4EB4FL + z * 0x165667B19E3779F9L;
            int i = (int) (h ^ (h >>> 29)) & mask;
            while (used[i]) {
                if (kx[i] == x && ky[i] == y && kz[i] == z) return i;
                i = (i + 1) & mask;
            }
            if (!insert) return -1;
            used[i] = true;
            kx[i] = x; ky[i] = y; kz[i] = z;
            head[i] = -1;
            return i;
        }
    }
}
