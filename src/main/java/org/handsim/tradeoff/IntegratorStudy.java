package org.handsim.tradeoff;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import org.handsim.chart.StudyTable;
import org.handsim.dynamics.ClosedFormFinger;
import org.handsim.dynamics.DormandPrince54;
import org.handsim.dynamics.FingerDynamicsOde;
import org.handsim.dynamics.Integrator;
import org.handsim.dynamics.IntegratorKind;
import org.handsim.dynamics.LinkChain;

/**
 * Chart 4: the forward-dynamics integrators (explicit Euler, semi-implicit Euler, RK4 and the
 * adaptive Dormand–Prince 5(4)) on a free finger: finger 1, all three joints, zero torque,
 * gravity off, from q = (0.2, 0.5, 0.4) rad, q̇ = (1.5, −2, 3) rad/s (the state of
 * EnergyConservationTest), integrated over 1 s. With no torque and no gravity the kinetic
 * energy is conserved, so its drift is the integrator's error. y: the relative energy drift
 * {@code |E(1 s) − E(0)| / E(0)} (the CSV also has the worst drift over the step ends; the
 * adaptive method is called once for the second, so for it the two agree); x: the median wall
 * time of the 1 s integration (without the energy evaluations). Settings: dt from 10 ms to 10 µs for the fixed-step methods, the tolerance
 * (absolute = relative) from 1e-3 to 1e-12 for Dormand–Prince. Default: RK4 at 1 ms, what
 * {@code handsim swing} uses.
 */
public final class IntegratorStudy implements Study {
    static final double[] DTS = {0.01, 0.005, 0.002, 0.001, 0.0005, 0.0002, 0.0001, 0.00005, 0.00002, 0.00001};
    static final double[] QUICK_DTS = {0.01, 0.001, 0.0001};
    static final double[] TOLS = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
    static final double[] QUICK_TOLS = {1e-4, 1e-8, 1e-12};
    static final int FINGER = 1;
    static final double[] START = {0.2, 0.5, 0.4, 1.5, -2, 3};
    static final double DURATION = 1.0;
    /**
     * The output step of the adaptive method: it is called once for the whole second and
     * chooses its own internal steps (with a shorter output step, its steps are capped by the
     * output step and loose tolerances all give the same run).
     */
    static final double OUTPUT_DT = DURATION;
    static final double DEFAULT_DT = 0.001;

    static final String EULER = IntegratorKind.EULER.label(), SEMI = IntegratorKind.SEMI_IMPLICIT.label(),
        RK4 = IntegratorKind.RK4.label(), DOPRI = IntegratorKind.DOPRI.label();
    static final List<String> METHODS = List.of(EULER, SEMI, RK4, DOPRI);
    static final List<String> COLUMNS = List.of("dt_s", "tolerance", "steps", "evaluations", "wall_s", "drift", "worst_drift");

    @Override
    public String id() {
        return "4-integrators";
    }

    /** A fresh integrator: {@code setting} is dt for the fixed-step methods, the tolerance for Dormand–Prince. */
    static Integrator integrator(String method, double setting) {
        return IntegratorKind.named(method).create(3, setting);
    }

    static FingerDynamicsOde freeFinger() {
        return new FingerDynamicsOde(new ClosedFormFinger(LinkChain.finger(FINGER)), new double[3], FingerDynamicsOde.Torques.ZERO);
    }

    /** The step the method is called with: dt, or the output step for Dormand–Prince. */
    static double callStep(String method, double setting) {
        return method.equals(DOPRI) ? OUTPUT_DT : setting;
    }

    /**
     * The outcome of one integration: internal steps, evaluations of f, the relative drift at
     * the end and the worst over the step ends (both +∞ if the run diverged), and why it
     * diverged (null if it did not).
     */
    record Measure(long steps, long evaluations, double drift, double worstDrift, String diverged) {}

    /** Integrates the free finger over {@code duration} and follows the energy after every call of the integrator. */
    static Measure measure(String method, double setting, double duration) {
        return measure(method, setting, duration, callStep(method, setting));
    }

    /** As {@link #measure(String, double, double)}, calling the integrator every {@code h} seconds. */
    static Measure measure(String method, double setting, double duration, double h) {
        FingerDynamicsOde ode = freeFinger();
        Integrator in = integrator(method, setting);
        double[] y = START.clone();
        double e0 = ode.energy(y), worst = 0, e = e0;
        long n = Math.round(duration / h);
        for (long i = 0; i < n; i++) {
            double t = i * h;
            if (!in.step(ode, t, y, h)) {
                return new Measure(steps(in, i), in.evaluations(), Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                    String.format(Locale.ROOT, "step failed at t = %.4g s", t + h));
            }
            e = ode.energy(y);
            if (!Double.isFinite(e)) {
                return new Measure(steps(in, i + 1), in.evaluations(), Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                    String.format(Locale.ROOT, "energy not finite at t = %.4g s", t + h));
            }
            worst = Math.max(worst, Math.abs(e - e0));
        }
        return new Measure(steps(in, n), in.evaluations(), Math.abs(e - e0) / e0, worst / e0, null);
    }

