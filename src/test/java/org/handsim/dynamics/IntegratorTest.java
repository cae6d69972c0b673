package org.handsim.dynamics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The integrators' order is a test, not a claim (docs/STYLE.md, item 11, after Hipparchus'
 * {@code doTestDecreasingSteps}): on problems with an exact solution the global error at a
 * fixed end time must shrink by 2ᵖ when the step halves.
 */
class IntegratorTest {
    /** x'' = −ω²x, x(0) = 1, x'(0) = 0: x = cos ωt, v = −ω sin ωt. State (x, v). */
    static final class Oscillator implements Ode {
        final double w;
        int calls;

        Oscillator(double w) {
            this.w = w;
        }

        @Override
        public int dimension() {
            return 2;
        }

        @Override
        public boolean derivative(double t, double[] y, double[] yDot) {
            calls++;
            yDot[0] = y[1];
            yDot[1] = -w * w * y[0];
            return true;
        }

        double error(double t, double[] y) {
            return Math.max(Math.abs(y[0] - Math.cos(w * t)), Math.abs(y[1] + w * Math.sin(w * t)));
        }
    }

    /** y' = y·cos t, y(0) = 1: y = exp(sin t) (non-autonomous; T = 1). */
    static final class Exponential implements Ode {
        @Override
        public int dimension() {
            return 1;
        }

        @Override
        public boolean derivative(double t, double[] y, double[] yDot) {
            yDot[0] = y[0] * Math.cos(t);
            return true;
        }

        static double exact(double t) {
            return Math.exp(Math.sin(t));
        }
    }

    private interface Stepper {
        boolean step(Ode ode, double t, double[] y, double h);
    }

    /** Global error at T = 1 with N equal steps. */
    private static double oscillatorError(Stepper s, int steps) {
        Oscillator ode = new Oscillator(2.0);
        double[] y = {1, 0};
        double h = 1.0 / steps;
        for (int i = 0; i < steps; i++) assertTrue(s.step(ode, i * h, y, h));
        return ode.error(1.0, y);
    }

    private static double exponentialError(Stepper s, int steps) {
        Exponential ode = new Exponential();
        double[] y = {1};
        double h = 1.0 / steps;
        for (int i = 0; i < steps; i++) assertTrue(s.step(ode, i * h, y, h));
        return Math.abs(y[0] - Exponential.exact(1.0));
    }

    /** Halves the step three times from N; every observed order log2(e(h)/e(h/2)) within ±0.15 of p. */
    private static void assertOrder(String name, int p, int n0, java.util.function.ToDoubleFunction<Integer> error) {
        double prev = error.applyAsDouble(n0);
        for (int n = 2 * n0; n <= 8 * n0; n *= 2) {
            double e = error.applyAsDouble(n);
            double observed = Math.log(prev / e) / Math.log(2);
            assertEquals(p, observed, 0.15, name + ": observed order " + observed + " from N = " + n / 2 + " to " + n
                + " (errors " + prev + ", " + e + ")");
            prev = e;
        }
    }

    @Test
    void explicitEulerIsFirstOrder() {
        ExplicitEuler e = new ExplicitEuler(2), e1 = new ExplicitEuler(1);
        assertOrder("euler/oscillator", 1, 400, n -> oscillatorError(e::step, n));
        assertOrder("euler/exponential", 1, 400, n -> exponentialError(e1::step, n));
        assertEquals(1, e.order());
    }

    @Test
    void semiImplicitEulerIsFirstOrder() {
        SemiImplicitEuler e = new SemiImplicitEuler(1);
        assertEquals(2, e.dimension());
        assertOrder("semi-implicit euler/oscillator", 1, 400, n -> oscillatorError(e::step, n));
    }

    @Test
    void rungeKutta4IsFourthOrder() {
        RungeKutta4 rk = new RungeKutta4(2), rk1 = new RungeKutta4(1);
        assertOrder("rk4/oscillator", 4, 10, n -> oscillatorError(rk::step, n));
        assertOrder("rk4/exponential", 4, 10, n -> exponentialError(rk1::step, n));
        Oscillator ode = new Oscillator(1);
        long before = rk.evaluations();
        rk.step(ode, 0, new double[] {1, 0}, 0.1);
        assertEquals(4, rk.evaluations() - before);
    }

    @Test
    void dormandPrinceFixedStepIsFifthOrder() {
        DormandPrince54 dp = new DormandPrince54(2, 1e-9, 1e-9), dp1 = new DormandPrince54(1, 1e-9, 1e-9);
        assertOrder("dopri5/oscillator", 5, 10, n -> oscillatorError(dp::fixedStep, n));
        assertOrder("dopri5/exponential", 5, 10, n -> exponentialError(dp1::fixedStep, n));
    }

