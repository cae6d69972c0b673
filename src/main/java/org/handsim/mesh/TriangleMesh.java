package org.handsim.mesh;

import org.handsim.math.RigidTransform;

/**
 * An immutable triangle mesh on primitive arrays (docs/STYLE.md, item 5), in metres.
 *
 * <ul>
 *   <li>{@code vertices}: x, y, z of vertex i at {@code [3i, 3i+1, 3i+2]};</li>
 *   <li>{@code triangles}: the three vertex indices of triangle t at {@code [3t, 3t+1, 3t+2]},
 *       counter-clockwise seen from outside (the unit normal points out);</li>
 *   <li>{@code normals}: the unit normal of triangle t at {@code [3t..3t+2]} (0, 0, 0 for a
 *       zero-area triangle);</li>
 *   <li>{@code areas}: the area of triangle t in m².</li>
 * </ul>
 *
 * <p>Zero-area triangles are kept if the caller passes them (the collision layer skips and
 * counts them); {@link #withoutDegenerate()} drops them, as the tessellation walk does.
 * Arrays handed to the constructor are owned by the mesh; accessors return the internal
 * arrays for speed and callers must not modify them.
 */
public final class TriangleMesh {
    private final String name;
    private final double[] vertices;
    private final int[] triangles;
    private final double[] normals;
    private final double[] areas;

    /**
     * @param name      a label for messages (a file name or a DEF name)
     * @param vertices  3·n coordinates in metres (owned by the mesh from now on)
     * @param triangles 3·m vertex indices (owned by the mesh from now on)
     * @throws IllegalArgumentException naming the offending index or value
     */
    public TriangleMesh(String name, double[] vertices, int[] triangles) {
        if (vertices.length % 3 != 0) {
            throw new IllegalArgumentException(name + ": vertex array length " + vertices.length + " is not a multiple of 3");
        }
        if (triangles.length % 3 != 0) {
            throw new IllegalArgumentException(name + ": triangle array length " + triangles.length + " is not a multiple of 3");
        }
        int n = vertices.length / 3;
        for (int i = 0; i < vertices.length; i++) {
            if (!Double.isFinite(vertices[i])) {
                throw new IllegalArgumentException(name + ": vertex " + (i / 3) + " has a non-finite coordinate " + vertices[i]);
            }
        }
        for (int i = 0; i < triangles.length; i++) {
            if (triangles[i] < 0 || triangles[i] >= n) {
                throw new IllegalArgumentException(name + ": triangle " + (i / 3) + " uses vertex index " + triangles[i]
                    + " outside [0, " + n + ")");
            }
        }
        this.name = name;
        this.vertices = vertices;
        this.triangles = triangles;
        int m = triangles.length / 3;
        this.normals = new double[3 * m];
        this.areas = new double[m];
        computeNormalsAndAreas(vertices, triangles, normals, areas);
    }

    /**
     * Unit normals and areas from the vertices (allocation-free); used by the constructor and
     * by callers that move a mesh's vertices in their own buffers.
     */
    public static void computeNormalsAndAreas(double[] v, int[] tri, double[] normalsOut, double[] areasOut) {
        int m = tri.length / 3;
        for (int t = 0; t < m; t++) {
            int a = 3 * tri[3 * t], b = 3 * tri[3 * t + 1], c = 3 * tri[3 * t + 2];
            double ux = v[b] - v[a], uy = v[b + 1] - v[a + 1], uz = v[b + 2] - v[a + 2];
            double wx = v[c] - v[a], wy = v[c + 1] - v[a + 1], wz = v[c + 2] - v[a + 2];
            double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            areasOut[t] = 0.5 * len;
            if (len > 0) {
                normalsOut[3 * t] = nx / len;
                normalsOut[3 * t + 1] = ny / len;
                normalsOut[3 * t + 2] = nz / len;
            } else {
                normalsOut[3 * t] = normalsOut[3 * t + 1] = normalsOut[3 * t + 2] = 0;
            }
        }
    }

    public String name() { return name; }
    public int vertexCount() { return vertices.length / 3; }
    public int triangleCount() { return triangles.length / 3; }
    /** Internal vertex array (x, y, z per vertex, metres); do not modify. */
    public double[] vertices() { return vertices; }
    /** Internal index array (3 per triangle); do not modify. */
    public int[] triangles() { return triangles; }
    /** Internal unit-normal array (3 per triangle); do not modify. */
    public double[] normals() { return normals; }
    /** Internal area array (m² per triangle); do not modify. */
    public double[] areas() { return areas; }

    /** Whether {@code other} has the same vertices (bit for bit) and triangles: the same mesh, whatever made it. */
    public boolean sameTrianglesAs(TriangleMesh other) {
        return java.util.Arrays.equals(vertices, other.vertices) && java.util.Arrays.equals(triangles, other.triangles);
    }

