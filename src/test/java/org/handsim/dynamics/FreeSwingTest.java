package org.handsim.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@link FreeSwing} and its {@link EnergyGuard}: an accurate run conserves energy and never
 * trips the guard; explicit Euler at a large step is stopped at a known step with the state
 * before it kept; a non-finite state and a failed step are stopped too.
 */
class FreeSwingTest {
    private static final double[] G = {0, 0, -9.81};

    private static FingerDynamicsOde ode(int k, double[] g) {
        return new FingerDynamicsOde(new ClosedFormFinger(LinkChain.finger(k)), g, FingerDynamicsOde.Torques.ZERO);
    }

    /**
     * The approach of {@link EnergyConservationTest} through FreeSwing: RK4 at 1e-4 s for 1 s under
     * gravity, the worst energy error relative to max(|E(0)|, largest kinetic energy) ≤ 1e-8;
     * the guard's energy scale bounds every kinetic energy met.
     */
    @Test
    void rk4ConservesEnergyUnderGravityAndTheScaleBoundsTheKineticEnergy() {
        for (int finger = 1; finger <= 3; finger++) {
            int k = finger;
            FingerDynamicsOde ode = ode(k, G);
            int n = ode.dof();
            double[] y = n == 3 ? new double[] {0.2, 0.5, 0.4, 1.5, -2, 3} : new double[] {0.5, 0.4, -2, 3};
            double e0 = ode.energy(y);
            EnergyGuard guard = new EnergyGuard(ode, y);
            double[] worst = {0, Math.abs(e0)}; // worst |E − E0|, scale
            double[] q = new double[n], qd = new double[n];
            long[] count = {0};
            FreeSwing.Result r = FreeSwing.run(ode, new RungeKutta4(2 * n), y, 1e-4, 1.0, (step, t, s, e) -> {
                assertEquals(count[0]++, step);
                assertEquals(Math.min(step * 1e-4, 1.0), t, 1e-15);
                worst[0] = Math.max(worst[0], Math.abs(e - e0));
                System.arraycopy(s, 0, q, 0, n);
                System.arraycopy(s, n, qd, 0, n);
                double kin = ode.dynamics().kineticEnergy(q, qd);
                worst[1] = Math.max(worst[1], kin);
                assertTrue(kin <= guard.scale(), "finger " + k + " t = " + t + ": kinetic " + kin + " > scale " + guard.scale());
            }, null);
            assertEquals(10_000, r.steps());
            assertEquals(10_001, count[0]);
            assertEquals(40_000, r.evaluations());
            double drift = worst[0] / worst[1];
            assertTrue(drift <= EnergyConservationTest.DRIFT, "finger " + k + ": relative drift " + drift);
            assertTrue(Math.abs(r.worstGrowth()) <= worst[0]);
            assertEquals(worst[1], r.driftScale(), 1e-15, "the drift's scale is max(|E(0)|, largest kinetic energy)");
            assertEquals(Math.abs(r.finalEnergy() - e0) / worst[1], r.relativeDrift(), 1e-18);
        }
    }

    /**
     * Explicit Euler at dt = 0.05 s from the stretched pose q = 0 at rest under gravity gains
     * energy every step; step 5 (t = 0.25 s) is the first past the bound, with E = 0.2072 J
     * against E(0) = −0.0170 J, scale 0.2621 J (explicit Euler on Pinocchio's articulated-body
     * algorithm, tools/dynamics/pinocchio_reference.py's model, gives the same energies:
     * E4 = 0.07238, E5 = 0.20716 J).
     */
    @Test
    void explicitEulerAtALargeStepIsStoppedWhereTheEnergyPassesTheBound() {
        FingerDynamicsOde ode = ode(1, G);
        double[] y = new double[6];
        EnergyGuard guard = new EnergyGuard(ode, y);
        assertEquals(0.5 * guard.scale() + EnergyGuard.FLOOR_J, guard.bound());
        List<Double> energies = new ArrayList<>();
        IntegrationStoppedException e = assertThrows(IntegrationStoppedException.class,
            () -> FreeSwing.run(ode, new ExplicitEuler(6), y, 0.05, 1.0, (step, t, s, en) -> energies.add(en), null));
        assertEquals(IntegrationStoppedException.Reason.ENERGY_GROWTH, e.reason());
        assertEquals(5, e.step());
        assertEquals(0.25, e.time(), 1e-15);
        assertEquals(0.20716, e.value(), 1e-5);
        assertEquals(-0.0170216, e.initialEnergy(), 1e-7);
        assertTrue(e.value() - e.initialEnergy() > e.bound());
        assertTrue(e.getMessage().startsWith("stopped at step 5 (t = 0.25 s): energy 0.207"), e.getMessage());
        assertEquals(5, energies.size(), "the start and steps 1..4 were handed on, step 5 was not");
        for (double en : energies) assertTrue(en - e.initialEnergy() <= e.bound());
        assertEquals(0.072384, energies.get(4), 1e-6);
        assertEquals(energies.get(4), ode.energy(y), 0.0 + 1e-15, "y holds the last accepted state");
    }