    /**
     * The adaptive method tracks its tolerance: over 10 s of the oscillator (about three
     * periods) the global error stays within 20·tol and falls about tenfold per tenfold tighter
     * tolerance (measured: error ≈ 11·tol from 1e-4 to 1e-12).
     */
    @Test
    void dormandPrinceControlsTheError() {
        double prevError = Double.POSITIVE_INFINITY;
        for (double tol = 1e-5; tol >= 1e-11; tol /= 10) {
            DormandPrince54 dp = new DormandPrince54(2, tol, tol);
            Oscillator ode = new Oscillator(2.0);
            double[] y = {1, 0};
            assertTrue(dp.step(ode, 0, y, 10.0));
            double e = ode.error(10.0, y);
            assertTrue(e < 20 * tol, "tol " + tol + ": error " + e);
            assertTrue(e < prevError / 5, "tol " + tol + ": error " + e + " after " + prevError);
            prevError = e;
        }
    }

    /** Output steps of 0.1 s cover the interval exactly; FSAL saves one evaluation per internal step. */
    @Test
    void dormandPrinceCoversEachRequestedIntervalAndReusesTheLastStage() {
        DormandPrince54 dp = new DormandPrince54(2, 1e-10, 1e-10);
        Oscillator ode = new Oscillator(2.0);
        double[] y = {1, 0};
        for (int i = 0; i < 100; i++) assertTrue(dp.step(ode, i * 0.1, y, 0.1));
        assertTrue(ode.error(10.0, y) < 20e-10, "error " + ode.error(10.0, y));
        assertEquals(ode.calls, dp.evaluations());
        assertEquals(1 + 6 * (dp.acceptedSteps() + dp.rejectedSteps()), dp.evaluations(), "6 new stages per attempt, one first stage");
        assertTrue(dp.acceptedSteps() >= 100);
    }

    @Test
    void aFailedRightHandSideLeavesTheStateUnchanged() {
        Ode failing = new Ode() {
            @Override
            public int dimension() {
                return 2;
            }

            @Override
            public boolean derivative(double t, double[] y, double[] yDot) {
                yDot[0] = y[1];
                yDot[1] = -y[0];
                return t < 0.05; // undefined from t = 0.05 on
            }
        };
        Integrator[] all = {new ExplicitEuler(2), new SemiImplicitEuler(1), new RungeKutta4(2), new DormandPrince54(2, 1e-8, 1e-8)};
        for (Integrator in : all) {
            double[] y = {1, 0.5};
            assertTrue(in.step(failing, 0, y, 0.01), in.name() + " first step");
            double[] before = y.clone();
            assertFalse(in.step(failing, 0.05, y, 0.1), in.name());
            assertArrayEquals(before, y, in.name() + " state unchanged");
        }
    }

    /**
     * A failure after accepted internal steps: Dormand–Prince must restore the state of the
     * call's start, not keep the part of the interval it had covered (f undefined from
     * t = 0.08; the call covers 0.01 to 0.11 and accepts a step before it reaches 0.08).
     */
    @Test
    void dormandPrinceRollsBackItsAcceptedInternalStepsWhenALaterOneFails() {
        Ode failing = new Ode() {
            @Override
            public int dimension() {
                return 2;
            }

            @Override
            public boolean derivative(double t, double[] y, double[] yDot) {
                yDot[0] = y[1];
                yDot[1] = -y[0];
                return t < 0.08;
            }
        };
        DormandPrince54 dp = new DormandPrince54(2, 1e-8, 1e-8);
        double[] y = {1, 0.5};
        assertTrue(dp.step(failing, 0, y, 0.01));
        double[] before = y.clone();
        long accepted = dp.acceptedSteps();
        assertFalse(dp.step(failing, 0.01, y, 0.1));
        assertTrue(dp.acceptedSteps() > accepted, "an internal step was accepted before the failure");
        assertArrayEquals(before, y, "state of the call's start restored");
        // and the remembered stage is not reused: a fresh call from there succeeds on a defined interval
        assertTrue(dp.step(failing, 0.01, y, 0.05));
    }

    @Test
    void misuseIsAnException() {
        RungeKutta4 rk = new RungeKutta4(2);
        Oscillator ode = new Oscillator(1);
        assertThrows(IllegalArgumentException.class, () -> rk.step(ode, 0, new double[] {1, 0}, 0));
        assertThrows(IllegalArgumentException.class, () -> rk.step(ode, 0, new double[] {1, 0}, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new RungeKutta4(3).step(ode, 0, new double[3], 0.1));
        assertThrows(IllegalArgumentException.class, () -> new DormandPrince54(2, 0, 1e-6));
        assertThrows(IllegalArgumentException.class, () -> new ExplicitEuler(0));
    }
}