    private static long steps(Integrator in, long calls) {
        return in instanceof DormandPrince54 ? ((DormandPrince54) in).acceptedSteps() : calls;
    }

    /** The timed work: the same integration without the energy evaluations; returns a state value. */
    static double integrate(String method, double setting, FingerDynamicsOde ode) {
        return integrate(method, setting, ode, callStep(method, setting));
    }

    static double integrate(String method, double setting, FingerDynamicsOde ode, double h) {
        Integrator in = integrator(method, setting);
        double[] y = START.clone();
        long n = Math.round(DURATION / h);
        for (long i = 0; i < n; i++) {
            if (!in.step(ode, i * h, y, h)) return Double.NaN;
        }
        return y[0];
    }

    @Override
    public StudyTable run(boolean quick, DoubleConsumer progress) {
        double[] dts = quick ? QUICK_DTS : DTS, tols = quick ? QUICK_TOLS : TOLS;
        StudyTable t = new StudyTable(id(), "Integrators: wall time against energy drift (free finger 1, gravity off, 1 s)", COLUMNS,
            "wall_s", "drift", "wall time of the 1 s integration (s, log)", "relative energy drift after 1 s (log)");
        FingerDynamicsOde ode = freeFinger();
        t.note("setup", String.format(Locale.ROOT,
            "finger 1, zero torque, gravity off, q0 = (0.2, 0.5, 0.4) rad, qd0 = (1.5, -2, 3) rad/s, E(0) = %.6g J (kinetic only)",
            ode.energy(START.clone())));
        t.note("drift", "drift = |E(1 s) - E(0)| / E(0) (CSV: worst_drift = max over step ends); Dormand-Prince: one call for the second, tol = abs = rel");
        t.note("semi", "semi-implicit Euler in (q, qd) is symplectic only for a constant mass matrix: with D(q) its drift grows with time");
        t.note("default", "default: RK4 at dt = 1 ms, the default of handsim swing (fourth order at four evaluations a step)");
        // warm the JIT on every method first, so the first timed method is not charged for it
        for (String method : METHODS) {
            double s = method.equals(DOPRI) ? 1e-8 : DEFAULT_DT;
            for (int i = 0; i < (quick ? 3 : 20); i++) integrate(method, s, ode);
        }
        int total = 3 * dts.length + tols.length, done = 0;
        List<String> diverged = new ArrayList<>();
        for (String method : METHODS) {
            double[] settings = method.equals(DOPRI) ? tols : dts;
            for (double s : settings) {
                Measure m = measure(method, s, DURATION);
                Timing.Result<Double> time = Timing.median(() -> integrate(method, s, ode), quick ? 1 : 5, quick ? 3 : 41, quick ? 0.05 : 0.5);
                boolean dopri = method.equals(DOPRI);
                String label = dopri ? String.format(Locale.ROOT, "%.0e", s) : DtStudy.ms(s);
                t.add(method, label, method.equals(RK4) && s == DEFAULT_DT,
                    dopri ? OUTPUT_DT : s, dopri ? s : Double.NaN, m.steps(), m.evaluations(), time.medianSeconds(), m.drift(), m.worstDrift());
                if (m.diverged() != null) diverged.add(method + " at " + label + " (" + m.diverged() + ")");
                if (progress != null) progress.accept((double) ++done / total);
            }
        }
        // the adaptive method as handsim swing runs it: called every 1 ms, its steps capped by that
        Measure capped = measure(DOPRI, 1e-10, DURATION, DEFAULT_DT);
        double cappedTime = Timing.median(() -> integrate(DOPRI, 1e-10, ode, DEFAULT_DT), quick ? 1 : 5, quick ? 3 : 41, quick ? 0.05 : 0.5).medianSeconds();
        t.note("capped", String.format(Locale.ROOT,
            "Dormand-Prince called every 1 ms (as handsim swing does, tol 1e-10): %d steps, %d evaluations, drift %.1e, %.2g s (not plotted)",
            capped.steps(), capped.evaluations(), capped.drift(), cappedTime));
        if (!diverged.isEmpty()) t.note("diverged", "diverged (drift = Infinity in the CSV, not plotted): " + String.join("; ", diverged));
        return t;
    }
}
