package org.handsim.cli;

import org.handsim.text.SafeText;
import org.handsim.text.Decimal;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.dynamics.ChainDynamics;
import org.handsim.dynamics.DormandPrince54;
import org.handsim.dynamics.FingerDynamicsOde;
import org.handsim.dynamics.FreeSwing;
import org.handsim.dynamics.HandDynamics;
import org.handsim.dynamics.Integrator;
import org.handsim.dynamics.IntegratorKind;
import org.handsim.dynamics.IntegrationStoppedException;
import org.handsim.dynamics.LinkChain;
import org.handsim.files.AtomicFile;
import org.handsim.hand.InputRanges;
import org.handsim.text.JsonWriter;
import org.handsim.files.OutputSet;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code handsim swing}: one free finger (zero joint torques: clutch disengaged, motor off, no
 * friction, no joint stops) swinging under gravity, integrated with a chosen method. Output
 * contract: DIR/swing.csv ({@link #HEADER}: the start state, then one row per step) and
 * DIR/swing.json ({@link #JSON_KEYS}), both written through {@link AtomicFile} and committed
 * only when the run completes. {@code energy_drift_rel} is {@code |E(T) − E(0)|} over
 * {@code max(|E(0)|, the largest kinetic energy of the run)} (the potential's zero, at the base
 * origin, is arbitrary). {@code wall_time_s} is the integration including the CSV formatting. A run stopped by the energy guard exits 4 and writes nothing;
 * files of an earlier run in DIR are left as they were (never deleted, never touched).
 */
@Command(name = "swing", mixinStandardHelpOptions = true,
    description = {"One free finger swinging under gravity, energy-guarded.",
        "Zero joint torques (clutch disengaged, motor off), no friction, no joint",
        "stops. Writes DIR/swing.csv, header",
        "  t_s,q1_rad,q2_rad,q3_rad,qd1_rad_s,qd2_rad_s,qd3_rad_s,energy_J",
        "(the start, then one row per step), and DIR/swing.json (finger,",
        "integrator, dt_s, steps, duration_s, energy_initial_J, energy_final_J,",
        "energy_drift_rel, wall_time_s). A guard stops the run (exit 4, nothing",
        "written, earlier files in DIR left untouched) when a state value is not",
        "finite, a step fails, or the energy grows by more than 50 %% of the",
        "energy scale (the largest kinetic energy the finger can reach)."})
public final class SwingCommand implements Callable<Integer> {
    /** The files of a swing's folder: swing.json is published last. */
    static final OutputSet.Layout LAYOUT = new OutputSet.Layout("swing.json", "swing\\.(csv|json)");
    static final String HEADER = "t_s,q1_rad,q2_rad,q3_rad,qd1_rad_s,qd2_rad_s,qd3_rad_s,energy_J";
    static final List<String> JSON_KEYS = List.of("finger", "integrator", "dt_s", "steps", "duration_s", "energy_initial_J",
        "energy_final_J", "energy_drift_rel", "wall_time_s");
    /** Absolute and relative tolerance of {@code --integrator dopri}. */
    static final double DOPRI_TOL = 1e-10;
    /** Most steps of one run (a CSV of about a gigabyte). */
    static final long MAX_STEPS = 10_000_000;

    @Spec CommandSpec spec;

    @Option(names = "--finger", paramLabel = "K", description = "finger 1, 2 or 3 (default 1)")
    Integer finger = 1;

    @Option(names = "--q", paramLabel = "a,b,c", description = {"start joint angles th_k1,th_k2,th_k3, rad",
        "(default 0,0,0; finger 3's first must be 0:",
        "it has no spread)"})
    String q = "0,0,0";

    @Option(names = "--qd", paramLabel = "a,b,c", description = "start joint velocities, rad/s (default 0,0,0)")
    String qd = "0,0,0";

    @Option(names = "--gravity", paramLabel = "gx,gy,gz", description = {"gravity in the finger base frame {k0}, m/s^2", "(default 0,0,-9.81)"})
    String gravity = "0,0,-9.81";

    @Option(names = "--integrator", paramLabel = "NAME", description = {"euler | semi-implicit | rk4 | dopri",
        "(default rk4; dopri: Dormand-Prince 5(4),",
        "tolerance 1e-10, adaptive inside each --dt)"})
    String integrator = "rk4";

    @Option(names = "--dt", paramLabel = "S", description = {"time step (dopri: the output step), seconds,", "in (0, 0.1] (default 0.001)"})
    double dt = 0.001;

    @Option(names = "--duration", paramLabel = "S", description = {"simulated time, seconds, in (0, 3600]", "(default 1)"})
    double duration = 1.0;

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default out/swing)")
    Path out = Path.of("out", "swing");

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        int k = Args.finger(finger);
        double[] q0 = Args.numbers("--q", q, 3, InputRanges.JOINT_ANGLE);
        double[] qd0 = Args.numbers("--qd", qd, 3, InputRanges.JOINT_SPEED);
        double[] g = Args.numbers("--gravity", gravity, 3, InputRanges.GRAVITY);
        if (!(dt > 0) || dt > 0.1) throw CliError.usage("handsim: --dt must be in (0, 0.1] seconds, got " + Args.typed(spec, "--dt"));
        if (!(duration > 0) || duration > 3600) throw CliError.usage("handsim: --duration must be in (0, 3600] seconds, got " + Args.typed(spec, "--duration"));
        double steps = Math.ceil(duration / dt - 1e-9);   // as a double: (long) of 3.6e303 would be 9223372036854775807
        if (steps > MAX_STEPS) {
            throw CliError.usage("handsim: --dt " + Decimal.format(dt) + " for --duration " + Decimal.format(duration) + " s needs "
                + Decimal.count(steps) + " steps, more than the limit of " + Decimal.count(MAX_STEPS) + " (a swing.csv of about a gigabyte)");
        }
        ChainDynamics dyn = HandDynamics.barrettHand().finger(k);
        LinkChain chain = dyn.chain();
        int n = chain.dof();
        double[] y = new double[2 * n];
        for (int j = 0; j < 3; j++) {
            int p = chain.dofOfLink(j);
            if (p >= 0) {
                y[p] = q0[j];
                y[n + p] = qd0[j];
            } else {
                if (q0[j] != chain.fixedValue(j)) {
                    throw CliError.usage("handsim: --q: finger " + k + " joint " + (j + 1) + " is fixed at " + chain.fixedValue(j) + " rad, got " + q0[j]);
                }
                if (qd0[j] != 0) throw CliError.usage("handsim: --qd: finger " + k + " joint " + (j + 1) + " is fixed, its velocity must be 0, got " + qd0[j]);
            }
        }
        Integrator in = integrator(integrator, n);
        FingerDynamicsOde ode = new FingerDynamicsOde(dyn, g, FingerDynamicsOde.Torques.ZERO);

        FreeSwing.Result result;
        double wall;
        try (OutputSet set = Args.outputSet(err, "--out", out, LAYOUT); AtomicFile csvFile = new AtomicFile(set.dir().resolve("swing.csv"))) {
            Path json = set.dir().resolve("swing.json");
            Writer w = csvFile.writer();
            w.write(HEADER);
            w.write('\n');
            StringBuilder row = new StringBuilder(256);
            double[] full = new double[6];
            FreeSwing.Sink sink = (step, t, state, energy) -> {
                for (int j = 0; j < 3; j++) {
                    int p = chain.dofOfLink(j);
                    full[j] = p >= 0 ? state[p] : chain.fixedValue(j);
                    full[3 + j] = p >= 0 ? state[n + p] : 0.0;
                }
                row.setLength(0);
                row.append(Args.csv(t));
                for (double v : full) row.append(',').append(Args.csv(v));
                row.append(',').append(Args.csv(energy)).append('\n');
                try {
                    w.append(row);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            };
            long t0 = System.nanoTime();
            try {
                result = FreeSwing.run(ode, in, y, dt, duration, sink, new ProgressBar(err, "handsim swing"));
            } catch (IntegrationStoppedException e) {
                throw new CliError(CliError.NUMERIC, "handsim: swing " + e.getMessage() + hint(in, e) + "; no output written");
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
            wall = (System.nanoTime() - t0) / 1e9;
            Map<String, Object> summary = new LinkedHashMap<>();
            summary.put("finger", k);
            summary.put("integrator", integrator);
            summary.put("dt_s", dt);
            summary.put("steps", result.steps());
            summary.put("duration_s", duration);
            summary.put("energy_initial_J", result.initialEnergy());
            summary.put("energy_final_J", result.finalEnergy());
            summary.put("energy_drift_rel", result.relativeDrift());
            summary.put("wall_time_s", wall);
            try (AtomicFile jsonFile = new AtomicFile(json)) {
                jsonFile.writer().write(JsonWriter.pretty(summary));
                csvFile.commit();
                jsonFile.commit();
            }
            set.publish();
        }
        stdout.println(String.format(Locale.ROOT,
            "finger %d, %s, dt = %s s: %d steps over %s s in %.3f s wall; energy %s J -> %s J (relative drift %.3g)",
            k, integrator, Decimal.format(dt), result.steps(), Decimal.format(duration), wall,
            Decimal.format(result.initialEnergy()), Decimal.format(result.finalEnergy()), result.relativeDrift()));
        stdout.println("wrote " + SafeText.escape(out.toString()) + "/{swing.csv, swing.json}");
        return 0;
    }

    static Integrator integrator(String name, int n) {
        try {
            return IntegratorKind.named(name).create(n, DOPRI_TOL);
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: --integrator must be euler, semi-implicit, rk4 or dopri, got '" + SafeText.quote(name) + "'");
        }
    }

    private String hint(Integrator in, IntegrationStoppedException e) {
        if (e.reason() == IntegrationStoppedException.Reason.STEP_FAILED && in instanceof DormandPrince54) return " (try a larger tolerance or a smaller --dt)";
        IntegratorKind kind = IntegratorKind.named(integrator);
        String what = kind == IntegratorKind.RK4 ? in.name() : kind.label();
        String alt = kind == IntegratorKind.RK4 ? "dopri or a smaller --dt" : "rk4 or a smaller --dt";
        return " (" + what + " is unstable at dt = " + dt + " s; try " + alt + ")";
    }
}
