package org.handsim.grasp;

/**
 * The primitive wrenches of a grasp (the L1 grasp wrench space, GraspIt!'s): for every contact
 * and every edge f of its linearised friction cone ({@link FrictionCone}), the 6-vector
 * <pre>  w = (f, (p − c) × f / R)</pre>
 * with c the torque origin (the object's centroid in the simulator) and R the characteristic
 * length (the object's largest centroid-to-vertex distance, GraspIt!'s convention), so force
 * and torque parts are both in newtons. Layout: wrench j occupies {@code w[6j .. 6j+5]},
 * contact i's edges are wrenches i·m .. i·m + m − 1.
 */
public final class GraspWrenches {
    private GraspWrenches() {}

    /**
     * @param n       number of contacts
     * @param points  3·n contact points, metres (any frame, the same as c and the normals)
     * @param normals 3·n contact normals: the direction of the force the finger applies,
     *                into the object (need not be unit; normalised)
     * @param mu      Coulomb coefficient μ ≥ 0
     * @param m       cone edges ≥ 1
     * @param c       torque origin, metres
     * @param r       characteristic length R &gt; 0, metres
     * @return 6·n·m values
     */
    public static double[] of(int n, double[] points, double[] normals, double mu, int m, double[] c, double r) {
        if (!(r > 0) || !Double.isFinite(r)) {
            throw new IllegalArgumentException("characteristic length R must be a finite number > 0, got " + r);
        }
        double[] w = new double[6 * n * m];
        double[] f = new double[3 * m];
        for (int i = 0; i < n; i++) {
            FrictionCone.edges(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2], mu, m, f, 0);
            double rx = points[3 * i] - c[0], ry = points[3 * i + 1] - c[1], rz = points[3 * i + 2] - c[2];
            for (int e = 0; e < m; e++) {
                double fx = f[3 * e], fy = f[3 * e + 1], fz = f[3 * e + 2];
                int o = 6 * (i * m + e);
                w[o] = fx; w[o + 1] = fy; w[o + 2] = fz;
                w[o + 3] = (ry * fz - rz * fy) / r;
                w[o + 4] = (rz * fx - rx * fz) / r;
                w[o + 5] = (rx * fy - ry * fx) / r;
            }
        }
        return w;
    }
}
