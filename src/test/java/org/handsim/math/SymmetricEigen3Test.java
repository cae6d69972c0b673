package org.handsim.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** {@link SymmetricEigen3}: the worked example, and V·diag(λ)·Vᵀ = A with V orthonormal and right-handed on seeded matrices. */
class SymmetricEigen3Test {
    @Test
    void theWorkedExample() {
        double[] vals = new double[3], vecs = new double[9];
        SymmetricEigen3.decompose(new double[] {2, 1, 0, 1, 2, 0, 0, 0, 5}, vals, vecs);
        assertEquals(1, vals[0], 1e-15);
        assertEquals(3, vals[1], 1e-15);
        assertEquals(5, vals[2], 1e-15);
        double s = Math.sqrt(0.5);
        assertEquals(s, Math.abs(vecs[0]), 1e-15);
        assertEquals(-Math.signum(vecs[0]) * s, vecs[3], 1e-15);
        assertEquals(1, Math.abs(vecs[8]), 1e-15);
    }

    @Test
    void reconstructsSeededMatrices() {
        SplittableRandom r = new SplittableRandom(7);
        double[] vals = new double[3], vecs = new double[9];
        for (int n = 0; n < 200; n++) {
            double[] a = new double[9];
            for (int i = 0; i < 3; i++) {
                for (int j = i; j < 3; j++) {
                    double x = r.nextDouble() * 2 - 1;
                    a[3 * i + j] = x;
                    a[3 * j + i] = x;
                }
            }
            if (n % 10 == 0) { a[0] = a[4] = 0.5; a[1] = a[3] = 0; }   // repeated eigenvalues in a block
            SymmetricEigen3.decompose(a, vals, vecs);
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    double rec = 0, dot = 0;
                    for (int k = 0; k < 3; k++) {
                        rec += vecs[3 * i + k] * vals[k] * vecs[3 * j + k];
                        dot += vecs[3 * k + i] * vecs[3 * k + j];
                    }
                    assertEquals(a[3 * i + j], rec, 1e-14, "A[" + i + "][" + j + "], case " + n);
                    assertEquals(i == j ? 1 : 0, dot, 1e-14, "VᵀV, case " + n);
                }
            }
            double det = vecs[0] * (vecs[4] * vecs[8] - vecs[5] * vecs[7]) - vecs[1] * (vecs[3] * vecs[8] - vecs[5] * vecs[6])
                + vecs[2] * (vecs[3] * vecs[7] - vecs[4] * vecs[6]);
            assertEquals(1, det, 1e-14);
            assertFalse(vals[0] > vals[1] || vals[1] > vals[2]);
        }
        assertFalse(SymmetricEigen3.decompose(new double[] {Double.NaN, 0, 0, 0, 1, 0, 0, 0, 1}, vals, vecs));
    }
}
