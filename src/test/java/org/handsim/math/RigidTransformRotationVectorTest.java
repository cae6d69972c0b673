package org.handsim.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** {@link RigidTransform#rotationVector()} against {@link RigidTransform#fromPose} (Rodrigues), by hand and by round trip. */
class RigidTransformRotationVectorTest {
    static final double TOL = 1e-12;

    @Test
    void handWorkedQuarterTurnAboutZ() {
        // Rz(90°): x → y; the matrix [0 -1 0; 1 0 0; 0 0 1] has axis z, angle π/2
        RigidTransform t = RigidTransform.of(new double[] {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0});
        double[] r = t.rotationVector();
        assertEquals(0, r[0], TOL);
        assertEquals(0, r[1], TOL);
        assertEquals(Math.PI / 2, r[2], TOL);
    }

    @Test
    void halfTurnAboutXYDiagonal() {
        // angle π about (1,1,0)/√2: R = 2uuᵀ − I = [0 1 0; 1 0 0; 0 0 −1]; v = 0, the axis comes from the symmetric part
        RigidTransform t = RigidTransform.of(new double[] {0, 1, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0});
        double[] r = t.rotationVector();
        double s = Math.PI / Math.sqrt(2);
        assertEquals(Math.PI, Math.sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]), TOL);
        // ±u both describe the half turn; the result is one of them
        assertEquals(Math.abs(s), Math.abs(r[0]), TOL);
        assertEquals(r[0], r[1], TOL);
        assertEquals(0, r[2], TOL);
    }

    @Test
    void identityIsZero() {
        double[] r = RigidTransform.IDENTITY.rotationVector();
        assertEquals(0, r[0]);
        assertEquals(0, r[1]);
        assertEquals(0, r[2]);
    }

    /** Random axes, angles over (0, π] including near 0 and near π: fromPose(rotationVector(R)) = R. */
    @Test
    void roundTripRebuildsTheMatrix() {
        SplittableRandom rnd = new SplittableRandom(345);
        double[] angles = new double[2000];
        for (int i = 0; i < angles.length; i++) {
            angles[i] = i % 4 == 0 ? Math.PI - 1e-9 * rnd.nextDouble() : i % 4 == 1 ? 1e-7 * rnd.nextDouble() : Math.PI * rnd.nextDouble();
        }
        angles[0] = Math.PI;
        for (double ang : angles) {
            double[] u = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double l = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            RigidTransform t = RigidTransform.fromPose(0, 0, 0, u[0] / l * ang, u[1] / l * ang, u[2] / l * ang);
            double[] r = t.rotationVector();
            assertTrue(Math.sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) <= Math.PI + 1e-15);
            RigidTransform back = RigidTransform.fromPose(0, 0, 0, r[0], r[1], r[2]);
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 3; col++) assertEquals(t.get(row, col), back.get(row, col), 1e-9, "angle " + ang);
            }
        }
    }
}
