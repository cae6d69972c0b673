package org.handsim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.body.ContactSolver;
import org.handsim.chart.ChartSet;
import org.handsim.chart.HoldTestChart;
import org.handsim.files.AtomicFile;
import org.handsim.files.OutputSet;
import org.handsim.hold.DirectionResult;
import org.handsim.hold.HoldReport;
import org.handsim.hold.HoldSettings;
import org.handsim.hold.HoldTest;
import org.handsim.hold.RampResult;
import org.handsim.model.SimulationException;
import org.handsim.process.SteadyTiming;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.text.JsonWriter;
import org.handsim.text.SafeText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code handsim hold-test}: does the grasp hold when the world pushes on the object? */
@Command(name = "hold-test", mixinStandardHelpOptions = true,
    description = {"Closes a scenario's grasp, frees the object and pushes it along six directions to see if it stays in the hand.",
        "DexGraspBench's test: close the fingers as the scenario says until they stall,",
        "lock every finger joint (the worms are not back-drivable), free the object",
        "(a fixed object is freed here, its mass from --mass or --density, else a free",
        "object's mass_kg/density_kg_m3/inertia_kg_m2, else its closed mesh at",
        "1000 kg/m3), and from that same state push its centre of mass",
        "with F (default 10 m/s2 x its mass) along -x, +x, -y, +y, -z, +z of the world",
        "frame for T seconds each, gravity off (--gravity keeps the scenario's).",
        "A direction holds if the object moves less than 5 cm and turns less than 15 deg",
        "throughout (--max-displacement, --max-rotation). --ramp also raises the force",
        "from 0 until the object moves 5 mm or turns 5 deg and ranks the directions by",
        "the force they held. Prints the six verdicts and writes hold-test.json,",
        "hold-test.csv and hold-test.png/.svg (displacement and rotation against time)",
        "into out/<scenario name>/ (or --out DIR). Exit 0 whatever the verdict."})
public final class HoldTestCommand implements Callable<Integer> {
    /** The files of a hold test in its folder: hold-test.json is published last. */
    static final OutputSet.Layout LAYOUT = new OutputSet.Layout("hold-test.json", "hold-test\\.(json|csv|png|svg)");

    @Spec CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENARIO", description = "scenario JSON file (e.g. scenarios/mug-grasp.json)")
    Path scenarioFile;

