package org.handsim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.handsim.chart.ChartSet;
import org.handsim.chart.GraspChart;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.model.SimulationException;
import org.handsim.files.AtomicFile;
import org.handsim.text.Decimal;
import org.handsim.text.JsonWriter;
import org.handsim.files.OutputSet;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim grasp}: how good the grasp of a scenario is, and how much it holds. */
@Command(name = "grasp", mixinStandardHelpOptions = true,
    description = {"Runs a scenario to time T and evaluates its grasp and the load it holds.",
        "Runs the scenario (default: the paper's experiment) to time T (default: its",
        "end) and prints its grasp there as one JSON line (README, output contracts):",
        "  {\"time_s\":t,\"contacts\":[{\"finger\":k,\"link\":j,\"point\":[..],",
        "   \"normal\":[..],\"force_N\":[..]}],\"force_closure\":bool,\"epsilon\":e,",
        "   \"volume\":v,\"hold_N\":{\"+x\":F,\"-x\":F,\"+y\":F,\"-y\":F,\"+z\":F,\"-z\":F},",
        "   \"hold_min_N\":F,\"hold_joint_limits_Nm\":[[l11,l12,l13],[l21,l22,l23],",
        "   [l32,l33]],\"hold_cap_N\":C,\"torque_residual_Nm\":[r1,r2,r3],",
        "   \"joint_torques_Nm\":[[t11,t12,t13],[t21,t22,t23],[t32,t33]],",
        "   \"center_m\":[x,y,z],\"radius_m\":R,\"friction\":mu,\"cone_edges\":m,",
        "   \"max_worm_reaction_Nm\":[w1,w2,w3]}",
        "World frame; normals point into the object; epsilon and volume of the grasp",
        "wrench space (torques about center_m, the object's centroid, divided by",
        "radius_m, its largest centroid-to-vertex distance; cones of friction and",
        "cone_edges: handsim quality given this output computes the same epsilon);",
        "hold_N: the largest force through the object's centroid the grasp holds",
        "with every joint within its limit (hold_joint_limits_Nm, null: none known),",
        "at most hold_cap_N, the hand's rated 58.84 N; torque_residual_Nm: per finger",
        "how far its contact forces miss its joint torques (0: a static equilibrium);",
        "joint_torques_Nm: the torque each joint carries at T (the drive's, or the",
        "reaction of the worm or motor holding it); max_worm_reaction_Nm: per finger",
        "the largest torque its inner joint's worm held up to T (null: it never did).",
        "--chart BASE also evaluates the grasp every --every seconds along the run and",
        "writes BASE.png, BASE.svg (epsilon and the smallest hold against time) and",
        "BASE.csv."})
public final class GraspCommand implements Callable<Integer> {
    /** Header of the {@code --chart} CSV. */
    static final String CHART_HEADER = "time_s,force_closure,epsilon,volume,hold_min_N";

    @Spec CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENARIO", description = "scenario JSON file")
    Path scenarioFile;

    @picocli.CommandLine.Mixin HandOptions hand = new HandOptions();

