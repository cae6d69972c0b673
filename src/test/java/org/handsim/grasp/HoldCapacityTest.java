package org.handsim.grasp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The hold LP against cases solved by hand, and its optimum checked independently: the
 * returned contact forces balance the load (force and torque), lie in their cones, and every
 * joint torque, recomputed here from the forces, is within its limit.
 *
 * <p><b>The pinch by hand.</b> Two contacts on opposite faces of an object centred at c = 0:
 * p1 = (−a, 0, 0) pushing +x, p2 = (a, 0, 0) pushing −x. Each sits on a link turning about an
 * axis along y through o_i = p_i − (0, 0, h): the torque a contact force f puts on its joint is
 * (e_y × (0, 0, h)) · f = h f_x, the normal force times h (a tangential force along z passes
 * through the axis). Joint limit L. With f_i = (±N_i, 0, T_i):
 * <ul>
 *   <li>load F along +z: the torque about c, (0, a (T1 − T2), 0) = 0, gives T1 = T2 = T; the
 *       x-balance N1 = N2 = N; the z-balance 2T = −F. Friction |T| ≤ μN (the cone has an edge
 *       exactly along ±z: FrictionCone's t1 is ±e_z for n = ±e_x) and the joints h N ≤ L give
 *       <b>F = 2 μ L / h</b>: friction binds (F ∝ μ) and the joints bind (F ∝ L);</li>
 *   <li>load F along −x: the x-balance N1 − N2 − F = 0 gives F = N1 − N2, largest with
 *       N1 = L/h, N2 = 0: <b>F = L / h</b>, whatever μ — only the joint binds;</li>
 *   <li>μ = 0, load along z: no tangential force at all, <b>F = 0</b>.</li>
 * </ul>
 * With a = 0.03 m, h = 0.05 m, L = 1.26 N·m, μ = 0.5: F(+z) = 25.2 N, F(−x) = 25.2 N.
 */
class HoldCapacityTest {
    static final double A = 0.03, H = 0.05, L = 1.26, CAP = 1000;

    static HoldCapacity pinch(double mu, double limit) {
        HoldCapacity hc = new HoldCapacity(mu, FrictionCone.DEFAULT_EDGES, new double[3], A, CAP);
        int j1 = hc.addJoint(new double[] {0, 1, 0}, new double[] {-A, 0, -H}, limit);
        int j2 = hc.addJoint(new double[] {0, 1, 0}, new double[] {A, 0, -H}, limit);
        hc.addContact(new double[] {-A, 0, 0}, new double[] {1, 0, 0}, j1);
        hc.addContact(new double[] {A, 0, 0}, new double[] {-1, 0, 0}, j2);
        return hc;
    }

    @Test
    void tangentialLoadOnAPinchIsTwoMuLOverH() {
        for (double mu : new double[] {0.25, 0.5, 1.0}) {
            HoldCapacity.Result r = pinch(mu, L).hold(new double[] {0, 0, 1});
            assertEquals(2 * mu * L / H, r.forceN(), 1e-6, "mu " + mu);
            assertEquals(HoldCapacity.Outcome.HELD, r.outcome());
        }
        // the joint bound binds as well: twice the limit, twice the load
        assertEquals(2 * 0.5 * 2 * L / H, pinch(0.5, 2 * L).hold(new double[] {0, 0, -1}).forceN(), 1e-6);
    }

    @Test
    void normalLoadOnAPinchIsLOverHWhateverMu() {
        for (double mu : new double[] {0, 0.5, 1.0}) {
            assertEquals(L / H, pinch(mu, L).hold(new double[] {-1, 0, 0}).forceN(), 1e-6, "mu " + mu);
            assertEquals(L / H, pinch(mu, L).hold(new double[] {1, 0, 0}).forceN(), 1e-6, "mu " + mu);
        }
    }

    @Test
    void frictionlessPinchHoldsNoTangentialLoad() {
        double[] six = pinch(0, L).holdSix();
        assertEquals(L / H, six[0], 1e-6);
        assertEquals(L / H, six[1], 1e-6);
        for (int d = 2; d < 6; d++) assertEquals(0, six[d], 1e-9, "direction " + d);
    }

    @Test
    void noContactsHoldNothing() {
        HoldCapacity hc = new HoldCapacity(0.5, 8, new double[3], 1, CAP);
        HoldCapacity.Result r = hc.hold(new double[] {0, 0, 1});
        assertEquals(0, r.forceN());
        assertEquals(HoldCapacity.Outcome.NO_CONTACTS, r.outcome());
        for (double f : hc.holdSix()) assertEquals(0, f);
    }

    /**
     * Contacts that load no limited joint (links fixed to the palm): any load the cones can
     * balance is held — the LP without the cap is unbounded — so the answer is the cap, marked.
     */
    @Test
    void unlimitedJointsGiveTheCap() {
        HoldCapacity hc = new HoldCapacity(0.5, 8, new double[3], A, 58.86);
        hc.addContact(new double[] {-A, 0, 0}, new double[] {1, 0, 0});
        hc.addContact(new double[] {A, 0, 0}, new double[] {-1, 0, 0});
        HoldCapacity.Result r = hc.hold(new double[] {0, 0, 1});
        assertEquals(58.86, r.forceN(), 1e-9);
        assertEquals(HoldCapacity.Outcome.CAPPED, r.outcome());
    }

    @Test
    void badInputIsRefusedWithTheValue() {
        assertThrows(IllegalArgumentException.class, () -> new HoldCapacity(-0.1, 8, new double[3], 1, 10));
        assertThrows(IllegalArgumentException.class, () -> new HoldCapacity(0.5, 8, new double[3], 0, 10));
        assertThrows(IllegalArgumentException.class, () -> new HoldCapacity(0.5, 8, new double[3], 1, Double.POSITIVE_INFINITY));
        HoldCapacity hc = new HoldCapacity(0.5, 8, new double[3], 1, 10);
        assertThrows(IllegalArgumentException.class, () -> hc.addJoint(new double[] {0, 0, 1}, new double[3], Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> hc.addContact(new double[3], new double[] {0, 0, 1}, 3));
        assertThrows(IllegalArgumentException.class, () -> hc.hold(new double[3]));
    }

    /**
     * 200 seeded grasps of 2–6 contacts round a sphere (normals into its centre, tilted), on
     * 1–3 joints each with random axes and limits: the optimum's forces, recomputed here, balance
     * F·d in force and in torque about c, lie in their cones (normal part ≥ 0, tangential part at
     * most μ times it), and every joint torque is within its limit and equals the one reported.
     */
    @Test
    void theOptimumBalancesTheLoadAndRespectsEveryBound() {
        Random rnd = new Random(12);
        int held = 0;
        for (int trial = 0; trial < 200; trial++) {
            double mu = 0.2 + 0.8 * rnd.nextDouble();
            double[] c = {0.01 * rnd.nextGaussian(), 0.01 * rnd.nextGaussian(), 0.01 * rnd.nextGaussian()};
            HoldCapacity hc = new HoldCapacity(mu, 8, c, 0.05, 500);
            int n = 2 + rnd.nextInt(5);
            int nj = 1 + rnd.nextInt(3);
            double[][] axes = new double[nj][], origins = new double[nj][];
            double[] limits = new double[nj];
            for (int j = 0; j < nj; j++) {
                axes[j] = unit(rnd);
                origins[j] = new double[] {0.1 * rnd.nextGaussian(), 0.1 * rnd.nextGaussian(), 0.1 * rnd.nextGaussian()};
                limits[j] = 0.2 + 2 * rnd.nextDouble();
                hc.addJoint(axes[j], origins[j], limits[j]);
            }
            double[][] p = new double[n][], nrm = new double[n][];
            int[][] chain = new int[n][];
            for (int i = 0; i < n; i++) {
                double[] u = unit(rnd);
                p[i] = new double[] {c[0] + 0.05 * u[0], c[1] + 0.05 * u[1], c[2] + 0.05 * u[2]};
                double[] tilt = unit(rnd);
                nrm[i] = new double[] {-u[0] + 0.3 * tilt[0], -u[1] + 0.3 * tilt[1], -u[2] + 0.3 * tilt[2]};
                int k = 1 + rnd.nextInt(nj);
                chain[i] = new int[k];
                for (int q = 0; q < k; q++) chain[i][q] = q;
                hc.addContact(p[i], nrm[i], chain[i]);
            }
            for (double[] d : HoldCapacity.SIX_DIRECTIONS) {
                HoldCapacity.Result r = hc.hold(d);
                assertTrue(r.forceN() >= 0 && r.forceN() <= 500, "F in [0, cap]: " + r.forceN());
                double[] f = r.contactForces();
                double[] sum = {r.forceN() * d[0], r.forceN() * d[1], r.forceN() * d[2]}, mom = new double[3];
                double scale = 1 + r.forceN();
                for (int i = 0; i < n; i++) {
                    double[] fi = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
                    for (int q = 0; q < 3; q++) sum[q] += fi[q];
                    double[] rr = {p[i][0] - c[0], p[i][1] - c[1], p[i][2] - c[2]};
                    mom[0] += rr[1] * fi[2] - rr[2] * fi[1];
                    mom[1] += rr[2] * fi[0] - rr[0] * fi[2];
                    mom[2] += rr[0] * fi[1] - rr[1] * fi[0];
                    // in the cone: normal part >= 0, tangential at most mu times it (the circumscribed circle)
                    double nl = Math.sqrt(nrm[i][0] * nrm[i][0] + nrm[i][1] * nrm[i][1] + nrm[i][2] * nrm[i][2]);
                    double fn = (fi[0] * nrm[i][0] + fi[1] * nrm[i][1] + fi[2] * nrm[i][2]) / nl;
                    double ft = Math.sqrt(Math.max(0, fi[0] * fi[0] + fi[1] * fi[1] + fi[2] * fi[2] - fn * fn));
                    assertTrue(fn >= -1e-7 * scale && ft <= mu * fn + 1e-7 * scale, "trial " + trial + ": force outside its cone");
                }
                for (int q = 0; q < 3; q++) {
                    assertEquals(0, sum[q], 1e-7 * scale, "trial " + trial + ": force balance");
                    assertEquals(0, mom[q], 1e-7 * scale * 0.05, "trial " + trial + ": torque balance");
                }
                for (int j = 0; j < nj; j++) {
                    double tau = 0;
                    for (int i = 0; i < n; i++) {
                        boolean loads = false;
                        for (int q : chain[i]) loads |= q == j;
                        if (!loads) continue;
                        double[] rr = {p[i][0] - origins[j][0], p[i][1] - origins[j][1], p[i][2] - origins[j][2]};
                        double[] z = axes[j];
                        double[] t = {z[1] * rr[2] - z[2] * rr[1], z[2] * rr[0] - z[0] * rr[2], z[0] * rr[1] - z[1] * rr[0]};
                        tau += t[0] * f[3 * i] + t[1] * f[3 * i + 1] + t[2] * f[3 * i + 2];
                    }
                    assertTrue(Math.abs(tau) <= limits[j] * (1 + 1e-7) + 1e-9, "trial " + trial + ": joint " + j + " torque " + tau + " > " + limits[j]);
                    assertEquals(tau, r.jointTorques()[j], 1e-7 * (1 + limits[j]));
                }
                if (r.forceN() > 0) held++;
            }
        }
        assertTrue(held > 300, "loads held: " + held);
    }

    private static double[] unit(Random rnd) {
        double[] v = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }
}
