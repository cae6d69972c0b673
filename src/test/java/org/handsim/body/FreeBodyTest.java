package org.handsim.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.collision.TestMeshes;
import org.handsim.dynamics.TorqueFreeRotation;
import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;
import org.junit.jupiter.api.Test;

/**
 * {@link FreeBody} without contacts against exact answers: free fall (closed form), the
 * torque-free tumble of an asymmetric box against an independent high-accuracy integration of
 * Euler's equations with quaternion kinematics (Dormand–Prince 5(4) at 1e-13), the invariants
 * it must keep, and its order.
 */
class FreeBodyTest {
    static final double G = 9.80665;
    static final MassProperties BOX = MassProperties.ofSolid(TestMeshes.box(0.05, 0.03, 0.015, 1), 800);

    /** x = x₀ + v₀t + ½gt² after 0.5 s, to 1e-9 m, at two step sizes (one that does not divide 0.5 s in binary), spinning meanwhile. */
    @Test
    void freeFallIsExact() {
        for (int n : new int[] {500, 333}) {
            double h = 0.5 / n;
            FreeBody b = new FreeBody(BOX, RigidTransform.fromPose(0.1, -0.2, 0.3, 0.2, 0.1, -0.4));
            double[] x0 = b.position(new double[3]);
            double[] v0 = {0.5, 0.2, 1.0};
            b.setVelocity(v0, new double[] {3, -1, 2});
            double[] f = {0, 0, -G * b.mass()}, tau = new double[3];
            for (int i = 0; i < n; i++) b.step(h, f, tau);
            double t = n * h;
            double[] x = b.position(new double[3]), v = b.velocity(new double[3]);
            double[] g = {0, 0, -G};
            for (int k = 0; k < 3; k++) {
                assertEquals(x0[k] + v0[k] * t + 0.5 * g[k] * t * t, x[k], 1e-9, "x[" + k + "], h = " + h);
                assertEquals(v0[k] + g[k] * t, v[k], 1e-12, "v[" + k + "], h = " + h);
            }
        }
    }

    /**
     * An asymmetric box (principal moments 1:3.4:4.2) tumbling torque-free for 2 s near its
     * unstable middle axis, at dt = 1 ms: energy and angular momentum kept to 1e-6 relative (they
     * are kept to rounding), the orientation within 1e-6 rad of Euler's equations integrated by
     * Dormand–Prince at 1e-13 (a different method on a different formulation: body angular
     * velocity and quaternion rates).
     */
    @Test
    void anAsymmetricBoxTumblesAsEulersEquationsSay() {
        double h = 1e-3;
        int n = 2000;
        double[] w0 = {0.3, 4.0, -0.5};
        FreeBody b = tumbler(w0);
        double e0 = b.kineticEnergy();
        double[] l0 = b.angularMomentum(new double[3]);
        double[] zero = new double[3];
        double worstE = 0, worstL = 0;
        for (int i = 0; i < n; i++) {
            b.step(h, zero, zero);
            double[] l = b.angularMomentum(new double[3]);
            worstE = Math.max(worstE, Math.abs(b.kineticEnergy() - e0) / e0);
            worstL = Math.max(worstL, Math.sqrt(sq(l[0] - l0[0]) + sq(l[1] - l0[1]) + sq(l[2] - l0[2])) / norm(l0));
        }
        assertTrue(worstE < 1e-6, "energy kept to " + worstE);
        assertTrue(worstL < 1e-6, "angular momentum kept to " + worstL);
        double[] ref = reference(w0, n * h);
        double err = Quaternion.angleBetween(ref, 0, b.orientation(new double[4]), 0);
        assertTrue(err < 1e-6, "orientation off Euler's equations by " + err + " rad");
        // it really tumbled: the box turned over (its orientation moved far from the start)
        assertTrue(Quaternion.angleBetween(ref, 0, start(), 0) > 1, "turned by " + Quaternion.angleBetween(ref, 0, start(), 0));
        System.out.printf("tumble 2 s at 1 ms: energy %.2e, momentum %.2e, orientation %.2e rad%n", worstE, worstL, err);
    }

    /** Fourth order (Yoshida's triple jump of a symmetric second-order map): halving the step divides the orientation error by about 16. */
    @Test
    void theFreeRotationIsFourthOrder() {
        double[] w0 = {0.3, 4.0, -0.5};
        double t = 0.5;
        double[] ref = reference(w0, t);
        double[] err = new double[3];
        int[] steps = {50, 100, 200};
        for (int s = 0; s < 3; s++) {
            FreeBody b = tumbler(w0);
            double[] zero = new double[3];
            for (int i = 0; i < steps[s]; i++) b.step(t / steps[s], zero, zero);
            err[s] = Quaternion.angleBetween(ref, 0, b.orientation(new double[4]), 0);
        }
        for (int s = 1; s < 3; s++) {
            double ratio = err[s - 1] / err[s];
            assertTrue(ratio > 13 && ratio < 19, "error ratio " + ratio + " (errors " + err[s - 1] + ", " + err[s] + ")");
        }
    }

    private static double[] start() {
        double[] q = new double[4];
        Quaternion.fromRotationVector(0.4, -0.3, 0.8, q, 0);
        return q;
    }

    private static FreeBody tumbler(double[] w0Body) {
        FreeBody b = new FreeBody(BOX, RigidTransform.fromPose(0, 0, 0, 0.4, -0.3, 0.8));
        double[] r = new double[9];
        Quaternion.toMatrix(start(), 0, r, 0);
        double[] w = new double[3];
        for (int i = 0; i < 3; i++) w[i] = r[3 * i] * w0Body[0] + r[3 * i + 1] * w0Body[1] + r[3 * i + 2] * w0Body[2];
        b.setVelocity(new double[3], w);
        return b;
    }

    /** The independent reference: Euler's equations by Dormand–Prince 5(4) at 1e-13. */
    private static double[] reference(double[] w0Body, double t) {
        return TorqueFreeRotation.orientationAfter(BOX.inertia(), BOX.inverseInertia(), w0Body, start(), t);
    }

    private static double sq(double a) { return a * a; }

    private static double norm(double[] a) { return Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
}
