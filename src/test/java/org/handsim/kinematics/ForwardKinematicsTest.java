package org.handsim.kinematics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Forward kinematics against values derived by hand.
 *
 * <p>Derivation (Table I, standard DH, A1 = 0.050, A2 = 0.070, A3 = 0.056 m, Φ2 = 2.46°,
 * Φ3 = 50°). Row 1 has α = 90°, so with θk1 = 0: o1 = (A1, 0, 0) and the joint-2 axis z1 =
 * (0, −1, 0); links 2 and 3 then lie in the x–z plane of {k0}. With the DH angles φ2 = θ2 + Φ2,
 * φ3 = θ3 + Φ3: o2 = o1 + A2 (cos φ2, 0, sin φ2), o3 = o2 + A3 (cos(φ2+φ3), 0, sin(φ2+φ3)).
 * The poses below pick joint angles that make φ2, φ3 round so the origins are exact numbers:
 * <pre>
 *  pose  θ2       θ3      φ2   φ3   o2               o3 (fingertip)
 *  A    −2.46°   −50°     0    0    (0.120, 0, 0)    (0.176, 0, 0)        stretched
 *  B    87.54°   −50°     90   0    (0.050, 0, 0.070) (0.050, 0, 0.126)   pointing up
 *  C    87.54°    40°     90   90   (0.050, 0, 0.070) (−0.006, 0, 0.070)  hooked back
 *  D    27.54°    10°     30   60   (0.05+0.07·√3/2, 0, 0.035) (same x, 0, 0.091)
 *  E    −2.46°    40°     0    90   (0.120, 0, 0)    (0.120, 0, 0.056)
 * </pre>
 * A spread θk1 = ±90° turns (x, 0, z) into (0, ±x, z).
 */
class ForwardKinematicsTest {
    private static final double TOL = 1e-15;
    private static final double D = Math.toRadians(1);
    private static final double S3 = Math.sqrt(3) / 2;

    /** {θ2, θ3} and the expected o2, o3 in the finger plane (x, z) for θk1 = 0. */
    private static final double[][] POSES = {
        {-2.46 * D, -50 * D, 0.120, 0, 0.176, 0},
        {87.54 * D, -50 * D, 0.050, 0.070, 0.050, 0.126},
        {87.54 * D, 40 * D, 0.050, 0.070, -0.006, 0.070},
        {27.54 * D, 10 * D, 0.05 + 0.07 * S3, 0.035, 0.05 + 0.07 * S3, 0.091},
        {-2.46 * D, 40 * D, 0.120, 0, 0.120, 0.056},
    };

    private static double[] origin(double[] frames, int j) {
        return new double[] {frames[12 * j + 3], frames[12 * j + 7], frames[12 * j + 11]};
    }

    @Test
    void fivePosesPerFingerByHand() {
        for (int k = 1; k <= 3; k++) {
            FingerKinematics fk = FingerKinematics.of(k);
            double spread = k == 1 ? -90 * D : k == 2 ? 90 * D : 0;
            double sign = k == 1 ? -1 : 1;
            for (double[] p : POSES) {
                double[] f = new double[FingerKinematics.FRAMES_LENGTH];
                fk.frames(new double[] {spread, p[0], p[1]}, f);
                assertArrayEquals(new double[] {0, 0, 0}, origin(f, 0), TOL);
                if (k == 3) {
                    assertArrayEquals(new double[] {0.050, 0, 0}, origin(f, 1), TOL);
                    assertArrayEquals(new double[] {p[2], 0, p[3]}, origin(f, 2), TOL);
                    assertArrayEquals(new double[] {p[4], 0, p[5]}, origin(f, 3), TOL);
                } else {
                    assertArrayEquals(new double[] {0, sign * 0.050, 0}, origin(f, 1), TOL);
                    assertArrayEquals(new double[] {0, sign * p[2], p[3]}, origin(f, 2), TOL);
                    assertArrayEquals(new double[] {0, sign * p[4], p[5]}, origin(f, 3), TOL);
                }
            }
        }
    }

    @Test
    void jointTwoAxisIsMinusYAtZeroSpread() {
        double[] f = new double[48];
        FingerKinematics.of(3).frames(new double[] {0, 0.3, 0.2}, f);
        assertArrayEquals(new double[] {0, -1, 0}, new double[] {f[12 + 2], f[12 + 6], f[12 + 10]}, TOL);
    }

    /**
     * Palm placement (BH8 manual Table 9): {k0} at (r·Aw, 0, Dw), turned by −(π/2)·j about z.
     * Fingers 1, 2 (j = 1): k0's x axis is −y of the palm, its y axis is +x: a point (x, y, z)
     * of {k0} is (r·Aw + y, −x, Dw + z) in {P}. Finger 3 (j = −1): (−y, x, Dw + z).
     */
    @Test
    void palmFrameByHand() {
        double[] f = new double[48];
        double[] p = POSES[3];
        FingerKinematics.of(1).framesInPalm(new double[] {0, p[0], p[1]}, f);
        assertArrayEquals(new double[] {-0.025, -p[4], 0.084 + p[5]}, origin(f, 3), TOL);
        FingerKinematics.of(2).framesInPalm(new double[] {0, p[0], p[1]}, f);
        assertArrayEquals(new double[] {0.025, -p[4], 0.084 + p[5]}, origin(f, 3), TOL);
        FingerKinematics.of(3).framesInPalm(new double[] {0, p[0], p[1]}, f);
        assertArrayEquals(new double[] {0, p[4], 0.084 + p[5]}, origin(f, 3), TOL);
        // fingers 1 and 2 side by side on -y, finger 3 opposite on +y
        FingerKinematics.of(1).framesInPalm(new double[] {0, 0, 0}, f);
        assertEquals(-0.050, f[12 + 7], TOL);
    }

    @Test
    void framesAgreeWithTheClosedFormFingertip() {
        Random rnd = new Random(345);
        double[] f = new double[48];
        double[] tip = new double[3];
        for (int k = 1; k <= 3; k++) {
            FingerKinematics fk = FingerKinematics.of(k);
            for (int i = 0; i < 10_000; i++) {
                double[] j = {k == 3 ? 0 : (rnd.nextDouble() - 0.5) * 2 * Math.PI, rnd.nextDouble() * 2.5, rnd.nextDouble() * 1.7};
                fk.frames(j, f);
                fk.fingertip(j, tip);
                assertArrayEquals(origin(f, 3), tip, 1e-15);
            }
        }
    }

    @Test
    void rotationBlocksStayOrthonormal() {
        Random rnd = new Random(7);
        double[] f = new double[48];
        for (int i = 0; i < 1000; i++) {
            FingerKinematics.of(2).framesInPalm(new double[] {rnd.nextDouble() * 3, rnd.nextDouble() * 2.4, rnd.nextDouble() * 1.7}, f);
            for (int j = 0; j < 4; j++) {
                for (int a = 0; a < 3; a++) {
                    for (int b = 0; b < 3; b++) {
                        double dot = 0;
                        for (int r = 0; r < 3; r++) dot += f[12 * j + 4 * r + a] * f[12 * j + 4 * r + b];
                        assertEquals(a == b ? 1 : 0, dot, 1e-14);
                    }
                }
            }
        }
    }

    @Test
    void badJointsAreRefused() {
        FingerKinematics fk3 = FingerKinematics.of(3);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> fk3.fingertip(new double[] {0.1, 0, 0}));
        assertEquals("finger 3 has no spread: t1 must be 0, got 0.1", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> FingerKinematics.of(1).fingertip(new double[] {0, Double.NaN, 0}));
    }
}
