package org.handsim.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.chart.ChartExport;
import org.handsim.chart.PlanCharts;
import org.handsim.grasp.FrictionCone;
import org.handsim.plan.PlanJob;
import org.handsim.plan.PlanOutput;
import org.handsim.plan.PlanSpec;
import org.handsim.plan.TrialResult;
import org.handsim.plan.TrialRunner;
import org.handsim.sim.Scenario;
import org.handsim.sim.UnitRule;
import org.handsim.sim.ScenarioException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim plan}: grasp planning (issue 13). */
@Command(name = "plan", mixinStandardHelpOptions = true,
    description = {"Searches grasps of an object and ranks them by epsilon.",
        "Each trial places the open hand on an approach",
        "direction (a seeded Fibonacci sphere), a roll, a spread and a standoff, moves it",
        "in until the palm or a finger meets the object, closes every finger with the",
        "clutch model until it stalls, and evaluates force closure, epsilon, volume and",
        "the minimum hold. Writes out/plan-<name>/ (or --out DIR): plan.csv, plan.json,",
        "best/01.json .. best/10.json (the ten best grasps by epsilon, as scenarios) and",
        "the charts epsilon-histogram and epsilon-directions (PNG and SVG).",
        "The same seed gives the same table on every engine and thread count (timing",
        "column aside). plan.csv's header:",
        "  trial,status,approach_x,approach_y,approach_z,roll_rad,spread_counts,",
        "  standoff_m,contacts,force_closure,epsilon,volume,hold_min_N,final_state1,",
        "  final_state2,final_state3,sim_time_s,wall_s,error"})
public final class PlanCommand implements Callable<Integer> {
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

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        if (trials < 1) throw CliError.usage("handsim: --trials must be >= 1, got " + trials);
        EngineChoice eng = EngineChoice.of(engine, master, threads, Runtime.getRuntime().availableProcessors());
        Args.frictionAndEdges(friction, null);
        Scenario.Units unit = Args.units(units);
        PlanSpec planSpec;
        TrialRunner runner;
        try {
            planSpec = PlanSpec.forTarget(target, trials, seed, friction, FrictionCone.DEFAULT_EDGES, unit);
            runner = new TrialRunner(planSpec);      // loads the object once here: a bad file is one error, not N rows
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, "handsim: " + e.getMessage());
        }
        Path dir = out != null ? out : Path.of("out", "plan-" + planSpec.name());
        if (unit == null) {
            boolean json = target.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".json");
            String notice = json ? Scenario.load(target).unitNotice("handsim plan")
                : UnitRule.notice("handsim plan", target, planSpec.units(), "--units");
            if (notice != null) err.println(notice);
        }
        ProgressBar bar = new ProgressBar(err, "handsim plan " + planSpec.name());
        long t0 = System.nanoTime();
        Map<String, Object> summary;
        PlanOutput output = new PlanOutput(dir, runner, rows -> bar.accept(rows / (double) trials));
        try (output) {
            try {
                eng.engine().run(new PlanJob(planSpec), trials, eng.settings("handsim plan " + planSpec.name()), output);
            } catch (Exception e) {
                throw eng.failed("plan " + planSpec.name(), e);
            }
            double wall = (System.nanoTime() - t0) / 1e9;
            summary = output.finish(wall, engine);
        }
        writeCharts(output, planSpec, dir);
        TrialResult best = output.bestFirst().isEmpty() ? null : output.bestFirst().get(0);
        stdout.println(String.format(Locale.ROOT, "plan-%s: %d trials (%d failed), %d with force closure, best epsilon %s%s;"
                + " %.2f s wall, %.1f trials/s (%s engine, %s)",
            planSpec.name(), trials, output.failed(), output.forceClosure(), fmt(best == null ? 0 : best.epsilon()),
            best == null ? "" : " (trial " + best.index() + ")", (double) summary.get("wall_time_s"), (double) summary.get("trials_per_s"),
            engine, eng.where()));
        stdout.println("wrote " + dir + "/{plan.csv, plan.json, best/01.json.." + String.format("%02d", output.bestFirst().size())
            + ".json, epsilon-histogram.png/.svg, epsilon-directions.png/.svg}");
        return output.failed() == trials ? 1 : 0;
    }

    static void writeCharts(PlanOutput o, PlanSpec s, Path dir) throws java.io.IOException {
        var h = o.histogram();
        int used = h.usedBins();
        long[] counts = java.util.Arrays.copyOf(h.counts(), used);
        ChartExport.write(PlanCharts.epsilonHistogram("Grasp quality over " + s.trials() + " trials (" + s.name() + ", seed " + s.seed() + ")",
            h.width(), counts, h.noClosure(), o.failed()), dir.resolve("epsilon-histogram"), 900, 550);
        var d = o.directions();
        ChartExport.write(PlanCharts.directionMap("Best ε by approach direction (" + s.name() + ", " + s.trials() + " trials)", d),
            dir.resolve("epsilon-directions"), 1000, 560);
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.4g", v);
    }
}
