package org.handsim.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.collision.TestMeshes;
import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;
import org.junit.jupiter.api.Test;

/**
 * {@link BodyStepper} on a box against an analytic plane (the contacts at the box's eight
 * corners within the margin, their gaps measured from the plane every step): resting, the
 * incline on both sides of tan a = μ, against the closed forms.
 */
class BodyStepperTest {
    static final double G = 9.80665, H = 0.001, MARGIN = 0.001;
    static final double HX = 0.03, HY = 0.02, HZ = 0.01;
    static final MassProperties BOX = MassProperties.ofSolid(TestMeshes.box(HX, HY, HZ, 1), 1000);

    /** A box resting on a level plane for 10 s: drift below 0.1 mm and 0.1°. */
    @Test
    void aBoxRestsOnAPlane() {
        double[] drift = run(0, 0.5, 10.0);
        assertTrue(drift[0] < 1e-4 && drift[1] < Math.toRadians(0.1), "drift " + drift[0] + " m, " + drift[1] + " rad");
        System.out.printf("rest 10 s: %.3e m, %.3e rad%n", drift[0], drift[1]);
    }

    /**
     * A box on a plane tilted by a: it stays when tan a &lt; μ, else slides with
     * g(sin a − μ cos a); displacement after 0.5 s within 2 % of ½at², both sides of the
     * threshold (μ = 0.5: the threshold is 26.57°).
     */
    @Test
    void aBoxOnAnInclineStaysOrSlidesAsCoulombSays() {
        double mu = 0.5;
        for (double deg : new double[] {10, 25, 28, 35}) {
            double a = Math.toRadians(deg);
            double[] r = run(a, mu, 0.5);
            double want = Math.tan(a) < mu ? 0 : 0.5 * G * (Math.sin(a) - mu * Math.cos(a)) * 0.25;
            System.out.printf("incline %.0f°: moved %.6e m along the slope, want %.6e%n", deg, r[2], want);
            if (want == 0) {
                assertTrue(Math.abs(r[2]) < 1e-6, deg + "°: moved " + r[2]);
            } else {
                assertEquals(want, r[2], 0.02 * want, deg + "°");
            }
        }
    }

    /**
     * Runs a box on the plane through the origin tilted by a about y, for t seconds;
     * returns {displacement of the centre, rotation angle, displacement down the slope}.
     */
    static double[] run(double a, double mu, double t) {
        double[] n = {Math.sin(a), 0, Math.cos(a)};          // the plane's normal
        // the box lies on the plane, its bottom face on it: turned by a about y, centre HZ above
        RigidTransform pose = RigidTransform.fromPose(HZ * n[0], 0, HZ * n[2], 0, a, 0);
        FreeBody b = new FreeBody(BOX, pose);
        BodyStepper s = new BodyStepper(b);
        BodyContacts c = new BodyContacts();
        double[] x0 = b.position(new double[3]), q0 = b.orientation(new double[4]);
        double[] f = {0, 0, -G * b.mass()}, tau = new double[3];
        double[] m = new double[12], p = new double[3];
        int steps = (int) Math.round(t / H);
        for (int i = 0; i < steps; i++) {
            c.clear();
            b.worldFromMesh(m, 0);
            for (int sx = -1; sx <= 1; sx += 2) {
                for (int sy = -1; sy <= 1; sy += 2) {
                    for (int sz = -1; sz <= 1; sz += 2) {
                        double[] local = {sx * HX, sy * HY, sz * HZ};
                        for (int k = 0; k < 3; k++) p[k] = m[4 * k] * local[0] + m[4 * k + 1] * local[1] + m[4 * k + 2] * local[2] + m[4 * k + 3];
                        double gap = p[0] * n[0] + p[1] * n[1] + p[2] * n[2];
                        if (gap <= MARGIN) c.add(p, n, gap, mu, null, 0);
                    }
                }
            }
            ContactSolver.Outcome o = s.step(H, f, tau, c);
            assertEquals(ContactSolver.Outcome.CONVERGED, o, "step " + i);
        }
        double[] x = b.position(new double[3]);
        double dx = x[0] - x0[0], dy = x[1] - x0[1], dz = x[2] - x0[2];
        double[] down = {Math.cos(a), 0, -Math.sin(a)};         // in the plane, downhill
        return new double[] {Math.sqrt(dx * dx + dy * dy + dz * dz), Quaternion.angleBetween(q0, 0, b.orientation(new double[4]), 0),
            dx * down[0] + dy * down[1] + dz * down[2]};
    }
}
