package org.handsim.tradeoff;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.handsim.chart.StudyTable;
import org.handsim.dynamics.SemiImplicitEuler;
import org.junit.jupiter.api.Test;

/**
 * Study 4 (integrators on a free finger): the quick run's rows, and the drift behaving as each
 * method's order says. Values (finger 1, gravity off, 1 s, E(0) = 1.6255 mJ), the same to 1e-12
 * relative from the same integrators on Pinocchio's articulated-body algorithm
 * (tools/dynamics/pinocchio_reference.py's model): explicit Euler 9.66e-3 at 10 ms, 9.37e-4 at
 * 1 ms, 4.68e-4 at 0.5 ms; RK4 2.03e-8 at 10 ms, 1.48e-9 at 5 ms; semi-implicit Euler's worst
 * 1.98e-3 at 1 ms over 1 s and 1.53e-2 over 10 s.
 */
class IntegratorStudyTest {
    private static double order(String method, double dt) {
        double coarse = IntegratorStudy.measure(method, dt, 1.0).drift();
        double fine = IntegratorStudy.measure(method, dt / 2, 1.0).drift();
        return Math.log(coarse / fine) / Math.log(2);
    }

    @Test
    void theQuickRunHasEveryMethodAtThreeSettingsAndOneDefault() {
        StudyTable t = new IntegratorStudy().run(true, null);
        assertEquals("4-integrators", t.id());
        assertEquals("series,setting,default,dt_s,tolerance,steps,evaluations,wall_s,drift,worst_drift", t.csvHeader());
        assertEquals(List.of("explicit Euler", "semi-implicit Euler", "RK4", "Dormand-Prince 5(4)"), t.series());
        assertEquals(12, t.rows().size());
        int defaults = 0;
        for (StudyTable.Row r : t.rows()) {
            double drift = t.value(r, "drift"), steps = t.value(r, "steps"), evals = t.value(r, "evaluations");
            assertTrue(drift > 0 && drift < 0.02, r.series() + " " + r.setting() + ": drift " + drift);
            assertTrue(t.value(r, "worst_drift") >= drift, r.setting());
            assertTrue(t.value(r, "wall_s") > 0, r.setting());
            if (r.series().equals("Dormand-Prince 5(4)")) {
                assertEquals(1.0, t.value(r, "dt_s"));
                assertTrue(evals > 6 * steps && evals <= 1 + 6 * steps + 60, r.setting() + ": " + evals + " evaluations for " + steps + " steps");
            } else {
                assertTrue(Double.isNaN(t.value(r, "tolerance")));
                assertEquals(Math.round(1.0 / t.value(r, "dt_s")), (long) steps, r.setting());
                assertEquals(r.series().equals("RK4") ? 4 * steps : steps, evals, r.setting());
            }
            if (r.isDefault()) {
                defaults++;
                assertEquals("RK4", r.series());
                assertEquals("1 ms", r.setting());
            }
        }
        assertEquals(1, defaults);
        assertFalse(t.notes().containsKey("diverged"));
        assertTrue(t.notes().get("capped").startsWith("Dormand-Prince called every 1 ms (as handsim swing does, tol 1e-10): 1000 steps, 6001 evaluations"),
            t.notes().get("capped"));
        StudyTable.Row euler10 = t.rows("explicit Euler").get(0);
        assertEquals("10 ms", euler10.setting());
        assertEquals(9.659405e-3, t.value(euler10, "drift"), 1e-8);
        assertEquals(2.031097e-8, t.value(t.rows("RK4").get(0), "drift"), 1e-13);
    }

    @Test
    void theDriftFallsAtEachFixedStepMethodsOrder() {
        double euler = order(IntegratorStudy.EULER, 0.001), semi = order(IntegratorStudy.SEMI, 0.001);
        double rk4 = order(IntegratorStudy.RK4, 0.01), rk4b = order(IntegratorStudy.RK4, 0.004);
        assertEquals(1, euler, 0.2, "explicit Euler");
        assertEquals(1, semi, 0.2, "semi-implicit Euler");
        assertEquals(4, rk4, 0.3, "RK4 from 10 to 5 ms");
        assertEquals(4, rk4b, 0.3, "RK4 from 4 to 2 ms");
    }

    /** The adaptive method's drift follows its tolerance: below 30·tol, and 1000 times smaller per 1e4 tighter tolerance. */
    @Test
    void dormandPrincesDriftFollowsItsTolerance() {
        double prev = Double.POSITIVE_INFINITY;
        for (double tol : new double[] {1e-4, 1e-8, 1e-12}) {
            IntegratorStudy.Measure m = IntegratorStudy.measure(IntegratorStudy.DOPRI, tol, 1.0);
            assertNull(m.diverged());
            assertTrue(m.drift() < 30 * tol, "tol " + tol + ": drift " + m.drift());
            assertTrue(m.drift() < prev / 1000, "tol " + tol + ": drift " + m.drift() + " after " + prev);
            prev = m.drift();
        }
    }

    /**
     * Semi-implicit Euler's energy error: bounded where it is symplectic (a constant mass matrix,
     * the harmonic oscillator: the worst error over 100 periods is that of the first), but not on
     * the finger, whose mass matrix D(q) varies: there the velocity form {@code v ← v + h·a(q, v),
     * q ← q + h·v} is not symplectic and the drift grows with time (×7.7 from 1 s to 10 s at
     * 1 ms, as Pinocchio's dynamics integrated the same way gives). RK4's stays below 1e-10 over
     * the same 10 s (3.9e-11).
     */
    @Test
    void semiImplicitEulerIsBoundedOnlyWhereItIsSymplectic() {
        SemiImplicitEuler e = new SemiImplicitEuler(1);
        org.handsim.dynamics.Ode osc = new org.handsim.dynamics.Ode() {
            public int dimension() { return 2; }
            public boolean derivative(double t, double[] y, double[] yDot) {
                yDot[0] = y[1];
                yDot[1] = -4 * y[0];
                return true;
            }
        };
        double[] y = {1, 0};
        double h = 0.01, worstFirst = 0, worstAll = 0;
        int period = (int) Math.round(Math.PI / h); // 2π/ω with ω = 2
        for (int i = 0; i < 100 * period; i++) {
            e.step(osc, i * h, y, h);
            double err = Math.abs(0.5 * y[1] * y[1] + 2 * y[0] * y[0] - 2) / 2;
            if (i < period) worstFirst = Math.max(worstFirst, err);
            worstAll = Math.max(worstAll, err);
        }
        assertTrue(worstFirst > 1e-3, "the error is O(h), not zero: " + worstFirst);
        assertTrue(worstAll < 1.1 * worstFirst, "oscillator: worst " + worstAll + " over 100 periods, " + worstFirst + " over the first");

        double one = IntegratorStudy.measure(IntegratorStudy.SEMI, 0.001, 1.0).worstDrift();
        double ten = IntegratorStudy.measure(IntegratorStudy.SEMI, 0.001, 10.0).worstDrift();
        assertEquals(1.9776e-3, one, 0.001e-3);
        assertTrue(ten > 5 * one && ten < 16 * one, "finger: worst drift " + ten + " over 10 s, " + one + " over 1 s");
        assertTrue(IntegratorStudy.measure(IntegratorStudy.RK4, 0.001, 10.0).worstDrift() < 1e-10);
    }
}
