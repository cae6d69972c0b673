package org.handsim.vrml;

/**
 * Normals for the view, generated the way VRML97 asks (clause 4.6.3.5 "Crease angle"): at each
 * corner, the area-weighted average of the normals of the faces around the vertex whose angle to
 * this face's normal is at most {@code creaseAngle}; with creaseAngle 0 every face is flat, with
 * creaseAngle ≥ π every vertex is smooth.
 *
 * <p>Cost: flat and fully smooth are O(triangles); the general case walks a vertex-to-triangle
 * table (compressed rows on primitive arrays), O(Σ valence²).
 */
final class Normals {
    private Normals() {}

    /** Sets {@code g.normals} and {@code g.normalIndex} from its points and triangles. */
    static void generate(TriGeometry g, double creaseAngle) {
        int[] tri = g.coordIndex;
        int m = tri.length / 3;
        float[] face = new float[3 * m];
        double[] weight = new double[3 * m]; // area-weighted (unnormalised) face normals
        for (int t = 0; t < m; t++) {
            int a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
            double ax = px(g, a, 0), ay = px(g, a, 1), az = px(g, a, 2);
            double ux = px(g, b, 0) - ax, uy = px(g, b, 1) - ay, uz = px(g, b, 2) - az;
            double vx = px(g, c, 0) - ax, vy = px(g, c, 1) - ay, vz = px(g, c, 2) - az;
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            weight[3 * t] = nx; weight[3 * t + 1] = ny; weight[3 * t + 2] = nz;
            unit(nx, ny, nz, face, 3 * t); // +y for a zero-area triangle
        }
        if (!(creaseAngle > 1e-6)) {
            int[] ni = new int[3 * m];
            for (int t = 0; t < m; t++) ni[3 * t] = ni[3 * t + 1] = ni[3 * t + 2] = t;
            g.normals = face;
            g.normalIndex = ni;
            return;
        }
        int np = g.pointCount();
        if (creaseAngle >= Math.PI) {
            double[] acc = new double[3 * np];
            for (int k = 0; k < 3 * m; k++) {
                int v = tri[k], t = k / 3;
                acc[3 * v] += weight[3 * t]; acc[3 * v + 1] += weight[3 * t + 1]; acc[3 * v + 2] += weight[3 * t + 2];
            }
            float[] vn = new float[3 * np];
            for (int v = 0; v < np; v++) unit(acc[3 * v], acc[3 * v + 1], acc[3 * v + 2], vn, 3 * v);
            g.normals = vn;
            g.normalIndex = tri.clone();
            return;
        }
        // vertex -> triangles (CSR)
        int[] rowStart = new int[np + 1];
        for (int v : tri) rowStart[v + 1]++;
        for (int v = 0; v < np; v++) rowStart[v + 1] += rowStart[v];
        int[] fill = rowStart.clone();
        int[] adj = new int[3 * m];
        for (int k = 0; k < 3 * m; k++) adj[fill[tri[k]]++] = k / 3;
        double cosCrease = Math.cos(creaseAngle);
        float[] cn = new float[9 * m];
        int[] ni = new int[3 * m];
        for (int k = 0; k < 3 * m; k++) {
            int t = k / 3, v = tri[k];
            double fx = face[3 * t], fy = face[3 * t + 1], fz = face[3 * t + 2];
            double sx = 0, sy = 0, sz = 0;
            for (int r = rowStart[v]; r < rowStart[v + 1]; r++) {
                int s = adj[r];
                if (s == t || fx * face[3 * s] + fy * face[3 * s + 1] + fz * face[3 * s + 2] >= cosCrease) {
                    sx += weight[3 * s]; sy += weight[3 * s + 1]; sz += weight[3 * s + 2];
                }
            }
            if (!(sx * sx + sy * sy + sz * sz > 0)) { sx = fx; sy = fy; sz = fz; }
            unit(sx, sy, sz, cn, 3 * k);
            ni[k] = k;
        }
        g.normals = cn;
        g.normalIndex = ni;
    }

    private static double px(TriGeometry g, int i, int k) {
        return g.fpoints != null ? g.fpoints[3 * i + k] : g.dpoints[3 * i + k];
    }

    /** Writes (x, y, z) normalised to out[o..o+2], or +y for a zero vector. */
    private static void unit(double x, double y, double z, float[] out, int o) {
        double l = Math.sqrt(x * x + y * y + z * z);
        if (l > 0) {
            out[o] = (float) (x / l); out[o + 1] = (float) (y / l); out[o + 2] = (float) (z / l);
        } else {
            out[o] = 0; out[o + 1] = 1; out[o + 2] = 0;
        }
    }
}
