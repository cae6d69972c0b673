package org.handsim.dynamics;

import static org.handsim.dynamics.DynamicsTesting.EXACT;
import static org.handsim.dynamics.DynamicsTesting.SEED;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import java.util.function.Function;
import org.handsim.hand.DhRow;
import org.handsim.hand.LinkInertia;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * One- and two-link planar arms whose equations of motion are derived by hand (below), built
 * as {@link LinkChain}s and solved by {@link LagrangeEuler} and {@link NewtonEuler}: the
 * results must match the formulas to rounding.
 *
 * <p>Set-up shared by both arms: every joint axis is z0 (α = 0, d = 0), link j has length l_j
 * (DH a_j = l_j, offset 0) and its frame {j} sits at the link's far end with x_j along the link,
 * so a centre of mass at distance lc_j from joint j is at (lc_j − l_j, 0, 0) in {j}. Gravity
 * g = (0, −g0, 0): y0 points up. Each link's inertia tensor has off-diagonal and x/y entries
 * that must not matter: rotation about a fixed z axis only sees Izz, and the z component of
 * ω × (I·ω) vanishes for ω = (0, 0, w).
 */
class PlanarArmTest {
    private static final double G0 = 9.81;

    private static LinkInertia link(double m, double lc, double l, double izz) {
        return LinkInertia.aboutCentreOfMass(m, new double[] {lc - l, 0, 0},
            new double[] {0.3 * izz, 0.01 * izz, -0.02 * izz, 0.8 * izz, 0.03 * izz, izz});
    }

    private static Function<LinkChain, ChainDynamics> algorithm(String name) {
        return name.equals("le") ? LagrangeEuler::new : NewtonEuler::new;
    }

    /**
     * One link, a pendulum: the centre of mass moves on a circle of radius lc,
     * p = lc·(cos q, sin q), so K = ½(m·lc² + Izz)·q̇² and V = m·g0·lc·sin q. Lagrange's equation
     * d/dt ∂L/∂q̇ − ∂L/∂q = τ gives
     * <pre>
     *   τ = (Izz + m·lc²)·q̈ + m·g0·lc·cos q       (H = 0: one joint has no Coriolis term)
     * </pre>
     */
    @ParameterizedTest
    @ValueSource(strings = {"le", "ne"})
    void oneLinkPendulum(String method) {
        double m = 0.7, l = 0.4, lc = 0.15, izz = 0.011;
        LinkChain arm = LinkChain.of(new DhRow[] {new DhRow(l, 0, 0, 0)}, new LinkInertia[] {link(m, lc, l, izz)});
        ChainDynamics d = algorithm(method).apply(arm);
        double[] g = {0, -G0, 0};
        Random r = new Random(SEED);
        for (int s = 0; s < 100; s++) {
            double q = -Math.PI + 2 * Math.PI * r.nextDouble(), qd = -5 + 10 * r.nextDouble(), qdd = -50 + 100 * r.nextDouble();
            double inertia = izz + m * lc * lc;
            double gravity = m * G0 * lc * Math.cos(q);
            double expect = inertia * qdd + gravity;
            double[] tau = d.inverseDynamics(new double[] {q}, new double[] {qd}, new double[] {qdd}, g, null);
            assertEquals(expect, tau[0], EXACT * (Math.abs(inertia * qdd) + Math.abs(gravity)));
            assertEquals(inertia, d.massMatrix(new double[] {q}, null)[0], EXACT * inertia);
            assertEquals(0, d.coriolisCentrifugal(new double[] {q}, new double[] {qd}, null)[0], EXACT * inertia * qd * qd);
            assertEquals(gravity, d.gravityTorque(new double[] {q}, g, null)[0], EXACT * m * G0 * lc);
            assertEquals(0.5 * inertia * qd * qd, d.kineticEnergy(new double[] {q}, new double[] {qd}), EXACT * inertia * qd * qd);
            assertEquals(m * G0 * lc * Math.sin(q), d.potentialEnergy(new double[] {q}, g), EXACT * m * G0 * lc);
        }
    }

