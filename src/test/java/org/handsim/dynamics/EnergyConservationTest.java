package org.handsim.dynamics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * Forward dynamics integrated with RK4 at dt = 1e-4 s for 1 s under zero torque: without
 * gravity the kinetic energy, with gravity the total energy, must stay within 1e-8 of its
 * scale. The scale is the larger of |E(0)| and the largest kinetic energy met on the way (the
 * energy that flows between kinetic and potential; the potential's zero, at the base origin,
 * is arbitrary). Measured: below 1e-10 in every case.
 */
class EnergyConservationTest {
    static final double DRIFT = 1e-8;
    private static final double DT = 1e-4;
    private static final int STEPS = 10_000;

    private static double worstDrift(ChainDynamics d, double[] g) {
        int n = d.dof();
        FingerDynamicsOde ode = new FingerDynamicsOde(d, g, FingerDynamicsOde.Torques.ZERO);
        double[] y = n == 3 ? new double[] {0.2, 0.5, 0.4, 1.5, -2, 3} : new double[] {0.5, 0.4, -2, 3};
        RungeKutta4 rk = new RungeKutta4(2 * n);
        double e0 = ode.energy(y);
        double scale = Math.abs(e0), worst = 0;
        double[] q = new double[n], qd = new double[n];
        for (int i = 0; i < STEPS; i++) {
            assertTrue(rk.step(ode, i * DT, y, DT), "step " + i);
            worst = Math.max(worst, Math.abs(ode.energy(y) - e0));
            System.arraycopy(y, 0, q, 0, n);
            System.arraycopy(y, n, qd, 0, n);
            scale = Math.max(scale, d.kineticEnergy(q, qd));
        }
        return worst / scale;
    }

    @Test
    void kineticEnergyIsConservedWithoutGravity() {
        for (int k = 1; k <= 3; k++) {
            double drift = worstDrift(new ClosedFormFinger(LinkChain.finger(k)), new double[3]);
            assertTrue(drift <= DRIFT, "finger " + k + ": relative drift " + drift);
        }
    }

    @Test
    void totalEnergyIsConservedUnderGravity() {
        double[][] gs = {{0, 0, -9.81}, {3, -5, -7.9}};
        for (int k = 1; k <= 3; k++) {
            for (double[] g : gs) {
                double drift = worstDrift(new ClosedFormFinger(LinkChain.finger(k)), g);
                assertTrue(drift <= DRIFT, "finger " + k + ", g = " + Arrays.toString(g) + ": relative drift " + drift);
            }
        }
    }

    @Test
    void theGeneralAlgorithmsConserveItToo() {
        LinkChain f1 = LinkChain.finger(1);
        double[] g = {0, 0, -9.81};
        assertTrue(worstDrift(new LagrangeEuler(f1), g) <= DRIFT);
        assertTrue(worstDrift(new NewtonEuler(f1), g) <= DRIFT);
    }
}
