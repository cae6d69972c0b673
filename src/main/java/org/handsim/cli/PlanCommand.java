package org.handsim.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.text.SafeText;
import org.handsim.chart.ChartSet;
import org.handsim.chart.PlanCharts;
import org.handsim.grasp.FrictionCone;
import org.handsim.plan.PlanJob;
import org.handsim.plan.PlanOutput;
import org.handsim.plan.PlanSpec;
import org.handsim.plan.TrialResult;
import org.handsim.plan.TrialRunner;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.UnitRule;
import org.handsim.scenario.ScenarioException;
import org.handsim.files.AtomicFile;
import org.handsim.text.JsonWriter;
import org.handsim.files.OutputSet;
import org.handsim.process.Phase;
import picocli.CommandLine.Command;
import org.handsim.hand.HandDescription;
import org.handsim.hold.HoldSettings;
import org.handsim.plan.PlanHold;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim plan}: grasp planning. */
@Command(name = "plan", mixinStandardHelpOptions = true,
    description = {"Searches grasps of an object and ranks them by epsilon.",
        "Each trial places the open hand on an approach",
        "direction (a seeded Fibonacci sphere, or along one of the object's principal",
        "axes), a roll, a spread, moves it in until the palm or a finger meets the",
        "object, backs it off by a standoff sampled for the object's size, closes every",
        "finger with the clutch model until it stalls, and evaluates force closure,",
        "epsilon, volume and the minimum hold. Writes out/plan-<name>/ (or --out DIR):",
        "plan.csv, plan.json,",
        "best/01.json .. best/10.json (the ten best grasps by epsilon among those with",
        "force closure, as scenarios; none when no trial has it, and one line on",
        "standard error says why and what to try) and the charts epsilon-histogram",
        "and epsilon-directions (PNG and SVG).",
        "The same seed gives the same table on every engine and thread count (timing",
        "column aside). plan.csv's header:",
        "  trial,status,approach_x,approach_y,approach_z,roll_rad,spread_counts,",
        "  standoff_m,contacts,force_closure,epsilon,volume,hold_min_N,final_state1,",
        "  final_state2,final_state3,sim_time_s,wall_s,error",
        "--hold-test also runs handsim hold-test's six pushes on every trial's grasp",
        "(F from --hold-force, else 10 m/s2 x the object's mass: --hold-mass, else a free",
        "object's mass fields, else its closed mesh at 1000 kg/m3; 2 s each at 1 ms,",
        "5 cm, 15 deg) and adds the columns",
        "  hold_-x,hold_+x,hold_-y,hold_+y,hold_-z,hold_+z,hold_margin",
        "(the six verdicts and the smallest margin); --rank-by hold-margin ranks the",
        "best grasps by that margin, then epsilon."})
public final class PlanCommand implements Callable<Integer> {
    /** The files of a plan's folder: plan.json is published last. */
    static final OutputSet.Layout LAYOUT = new OutputSet.Layout("plan.json",
        "plan\\.csv|plan\\.json|best/[0-9][0-9]\\.json|epsilon-(histogram|directions)\\.(png|svg)", "best");
    @Spec CommandSpec spec;

    @Parameters(index = "0", paramLabel = "TARGET", description = {"an object file (any format scenarios read), or a",
        "scenario JSON used as template (its object, finger",
        "motors, dt and outputs)"})
    Path target;

    @Option(names = "--trials", paramLabel = "N", description = "number of trials (default ${DEFAULT-VALUE})", defaultValue = "500")
    int trials;

    @Option(names = "--seed", paramLabel = "S", description = "seed of the trials (default ${DEFAULT-VALUE})", defaultValue = "1")
    long seed;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb friction of the contacts (default: the template's object.friction, else 0.5)")
    Double friction;

    @Option(names = "--units", paramLabel = "auto|mm|cm|m", defaultValue = "auto", description = {
        Args.UNITS_HELP_1, Args.UNITS_HELP_2, Args.UNITS_HELP_3, "(a template's object.units when it has one)"})
    String units;

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default out/plan-<name>)")
    Path out;

