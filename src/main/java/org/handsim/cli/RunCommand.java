package org.handsim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.text.SafeText;
import org.handsim.chart.ChartSet;
import org.handsim.chart.PaperCharts;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.trace.Recorder;
import org.handsim.scenario.Home;
import org.handsim.model.RunSummary;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.model.Simulation;
import org.handsim.model.SimulationException;
import org.handsim.tradeoff.Resolution;
import org.handsim.files.AtomicFile;
import org.handsim.text.JsonWriter;
import org.handsim.files.OutputSet;
import org.handsim.process.Phase;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim run}: the main job. */
@Command(name = "run", mixinStandardHelpOptions = true,
    description = {"Runs a scenario and writes its trace, summary and the paper's Fig. 7 and 8.",
        "SCENARIO defaults to the paper's breakaway experiment,",
        "scenarios/paper-breakaway.json. Writes trace.csv (streamed as the run goes),",
        "summary.json and fig7/fig8 (PNG and SVG; with a free object also",
        "object_motion, its displacement and rotation in the hand) into out/<scenario name>/",
        "(or --out DIR), all at once when every file is complete; a run that fails or",
        "is stopped leaves the folder as it was."})
public final class RunCommand implements Callable<Integer> {
    /** The files of a run's folder: summary.json is published last. */
    static final OutputSet.Layout LAYOUT = new OutputSet.Layout("summary.json", "trace\\.csv|summary\\.json|(fig[78]_finger[1-3]|object_motion)\\.(png|svg)");
    @Spec CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENARIO", description = "scenario JSON file")
    Path scenarioFile;

