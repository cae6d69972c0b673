package org.handsim.dynamics;

import static org.handsim.dynamics.DynamicsTesting.CROSS_CHECK;
import static org.handsim.dynamics.DynamicsTesting.EXACT;
import static org.handsim.dynamics.DynamicsTesting.FINITE_DIFFERENCE;
import static org.handsim.dynamics.DynamicsTesting.G0;
import static org.handsim.dynamics.DynamicsTesting.SEED;
import static org.handsim.dynamics.DynamicsTesting.STATES;
import static org.handsim.dynamics.DynamicsTesting.maxAbs;
import static org.handsim.dynamics.DynamicsTesting.randomState;
import static org.handsim.dynamics.DynamicsTesting.relative;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.hand.HandDescription;
import org.handsim.hand.LinkInertia;
import org.handsim.math.Cholesky;
import org.junit.jupiter.api.Test;

/**
 * The contract of {@link ChainDynamics} (docs/STYLE.md, item 9, after EJML's generic decomposition
 * tests): every implementation runs these cases on the three BarrettHand fingers — a value
 * worked by hand, checks against the definitions (τ = D·q̈ + H + C, H quadratic, C = ∂V/∂q,
 * D symmetric positive definite, kinetic energy ½q̇ᵀDq̇), a cross-check with a second algorithm
 * on 10 000 seeded random states per finger, the output-argument contract and the allocation
 * promise.
 */
abstract class AbstractChainDynamicsTest {
    /** The implementation under test. */
    abstract ChainDynamics create(LinkChain chain);

    /** A different algorithm to cross-check against. */
    abstract ChainDynamics reference(LinkChain chain);

    // ------------------------------------------------------------------ hand-worked values

    /**
     * A stretched finger (DH angles 0: q = (0, −Φ2, −Φ3)) held still against gravity.
     *
     * <p>With θ1 = 0 and α1 = 90°, frame {1} has axes x1 = x0, y1 = z0, z1 = −y0, and links 2
     * and 3 lie along x0: o1 = (A1, 0, 0), o2 = (A1 + A2, 0, 0), o3 = (A1 + A2 + A3, 0, 0), and
     * every frame j ≥ 1 has the rotation of {1}, so a centre of mass p_j (in {j}) sits at
     * o_j + (p_jx, −p_jz, p_jy) in {0}. The holding torque of joint i is
     * τ_i = −Σ_{j≥i} m_j·g·(z_{i−1} × (p̄_j − o_{i−1})).
     *
     * <p>Gravity g = (0, 0, −g0): for joint 2 (axis z1 = (0, −1, 0) through o1) and link j the
     * lever r = p̄_j − o1 = (o_jx − A1 + p_jx, −p_jz, p_jy) gives z1 × r = (−p_jy, 0, o_jx − A1 + p_jx)
     * and g·(z1 × r) = −g0·(o_jx − A1 + p_jx). Hence
     * <pre>
     *   τ2 = g0·[m2·(A2 + p2x) + m3·(A2 + A3 + p3x)],   τ3 = g0·m3·(A3 + p3x),
     * </pre>
     * and τ1 = 0 (z0 × r has no z component). Gravity g = (0, −g0, 0): z0 × p̄ = (−p̄y, p̄x, 0)
     * so τ1 = g0·Σ_j m_j·p̄_jx = g0·[m1·(A1 + p1x) + m2·(A1 + A2 + p2x) + m3·(A1 + A2 + A3 + p3x)],
     * while z1 × r has no y component: τ2 = τ3 = 0.
     */
    @Test
    void stretchedFingerHoldsAgainstGravityAsComputedByHand() {
        HandDescription h = HandDescription.barrettHand();
        double a1 = h.a1(), a2 = h.a2(), a3 = h.a3();
        LinkInertia l1 = h.finger(1).link(0), l2 = h.finger(1).link(1), l3 = h.finger(1).link(2);
        double m1 = l1.mass(), m2 = l2.mass(), m3 = l3.mass();
        double p1x = l1.com()[0], p2x = l2.com()[0], p3x = l3.com()[0];
        double tau2 = G0 * (m2 * (a2 + p2x) + m3 * (a2 + a3 + p3x));
        double tau3 = G0 * m3 * (a3 + p3x);
        double tau1 = G0 * (m1 * (a1 + p1x) + m2 * (a1 + a2 + p2x) + m3 * (a1 + a2 + a3 + p3x));
        // the numbers, for the record: m2(A2 + p2x) = 0.05795741·0.03172018, m3(A2 + A3 + p3x) = 0.03421781·0.08970974
        assertEquals(9.81 * (0.05795741 * 0.03172018 + 0.03421781 * 0.08970974), tau2, 1e-15);
        double phi2 = h.finger(1).dh(1).thetaOffset(), phi3 = h.finger(1).dh(2).thetaOffset();

        ChainDynamics f1 = create(LinkChain.finger(1));
        double[] q = {0, -phi2, -phi3}, zero = new double[3];
        double[] t = f1.inverseDynamics(q, zero, zero, new double[] {0, 0, -G0}, null);
        assertEquals(0, t[0], EXACT * tau2);
        assertEquals(tau2, t[1], EXACT * tau2);
        assertEquals(tau3, t[2], EXACT * tau2);
        t = f1.gravityTorque(q, new double[] {0, -G0, 0}, null);
        assertEquals(tau1, t[0], EXACT * tau1);
        assertEquals(0, t[1], EXACT * tau1);
        assertEquals(0, t[2], EXACT * tau1);

        ChainDynamics f3 = create(LinkChain.finger(3));
        t = f3.inverseDynamics(new double[] {-phi2, -phi3}, new double[2], new double[2], new double[] {0, 0, -G0}, null);
        assertEquals(2, t.length);
        assertEquals(tau2, t[0], EXACT * tau2);
        assertEquals(tau3, t[1], EXACT * tau2);
    }

