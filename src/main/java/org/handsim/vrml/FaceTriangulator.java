package org.handsim.vrml;

import java.util.Arrays;

/**
 * Splits the polygons of an IndexedFaceSet (or an Extrusion cap) into triangles, correctly for
 * concave and non-planar faces.
 *
 * <h2>Algorithm</h2>
 * <ol>
 *   <li><b>Best-fit plane.</b> The face normal is Newell's vector
 *       N = Σ<sub>i</sub> (y<sub>i</sub>−y<sub>i+1</sub>)(z<sub>i</sub>+z<sub>i+1</sub>), ... (the
 *       area vector of the polygon; for a non-planar polygon, the normal of the plane that
 *       best fits it; Sutherland, Sproull, Schumacker 1974, and Eberly, "Least squares fitting
 *       of data", for the planar case). Its direction follows the vertex order, so the face's
 *       counter-clockwise order about N is kept.</li>
 *   <li><b>Projection.</b> The vertices are expressed in an orthonormal basis (u, v) of that
 *       plane with u × v = N/|N|; in 2D the polygon then has positive signed area.</li>
 *   <li><b>Ear clipping</b> (Meisters 1975; Eberly, "Triangulation by ear clipping", 2002): a
 *       vertex b with neighbours a, c is an ear if the corner is strictly convex
 *       (cross(b−a, c−a) &gt; 0) and no other remaining vertex lies in or on triangle abc
 *       (only reflex vertices can, so only they are tested). Clipping an ear removes b and emits
 *       triangle (a, b, c), which has the face's orientation.</li>
 *   <li><b>No ear</b> in a whole round: a collinear vertex is clipped (zero-area triangle, area
 *       preserved); if there is none, the face crosses itself (or is badly non-planar) and the
 *       rest is fan-triangulated and counted ({@link #fannedConcave}, reported as a warning).
 *       A work budget of O(n²) per face bounds the time whatever the input. Exactly n−2
 *       triangles are always produced, so counts match the
 *       "n-gon = n−2 triangles" convention and zero-area pieces are later dropped and counted
 *       by the tessellation walk.</li>
 * </ol>
 *
 * <p>Triangles come out as <em>positions in the index list</em> (not vertex numbers), so the
 * caller can look up coordinate, normal and colour indices of each corner from the same
 * position. Faces with more than {@link #MAX_EAR_CLIP} vertices are fan-triangulated if convex
 * and otherwise fan-triangulated with a warning (ear clipping is O(n²)).
 *
 * <p>Scratch arrays are reused between faces; not thread-safe.
 */
final class FaceTriangulator {
    /** Faces larger than this are not ear-clipped (cost O(n²)). */
    static final int MAX_EAR_CLIP = 5000;

    /** Output: three positions per triangle. */
    int[] tri = new int[48];
    /** Output: the face number of each triangle. */
    int[] face = new int[16];
    /** Number of triangles produced. */
    int count;
    /** Faces with fewer than three vertices (skipped). */
    int shortFaces;
    /** Faces fan-triangulated although not convex: too large to ear-clip, or self-intersecting. */
    int fannedConcave;

    private double[] x = new double[16], y = new double[16];
    private int[] prev = new int[16], next = new int[16];
    private boolean[] reflex = new boolean[16];

    void reset() {
        count = 0;
        shortFaces = 0;
        fannedConcave = 0;
    }

    /**
     * Triangulates every face of an index list with -1 separators (a last face without -1 is
     * accepted). Indices must already be validated against {@code pts}.
     *
     * @param pts x, y, z per point
     * @param idx the index list
     */
    void triangulateAll(float[] pts, int[] idx) {
        int start = 0;
        int f = 0;
        int n = idx.length;
        for (int i = 0; i <= n; i++) {
            if (i == n || idx[i] < 0) {
                int len = i - start;
                if (len >= 3) {
                    if (len == 3) emit(start, start + 1, start + 2, f);
                    else polygon(pts, idx, start, len, f);
                } else if (len > 0) {
                    shortFaces++;
                }
                if (i < n || len > 0) f++;
                start = i + 1;
            }
        }
    }

    private void emit(int a, int b, int c, int f) {
        if (3 * count + 3 > tri.length) tri = Arrays.copyOf(tri, tri.length * 2);
        if (count == face.length) face = Arrays.copyOf(face, face.length * 2);
        tri[3 * count] = a;
        tri[3 * count + 1] = b;
        tri[3 * count + 2] = c;
        face[count] = f;
        count++;
    }

