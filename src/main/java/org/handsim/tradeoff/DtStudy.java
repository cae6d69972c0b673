package org.handsim.tradeoff;

import java.util.List;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import org.handsim.chart.StudyTable;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;

/**
 * Chart 1: the time step dt on the paper's experiment (scenarios/paper-breakaway.json, finger 3
 * against the cube). For each dt from 0.05 to 20 ms: the wall time per simulated second (median
 * of timed runs without a trace, work saving on, as {@code handsim run} does it) against the
 * relative error of three results — the breakaway time, the peak τ32 and the peak contact force
 * — measured against a reference run at dt = 0.01 ms, and of the τ32 trace itself (RMS of the
 * coarse trace, linearly interpolated, minus the reference, over the peak). The events are
 * located inside the step (HandModel), so the three results hardly depend on dt; the trace does.
 * The default is the scenario's dt (1 ms).
 */
public final class DtStudy implements Study {
    /** Time steps of the full run, seconds. */
    static final double[] DTS = {0.00005, 0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02};
    static final double[] QUICK_DTS = {0.0002, 0.001, 0.005, 0.02};
    static final double REFERENCE_DT = 0.00001, QUICK_REFERENCE_DT = 0.00005;
    static final int FINGER = 3;

    static final List<String> COLUMNS = List.of("dt_s", "steps", "wall_s_per_sim_s", "value", "reference", "abs_error", "rel_error");

    private final Scenario scenario;

    public DtStudy() {
        this(Scenario.load(Home.paperScenario()));
    }

    public DtStudy(Scenario scenario) {
        this.scenario = scenario;
    }

    @Override
    public String id() {
        return "1-dt";
    }

    /** The results a run of the paper's experiment is judged by (finger 3), and its τ32 trace. */
    record Outcome(double breakawayTime, double peakTau32, double peakForce, long steps, double[] tau32) {
        double[] values() { return new double[] {breakawayTime, peakTau32, peakForce}; }
    }

    static final String[] SERIES = {"breakaway time", "peak tau32", "peak contact force", "tau32 trace (RMS / peak)"};

    /** Runs the scenario and returns its outcome (peaks over every step, τ32 at every step). */
    static Outcome outcome(Scenario s) {
        HandModel m = Simulation.model(s, false);
        double[] trace = new double[(int) m.totalSteps() + 1];
        trace[0] = m.torques(FINGER)[2];
        double peakTau = Math.abs(trace[0]);
        while (m.running()) {
            m.step();
            double tau = m.torques(FINGER)[2];
            trace[(int) m.stepIndex()] = tau;
            peakTau = Math.max(peakTau, Math.abs(tau));
        }
        return new Outcome(m.breakawayTime(FINGER), peakTau, m.maxContactForce(FINGER), m.stepIndex(), trace);
    }

    /**
     * RMS over the reference's steps of (the coarse τ32 trace, linearly interpolated as a chart
     * draws it) − (the reference trace): what a coarser dt loses between its samples.
     */
    static double traceRms(Outcome coarse, double coarseDt, Outcome ref, double refDt) {
        double sum = 0;
        int n = ref.tau32().length;
        double[] c = coarse.tau32();
        for (int i = 0; i < n; i++) {
            double x = i * refDt / coarseDt;
            int j = Math.min((int) Math.floor(x), c.length - 2);
            double f = Math.min(1, x - j);
            double v = c[j] + f * (c[j + 1] - c[j]);
            double d = v - ref.tau32()[i];
            sum += d * d;
        }
        return Math.sqrt(sum / n);
    }

    @Override
    public StudyTable run(boolean quick, DoubleConsumer progress) {
        double[] dts = quick ? QUICK_DTS : DTS;
        double refDt = quick ? QUICK_REFERENCE_DT : REFERENCE_DT;
        StudyTable t = new StudyTable(id(), "Time step: wall time against error (paper experiment, finger 3)", COLUMNS,
            "wall_s_per_sim_s", "rel_error", "wall time per simulated second (s, log)", "relative error against dt = "
                + ms(refDt) + " (log)");
        Outcome ref = outcome(scenario.withDt(refDt));
        double[] refValues = ref.values();
        t.note("reference", String.format(Locale.ROOT,
            "reference dt = %s: breakaway %.9f s, peak tau32 %.6f N*m, peak force %.6f N; points: dt from %s to %s, default %s (the scenario's)",
            ms(refDt), ref.breakawayTime(), ref.peakTau32(), ref.peakForce(), ms(dts[0]), ms(dts[dts.length - 1]), ms(scenario.dt())));
        if (progress != null) progress.accept(0.3);
        for (int i = 0; i < dts.length; i++) {
            Scenario s = scenario.withDt(dts[i]);
            Outcome o = outcome(s);
            Timing.Result<Double> time = Timing.median(() -> {
                HandModel m = Simulation.model(s, false);
                m.run(null);
                return m.breakawayTime(FINGER);
            }, quick ? 1 : 3, quick ? 3 : 15, quick ? 0.1 : 1.0);
            double perSimSecond = time.medianSeconds() / s.duration();
            double[] v = o.values();
            for (int j = 0; j < v.length; j++) {
                double abs = Math.abs(v[j] - refValues[j]);
                t.add(SERIES[j], ms(dts[i]), dts[i] == scenario.dt(),
                    dts[i], o.steps(), perSimSecond, v[j], refValues[j], abs, abs / Math.abs(refValues[j]));
            }
            double rms = traceRms(o, dts[i], ref, refDt);
            t.add(SERIES[3], ms(dts[i]), dts[i] == scenario.dt(), dts[i], o.steps(), perSimSecond, rms, 0, rms, rms / ref.peakTau32());
            if (progress != null) progress.accept(0.3 + 0.7 * (i + 1) / dts.length);
        }
        return t;
    }

    static String ms(double dt) {
        double v = dt * 1000;
        return (v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v)) + " ms";
    }
}
