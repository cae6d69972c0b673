package org.handsim.body;

import java.util.Arrays;
import org.handsim.mesh.TriangleMesh;

/**
 * Which vertices and triangles of a mesh touch, for deciding whether a feature can be the
 * closest one in a direction ({@link ProximityContacts}): each vertex's neighbours (the far
 * ends of its edges) and, for each triangle edge, the vertex opposite it in the triangle across
 * that edge. Vertices at the same position (bit for bit) count as one, so a tessellation that
 * repeats vertices along seams still has its neighbours across them.
 *
 * <p>Immutable after construction; indices are the mesh's own vertex indices.
 */
public final class MeshTopology {
    private final int[] start, neighbours;      // per vertex: neighbours[start[v] .. start[v+1])
    private final int[] across;                 // per triangle edge 3t + e (from corner e to e+1): the opposite vertex across it, or −1

    /** Builds the topology of {@code mesh}. */
    public MeshTopology(TriangleMesh mesh) {
        double[] v = mesh.vertices();
        int[] tri = mesh.triangles();
        int n = mesh.vertexCount(), m = mesh.triangleCount();
        // canonical id per vertex: equal positions share one
        Integer[] idx = new Integer[n];
        for (int i = 0; i < n; i++) idx[i] = i;
        Arrays.sort(idx, (x, y) -> {
            int c = Double.compare(v[3 * x], v[3 * y]);
            if (c == 0) c = Double.compare(v[3 * x + 1], v[3 * y + 1]);
            if (c == 0) c = Double.compare(v[3 * x + 2], v[3 * y + 2]);
            return c;
        });
        int[] canon = new int[n];
        int ids = 0;
        for (int i = 0; i < n; i++) {
            if (i > 0 && v[3 * idx[i]] == v[3 * idx[i - 1]] && v[3 * idx[i] + 1] == v[3 * idx[i - 1] + 1]
                && v[3 * idx[i] + 2] == v[3 * idx[i - 1] + 2]) {
                canon[idx[i]] = canon[idx[i - 1]];
            } else {
                canon[idx[i]] = ids++;
            }
        }
        // directed edges (canonical), sorted: neighbours and the triangle across each edge
        long[] key = new long[3 * m];
        for (int t = 0; t < m; t++) {
            for (int e = 0; e < 3; e++) {
                long a = canon[tri[3 * t + e]], b = canon[tri[3 * t + (e + 1) % 3]];
                key[3 * t + e] = (a * ids + b) * (3L * m) + (3L * t + e);
            }
        }
        long span = 3L * m;
        Arrays.sort(key);
        across = new int[3 * m];
        Arrays.fill(across, -1);
        for (int i = 0; i < key.length; i++) {
            long pair = key[i] / span;
            int te = (int) (key[i] % span);
            long a = pair / ids, b = pair % ids;
            long rev = b * ids + a;
            int j = lowerBound(key, rev * span);
            if (j < key.length && key[j] / span == rev) {
                int tr = (int) (key[j] % span), t2 = tr / 3, e2 = tr % 3;
                across[te] = tri[3 * t2 + (e2 + 2) % 3];
            }
        }
        // neighbours per canonical id, then per vertex
        int[] count = new int[ids + 1];
        long[] und = new long[2 * key.length];
        int nu = 0;
        for (long k : key) {
            long pair = k / span;
            long a = pair / ids, b = pair % ids;
            und[nu++] = a * ids + b;
            und[nu++] = b * ids + a;
        }
        Arrays.sort(und, 0, nu);
        int[] repr = new int[ids];
        for (int i = 0; i < n; i++) repr[canon[i]] = i;
        int distinct = 0;
        for (int i = 0; i < nu; i++) {
            if (i == 0 || und[i] != und[i - 1]) {
                und[distinct++] = und[i];
                count[(int) (und[i] / ids) + 1]++;
            }
        }
        for (int i = 0; i < ids; i++) count[i + 1] += count[i];
        int[] canonNb = new int[distinct];
        for (int i = 0; i < distinct; i++) canonNb[i] = repr[(int) (und[i] % ids)];
        start = new int[n + 1];
        int total = 0;
        for (int i = 0; i < n; i++) total += count[canon[i] + 1] - count[canon[i]];
        neighbours = new int[total];
        int o = 0;
        for (int i = 0; i < n; i++) {
            start[i] = o;
            int c = canon[i];
            for (int k = count[c]; k < count[c + 1]; k++) neighbours[o++] = canonNb[k];
        }
        start[n] = o;
    }

    private static int lowerBound(long[] a, long x) {
        int lo = 0, hi = a.length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (a[mid] < x) lo = mid + 1; else hi = mid;
        }
        return lo;
    }

    /** @return the index in {@link #neighbours()} where vertex v's neighbours begin */
    public int neighbourStart(int v) { return start[v]; }

    /** @return the index in {@link #neighbours()} where vertex v's neighbours end */
    public int neighbourEnd(int v) { return start[v + 1]; }

    /** @return the neighbour array (vertex indices; do not modify) */
    public int[] neighbours() { return neighbours; }

    /** @return the vertex opposite edge e (corner e to e + 1) of triangle t in the triangle across it, or −1 at a border */
    public int across(int t, int e) { return across[3 * t + e]; }
}
