package org.handsim.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.handsim.collision.TestMeshes;
import org.handsim.math.RigidTransform;
import org.junit.jupiter.api.Test;

/** {@link TriangleMesh#secondMoments()} against boxes integrated by hand. */
class SecondMomentsTest {
    /**
     * A box of half extents (hx, hy, hz) centred at c: ∫x² dV = V·(hx²/3 + cx²) (the box's own
     * moment plus the shift), ∫xy dV = V·cx·cy (the box's own product is 0 by symmetry),
     * V = 8·hx·hy·hz. Subdivided faces and a rotated copy must not change the result.
     */
    @Test
    void anOffsetBoxAsIntegratedByHand() {
        double hx = 0.02, hy = 0.015, hz = 0.01;
        double cx = 0.03, cy = -0.012, cz = 0.007;
        double vol = 8 * hx * hy * hz;
        double[] expect = {
            vol * (hx * hx / 3 + cx * cx), vol * cx * cy, vol * cx * cz,
            vol * (hy * hy / 3 + cy * cy), vol * cy * cz, vol * (hz * hz / 3 + cz * cz)};
        for (int div = 1; div <= 3; div++) {
            TriangleMesh box = TestMeshes.box(hx, hy, hz, div).transformed(RigidTransform.translation(cx, cy, cz));
            double[] s = box.secondMoments();
            for (int i = 0; i < 6; i++) assertEquals(expect[i], s[i], 1e-14 * expect[0], "entry " + i + ", div " + div);
        }
    }

    /**
     * Turning a body by R turns its second moments to R·Σ·Rᵀ: checked on a box turned about a
     * random axis (the products are then far from zero).
     */
    @Test
    void secondMomentsTurnWithTheBody() {
        SplittableRandom r = new SplittableRandom(19);
        double hx = 0.02, hy = 0.015, hz = 0.01;
        TriangleMesh box = TestMeshes.box(hx, hy, hz, 2).transformed(RigidTransform.translation(0.01, 0.02, -0.005));
        double[] s0 = box.secondMoments();
        double[][] s = {{s0[0], s0[1], s0[2]}, {s0[1], s0[3], s0[4]}, {s0[2], s0[4], s0[5]}};
        for (int trial = 0; trial < 5; trial++) {
            RigidTransform t = RigidTransform.fromPose(0, 0, 0, r.nextDouble() - 0.5, r.nextDouble() - 0.5, r.nextDouble() - 0.5);
            double[] turned = box.transformed(t).secondMoments();
            double[][] rot = new double[3][3];
            for (int i = 0; i < 3; i++) {
                for (int k = 0; k < 3; k++) rot[i][k] = t.get(i, k);
            }
            int[][] idx = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
            for (int e = 0; e < 6; e++) {
                int i = idx[e][0], j = idx[e][1];
                double v = 0;
                for (int a = 0; a < 3; a++) {
                    for (int b = 0; b < 3; b++) v += rot[i][a] * s[a][b] * rot[j][b];
                }
                assertEquals(v, turned[e], 1e-14 * s0[0], "entry " + e);
            }
        }
    }
}
