package org.handsim.vrml;

/**
 * Triangle meshes of the VRML97 geometric primitives (clause 6: Box, Sphere, Cylinder, Cone),
 * centred at the origin, axis along +y, outward counter-clockwise faces, vertices shared so a
 * full primitive is a closed 2-manifold.
 *
 * <p>The resolution is a parameter, {@code divisions} = number of segments around the y axis
 * (at least 3). The Sphere has {@code max(2, divisions/2)} latitude bands, closed by a fan at
 * each pole (no zero-area triangles). All vertices lie on the exact surface, so the area and
 * volume of the polyhedron approach the analytic values from below with an error of order
 * 1/divisions² (for a circle of n segments, the inscribed polygon's area is
 * (n/2)·r²·sin(2π/n) = πr²(1 − (2π²/3)/n² + ...)).
 *
 * <p>Normals for the view: Box faces flat; Sphere smooth; Cylinder and Cone sides smooth
 * around, caps flat.
 */
final class Primitives {
    private Primitives() {}

    /** Box of full sizes sx, sy, sz: 8 vertices, 12 triangles. */
    static TriGeometry box(double sx, double sy, double sz) {
        double hx = sx / 2, hy = sy / 2, hz = sz / 2;
        double[] p = new double[24];
        for (int i = 0; i < 8; i++) {
            p[3 * i] = (i & 1) != 0 ? hx : -hx;
            p[3 * i + 1] = (i & 2) != 0 ? hy : -hy;
            p[3 * i + 2] = (i & 4) != 0 ? hz : -hz;
        }
        int[][] quads = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
        float[] normals = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
        int[] ci = new int[36], ni = new int[36];
        for (int f = 0; f < 6; f++) {
            int[] q = quads[f];
            int o = 6 * f;
            ci[o] = q[0]; ci[o + 1] = q[1]; ci[o + 2] = q[2];
            ci[o + 3] = q[0]; ci[o + 4] = q[2]; ci[o + 5] = q[3];
            for (int k = 0; k < 6; k++) ni[o + k] = f;
        }
        return mesh(p, ci, normals, ni);
    }

    /** Sphere of radius r with {@code n} segments around and max(2, n/2) bands. */
    static TriGeometry sphere(double r, int n) {
        int bands = Math.max(2, n / 2);
        int rings = bands - 1;
        int nv = 2 + rings * n;
        double[] p = new double[3 * nv];
        float[] nor = new float[3 * nv];
        p[1] = r;
        nor[1] = 1;
        for (int j = 1; j <= rings; j++) {
            double th = Math.PI * j / bands;
            double y = Math.cos(th), rho = Math.sin(th);
            for (int k = 0; k < n; k++) {
                double ph = 2 * Math.PI * k / n;
                int v = 1 + (j - 1) * n + k;
                double ux = rho * Math.sin(ph), uz = rho * Math.cos(ph);
                p[3 * v] = r * ux; p[3 * v + 1] = r * y; p[3 * v + 2] = r * uz;
                nor[3 * v] = (float) ux; nor[3 * v + 1] = (float) y; nor[3 * v + 2] = (float) uz;
            }
        }
        int south = nv - 1;
        p[3 * south + 1] = -r;
        nor[3 * south + 1] = -1;
        int[] ci = new int[3 * (2 * n + 2 * n * (rings - 1))];
        int o = 0;
        for (int k = 0; k < n; k++) {
            int k1 = (k + 1) % n;
            ci[o++] = 0; ci[o++] = 1 + k; ci[o++] = 1 + k1;
        }
        for (int j = 1; j < rings; j++) {
            int up = 1 + (j - 1) * n, lo = 1 + j * n;
            for (int k = 0; k < n; k++) {
                int k1 = (k + 1) % n;
                ci[o++] = up + k; ci[o++] = lo + k; ci[o++] = lo + k1;
                ci[o++] = up + k; ci[o++] = lo + k1; ci[o++] = up + k1;
            }
        }
        int last = 1 + (rings - 1) * n;
        for (int k = 0; k < n; k++) {
            int k1 = (k + 1) % n;
            ci[o++] = last + k; ci[o++] = south; ci[o++] = last + k1;
        }
        return mesh(p, ci, nor, ci.clone());
    }