    /** The same start with RK4 at the same large step stays inside the bound (the guard is not merely strict). */
    @Test
    void rk4AtTheSameStepIsNotStopped() {
        FingerDynamicsOde ode = ode(1, G);
        FreeSwing.Result r = FreeSwing.run(ode, new RungeKutta4(6), new double[6], 0.05, 1.0, null, null);
        assertEquals(20, r.steps());
        assertTrue(r.worstGrowth() < 0.05 * new EnergyGuard(ode, new double[6]).scale(), "growth " + r.worstGrowth());
    }

    private static Integrator faulty(boolean nan) {
        RungeKutta4 rk = new RungeKutta4(6);
        return new Integrator() {
            int calls;
            public String name() { return "faulty"; }
            public int order() { return 4; }
            public int dimension() { return 6; }
            public long evaluations() { return rk.evaluations(); }
            public boolean step(Ode ode, double t, double[] y, double h) {
                if (++calls < 3) return rk.step(ode, t, y, h);
                if (!nan) return false;
                y[4] = Double.NaN;
                return true;
            }
        };
    }

    @Test
    void aNonFiniteStateOrAFailedStepStopsTheRunAtThatStep() {
        FingerDynamicsOde ode = ode(1, G);
        double[] y = {0.1, 0.2, 0.3, 0, 0, 0};
        IntegrationStoppedException nan = assertThrows(IntegrationStoppedException.class,
            () -> FreeSwing.run(ode, faulty(true), y, 0.01, 1.0, null, null));
        assertEquals(IntegrationStoppedException.Reason.NON_FINITE, nan.reason());
        assertEquals(3, nan.step());
        assertEquals(0.03, nan.time(), 1e-15);
        assertTrue(Double.isNaN(nan.value()));
        assertTrue(nan.getMessage().contains("qd2"), nan.getMessage());
        for (double v : y) assertFalse(Double.isNaN(v), "the NaN state was not kept");
        IntegrationStoppedException failed = assertThrows(IntegrationStoppedException.class,
            () -> FreeSwing.run(ode, faulty(false), new double[] {0.1, 0.2, 0.3, 0, 0, 0}, 0.01, 1.0, null, null));
        assertEquals(IntegrationStoppedException.Reason.STEP_FAILED, failed.reason());
        assertEquals(3, failed.step());
        assertTrue(failed.getMessage().startsWith("stopped at step 3 (t = 0.03 s): faulty could not take the step"), failed.getMessage());
    }

    @Test
    void theLastStepIsClippedToTheDuration() {
        assertEquals(4, FreeSwing.steps(0.3, 1.0));
        assertEquals(1000, FreeSwing.steps(0.001, 1.0));
        assertEquals(3, FreeSwing.steps(0.1, 0.3));
        List<Double> times = new ArrayList<>();
        // at rest without gravity: steps of 0.3 s under gravity would swing the light outer link
        // faster than RK4 can follow, and the guard would stop the run; only the times matter here
        FreeSwing.run(ode(2, new double[3]), new RungeKutta4(6), new double[6], 0.3, 1.0, (s, t, y, e) -> times.add(t), null);
        assertEquals(List.of(0.0, 0.3, 0.6, 0.9, 1.0), times, "step × dt in decimal (process.StepClock): 0.9, not 3 × 0.3 = 0.8999999999999999");
        assertThrows(IllegalArgumentException.class, () -> FreeSwing.steps(0, 1));
    }

    /** At rest without gravity nothing moves and the scale is 0: the absolute floor keeps the guard quiet. */
    @Test
    void aChainAtRestWithoutGravityIsNotStopped() {
        double[] g0 = new double[3];
        FingerDynamicsOde ode = ode(1, g0);
        double[] y = {0.3, 0.4, 0.5, 0, 0, 0};
        assertEquals(0.0, new EnergyGuard(ode, y).scale());
        FreeSwing.Result r = FreeSwing.run(ode, new ExplicitEuler(6), y, 0.01, 1.0, null, null);
        assertTrue(r.finalEnergy() == 0, "energy " + r.finalEnergy());
        assertEquals(0.3, y[0]);
    }
}
