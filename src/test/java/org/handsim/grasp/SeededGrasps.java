package org.handsim.grasp;

import java.util.Random;

/** Seeded random contact sets for the grasp tests: contacts on a sphere, a box or a cylinder, normals into the object. */
final class SeededGrasps {
    private SeededGrasps() {}

    /** One set: n contacts, their points and normals (3 values each). */
    record Contacts(int n, double[] points, double[] normals) {}

    /** n contacts on object kind (0 sphere r 0.04, 1 box 0.1×0.06×0.04, 2 cylinder r 0.035 h 0.12), normals tilted by up to ~tilt rad. */
    static Contacts on(int kind, int n, double tilt, Random rnd) {
        double[] p = new double[3 * n], q = new double[3 * n];
        for (int i = 0; i < n; i++) {
            double[] pt = new double[3], nm = new double[3];
            if (kind == 0) {
                double x = rnd.nextGaussian(), y = rnd.nextGaussian(), z = rnd.nextGaussian();
                double l = Math.sqrt(x * x + y * y + z * z);
                pt[0] = 0.04 * x / l; pt[1] = 0.04 * y / l; pt[2] = 0.04 * z / l;
                nm[0] = -x / l; nm[1] = -y / l; nm[2] = -z / l;
            } else if (kind == 1) {
                double[] h = {0.05, 0.03, 0.02};
                int f = rnd.nextInt(6), axis = f / 2;
                double sign = f % 2 == 0 ? 1 : -1;
                for (int k = 0; k < 3; k++) pt[k] = (2 * rnd.nextDouble() - 1) * h[k];
                pt[axis] = sign * h[axis];
                nm[axis] = -sign;
            } else {
                double t = 2 * Math.PI * rnd.nextDouble();
                pt[0] = 0.035 * Math.cos(t); pt[1] = 0.035 * Math.sin(t); pt[2] = 0.06 * (2 * rnd.nextDouble() - 1);
                nm[0] = -Math.cos(t); nm[1] = -Math.sin(t);
            }
            for (int k = 0; k < 3; k++) {
                p[3 * i + k] = pt[k];
                q[3 * i + k] = nm[k] + tilt * rnd.nextGaussian();
            }
        }
        return new Contacts(n, p, q);
    }

    /** The wrenches of a set about the origin with R = 0.06 m. */
    static double[] wrenches(Contacts c, double mu, int m) {
        return GraspWrenches.of(c.n(), c.points(), c.normals(), mu, m, new double[3], 0.06);
    }
}