    @Option(names = "--at", paramLabel = "T", description = "evaluate at time T seconds (the first step at or after it; default: the end)")
    Double at;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb friction coefficient of the contacts (default: the scenario's object.friction, else 0.5)")
    Double friction;

    @Option(names = "--edges", paramLabel = "M", description = "edges of the linearised friction cones (default 8)")
    Integer edges;

    @Option(names = "--chart", paramLabel = "BASE", description = "also write BASE.png, BASE.svg and BASE.csv: the grasp against time")
    Path chart;

    @Option(names = "--every", paramLabel = "S", description = "sampling interval of --chart, seconds (default 0.02)")
    Double every;

    @Override
    public Integer call() throws IOException {
        java.io.PrintWriter err = spec.commandLine().getErr();
        Scenario scenario = RunCommand.loadScenario(scenarioFile != null ? scenarioFile : Home.paperScenario(), "handsim grasp", err);
        scenario = withFriction(scenario, friction, edges);
        scenario = hand.apply(scenario);
        double interval = every != null ? every : 0.02;
        if (every != null && chart == null) throw CliError.usage("handsim: --every needs --chart");
        Args.outputPath("--chart", chart);
        if (chart != null && chart.getFileName() == null) throw CliError.usage("handsim: --chart must name a file base, got '" + chart + "'");
        if (!(interval > 0) || !Double.isFinite(interval)) throw CliError.usage("handsim: --every must be > 0 seconds, got " + Args.typed(spec, "--every"));
        double mu = scenario.friction();
        int m = scenario.coneEdges();
        HandModel model = Simulation.model(scenario, false);
        for (String w : model.startWarnings()) err.println("handsim: warning: " + w);
        double end = model.totalSteps() * scenario.dt();
        double until = end;
        if (at != null) {
            if (!(at >= 0) || at > end + 1e-9 * scenario.dt()) {
                throw CliError.usage("handsim: --at must be in [0, " + (float) end + "] seconds (the scenario's duration), got " + Args.typed(spec, "--at"));
            }
            until = at;
        }
        List<GraspAssessment> samples = new ArrayList<>();
        try {
            double next = 0;
            if (chart != null) { samples.add(GraspAssessment.of(model.graspInput(), mu, m)); next = interval; }
            while (model.running() && model.time() < until - 1e-9 * scenario.dt()) {
                model.step();
                if (chart != null && model.time() >= next - 1e-9 * scenario.dt()) {
                    samples.add(GraspAssessment.of(model.graspInput(), mu, m));
                    while (next <= model.time() + 1e-9 * scenario.dt()) next += interval;
                }
            }
        } catch (SimulationException e) {
            throw new CliError(CliError.NUMERIC, "handsim: " + scenario.file() + ": run stopped: " + e.getMessage() + " (no output written)");
        }
        GraspAssessment g = GraspAssessment.of(model.graspInput(), mu, m);
        if (chart != null) {
            if (samples.isEmpty() || samples.get(samples.size() - 1).timeS() != g.timeS()) samples.add(g);
            writeChart(spec.commandLine().getErr(), chart, samples, model, scenario.name());
        }
        java.util.Map<String, Object> out = g.toJson();
        java.util.List<Object> worm = new java.util.ArrayList<>();
        for (int k = 1; k <= 3; k++) worm.add(Double.isNaN(model.maxWormReaction(k)) ? null : model.maxWormReaction(k));
        out.put("max_worm_reaction_Nm", worm);
        spec.commandLine().getOut().println(JsonWriter.write(out));
        return 0;
    }

    /**
     * The scenario with {@code --friction} and {@code --edges} applied (exit 2 naming the value if
     * one is out of range), for every command that takes them.
     */
    static Scenario withFriction(Scenario s, Double friction, Integer edges) {
        Args.frictionAndEdges(friction, edges);
        if (friction != null) s = s.withFriction(friction);
        if (edges != null) s = s.withConeEdges(edges);
        return s;
    }

    /** BASE.csv, BASE.png and BASE.svg, published together ({@link OutputSet} of BASE's folder). */
    private static void writeChart(PrintWriter err, Path chart, List<GraspAssessment> samples, HandModel model, String name) throws IOException {
        Path folder = chart.toAbsolutePath().getParent();
        String stem = chart.getFileName().toString();
        OutputSet.Layout layout = new OutputSet.Layout(null, java.util.regex.Pattern.quote(stem) + "\\.(png|svg|csv)");
        try (OutputSet set = Args.outputSet(err, "--chart", folder, layout)) {
            writeChartFiles(set.dir().resolve(stem), samples, model, name, err);
            set.publish();
        }
    }

    private static void writeChartFiles(Path base, List<GraspAssessment> samples, HandModel model, String name, PrintWriter err) throws IOException {
        double[] breakaways = {model.breakawayTime(1), model.breakawayTime(2), model.breakawayTime(3)};
        ChartSet set = ChartSet.start(null);
        set.add(base, 900, 650, () -> GraspChart.epsilonAndHold(samples, breakaways, model.hand().handRatingN(),
            "Grasp quality and hold against time (" + name + ", μ = " + model.scenario().friction() + ", "
            + model.scenario().coneEdges() + " cone edges)"));
        Charts.finish(set, err);   // without the chart, its table (BASE.csv) is still written
        try (AtomicFile f = new AtomicFile(Path.of(base + ".csv"))) {
            Writer w = f.writer();
            w.write(CHART_HEADER);
            w.write('\n');
            for (GraspAssessment s : samples) {
                w.write(Args.csv(s.timeS()) + "," + s.quality().forceClosure() + "," + Args.csv(s.quality().epsilon()) + ","
                    + Args.csv(s.quality().volume()) + "," + Decimal.orEmpty(s.holdMinN()) + "\n");
            }
            f.commit();
        }
    }
}
