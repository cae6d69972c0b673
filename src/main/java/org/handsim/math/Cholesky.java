package org.handsim.math;

/**
 * Cholesky factorisation {@code A = L·Lᵀ} of a small dense symmetric positive-definite matrix,
 * and the triangular solves that go with it: the way the dynamics solves
 * {@code D(Θ)·Θ̈ = τ − H − C} without forming {@code D⁻¹} (Golub–Van Loan, Matrix Computations,
 * 4th ed., Algorithm 4.2.1, the "gaxpy" Cholesky).
 *
 * <p>Matrices are {@code n×n}, row-major in a flat {@code double[]} of length at least
 * {@code n·n}. {@link #decompose} works in place: on success the lower triangle (diagonal
 * included) holds L; the strict upper triangle is left as it was and never read again.
 *
 * <p><b>Failure is an outcome</b> (docs/STYLE.md, item 8, after EJML's {@code decompose} returning
 * false): a matrix that is not numerically positive definite makes {@link #decompose} return
 * {@code false}. "Numerically" means every pivot {@code d_j = a_jj − Σ l_jk²} must exceed
 * {@link #PIVOT_TOLERANCE} times the original diagonal entry {@code a_jj}: a pivot that small
 * means the column is (to working precision) a combination of the earlier ones, and solving
 * with it would return accelerations dominated by rounding. NaN or infinite entries fail too.
 *
 * <p>Worked example: {@code A = [[4, 2], [2, 3]]} gives {@code L = [[2, 0], [1, √2]]}; solving
 * {@code A·x = (2, 1)} gives {@code x = (0.5, 0)}.
 *
 * <p>All methods are static and allocation-free; thread-safe as long as callers do not share
 * arrays.
 */
public final class Cholesky {
    /** A pivot at most this fraction of its original diagonal entry counts as "not positive definite". */
    public static final double PIVOT_TOLERANCE = 1e-12;

    private Cholesky() {}

    /**
     * Factorises {@code a} (n×n, row-major, symmetric: only the lower triangle is read) in
     * place into its Cholesky factor L (lower triangle).
     *
     * @return true on success; false if {@code a} is not numerically positive definite (then
     *         the lower triangle of {@code a} holds partial results: refill before reuse)
     */
    public static boolean decompose(double[] a, int n) {
        checkSize(a, n);
        for (int j = 0; j < n; j++) {
            int rj = j * n;
            double ajj = a[rj + j];
            double d = ajj;
            for (int k = 0; k < j; k++) d -= a[rj + k] * a[rj + k];
            if (!(d > PIVOT_TOLERANCE * ajj) || !(d < Double.POSITIVE_INFINITY)) return false;
            double ljj = Math.sqrt(d);
            a[rj + j] = ljj;
            double inv = 1.0 / ljj;
            for (int i = j + 1; i < n; i++) {
                int ri = i * n;
                double s = a[ri + j];
                for (int k = 0; k < j; k++) s -= a[ri + k] * a[rj + k];
                if (Double.isNaN(s)) return false;
                a[ri + j] = s * inv;
            }
        }
        return true;
    }

    /**
     * Solves {@code L·Lᵀ·x = b} in place ({@code b} becomes x) with the factor from
     * {@link #decompose}: forward substitution with L, then back substitution with Lᵀ.
     */
    public static void solve(double[] l, int n, double[] b) {
        checkSize(l, n);
        if (b.length < n) throw new IllegalArgumentException("right-hand side needs " + n + " entries, got " + b.length);
        for (int i = 0; i < n; i++) {
            int ri = i * n;
            double s = b[i];
            for (int k = 0; k < i; k++) s -= l[ri + k] * b[k];
            b[i] = s / l[ri + i];
        }
        for (int i = n - 1; i >= 0; i--) {
            double s = b[i];
            for (int k = i + 1; k < n; k++) s -= l[k * n + i] * b[k];
            b[i] = s / l[i * n + i];
        }
    }

    private static void checkSize(double[] a, int n) {
        if (n < 1) throw new IllegalArgumentException("matrix size n must be >= 1, got " + n);
        if (a.length < n * n) throw new IllegalArgumentException("an " + n + "x" + n + " matrix needs " + n * n + " entries, got " + a.length);
    }
}