    // ------------------------------------------------------------------ cross-check

    @Test
    void agreesWithTheReferenceAlgorithmOnRandomStates() {
        for (int k = 1; k <= 3; k++) {
            LinkChain chain = LinkChain.finger(k);
            ChainDynamics a = create(chain), b = reference(chain);
            int n = chain.dof();
            double[] ta = new double[n], tb = new double[n];
            double[] da = new double[n * n], db = new double[n * n];
            double[] ha = new double[n], hb = new double[n], ca = new double[n], cb = new double[n];
            Random r = new Random(SEED + k);
            double worstTau = 0, worstD = 0, worstH = 0, worstC = 0, worstE = 0;
            for (int s = 0; s < STATES; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                a.inverseDynamics(st.q, st.qd, st.qdd, st.g, ta);
                b.inverseDynamics(st.q, st.qd, st.qdd, st.g, tb);
                worstTau = Math.max(worstTau, relative(ta, tb));
                a.terms(st.q, st.qd, st.g, da, ha, ca);
                b.terms(st.q, st.qd, st.g, db, hb, cb);
                double dScale = maxAbs(db);
                worstD = Math.max(worstD, relative(da, db));
                // H and C can be small by cancellation: measure against the size of their terms
                worstH = Math.max(worstH, relative(ha, hb, dScale * DynamicsTesting.dot(st.qd, st.qd)));
                worstC = Math.max(worstC, relative(ca, cb, G0 * 0.25 * totalMass(chain)));
                double ka = a.kineticEnergy(st.q, st.qd), kb = b.kineticEnergy(st.q, st.qd);
                worstE = Math.max(worstE, Math.abs(ka - kb) / kb);
                double va = a.potentialEnergy(st.q, st.g), vb = b.potentialEnergy(st.q, st.g);
                worstE = Math.max(worstE, Math.abs(va - vb) / (G0 * 0.25 * totalMass(chain)));
            }
            String what = getClass().getSimpleName() + " finger " + k + ": ";
            assertTrue(worstTau <= CROSS_CHECK, what + "tau max relative difference " + worstTau);
            assertTrue(worstD <= CROSS_CHECK, what + "D max relative difference " + worstD);
            assertTrue(worstH <= CROSS_CHECK, what + "H max relative difference " + worstH);
            assertTrue(worstC <= CROSS_CHECK, what + "C max relative difference " + worstC);
            assertTrue(worstE <= CROSS_CHECK, what + "energy max relative difference " + worstE);
        }
    }

    static double totalMass(LinkChain c) {
        double m = 0;
        for (int j = 0; j < c.links(); j++) m += c.link(j).mass();
        return m;
    }

    // ------------------------------------------------------------------ the definitions

