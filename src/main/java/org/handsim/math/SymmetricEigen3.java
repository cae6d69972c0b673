package org.handsim.math;

/**
 * Eigenvalues and eigenvectors of a symmetric 3×3 matrix by cyclic Jacobi rotations
 * (Golub–Van Loan, <i>Matrix Computations</i>, 4th ed., §8.5.2, Algorithm 8.5.3): each sweep
 * zeroes the three off-diagonal entries in turn with a plane rotation; the off-diagonal norm
 * falls quadratically once small, so a handful of sweeps reach rounding level. The vectors come
 * out orthonormal to rounding and as a right-handed frame.
 *
 * <p>Worked example: {@code [[2, 1, 0], [1, 2, 0], [0, 0, 5]]} has eigenvalues 1, 3, 5 with
 * vectors (1, −1, 0)/√2, (1, 1, 0)/√2, (0, 0, 1).
 *
 * <p>Static; thread-safe as long as callers do not share arrays.
 */
public final class SymmetricEigen3 {
    private SymmetricEigen3() {}

    /**
     * Decomposes {@code a} (9 values, row-major, symmetric: the upper triangle is read) into
     * {@code values} (3, ascending) and {@code vectors} (9, row-major: column j is the unit
     * eigenvector of {@code values[j]}, the columns a right-handed frame), so that
     * {@code a = V·diag(values)·Vᵀ}.
     *
     * @return false if {@code a} has a non-finite entry (outputs then undefined)
     */
    public static boolean decompose(double[] a, double[] values, double[] vectors) {
        double a00 = a[0], a01 = a[1], a02 = a[2], a11 = a[4], a12 = a[5], a22 = a[8];
        if (!Double.isFinite(a00 + a01 + a02 + a11 + a12 + a22)) return false;
        double[] v = vectors;
        v[0] = 1; v[1] = 0; v[2] = 0; v[3] = 0; v[4] = 1; v[5] = 0; v[6] = 0; v[7] = 0; v[8] = 1;
        double[] m = {a00, a01, a02, a01, a11, a12, a02, a12, a22};
        for (int sweep = 0; sweep < 50; sweep++) {
            double off = m[1] * m[1] + m[2] * m[2] + m[5] * m[5];
            double diag = m[0] * m[0] + m[4] * m[4] + m[8] * m[8];
            if (off <= 1e-34 * diag || off == 0) break;
            rotate(m, v, 0, 1);
            rotate(m, v, 0, 2);
            rotate(m, v, 1, 2);
        }
        values[0] = m[0]; values[1] = m[4]; values[2] = m[8];
        // ascending, columns along
        for (int i = 0; i < 2; i++) {
            for (int j = 0; j < 2 - i; j++) {
                if (values[j] > values[j + 1]) {
                    double t = values[j]; values[j] = values[j + 1]; values[j + 1] = t;
                    for (int r = 0; r < 3; r++) {
                        double s = v[3 * r + j]; v[3 * r + j] = v[3 * r + j + 1]; v[3 * r + j + 1] = s;
                    }
                }
            }
        }
        // right-handed: third column = first × second
        double cx = v[3] * v[7] - v[6] * v[4], cy = v[6] * v[1] - v[0] * v[7], cz = v[0] * v[4] - v[3] * v[1];
        if (cx * v[2] + cy * v[5] + cz * v[8] < 0) {
            v[2] = -v[2]; v[5] = -v[5]; v[8] = -v[8];
        }
        return true;
    }

    /** One Jacobi rotation in the (p, q) plane zeroing m[p][q]; accumulates V ← V·J. */
    private static void rotate(double[] m, double[] v, int p, int q) {
        double apq = m[3 * p + q];
        if (apq == 0) return;
        double app = m[3 * p + p], aqq = m[3 * q + q];
        double theta = (aqq - app) / (2 * apq);
        double t = Math.signum(theta) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
        if (theta == 0) t = 1;
        double c = 1 / Math.sqrt(t * t + 1), s = t * c;
        // m ← Jᵀ m J with J the rotation in the (p, q) plane
        for (int k = 0; k < 3; k++) {
            double mkp = m[3 * k + p], mkq = m[3 * k + q];
            m[3 * k + p] = c * mkp - s * mkq;
            m[3 * k + q] = s * mkp + c * mkq;
        }
        for (int k = 0; k < 3; k++) {
            double mpk = m[3 * p + k], mqk = m[3 * q + k];
            m[3 * p + k] = c * mpk - s * mqk;
            m[3 * q + k] = s * mpk + c * mqk;
        }
        m[3 * p + q] = 0;
        m[3 * q + p] = 0;
        for (int k = 0; k < 3; k++) {
            double vkp = v[3 * k + p], vkq = v[3 * k + q];
            v[3 * k + p] = c * vkp - s * vkq;
            v[3 * k + q] = s * vkp + c * vkq;
        }
    }
}