    /** @return the number of zero-area triangles */
    public int degenerateCount() {
        int c = 0;
        for (double a : areas) {
            if (!(a > 0)) c++;
        }
        return c;
    }

    /** @return this mesh without its zero-area triangles (this itself if it has none) */
    public TriangleMesh withoutDegenerate() {
        int bad = degenerateCount();
        if (bad == 0) return this;
        int[] kept = new int[triangles.length - 3 * bad];
        int k = 0;
        for (int t = 0; t < areas.length; t++) {
            if (areas[t] > 0) {
                kept[k++] = triangles[3 * t];
                kept[k++] = triangles[3 * t + 1];
                kept[k++] = triangles[3 * t + 2];
            }
        }
        return new TriangleMesh(name, vertices, kept);
    }

    /** @return the total surface area in m² */
    public double area() {
        double s = 0;
        for (double a : areas) s += a;
        return s;
    }

    /**
     * Enclosed volume by the divergence theorem, Σ (a · (b × c)) / 6 over triangles, in m³.
     * Meaningful only when {@link #isClosed()}; positive for outward (counter-clockwise) faces.
     */
    public double signedVolume() {
        double s = 0;
        double[] v = vertices;
        for (int t = 0; t < triangles.length; t += 3) {
            int a = 3 * triangles[t], b = 3 * triangles[t + 1], c = 3 * triangles[t + 2];
            s += v[a] * (v[b + 1] * v[c + 2] - v[b + 2] * v[c + 1])
               - v[a + 1] * (v[b] * v[c + 2] - v[b + 2] * v[c])
               + v[a + 2] * (v[b] * v[c + 1] - v[b + 1] * v[c]);
        }
        return s / 6.0;
    }