    @Test
    void torqueIsMassMatrixTimesAccelerationPlusCoriolisPlusGravity() {
        for (int k = 1; k <= 3; k++) {
            LinkChain chain = LinkChain.finger(k);
            ChainDynamics d = create(chain);
            int n = chain.dof();
            Random r = new Random(SEED);
            for (int s = 0; s < 200; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                double[] dm = d.massMatrix(st.q, null);
                double[] h = d.coriolisCentrifugal(st.q, st.qd, null);
                double[] c = d.gravityTorque(st.q, st.g, null);
                double[] expect = new double[n];
                for (int i = 0; i < n; i++) {
                    expect[i] = h[i] + c[i];
                    for (int j = 0; j < n; j++) expect[i] += dm[i * n + j] * st.qdd[j];
                }
                assertTrue(relative(d.inverseDynamics(st.q, st.qd, st.qdd, st.g, null), expect) <= EXACT * 10);
                // terms() gives the same three
                double[] d2 = new double[n * n], h2 = new double[n], c2 = new double[n];
                d.terms(st.q, st.qd, st.g, d2, h2, c2);
                assertTrue(relative(d2, dm) <= EXACT);
                assertTrue(relative(h2, h, maxAbs(dm)) <= EXACT);
                assertTrue(relative(c2, c) <= EXACT);
            }
        }
    }

    @Test
    void coriolisIsQuadraticInVelocityAndGravityLinearInG() {
        LinkChain chain = LinkChain.finger(1);
        ChainDynamics d = create(chain);
        Random r = new Random(SEED);
        for (int s = 0; s < 100; s++) {
            DynamicsTesting.State st = randomState(chain, r);
            double[] h = d.coriolisCentrifugal(st.q, st.qd, null);
            double[] qd2 = st.qd.clone();
            for (int i = 0; i < qd2.length; i++) qd2[i] *= -3;
            double[] h9 = d.coriolisCentrifugal(st.q, qd2, null);
            double scale = maxAbs(d.massMatrix(st.q, null)) * DynamicsTesting.dot(st.qd, st.qd);
            for (int i = 0; i < h.length; i++) assertEquals(9 * h[i], h9[i], 1e-13 * 9 * scale);
            assertEquals(0.0, maxAbs(d.coriolisCentrifugal(st.q, new double[3], null)));
            double[] c = d.gravityTorque(st.q, st.g, null);
            double[] g2 = {2 * st.g[0], 2 * st.g[1], 2 * st.g[2]};
            double[] c2 = d.gravityTorque(st.q, g2, null);
            for (int i = 0; i < c.length; i++) assertEquals(2 * c[i], c2[i], 1e-14);
            assertEquals(0.0, maxAbs(d.gravityTorque(st.q, new double[3], null)));
        }
    }

    /** C = ∂V/∂q (the gravity torque is the gradient of the potential energy, FGL §3.2). */
    @Test
    void gravityTorqueIsTheGradientOfPotentialEnergy() {
        for (int k = 1; k <= 3; k += 2) {
            LinkChain chain = LinkChain.finger(k);
            ChainDynamics d = create(chain);
            int n = chain.dof();
            Random r = new Random(SEED);
            double eps = 1e-6;
            for (int s = 0; s < 100; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                double[] c = d.gravityTorque(st.q, st.g, null);
                for (int i = 0; i < n; i++) {
                    double[] qp = st.q.clone(), qm = st.q.clone();
                    qp[i] += eps;
                    qm[i] -= eps;
                    double fd = (d.potentialEnergy(qp, st.g) - d.potentialEnergy(qm, st.g)) / (2 * eps);
                    assertEquals(fd, c[i], FINITE_DIFFERENCE * G0 * 0.25 * totalMass(chain), "dV/dq" + i);
                }
            }
        }
    }