    @picocli.CommandLine.Mixin HandOptions hand = new HandOptions();

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default out/<scenario name>)")
    Path out;

    @Option(names = "--dt", paramLabel = "S", description = "override the scenario's time step, seconds")
    Double dt;

    @Option(names = "--no-charts", description = "skip the charts")
    boolean noCharts;

    @Option(names = "--no-lazy", description = {"compute every finger fully every step (no work saving;",
        "for comparison: same results, more collision queries and dynamics calls)"})
    boolean noLazy;

    @Option(names = "--tolerance", paramLabel = "LENGTH", description = {"contact tolerance, e.g. 0.5mm, 0.0005m, 1e-3 (m):",
        "tessellate the object at the coarsest divisions",
        "whose worst contact-centre error (chart",
        "2-tessellation) is at most LENGTH"})
    String tolerance;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb friction coefficient of the contacts (default: the scenario's object.friction, else 0.5)")
    Double friction;

    @Option(names = "--edges", paramLabel = "M", description = "edges of the linearised friction cones (default 8)")
    Integer edges;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        Path file = scenarioFile != null ? scenarioFile : Home.paperScenario();
        Scenario scenario = loadScenario(file, "handsim run", err);
        if (dt != null) {
            if (!(dt > 0) || dt > 0.1) throw CliError.usage("handsim: --dt must be in (0, 0.1] seconds, got " + Args.typed(spec, "--dt"));
            try {
                scenario = scenario.withDt(dt);
            } catch (IllegalArgumentException e) {   // too many steps for the scenario's duration
                throw CliError.usage("handsim: --dt " + org.handsim.text.Decimal.format(dt) + ": " + e.getMessage());
            }
        }
        scenario = GraspCommand.withFriction(scenario, friction, edges);
        scenario = hand.apply(scenario);
        Double toleranceM = tolerance != null ? parseTolerance(tolerance) : null;
        String toleranceLine = null;
        if (toleranceM != null) {
            Scenario.ObjectPlacement o = scenario.object();
            Resolution.Choice c = o == null ? null : chooseResolution(o, toleranceM, err);
            if (o == null) err.println("handsim: --tolerance has no effect: the scenario has no object");
            if (c != null && !c.fixedMesh()) {
                scenario = scenario.withObject(o.withDivisions(c.divisions()));
                toleranceLine = String.format(Locale.ROOT, "tolerance %s: divisions %d (%d triangles), expected worst contact-centre error %s"
                    + " (object radius %s, chart 2-tessellation)", Resolution.mm(toleranceM), c.divisions(), c.triangles(),
                    Resolution.mm(c.expectedErrorM()), Resolution.mm(c.sizeM()));
            }
        }
        Path dir = out != null ? Args.outputPath("--out", out) : Path.of("out", scenario.name());
        boolean charts = scenario.writeCharts() && !noCharts;
        ChartSet chartSet = charts ? ChartSet.start(PaperCharts::warmUp) : null;   // fonts and Java2D set up while the run goes on
        if (noCharts && !scenario.writeCharts()) err.println("handsim: --no-charts has no effect: the scenario writes no charts (outputs.charts is false)");
        List<String> written = new ArrayList<>();
        Map<String, Object> summary;
        HandModel model;
        double wall, setup, chartSeconds = 0;
        // every file goes to the set's private folder; the folder gets them all, or none, at the end
        try (OutputSet set = Args.outputSet(err, "--out", dir, LAYOUT)) {
            Path stage = set.dir();
            Phase.reach("opened");
            // memory stays flat in the number of steps: the trace streams to its file as the run
            // goes, and memory keeps only the rows the charts draw (Recorder.bounded)
            try (Recorder rec = scenario.writeTrace() || charts
                ? Recorder.bounded(scenario.writeTrace() ? stage.resolve("trace.csv") : null, HandModel.totalSteps(scenario) + 1) : null) {
                long t0 = System.nanoTime();
                try {
                    model = Simulation.model(scenario, rec).lazy(!noLazy);
                } catch (ScenarioException e) {   // the object or a hand model cannot be loaded
                    throw new CliError(CliError.LOAD, e.getMessage());
                }
                setup = (System.nanoTime() - t0) / 1e9;
                List<String> warnings = model.startWarnings();
                for (String w : warnings) err.println("handsim: warning: " + w);
                Phase.reach("loaded");
                long t1 = System.nanoTime();
                try {
                    model.run(Phase.atHalf("half-run", new ProgressBar(err, "handsim run " + scenario.name())));
                } catch (SimulationException e) {
                    throw new CliError(CliError.NUMERIC, "handsim: " + file + ": run stopped: " + e.getMessage() + " (no output written)");
                }
                wall = (System.nanoTime() - t1) / 1e9;
                // what the run found (stretches without a static equilibrium, forces above the
                // ratings; once each, not per step) is said once the trace is whole: a trace that
                // fails to write fails the run whether the writer's thread noticed during the run
                // or at its end, and the output must not depend on which
                List<String> found = List.copyOf(model.warnings().subList(warnings.size(), model.warnings().size()));
                warnings = model.warnings();
                Phase.reach("ran");
                long t3 = System.nanoTime();
                // the charts are drawn on the set's workers while the grasp is evaluated
                List<String> chartFiles = chartSet != null ? addCharts(chartSet, rec, model, stage) : List.of();
                summary = RunSummary.of(model, wall);
                summary.put("grasp", GraspAssessment.of(model.graspInput(), scenario.friction(), scenario.coneEdges()).toJson());
                summary.put("setup_time_s", setup);
                summary.put("warnings", warnings);
                if (toleranceM != null) {
                    summary.put("tolerance_m", toleranceM);
                    if (scenario.object() != null) summary.put("divisions", scenario.object().divisions());
                }
                if (scenario.writeTrace()) written.add("trace.csv");
                String missing = chartSet != null ? Charts.finish(chartSet, err) : null;   // the charts were drawn meanwhile
                if (missing != null) summary.put(Charts.MISSING_KEY, missing);
                else written.addAll(chartFiles);
                Phase.reach("chart");
                chartSeconds = (System.nanoTime() - t3) / 1e9;
                // the trace writer worked on its own thread during the run and the charts; now it completes
                if (rec != null) rec.finish();
                for (String w : found) err.println("handsim: warning: " + w);
                Phase.reach("trace");
                Map<String, Object> phases = new java.util.LinkedHashMap<>();
                phases.put("load_s", setup);
                phases.put("run_s", wall);
                phases.put("trace_s", rec != null ? rec.writeSeconds() : 0.0);
                phases.put("charts_s", chartSeconds);
                summary.put("phase_times", phases);
            }
            AtomicFile.writeString(stage.resolve("summary.json"), JsonWriter.pretty(summary));
            written.add("summary.json");
            set.publish();
        }
        if (toleranceLine != null) stdout.println(toleranceLine);
        stdout.println(headline(model, wall));
        stdout.println("wrote " + SafeText.escape(dir.toString()) + "/{" + String.join(", ", written) + "}");
        return 0;
    }

    /** Queues Fig. 7 and Fig. 8 of every finger that moved (drawn on the set's workers); returns their names for the "wrote" line. */
    private static List<String> addCharts(ChartSet set, Recorder rec, HandModel model, Path dir) {
        List<String> files = new ArrayList<>();
        String scenario = model.scenario().name();
        for (int k = 1; k <= 3; k++) {
            if (!rec.moved(k)) continue;
            int f = k;
            double tb = model.breakawayTime(k);
            set.add(dir.resolve("fig7_finger" + k), 900, 1100,
                () -> PaperCharts.figure7(rec, f, tb, "Joints " + f + "2 and " + f + "3 (finger " + f + ", " + scenario + ")"));
            set.add(dir.resolve("fig8_finger" + k), 900, 450,
                () -> PaperCharts.figure8(rec, f, tb, "Contact force on finger " + f + " (" + scenario + ")"));
            files.add("fig7_finger" + k + ".png/.svg");
            files.add("fig8_finger" + k + ".png/.svg");
        }
        if (rec.objectColumns()) {
            double released = model.objectReleasedAt(), dropped = model.objectDroppedAt();
            set.add(dir.resolve("object_motion"), 900, 700,
                () -> PaperCharts.objectMotion(rec, released, dropped, "The object in the hand (" + scenario + ")"));
            files.add("object_motion.png/.svg");
        }
        return files;
    }

    /** {@code --tolerance} as metres; exit 2 naming the value if it is not a length. */
    private static double parseTolerance(String text) {
        try {
            return Resolution.parseLength(text);
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: --tolerance: " + e.getMessage());
        }
    }

    /**
     * The object's divisions for a tolerance (chart 2-tessellation's table). A fixed mesh gets a
     * note on standard error and is run as it is; a tolerance no tessellation meets is exit 2
     * with the best achievable error.
     */
    private Resolution.Choice chooseResolution(Scenario.ObjectPlacement o, double toleranceM, PrintWriter err) {
        Resolution.Choice c;
        try {
            c = Resolution.choose(o.file(), o.meshScale(), toleranceM);
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage());
        }
        if (c.fixedMesh()) {
            err.println("handsim: --tolerance has no effect: " + o.file() + " is a fixed mesh of " + c.triangles() + " triangles");
        } else if (!c.met()) {
            throw CliError.usage("handsim: --tolerance " + tolerance.trim() + " cannot be met for " + o.file() + ": the best achievable"
                + " worst contact-centre error is " + Resolution.mm(c.expectedErrorM()) + " (divisions " + c.divisions()
                + ", object radius " + Resolution.mm(c.sizeM()) + ")");
        }
        return c;
    }

    static Scenario loadScenario(Path file) {
        try {
            return Scenario.load(file);
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage());
        }
    }

    /** {@link #loadScenario(Path)}, then the unit rule's notice on {@code err} when the object's size chose its unit. */
    static Scenario loadScenario(Path file, String who, PrintWriter err) {
        Scenario s = loadScenario(file);
        String notice = s.unitNotice(who);
        if (notice != null) err.println(notice);
        return s;
    }

    static String headline(HandModel m, double wall) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "%s: %.3f s simulated in %d steps, %.3f s wall (%.0f steps/s, %.0fx real time)",
            m.scenario().name(), m.time(), m.stepIndex(), wall, m.stepIndex() / wall, m.time() / wall));
        for (int k = 1; k <= 3; k++) {
            if (!Double.isNaN(m.breakawayTime(k))) {
                sb.append(String.format(Locale.ROOT, "%n  finger %d: breakaway at t = %.4f s, tau%d2 = %.3f N*m, contact force %.2f N",
                    k, m.breakawayTime(k), k, m.breakawayTorque(k), m.breakawayForce(k)));
            }
            if (m.maxContactForce(k) > 0) {
                sb.append(String.format(Locale.ROOT, "%n  finger %d: max contact force %.2f N, final state %s", k, m.maxContactForce(k), m.state(k)));
            }
        }
        return sb.toString();
    }
}
