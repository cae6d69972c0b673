package org.handsim.hold;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.handsim.grasp.GraspAssessment;
import org.junit.jupiter.api.Test;

/**
 * The squeeze a freed grasp keeps, against cases solved by hand: the balanced forces nearest
 * the closing's (least squares over the cones, DESIGN.md decision 5's metric).
 */
class BalancedPreloadTest {
    static GraspAssessment.Contact contact(double[] p, double[] n, double[] f) {
        return new GraspAssessment.Contact(1, 3, p, n, f);
    }

    @Test
    void twoOpposedContactsMeetHalfWay() {
        // 10 N and 6 N squeezing along x through the centre: nearest equal and opposite pair, 8 N each
        // (minimise (a − 10)² + (b − 6)² with a = b)
        double[] f = BalancedPreload.of(List.of(
            contact(new double[] {-0.03, 0, 0}, new double[] {1, 0, 0}, new double[] {10, 0, 0}),
            contact(new double[] {0.03, 0, 0}, new double[] {-1, 0, 0}, new double[] {-6, 0, 0})), new double[3], 0.5);
        assertEquals(8, f[0], 1e-6);
        assertEquals(-8, f[3], 1e-6);
        for (int i : new int[] {1, 2, 4, 5}) assertEquals(0, f[i], 1e-6);
    }

    @Test
    void contactsThatCannotSqueezeKeepNothing() {
        // two contacts pushing the same way cannot balance each other: nothing is kept
        double[] f = BalancedPreload.of(List.of(
            contact(new double[] {-0.03, 0, 0}, new double[] {1, 0, 0}, new double[] {5, 0, 0}),
            contact(new double[] {-0.03, 0.02, 0}, new double[] {1, 0, 0}, new double[] {5, 0, 0})), new double[3], 0.5);
        for (double v : f) assertEquals(0, v, 1e-6);
    }

    @Test
    void anUnbalancedTwistIsLeftOut() {
        double[] f = BalancedPreload.of(List.of(
            contact(new double[] {0, -0.04, 0}, new double[] {0, 1, 0}, new double[] {0.5, 7, 0}),
            contact(new double[] {0, 0.04, 0}, new double[] {0, -1, 0}, new double[] {-0.5, -7, 0})), new double[3], 0.5);
        // the tangential 0.5 N make a torque 2·0.5·0.04 about z: not balanced; the nearest balanced pair drops it
        assertEquals(0, f[0], 1e-6);
        assertEquals(7, f[1], 1e-6);
        assertEquals(-7, f[4], 1e-6);
    }

    @Test
    void aFrictionlessWrapKeepsItsSqueeze() {
        // three frictionless contacts 120° apart round an axis along x, pushing towards it with
        // 10, 10 and 4 N: nearest balanced triple (a, b, c) with f = Σ a_i n_i = 0 in the plane
        // forces a = b = c; least squares (a−10)² + (b−10)² + (c−4)² gives 8 N each. The rows along
        // the axis and the torque rows are all zeros (the forces meet on the axis: rows ojAlgo's
        // solver stops at zero on when they are left in).
        double[][] n = new double[3][];
        List<GraspAssessment.Contact> cs = new java.util.ArrayList<>();
        double[] given = {10, 10, 4};
        for (int i = 0; i < 3; i++) {
            double a = 2 * Math.PI * i / 3;
            n[i] = new double[] {0, -Math.cos(a), -Math.sin(a)};
            double[] p = {0, 0.04 * Math.cos(a), 0.04 * Math.sin(a)};
            cs.add(contact(p, n[i], new double[] {0, given[i] * n[i][1], given[i] * n[i][2]}));
        }
        double[] f = BalancedPreload.of(cs, new double[3], 0);
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) assertEquals(8 * n[i][k], f[3 * i + k], 1e-6, "contact " + i + " component " + k);
        }
    }
}
