package org.handsim.math;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class CholeskyTest {
    private static final double TOL = 1e-14;

    @Test
    void workedExampleFromTheJavadoc() {
        double[] a = {4, 2, 2, 3};
        assertTrue(Cholesky.decompose(a, 2));
        assertEquals(2, a[0], TOL);
        assertEquals(1, a[2], TOL);
        assertEquals(Math.sqrt(2), a[3], TOL);
        double[] b = {2, 1};
        Cholesky.solve(a, 2, b);
        assertArrayEquals(new double[] {0.5, 0}, b, TOL);
    }

    @Test
    void oneByOne() {
        double[] a = {9};
        assertTrue(Cholesky.decompose(a, 1));
        assertEquals(3.0, a[0]);
        double[] b = {6};
        Cholesky.solve(a, 1, b);
        assertEquals(2.0 / 3.0, b[0], TOL);
    }

    @Test
    void randomSpdMatricesSolveToTheirRightHandSide() {
        Random r = new Random(345);
        for (int n = 1; n <= 6; n++) {
            for (int trial = 0; trial < 50; trial++) {
                // A = B·Bᵀ + n·E is symmetric positive definite
                double[] bm = new double[n * n];
                for (int i = 0; i < n * n; i++) bm[i] = r.nextGaussian();
                double[] a = new double[n * n];
                for (int i = 0; i < n; i++) {
                    for (int k = 0; k < n; k++) {
                        double s = i == k ? n : 0;
                        for (int j = 0; j < n; j++) s += bm[i * n + j] * bm[k * n + j];
                        a[i * n + k] = s;
                    }
                }
                double[] x = new double[n];
                for (int i = 0; i < n; i++) x[i] = r.nextGaussian();
                double[] b = new double[n];
                for (int i = 0; i < n; i++) {
                    for (int k = 0; k < n; k++) b[i] += a[i * n + k] * x[k];
                }
                double[] l = a.clone();
                assertTrue(Cholesky.decompose(l, n));
                // L·Lᵀ reproduces A
                for (int i = 0; i < n; i++) {
                    for (int k = 0; k <= i; k++) {
                        double s = 0;
                        for (int j = 0; j <= k; j++) s += l[i * n + j] * l[k * n + j];
                        assertEquals(a[i * n + k], s, 1e-12 * Math.abs(a[i * n + i]));
                    }
                }
                Cholesky.solve(l, n, b);
                assertArrayEquals(x, b, 1e-10);
            }
        }
    }

    @Test
    void notPositiveDefiniteIsAnOutcome() {
        assertFalse(Cholesky.decompose(new double[] {1, 2, 2, 1}, 2), "indefinite");
        assertFalse(Cholesky.decompose(new double[] {0}, 1), "zero");
        assertFalse(Cholesky.decompose(new double[] {-1}, 1), "negative");
        assertFalse(Cholesky.decompose(new double[] {1, 1, 1, 1}, 2), "singular");
        assertFalse(Cholesky.decompose(new double[] {1, 1, 1, 1 + 1e-14}, 2), "singular to working precision");
        assertTrue(Cholesky.decompose(new double[] {1, 1, 1, 1 + 1e-9}, 2), "ill-conditioned but definite");
        assertFalse(Cholesky.decompose(new double[] {Double.NaN}, 1), "NaN");
        assertFalse(Cholesky.decompose(new double[] {1, Double.NaN, Double.NaN, 1}, 2), "NaN off the diagonal");
        assertFalse(Cholesky.decompose(new double[] {Double.POSITIVE_INFINITY}, 1), "infinite");
    }

    @Test
    void misuseNamesTheProblem() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Cholesky.decompose(new double[3], 2));
        assertTrue(e.getMessage().contains("needs 4"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Cholesky.decompose(new double[1], 0));
        assertThrows(IllegalArgumentException.class, () -> Cholesky.solve(new double[] {1, 0, 0, 1}, 2, new double[1]));
    }
}