    /**
     * Two links, the planar elbow arm of Spong–Hutchinson–Vidyasagar, <i>Robot Modeling and
     * Control</i>, ch. 7, derived here again. Centres of mass p1 = lc1·(c1, s1), p2 = l1·(c1, s1) + lc2·(c12, s12) with
     * c12 = cos(q1 + q2); angular velocities q̇1 and q̇1 + q̇2. Then
     * <pre>
     *   |ṗ2|² = l1²·q̇1² + lc2²·(q̇1 + q̇2)² + 2·l1·lc2·cos q2·q̇1·(q̇1 + q̇2)
     *   K = ½·(m1·lc1² + I1)·q̇1² + ½·m2·|ṗ2|² + ½·I2·(q̇1 + q̇2)² = ½·q̇ᵀ·D·q̇ with
     *   d11 = m1·lc1² + m2·(l1² + lc2² + 2·l1·lc2·cos q2) + I1 + I2
     *   d12 = d21 = m2·(lc2² + l1·lc2·cos q2) + I2
     *   d22 = m2·lc2² + I2
     *   V = m1·g0·lc1·s1 + m2·g0·(l1·s1 + lc2·s12)
     * </pre>
     * Only d11 and d12 depend on q (on q2), with ∂d11/∂q2 = 2h, ∂d12/∂q2 = h, where
     * h = −m2·l1·lc2·sin q2. The Christoffel symbols c_ikm = ½(∂d_ik/∂q_m + ∂d_im/∂q_k −
     * ∂d_km/∂q_i) are c112 = c121 = c122 = h and c211 = −h, all others 0, so
     * <pre>
     *   H1 = h·(2·q̇1·q̇2 + q̇2²),   H2 = −h·q̇1²
     *   C1 = ∂V/∂q1 = (m1·lc1 + m2·l1)·g0·c1 + m2·lc2·g0·c12,   C2 = m2·lc2·g0·c12
     *   τ = D·q̈ + H + C
     * </pre>
     */
    @ParameterizedTest
    @ValueSource(strings = {"le", "ne"})
    void twoLinkPlanarArm(String method) {
        double m1 = 1.3, l1 = 0.5, lc1 = 0.2, i1 = 0.03;
        double m2 = 0.6, l2 = 0.35, lc2 = 0.12, i2 = 0.008;
        LinkChain arm = LinkChain.of(new DhRow[] {new DhRow(l1, 0, 0, 0), new DhRow(l2, 0, 0, 0)},
            new LinkInertia[] {link(m1, lc1, l1, i1), link(m2, lc2, l2, i2)});
        ChainDynamics d = algorithm(method).apply(arm);
        double[] g = {0, -G0, 0};
        Random r = new Random(SEED);
        for (int s = 0; s < 200; s++) {
            double q1 = -Math.PI + 2 * Math.PI * r.nextDouble(), q2 = -Math.PI + 2 * Math.PI * r.nextDouble();
            double qd1 = -5 + 10 * r.nextDouble(), qd2 = -5 + 10 * r.nextDouble();
            double qdd1 = -50 + 100 * r.nextDouble(), qdd2 = -50 + 100 * r.nextDouble();
            double c2 = Math.cos(q2), c1 = Math.cos(q1), c12 = Math.cos(q1 + q2);
            double d11 = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2) + i1 + i2;
            double d12 = m2 * (lc2 * lc2 + l1 * lc2 * c2) + i2;
            double d22 = m2 * lc2 * lc2 + i2;
            double h = -m2 * l1 * lc2 * Math.sin(q2);
            double h1 = h * (2 * qd1 * qd2 + qd2 * qd2), h2 = -h * qd1 * qd1;
            double g1 = (m1 * lc1 + m2 * l1) * G0 * c1 + m2 * lc2 * G0 * c12, g2 = m2 * lc2 * G0 * c12;
            double tau1 = d11 * qdd1 + d12 * qdd2 + h1 + g1, tau2 = d12 * qdd1 + d22 * qdd2 + h2 + g2;

            double[] q = {q1, q2}, qd = {qd1, qd2}, qdd = {qdd1, qdd2};
            double[] dm = d.massMatrix(q, null);
            double dScale = d11;
            assertEquals(d11, dm[0], EXACT * dScale);
            assertEquals(d12, dm[1], EXACT * dScale);
            assertEquals(d12, dm[2], EXACT * dScale);
            assertEquals(d22, dm[3], EXACT * dScale);
            double[] hv = d.coriolisCentrifugal(q, qd, null);
            double hScale = dScale * (qd1 * qd1 + qd2 * qd2);
            assertEquals(h1, hv[0], EXACT * hScale);
            assertEquals(h2, hv[1], EXACT * hScale);
            double[] cv = d.gravityTorque(q, g, null);
            double cScale = (m1 + m2) * G0 * l1;
            assertEquals(g1, cv[0], EXACT * cScale);
            assertEquals(g2, cv[1], EXACT * cScale);
            double[] tau = d.inverseDynamics(q, qd, qdd, g, null);
            double tScale = dScale * 100 + hScale + cScale;
            assertEquals(tau1, tau[0], EXACT * tScale);
            assertEquals(tau2, tau[1], EXACT * tScale);
        }
    }
}