    /** Triangulates one polygon whose corners are the points {@code idx[start .. start+n-1]}. */
    void polygon(float[] pts, int[] idx, int start, int n, int f) {
        ensure(n);
        // Newell normal
        double nx = 0, ny = 0, nz = 0;
        for (int k = 0; k < n; k++) {
            int kk = k + 1 == n ? 0 : k + 1;
            int p = 3 * idx[start + k], q = 3 * idx[start + kk];
            double x0 = pts[p], y0 = pts[p + 1], z0 = pts[p + 2];
            double x1 = pts[q], y1 = pts[q + 1], z1 = pts[q + 2];
            nx += (y0 - y1) * (z0 + z1);
            ny += (z0 - z1) * (x0 + x1);
            nz += (x0 - x1) * (y0 + y1);
        }
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 0)) {
            // zero area vector: all points collinear (any split has zero area) or a face that
            // crosses itself so its parts cancel (a bow tie): fan it, and count the latter
            if (!collinear(pts, idx, start, n)) fannedConcave++;
            for (int k = 1; k + 1 < n; k++) emit(start, start + k, start + k + 1, f);
            return;
        }
        nx /= len; ny /= len; nz /= len;
        // u: a unit vector perpendicular to N; v = N x u (so u x v = N)
        double ux, uy, uz;
        if (Math.abs(nx) < 0.6) { ux = 0; uy = nz; uz = -ny; } else { ux = -nz; uy = 0; uz = nx; }
        double ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
        ux /= ul; uy /= ul; uz /= ul;
        double vx = ny * uz - nz * uy, vy = nz * ux - nx * uz, vz = nx * uy - ny * ux;
        for (int k = 0; k < n; k++) {
            int p = 3 * idx[start + k];
            double px = pts[p], py = pts[p + 1], pz = pts[p + 2];
            x[k] = px * ux + py * uy + pz * uz;
            y[k] = px * vx + py * vy + pz * vz;
        }
        if (n > MAX_EAR_CLIP) {
            if (!isConvex(n)) fannedConcave++;
            for (int k = 1; k + 1 < n; k++) emit(start, start + k, start + k + 1, f);
            return;
        }
        earClip(start, n, f);
    }

    /** True if every point lies on the line through the first point and the farthest one. */
    private static boolean collinear(float[] pts, int[] idx, int start, int n) {
        double[] p0 = point(pts, idx, start, 0), far = p0;
        double best = 0;
        for (int k = 1; k < n; k++) {
            double[] q = point(pts, idx, start, k);
            double d = (q[0] - p0[0]) * (q[0] - p0[0]) + (q[1] - p0[1]) * (q[1] - p0[1]) + (q[2] - p0[2]) * (q[2] - p0[2]);
            if (d > best) { best = d; far = q; }
        }
        double ux = far[0] - p0[0], uy = far[1] - p0[1], uz = far[2] - p0[2];
        for (int k = 1; k < n; k++) {
            double[] q = point(pts, idx, start, k);
            double wx = q[0] - p0[0], wy = q[1] - p0[1], wz = q[2] - p0[2];
            double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
            if (cx != 0 || cy != 0 || cz != 0) return false;
        }
        return true;
    }

    private static double[] point(float[] pts, int[] idx, int start, int k) {
        int p = 3 * idx[start + k];
        return new double[] {pts[p], pts[p + 1], pts[p + 2]};
    }

    private void ensure(int n) {
        if (x.length < n) {
            int m = Math.max(n, 2 * x.length);
            x = new double[m];
            y = new double[m];
            prev = new int[m];
            next = new int[m];
            reflex = new boolean[m];
        }
    }

    private boolean isConvex(int n) {
        for (int k = 0; k < n; k++) {
            int a = k == 0 ? n - 1 : k - 1, c = k + 1 == n ? 0 : k + 1;
            if (cross(a, k, c) < 0) return false;
        }
        return true;
    }

    /** Twice the signed area of triangle (a, b, c) in the projection plane. */
    private double cross(int a, int b, int c) {
        return (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]);
    }

    private void earClip(int start, int n, int f) {
        for (int k = 0; k < n; k++) {
            prev[k] = k == 0 ? n - 1 : k - 1;
            next[k] = k + 1 == n ? 0 : k + 1;
        }
        for (int k = 0; k < n; k++) reflex[k] = cross(prev[k], k, next[k]) <= 0;
        int remaining = n;
        int b = 0;
        int sinceLastClip = 0;
        long budget = 8L * n * n + 1_000_000; // ear tests and their inner loops; O(n²) for any real face
        work = 0;
        while (remaining > 3) {
            if (!reflex[b] && isEar(b)) {
                b = clip(b, start, f);
                remaining--;
                sinceLastClip = 0;
                continue;
            }
            b = next[b];
            if (++sinceLastClip > remaining || work > budget) {
                // no ear in a whole round: clip a collinear corner (zero area, nothing lost) if
                // there is one; otherwise the face crosses itself: fan the rest and say so
                int k = b, found = -1;
                for (int s = 0; s < remaining && work <= budget; s++, work++) {
                    if (cross(prev[k], k, next[k]) == 0) { found = k; break; }
                    k = next[k];
                }
                if (found < 0) {
                    fannedConcave++;
                    int a = b;
                    for (int c = next[a]; next[c] != a; c = next[c]) emit(start + a, start + c, start + next[c], f);
                    return;
                }
                b = clip(found, start, f);
                remaining--;
                sinceLastClip = 0;
            }
        }
        emit(start + prev[b], start + b, start + next[b], f);
    }

    /** Inner-loop iterations of the current face (bounded by a budget). */
    private long work;

    /** Emits ear b, unlinks it, updates the neighbours' reflex flags; returns the next vertex to try. */
    private int clip(int b, int start, int f) {
        int a = prev[b], c = next[b];
        emit(start + a, start + b, start + c, f);
        next[a] = c;
        prev[c] = a;
        reflex[a] = cross(prev[a], a, c) <= 0;
        reflex[c] = cross(a, c, next[c]) <= 0;
        return a;
    }

    private boolean isEar(int b) {
        int a = prev[b], c = next[b];
        double area = cross(a, b, c);
        if (!(area > 0)) return false;
        double ax = x[a], ay = y[a], bx = x[b], by = y[b], cx = x[c], cy = y[c];
        for (int k = next[c]; k != a; k = next[k]) {
            work++;
            if (!reflex[k]) continue;
            double px = x[k], py = y[k];
            if ((px == ax && py == ay) || (px == bx && py == by) || (px == cx && py == cy)) continue;
            if ((bx - ax) * (py - ay) - (by - ay) * (px - ax) >= 0
                && (cx - bx) * (py - by) - (cy - by) * (px - bx) >= 0
                && (ax - cx) * (py - cy) - (ay - cy) * (px - cx) >= 0) {
                return false;
            }
        }
        return true;
    }
}