    @Test
    void kineticEnergyIsHalfQdTransposeDQd() {
        LinkChain chain = LinkChain.finger(2);
        ChainDynamics d = create(chain);
        Random r = new Random(SEED);
        for (int s = 0; s < 100; s++) {
            DynamicsTesting.State st = randomState(chain, r);
            double[] dm = d.massMatrix(st.q, null);
            double e = 0;
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) e += 0.5 * st.qd[i] * dm[3 * i + j] * st.qd[j];
            }
            assertEquals(e, d.kineticEnergy(st.q, st.qd), EXACT * e);
        }
    }

    /** D symmetric positive definite on a 13-point grid per joint over the joint range, and at random states. */
    @Test
    void massMatrixIsSymmetricPositiveDefiniteOverTheJointRange() {
        HandDescription h = HandDescription.barrettHand();
        double[][] lim = {{-Math.PI, Math.PI}, h.theta2Limits(), h.theta3Limits()};
        int steps = 12;
        for (int k = 1; k <= 3; k += 2) {
            LinkChain chain = LinkChain.finger(k);
            ChainDynamics d = create(chain);
            int n = chain.dof();
            double[] q = new double[n], dm = new double[n * n];
            int[] idx = new int[n];
            int checked = 0;
            double minPivotRatio = Double.POSITIVE_INFINITY;
            while (true) {
                for (int p = 0; p < n; p++) {
                    double[] l = lim[chain.linkOfDof(p)];
                    q[p] = l[0] + (l[1] - l[0]) * idx[p] / steps;
                }
                d.massMatrix(q, dm);
                minPivotRatio = Math.min(minPivotRatio, checkSpd(dm, n, q));
                checked++;
                int p = 0;
                while (p < n && ++idx[p] > steps) idx[p++] = 0;
                if (p == n) break;
            }
            Random r = new Random(SEED);
            for (int s = 0; s < 2000; s++) {
                double[] qr = randomState(chain, r).q;
                d.massMatrix(qr, dm);
                minPivotRatio = Math.min(minPivotRatio, checkSpd(dm, n, qr));
            }
            assertEquals((int) Math.pow(steps + 1, n), checked);
            // far from singular: the smallest Cholesky pivot² relative to its diagonal entry
            assertTrue(minPivotRatio > 1e-3, "finger " + k + ": min pivot ratio " + minPivotRatio);
        }
    }

    /** Asserts symmetry and positive definiteness; returns the smallest pivot²/diagonal ratio. */
    private static double checkSpd(double[] dm, int n, double[] q) {
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < i; j++) {
                assertEquals(dm[i * n + j], dm[j * n + i], EXACT * maxAbs(dm), "D symmetric at q = " + java.util.Arrays.toString(q));
            }
        }
        double[] l = dm.clone();
        assertTrue(Cholesky.decompose(l, n), "D positive definite at q = " + java.util.Arrays.toString(q));
        double ratio = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) ratio = Math.min(ratio, l[i * n + i] * l[i * n + i] / dm[i * n + i]);
        return ratio;
    }

    // ------------------------------------------------------------------ output contract

    @Test
    void outputArgumentsFollowTheContract() {
        LinkChain chain = LinkChain.finger(1);
        ChainDynamics d = create(chain);
        double[] q = {0.1, 0.2, 0.3}, qd = {1, 2, 3}, qdd = {4, 5, 6}, g = {0, 0, -G0};
        double[] out = new double[3];
        assertSame(out, d.inverseDynamics(q, qd, qdd, g, out));
        assertEquals(3, d.inverseDynamics(q, qd, qdd, g, null).length);
        assertEquals(9, d.massMatrix(q, null).length);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> d.inverseDynamics(q, qd, qdd, g, qd));
        assertTrue(e.getMessage().contains("tauOut"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> d.inverseDynamics(new double[2], qd, qdd, g, out));
        assertTrue(e.getMessage().contains("q needs 3"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> d.massMatrix(q, new double[8]));
        assertTrue(e.getMessage().contains("dOut needs 9"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> d.gravityTorque(q, new double[2], out));
        assertThrows(IllegalArgumentException.class, () -> d.terms(q, qd, g, null, new double[3], new double[3]));
        assertEquals(2, create(LinkChain.finger(3)).dof());
    }

    @Test
    void hotMethodsAllocateNothing() {
        LinkChain chain = LinkChain.finger(1);
        ChainDynamics d = create(chain);
        double[] q = {0.1, 0.2, 0.3}, qd = {1, 2, 3}, qdd = {4, 5, 6}, g = {0, 0, -G0};
        double[] tau = new double[3], dm = new double[9], h = new double[3], c = new double[3];
        Runnable work = () -> {
            for (int i = 0; i < 20_000; i++) {
                q[0] += 1e-6;
                d.inverseDynamics(q, qd, qdd, g, tau);
                d.terms(q, qd, g, dm, h, c);
                d.massMatrix(q, dm);
                d.kineticEnergy(q, qd);
                d.potentialEnergy(q, g);
            }
        };
        work.run(); // warm-up: let the JIT compile
        long bytes = DynamicsTesting.allocatedBytes(work);
        assertTrue(bytes < 1024, "allocated " + bytes + " bytes over 20 000 rounds");
    }
}