    /** Cylinder of radius r and height h; each part optional. Null if no part is on. */
    static TriGeometry cylinder(double r, double h, int n, boolean side, boolean top, boolean bottom) {
        if (!side && !top && !bottom) return null;
        double y = h / 2;
        int topC = 2 * n, botC = 2 * n + 1;
        double[] p = new double[3 * (2 * n + 2)];
        float[] nor = new float[3 * (n + 2)];
        for (int k = 0; k < n; k++) {
            double ph = 2 * Math.PI * k / n;
            double sx = Math.sin(ph), cz = Math.cos(ph);
            p[3 * k] = r * sx; p[3 * k + 1] = y; p[3 * k + 2] = r * cz;
            p[3 * (n + k)] = r * sx; p[3 * (n + k) + 1] = -y; p[3 * (n + k) + 2] = r * cz;
            nor[3 * k] = (float) sx; nor[3 * k + 2] = (float) cz;
        }
        p[3 * topC + 1] = y;
        p[3 * botC + 1] = -y;
        nor[3 * n + 1] = 1;
        nor[3 * (n + 1) + 1] = -1;
        int tris = (side ? 2 * n : 0) + (top ? n : 0) + (bottom ? n : 0);
        int[] ci = new int[3 * tris], ni = new int[3 * tris];
        int o = 0;
        for (int k = 0; k < n; k++) {
            int k1 = (k + 1) % n;
            if (side) {
                ci[o] = k; ni[o++] = k;
                ci[o] = n + k; ni[o++] = k;
                ci[o] = n + k1; ni[o++] = k1;
                ci[o] = k; ni[o++] = k;
                ci[o] = n + k1; ni[o++] = k1;
                ci[o] = k1; ni[o++] = k1;
            }
            if (top) {
                ci[o] = topC; ni[o++] = n;
                ci[o] = k; ni[o++] = n;
                ci[o] = k1; ni[o++] = n;
            }
            if (bottom) {
                ci[o] = botC; ni[o++] = n + 1;
                ci[o] = n + k1; ni[o++] = n + 1;
                ci[o] = n + k; ni[o++] = n + 1;
            }
        }
        return mesh(p, ci, nor, ni);
    }

    /** Cone with base radius rb and height h (apex at +h/2); each part optional. Null if none. */
    static TriGeometry cone(double rb, double h, int n, boolean side, boolean bottom) {
        if (!side && !bottom) return null;
        double y = h / 2;
        double len = Math.hypot(h, rb);
        double radial = len > 0 ? h / len : 0, up = len > 0 ? rb / len : 1;
        int apex = 0, center = n + 1;
        double[] p = new double[3 * (n + 2)];
        // normals: n at ring vertices, n at the apex (mid-angle), 1 down
        float[] nor = new float[3 * (2 * n + 1)];
        p[1] = y;
        for (int k = 0; k < n; k++) {
            double ph = 2 * Math.PI * k / n;
            double ph2 = 2 * Math.PI * (k + 0.5) / n;
            p[3 * (1 + k)] = rb * Math.sin(ph); p[3 * (1 + k) + 1] = -y; p[3 * (1 + k) + 2] = rb * Math.cos(ph);
            nor[3 * k] = (float) (radial * Math.sin(ph)); nor[3 * k + 1] = (float) up; nor[3 * k + 2] = (float) (radial * Math.cos(ph));
            nor[3 * (n + k)] = (float) (radial * Math.sin(ph2)); nor[3 * (n + k) + 1] = (float) up;
            nor[3 * (n + k) + 2] = (float) (radial * Math.cos(ph2));
        }
        p[3 * center + 1] = -y;
        nor[3 * 2 * n + 1] = -1;
        int tris = (side ? n : 0) + (bottom ? n : 0);
        int[] ci = new int[3 * tris], ni = new int[3 * tris];
        int o = 0;
        for (int k = 0; k < n; k++) {
            int k1 = (k + 1) % n;
            if (side) {
                ci[o] = apex; ni[o++] = n + k;
                ci[o] = 1 + k; ni[o++] = k;
                ci[o] = 1 + k1; ni[o++] = k1;
            }
            if (bottom) {
                ci[o] = center; ni[o++] = 2 * n;
                ci[o] = 1 + k1; ni[o++] = 2 * n;
                ci[o] = 1 + k; ni[o++] = 2 * n;
            }
        }
        return mesh(p, ci, nor, ni);
    }

    private static TriGeometry mesh(double[] points, int[] coordIndex, float[] normals, int[] normalIndex) {
        TriGeometry g = new TriGeometry();
        g.dpoints = points;
        g.coordIndex = coordIndex;
        g.normals = normals;
        g.normalIndex = normalIndex;
        return g;
    }
}