    /**
     * The centroid of the solid the mesh bounds (metres, the mesh's frame): Σ over triangles of
     * the signed tetrahedra (0, a, b, c), each at (a + b + c)/4 weighted by its signed volume,
     * divided by {@link #signedVolume()} (the divergence theorem; it needs the surface to close,
     * not the vertices to be welded). When the enclosed volume is negligible (an open patch, a
     * flat part: |V| ≤ 1e-9 · diagonal³) it is the area-weighted centroid of the surface
     * instead; for an empty mesh, the origin. The torque origin of grasp analysis (GraspIt!'s
     * centre of gravity for a uniform object).
     */
    public double[] centroid() {
        double[] v = vertices;
        double vol = 0, cx = 0, cy = 0, cz = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            int a = 3 * triangles[t], b = 3 * triangles[t + 1], c = 3 * triangles[t + 2];
            double d = v[a] * (v[b + 1] * v[c + 2] - v[b + 2] * v[c + 1])
                - v[a + 1] * (v[b] * v[c + 2] - v[b + 2] * v[c])
                + v[a + 2] * (v[b] * v[c + 1] - v[b + 1] * v[c]);
            vol += d;
            cx += d * (v[a] + v[b] + v[c]);
            cy += d * (v[a + 1] + v[b + 1] + v[c + 1]);
            cz += d * (v[a + 2] + v[b + 2] + v[c + 2]);
        }
        double diag = diagonal();
        if (Math.abs(vol / 6) > 1e-9 * diag * diag * diag) {
            return new double[] {cx / (4 * vol), cy / (4 * vol), cz / (4 * vol)};
        }
        double area = 0;
        cx = cy = cz = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            int a = 3 * triangles[t], b = 3 * triangles[t + 1], c = 3 * triangles[t + 2];
            double w = areas[t / 3];
            area += w;
            cx += w * (v[a] + v[b] + v[c]) / 3;
            cy += w * (v[a + 1] + v[b + 1] + v[c + 1]) / 3;
            cz += w * (v[a + 2] + v[b + 2] + v[c + 2]) / 3;
        }
        return area > 0 ? new double[] {cx / area, cy / area, cz / area} : new double[3];
    }

    /**
     * The second moments of the solid the mesh bounds about the origin of the mesh's frame, per
     * unit density: {@code (∫x², ∫xy, ∫xz, ∫y², ∫yz, ∫z²) dV} in m⁵, by the divergence theorem as
     * {@link #centroid()} (signed tetrahedra (0, a, b, c) of volume d/6, d = a·(b × c), each
     * contributing {@code d/120·(Σ_v v_i v_j + s_i s_j)} with s = a + b + c; Tonon 2004). Times a
     * density ρ this is {@code Σ = ∫ r rᵀ dm} and the inertia tensor about the origin is
     * {@code tr(Σ)·E − Σ}. Meaningful only for a closed surface with outward faces.
     */
    public double[] secondMoments() {
        double[] v = vertices;
        double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            int a = 3 * triangles[t], b = 3 * triangles[t + 1], c = 3 * triangles[t + 2];
            double d = v[a] * (v[b + 1] * v[c + 2] - v[b + 2] * v[c + 1])
                - v[a + 1] * (v[b] * v[c + 2] - v[b + 2] * v[c])
                + v[a + 2] * (v[b] * v[c + 1] - v[b + 1] * v[c]);
            double ax = v[a], ay = v[a + 1], az = v[a + 2];
            double bx = v[b], by = v[b + 1], bz = v[b + 2];
            double cx = v[c], cy = v[c + 1], cz = v[c + 2];
            double sx = ax + bx + cx, sy = ay + by + cy, sz = az + bz + cz;
            xx += d * (ax * ax + bx * bx + cx * cx + sx * sx);
            xy += d * (ax * ay + bx * by + cx * cy + sx * sy);
            xz += d * (ax * az + bx * bz + cx * cz + sx * sz);
            yy += d * (ay * ay + by * by + cy * cy + sy * sy);
            yz += d * (ay * az + by * bz + cy * cz + sy * sz);
            zz += d * (az * az + bz * bz + cz * cz + sz * sz);
        }
        return new double[] {xx / 120, xy / 120, xz / 120, yy / 120, yz / 120, zz / 120};
    }

    /**
     * A mesh is closed when every undirected edge is used by exactly two triangles, once in
     * each direction (an oriented 2-manifold without boundary). Vertices are compared by index,
     * so a mesh must share its vertices (welded) to be closed.
     */
    public boolean isClosed() {
        int m = triangleCount();
        if (m == 0) return false;
        long[] directed = new long[3 * m];
        int n = vertexCount();
        for (int t = 0; t < m; t++) {
            for (int e = 0; e < 3; e++) {
                long a = triangles[3 * t + e], b = triangles[3 * t + (e + 1) % 3];
                directed[3 * t + e] = a * n + b;
            }
        }
        java.util.Arrays.sort(directed);
        for (int i = 1; i < directed.length; i++) {
            if (directed[i] == directed[i - 1]) return false; // same directed edge twice
        }
        for (long d : directed) {
            long a = d / n, b = d % n;
            if (java.util.Arrays.binarySearch(directed, b * n + a) < 0) return false;
        }
        return true;
    }

    /** @return {{xmin, ymin, zmin}, {xmax, ymax, zmax}}; zeros for an empty mesh */
    public double[][] bounds() {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        if (vertices.length == 0) return new double[][] {{0, 0, 0}, {0, 0, 0}};
        for (int i = 0; i < vertices.length; i += 3) {
            for (int k = 0; k < 3; k++) {
                lo[k] = Math.min(lo[k], vertices[i + k]);
                hi[k] = Math.max(hi[k], vertices[i + k]);
            }
        }
        return new double[][] {lo, hi};
    }

    /** @return the length of the bounding box's diagonal, m (0 for an empty mesh) */
    public double diagonal() {
        double[][] b = bounds();
        double dx = b[1][0] - b[0][0], dy = b[1][1] - b[0][1], dz = b[1][2] - b[0][2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** @return a new mesh with every vertex mapped by {@code t} (same triangles) */
    public TriangleMesh transformed(RigidTransform t) {
        double[] out = new double[vertices.length];
        double[] p = new double[3];
        for (int i = 0; i < vertices.length; i += 3) {
            p[0] = vertices[i]; p[1] = vertices[i + 1]; p[2] = vertices[i + 2];
            t.apply(p, p);
            out[i] = p[0]; out[i + 1] = p[1]; out[i + 2] = p[2];
        }
        return new TriangleMesh(name, out, triangles);
    }

    /** @return a new mesh with every coordinate multiplied by {@code s} (s &gt; 0) */
    public TriangleMesh scaled(double s) {
        if (!(s > 0) || !Double.isFinite(s)) throw new IllegalArgumentException("scale must be a positive finite number, got " + s);
        double[] out = new double[vertices.length];
        for (int i = 0; i < out.length; i++) out[i] = vertices[i] * s;
        return new TriangleMesh(name, out, triangles);
    }

    /** Concatenates meshes into one (vertices not welded). */
    public static TriangleMesh concat(String name, java.util.List<TriangleMesh> parts) {
        int nv = 0, nt = 0;
        for (TriangleMesh p : parts) { nv += p.vertices.length; nt += p.triangles.length; }
        double[] v = new double[nv];
        int[] t = new int[nt];
        int vo = 0, to = 0;
        for (TriangleMesh p : parts) {
            System.arraycopy(p.vertices, 0, v, vo, p.vertices.length);
            int base = vo / 3;
            for (int i = 0; i < p.triangles.length; i++) t[to + i] = p.triangles[i] + base;
            vo += p.vertices.length;
            to += p.triangles.length;
        }
        return new TriangleMesh(name, v, t);
    }

    @Override
    public String toString() {
        return "TriangleMesh[" + name + ": " + vertexCount() + " vertices, " + triangleCount() + " triangles]";
    }
}