    @Option(names = "--engine", paramLabel = "local|spark", description = "local threads (default) or an Apache Spark job", defaultValue = "local")
    String engine;

    @Option(names = "--master", paramLabel = "URL", description = {"Spark master: local[*] (default), local[N] with",
        "--threads N, or spark://HOST:7077 for a standalone",
        "cluster (e.g. tools/spark-cluster start)"})
    String master;

    @Option(names = "--threads", paramLabel = "N", description = "worker threads (default: all cores)")
    Integer threads;

    @picocli.CommandLine.Mixin HandOptions hand = new HandOptions();

    @Option(names = "--hold-test", description = "run the six-direction hold test on every trial's grasp")
    boolean holdTest;

    @Option(names = "--hold-force", paramLabel = "N", description = "the hold test's push, newtons (default 10 m/s2 x the object's mass)")
    Double holdForce;

    @Option(names = "--hold-mass", paramLabel = "KG", description = "the object's mass for the hold test, kg (default: its closed mesh at 1000 kg/m3)")
    Double holdMass;

    @Option(names = "--rank-by", paramLabel = "epsilon|hold-margin", defaultValue = "epsilon",
        description = "what ranks the best grasps (default epsilon; hold-margin needs --hold-test)")
    String rankBy;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        if (trials < 1 || trials > PlanSpec.MAX_TRIALS) {
            throw CliError.usage("handsim: --trials must be in [1, " + PlanSpec.MAX_TRIALS + "] (a million trials take one to two hours"
                + " on two cores), got " + trials);
        }
        if (!rankBy.equals("epsilon") && !rankBy.equals("hold-margin")) {
            throw CliError.usage("handsim: --rank-by must be epsilon or hold-margin, got " + Args.typed(spec, "--rank-by"));
        }
        if (!holdTest && (rankBy.equals("hold-margin") || holdForce != null || holdMass != null)) {
            throw CliError.usage("handsim: " + (rankBy.equals("hold-margin") ? "--rank-by hold-margin" : holdForce != null ? "--hold-force" : "--hold-mass")
                + " needs --hold-test");
        }
        PlanHold planHold = null;
        if (holdTest) {
            if (holdMass != null && !(holdMass > 0 && Double.isFinite(holdMass))) {
                throw CliError.usage("handsim: --hold-mass must be a finite number > 0, got " + Args.typed(spec, "--hold-mass"));
            }
            try {
                HoldSettings hs = HoldSettings.defaults(HandDescription.barrettHand().handRatingN());
                if (holdForce != null) hs = hs.withForce(holdForce);
                planHold = new PlanHold(hs, holdMass != null ? holdMass : Double.NaN, Double.NaN, rankBy.equals("hold-margin"));
            } catch (IllegalArgumentException e) {
                throw CliError.usage("handsim: " + e.getMessage().replace("--force", "--hold-force"));
            }
        }
        EngineChoice eng = EngineChoice.of(engine, master, threads, Runtime.getRuntime().availableProcessors());
        Args.frictionAndEdges(friction, null);
        Scenario.Units unit = Args.units(units);
        PlanSpec planSpec;
        TrialRunner runner;
        try {
            hand.check();
            planSpec = PlanSpec.forTarget(target, trials, seed, friction, FrictionCone.DEFAULT_EDGES, unit).withHandParameters(hand.parameters())
                .withHold(planHold);
            runner = new TrialRunner(planSpec);      // loads the object once here: a bad file is one error, not N rows
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, "handsim: " + e.getMessage());
        } catch (IllegalArgumentException e) {      // the hold test cannot know the object's mass
            throw new CliError(CliError.LOAD, "handsim: " + target + ": " + e.getMessage());
        }
        Path dir = out != null ? Args.outputPath("--out", out) : Path.of("out", "plan-" + planSpec.name());
        if (unit == null) {
            boolean json = target.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".json");
            String notice = json ? Scenario.load(target).unitNotice("handsim plan")
                : UnitRule.notice("handsim plan", target, planSpec.units(), "--units");
            if (notice != null) err.println(notice);
        }
        ProgressBar bar = new ProgressBar(err, "handsim plan " + planSpec.name());
        long t0 = System.nanoTime();
        Map<String, Object> summary;
        PlanOutput output;
        boolean charts;
        // every file goes to the set's private folder; the folder gets them all, or none, at the end
        try (OutputSet set = Args.outputSet(err, "--out", dir, LAYOUT)) {
            Phase.reach("opened");
            java.util.function.DoubleConsumer progress = Phase.atHalf("half-trials", bar);
            output = new PlanOutput(set.dir(), dir, runner, rows -> progress.accept(rows / (double) trials));
            eng.announce(err, "plan " + planSpec.name());
            try (output) {
                try {
                    eng.engine().run(new PlanJob(planSpec), trials, eng.settings("handsim plan " + planSpec.name()), output);
                } catch (Exception e) {
                    throw eng.failed("plan " + planSpec.name(), e);
                }
                double wall = (System.nanoTime() - t0) / 1e9;
                summary = output.finish(wall, engine);
            }
            charts = writeCharts(output, planSpec, set.dir(), summary, err);
            Phase.reach("charts");
            set.publish();
        }
        TrialResult best = output.bestFirst().isEmpty() ? null : output.bestFirst().get(0);
        stdout.println(String.format(Locale.ROOT, "plan-%s: %d trials (%d failed), %d with force closure, best epsilon %s%s;"
                + " %.2f s wall, %.1f trials/s (%s engine, %s)",
            planSpec.name(), trials, output.failed(), output.forceClosure(), fmt(best == null ? 0 : best.epsilon()),
            best == null ? "" : " (trial " + best.index() + ")", (double) summary.get("wall_time_s"), (double) summary.get("trials_per_s"),
            engine, eng.where()));
        if (holdTest) {
            stdout.println(String.format(Locale.ROOT, "hold test: %d of %d trials held in all six directions%s", output.heldAll(),
                trials - output.failed(), rankBy.equals("hold-margin") ? "; best/ ranked by the smallest hold margin" : ""));
        }
        int nBest = output.bestFirst().size();
        stdout.println("wrote " + SafeText.escape(dir.toString()) + "/{plan.csv, plan.json" + (nBest == 0 ? "" : nBest == 1 ? ", best/01.json"
            : ", best/01.json.." + String.format("%02d", nBest) + ".json")
            + (charts ? ", epsilon-histogram.png/.svg, epsilon-directions.png/.svg" : "") + "}");
        if (output.forceClosure() == 0 && output.failed() < trials) {
            err.println("handsim plan: no grasp with force closure, so no best/ grasps: "
                + org.handsim.plan.TrialOutcome.advice(output.outcomes(), trials - output.failed(), runner.objectExtent()));
        }
        return output.failed() == trials ? 1 : 0;
    }

    /**
     * Draws and writes the two charts; when they cannot be drawn, the warning and plan.json
     * rewritten with {@code charts_missing} (every table is written already). Returns whether
     * the charts were written.
     */
    static boolean writeCharts(PlanOutput o, PlanSpec s, Path dir, Map<String, Object> summary, PrintWriter err) throws java.io.IOException {
        var h = o.histogram();
        int used = h.usedBins();
        long[] counts = java.util.Arrays.copyOf(h.counts(), used);
        var d = o.directions();
        ChartSet set = ChartSet.start(null);
        set.add(dir.resolve("epsilon-histogram"), 900, 550, () -> PlanCharts.epsilonHistogram("Grasp quality over " + s.trials()
            + " trials (" + s.name() + ", seed " + s.seed() + ")", h.width(), counts, h.noClosure(), o.failed()));
        set.add(dir.resolve("epsilon-directions"), 1000, 560, () -> PlanCharts.directionMap("Best ε by approach direction ("
            + s.name() + ", " + s.trials() + " trials)", d));
        String missing = Charts.finish(set, err);
        if (missing == null) return true;
        summary.put(Charts.MISSING_KEY, missing);
        AtomicFile.writeString(dir.resolve("plan.json"), JsonWriter.pretty(summary));
        return false;
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.4g", v);
    }
}