    @picocli.CommandLine.Mixin HandOptions hand = new HandOptions();

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default out/<scenario name>)")
    Path out;

    @Option(names = "--force", paramLabel = "N", description = "the push F, newtons (default 10 m/s2 x the object's mass)")
    Double force;

    @Option(names = "--duration", paramLabel = "S", description = "how long each push lasts, seconds (default 2)")
    Double duration;

    @Option(names = "--dt", paramLabel = "S", description = "time step of the pushes, seconds (default 0.001)")
    Double dt;

    @Option(names = "--gravity", description = "keep the scenario's gravity during the pushes (default: off)")
    boolean gravity;

    @Option(names = "--max-displacement", paramLabel = "M", description = "a direction holds below this displacement, metres (default 0.05)")
    Double maxDisplacement;

    @Option(names = "--max-rotation", paramLabel = "DEG", description = "and below this rotation, degrees (default 15)")
    Double maxRotation;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb friction coefficient (default: the scenario's object.friction, else 0.5)")
    Double friction;

    @Option(names = "--mass", paramLabel = "KG", description = "the object's mass, kg (an open mesh: a thin shell of it)")
    Double mass;

    @Option(names = "--density", paramLabel = "KG_M3", description = "the object's density, kg/m3 (default 1000 for a closed mesh)")
    Double density;

    @Option(names = "--ramp", description = "also raise the force from 0 along each direction until the object gives way")
    boolean ramp;

    @Option(names = "--ramp-displacement", paramLabel = "M", description = "the ramp stops at this displacement, metres (default 0.005)")
    Double rampDisplacement;

    @Option(names = "--ramp-rotation", paramLabel = "DEG", description = "or at this rotation, degrees (default 5)")
    Double rampRotation;

    @Option(names = "--ramp-rate", paramLabel = "N_PER_S", description = "how fast the ramp raises the force, N/s (default 10)")
    Double rampRate;

    @Option(names = "--ramp-max", paramLabel = "N", description = "the ramp's largest force, N (default the hand's rated 58.84 N)")
    Double rampMax;

    @Option(names = "--no-chart", description = "skip the chart")
    boolean noChart;

    @Option(names = "--timing", description = {"also time one six-direction test of the locked grasp,",
        "warm, in this process (median; adds seconds)"})
    boolean timing;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        Scenario scenario = RunCommand.loadScenario(scenarioFile, "handsim hold-test", err);
        scenario = GraspCommand.withFriction(scenario, friction, null);
        scenario = hand.apply(scenario);
        HoldSettings defaults = HoldSettings.defaults(scenario.hand().handRatingN());
        HoldSettings settings;
        try {
            settings = new HoldSettings(force != null ? force : Double.NaN, or(duration, defaults.durationS()), or(dt, defaults.dtS()), gravity,
                or(maxDisplacement, defaults.maxDisplacementM()), or(maxRotation, defaults.maxRotationDeg()),
                or(rampDisplacement, defaults.rampDisplacementM()), or(rampRotation, defaults.rampRotationDeg()),
                or(rampRate, defaults.rampRateNPerS()), or(rampMax, defaults.rampMaxN()));
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        }
        if (mass != null && !(mass > 0 && Double.isFinite(mass))) throw CliError.usage("handsim: --mass must be a finite number > 0, got " + Args.typed(spec, "--mass"));
        if (density != null && !(density > 0 && Double.isFinite(density))) {
            throw CliError.usage("handsim: --density must be a finite number > 0, got " + Args.typed(spec, "--density"));
        }
        if (mass != null && density != null) throw CliError.usage("handsim: give --mass or --density, not both");
        if (scenario.object() == null) throw CliError.usage("handsim: " + scenario.file() + ": the scenario has no object to push");
        Path dir = out != null ? Args.outputPath("--out", out) : Path.of("out", scenario.name());
        HoldReport report;
        try {
            report = HoldReport.of(scenario, mass != null ? mass : Double.NaN, density != null ? density : Double.NaN, settings, ramp);
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage());
        } catch (IllegalArgumentException e) {   // the object's mass cannot be known
            throw new CliError(CliError.LOAD, "handsim: " + scenario.file() + ": object " + scenario.object().file() + ": " + e.getMessage());
        } catch (SimulationException e) {
            throw new CliError(CliError.NUMERIC, "handsim: " + scenario.file() + ": closing stopped: " + e.getMessage() + " (no output written)");
        }
        Map<String, Object> json = report.toJson();
        if (timing) json.put("timing", time(report));
        List<String> written = new ArrayList<>();
        try (OutputSet set = Args.outputSet(err, "--out", dir, LAYOUT)) {
            Path stage = set.dir();
            if (!noChart) {
                ChartSet charts = ChartSet.start(null);
                String title = String.format(Locale.ROOT, "Hold test (%s): %s N for %s s along each world axis, μ = %s",
                    scenario.name(), Args.csv(round(report.test().forceN())), Args.csv(settings.durationS()), Args.csv(report.test().grasp().friction()));
                charts.add(stage.resolve("hold-test"), 900, 700, () -> HoldTestChart.displacementAndRotation(report.directions(),
                    settings.maxDisplacementM(), settings.maxRotationDeg(), title));
                String missing = Charts.finish(charts, err);
                if (missing != null) json.put(Charts.MISSING_KEY, missing);
                else written.add("hold-test.png/.svg");
            }
            AtomicFile.writeString(stage.resolve("hold-test.csv"), report.csv());
            written.add(0, "hold-test.csv");
            AtomicFile.writeString(stage.resolve("hold-test.json"), JsonWriter.pretty(json));
            written.add(0, "hold-test.json");
            set.publish();
        }
        for (String line : verdicts(report)) stdout.println(line);
        String unsettled = unconverged(report);
        if (unsettled != null) err.println(unsettled);
        if (timing) {
            stdout.println(String.format(Locale.ROOT, "timing: one six-direction test %.4f s (median of %s, warm, in-process)",
                ((Map<?, ?>) json.get("timing")).get("six_directions_s_median"), ((Map<?, ?>) json.get("timing")).get("samples")));
        }
        stdout.println("wrote " + SafeText.escape(dir.toString()) + "/{" + String.join(", ", written) + "}");
        return 0;
    }

    /** What the command prints: a headline, one line per direction, the ramp's ranking, the summary. */
    static List<String> verdicts(HoldReport r) {
        List<String> out = new ArrayList<>();
        HoldSettings s = r.test().settings();
        out.add(String.format(Locale.ROOT, "%s: hold test, F = %.3f N (object %.4f kg, %s), %s s per direction, gravity %s, mu %s; world frame",
            r.scenario(), r.test().forceN(), r.mass().mass(), r.massSource(), Args.csv(s.durationS()), s.gravity() ? "on" : "off",
            Args.csv(r.test().grasp().friction())));
        for (DirectionResult d : r.directions()) {
            String when = d.passed() ? "" : String.format(Locale.ROOT, " (crossed at %.3f s%s)", d.failedAtS(),
                Double.isNaN(d.contactLostS()) ? "" : String.format(Locale.ROOT, ", no contact from %.3f s", d.contactLostS()));
            out.add(String.format(Locale.ROOT, "  %s  %-6s  moved %.4g mm, turned %.4g deg%s", d.direction(), d.passed() ? "held" : "FAILED",
                d.displacementM() * 1000, d.rotationDeg(), when));
        }
        if (r.ramps() != null) {
            List<RampResult> rank = new ArrayList<>(r.ramps());
            rank.sort((a, b) -> Double.compare(a.forceN(), b.forceN()));
            StringBuilder sb = new StringBuilder("ramp, weakest first:");
            for (RampResult x : rank) sb.append(String.format(Locale.ROOT, " %s %s%.2f N", x.direction(), x.heldAtMax() ? ">= " : "", x.forceN()));
            out.add(sb.toString());
        }
        out.add(String.format(Locale.ROOT, "%d of 6 directions held (smallest margin %.3f)", r.passedCount(), r.smallestMargin()));
        return out;
    }

    /**
     * A note for stderr when some steps did not settle Coulomb's fixed point (each step's solves
     * are exact; the step then used the last), or null: the results stand, the reader should know.
     */
    static String unconverged(HoldReport r) {
        long n = (long) r.test().settling()[4], steps = Math.round(r.test().settling()[2] / r.test().settings().dtS());
        for (DirectionResult d : r.directions()) {
            n += d.unconvergedSteps();
            steps += Math.round(d.simulatedS() / r.test().settings().dtS());
        }
        if (n == 0) return null;
        return "handsim hold-test: note: " + ContactSolver.unsettledSteps(n + " of " + steps) + " (unconverged_steps in hold-test.json)";
    }

    /** The warm in-process median of one six-direction test of the report's locked grasp. */
    private static Map<String, Object> time(HoldReport r) {
        HoldTest t = r.test();
        SteadyTiming.Result res = SteadyTiming.median(() -> {
            List<DirectionResult> d = new HoldTest(t.grasp(), t.settings()).run();
            return d.get(0).displacementM();
        }, 11);
        Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("six_directions_s_median", res.medianSeconds());
        m.put("samples", res.samples());
        m.put("warmup_s", res.warmupSeconds());
        return m;
    }

    private static double or(Double v, double d) { return v != null ? v : d; }

    private static double round(double v) { return Math.round(v * 1e4) / 1e4; }
}
