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
    /**
     * A box pinched between two jaws, each a follower about a hinge L = 0.1 m below the contacts
     * pressing with τ = 0.05 N·m (so N = τ/L = 0.5 N a side), gravity along the jaws' faces, μ = 0.6:
     * friction holds 2μN/g = 61.2 g. A box of 0.8× that stays put (moves less than 1 µm in 0.5 s);
     * one of 1.25× slides down with a = g − 2μN/m (within 2 % after 0.5 s); the jaws never open.
     */
    @Test
    void aPinchedBoxHoldsOrSlidesAsTheJawsTorqueSays() {
        double tauNm = 0.05, arm = 0.1, mu = 0.6, n = tauNm / arm;
        double holdKg = 2 * mu * n / G;
        for (double factor : new double[] {0.8, 1.25}) {
            double mass = factor * holdKg;
            double[] r = pinch(mass, tauNm, arm, mu, 0.5);
            double want = factor < 1 ? 0 : 0.5 * (G - 2 * mu * n / mass) * 0.25;
            System.out.printf("pinch %.2f x: fell %.6e m, want %.6e; jaws closed by %.3e, %.3e rad%n", factor, r[0], want, r[1], r[2]);
            if (want == 0) assertTrue(Math.abs(r[0]) < 1e-6, "fell " + r[0]);
            else assertEquals(want, r[0], 0.02 * want);
            assertTrue(r[1] >= -1e-12 && r[2] >= -1e-12, "a jaw opened: " + r[1] + ", " + r[2]);
        }
    }

    /** {fall, jaw 1 angle, jaw 2 angle} after t seconds. */
    static double[] pinch(double mass, double tauNm, double arm, double mu, double t) {
        double w = 0.02, hy = 0.01;
        double ix = mass / 12 * (4 * hy * hy + 4 * HZ * HZ);
        MassProperties props = MassProperties.of(mass, new double[3], new double[] {ix, 0, 0, 0, ix, 0, 0, 0, ix * 1.5});
        FreeBody b = new FreeBody(props, RigidTransform.IDENTITY);
        BodyStepper s = new BodyStepper(b);
        BodyContacts c = new BodyContacts();
        double[] f = {0, 0, -G * mass}, tau = new double[3], x = new double[3];
        double jaw1 = 0, jaw2 = 0;                  // closing angles
        double linkInertia = 1e-4;
        int steps = (int) Math.round(t / H);
        for (int i = 0; i < steps; i++) {
            c.clear();
            s.clearFollowers();
            b.position(x);
            // jaw 1: face at x = −w/2 + jaw1·arm pressing +x, hinge along +y at (−w/2, ·, z0 − arm); jaw 2 mirrored
            double z0 = x[2];
            int f1 = s.addFollower(new double[] {0, 1, 0}, new double[] {-w / 2, 0, z0 - arm}, linkInertia, tauNm);
            int f2 = s.addFollower(new double[] {0, -1, 0}, new double[] {w / 2, 0, z0 - arm}, linkInertia, tauNm);
            for (int sy = -1; sy <= 1; sy += 2) {
                double gap1 = (x[0] - w / 2) - (-w / 2 + jaw1 * arm);
                int k = c.add(new double[] {x[0] - w / 2, x[1] + sy * hy, z0}, new double[] {1, 0, 0}, gap1, mu, null, 1);
                c.dependsOn(k, f1);
                double gap2 = (w / 2 - jaw2 * arm) - (x[0] + w / 2);
                k = c.add(new double[] {x[0] + w / 2, x[1] + sy * hy, z0}, new double[] {-1, 0, 0}, gap2, mu, null, 2);
                c.dependsOn(k, f2);
            }
            assertEquals(ContactSolver.Outcome.CONVERGED, s.step(H, f, tau, c), "step " + i);
            jaw1 += H * s.followerVelocity(f1);
            jaw2 += H * s.followerVelocity(f2);
        }
        b.position(x);
        return new double[] {-x[2], jaw1, jaw2};
    }
}
