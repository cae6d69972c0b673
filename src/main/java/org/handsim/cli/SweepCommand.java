package org.handsim.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.model.Simulation;
import org.handsim.model.SimulationException;
import org.handsim.scenario.SceneMeshes;
import org.handsim.scenario.Sweep;
import org.handsim.text.Decimal;
import org.handsim.text.SafeText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim sweep}: many scenarios in parallel in one JVM, one summary table. */
@Command(name = "sweep", mixinStandardHelpOptions = true,
    description = {"Runs every run of SWEEP.json in parallel and writes one summary table.",
        "The table is out/<sweep name>/summary.csv (or --out DIR), one row per run in",
        "the file's order, written as the runs finish; header:",
        "  run,scenario,status,sim_time_s,steps,wall_time_s,",
        "  final_state1,breakaway1_s,breakaway_force1_N,max_force1_N,",
        "  final_state2,breakaway2_s,breakaway_force2_N,max_force2_N,",
        "  final_state3,breakaway3_s,breakaway_force3_N,max_force3_N,error,",
        "  force_closure,epsilon,volume,hold_min_N",
        "A run that fails is a row with status 'failed' and its error; the others",
        "go on (exit 1 if any failed)."})
public final class SweepCommand implements Callable<Integer> {
    static final String HEADER = "run,scenario,status,sim_time_s,steps,wall_time_s,"
        + "final_state1,breakaway1_s,breakaway_force1_N,max_force1_N,"
        + "final_state2,breakaway2_s,breakaway_force2_N,max_force2_N,"
        + "final_state3,breakaway3_s,breakaway_force3_N,max_force3_N,error,"
        + "force_closure,epsilon,volume,hold_min_N";

    @Spec CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SWEEP.json", description = "the sweep file")
    Path file;

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default out/<sweep name>)")
    Path out;

    @Option(names = "--threads", paramLabel = "N", description = "worker threads (default: the file's, else all cores)")
    Integer threads;

    @Option(names = "--engine", paramLabel = "local|spark", description = "local threads (default) or an Apache Spark job", defaultValue = "local")
    String engine;

    @Option(names = "--master", paramLabel = "URL", description = "Spark master (default local[*]; spark://HOST:7077 for a cluster)")
    String master;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb friction coefficient of every run's contacts (default: each scenario's)")
    Double friction;

    @Option(names = "--edges", paramLabel = "M", description = "edges of the linearised friction cones (default 8)")
    Integer edges;

    @picocli.CommandLine.Mixin HandOptions hand = new HandOptions();

    @Override
    public Integer call() throws Exception {
        Sweep sweep;
        try {
            sweep = Sweep.load(file);
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage());
        }
        Args.frictionAndEdges(friction, edges);
        hand.check();
        unitNotices(sweep, spec.commandLine().getErr());
        return SweepJob.run(this, sweep, sweep.threads());
    }

    /**
     * The unit rule's notices and size warnings of the sweep's objects, each distinct line once,
     * before the runs (which may run elsewhere: Spark). A run that cannot be built is skipped
     * here: its row says why.
     */
    static void unitNotices(Sweep sweep, java.io.PrintWriter err) {
        java.util.Set<String> said = new java.util.LinkedHashSet<>();
        for (Sweep.Run run : sweep.runs()) {
            try {
                Scenario s = run.scenario().get();
                Scenario.ObjectPlacement o = s.object();
                if (o == null) continue;
                String notice = s.unitNotice("handsim sweep");
                if (notice != null) said.add(notice);
                String size = org.handsim.scenario.UnitRule.sizeWarning(o.file(),
                    org.handsim.scenario.SceneMeshes.mesh(o.file(), o.divisions(), o.meshScale()), o.units());
                if (size != null) said.add("handsim: warning: " + run.label() + ": " + size);
            } catch (RuntimeException e) {
                // the run's row reports it
            }
        }
        said.forEach(err::println);
        err.flush();
    }

    static String runOne(Sweep.Run run, Double friction, Integer edges, org.handsim.hand.HandParameters handParameters) {
        String label = SafeText.csvCell(run.label());
        String scenarioName = "";
        try {
            Scenario s = GraspCommand.withFriction(run.scenario().get(), friction, edges).withHandParameters(handParameters);
            scenarioName = s.name();
            HandModel m = Simulation.model(s, false);
            long t = System.nanoTime();
            m.run(null);
            double wall = (System.nanoTime() - t) / 1e9;
            StringBuilder sb = new StringBuilder();
            sb.append(label).append(',').append(SafeText.csvCell(scenarioName)).append(",ok,").append(Decimal.format(m.time())).append(',')
                .append(m.stepIndex()).append(',').append(Decimal.format(wall));
            for (int k = 1; k <= 3; k++) {
                sb.append(',').append(m.state(k)).append(',').append(Decimal.orEmpty(m.breakawayTime(k))).append(',')
                    .append(Decimal.orEmpty(m.breakawayForce(k))).append(',').append(Decimal.format(m.maxContactForce(k)));
            }
            GraspAssessment g = GraspAssessment.of(m.graspInput(), s.friction(), s.coneEdges());
            sb.append(",,").append(g.quality().forceClosure()).append(',').append(Decimal.format(g.quality().epsilon())).append(',')
                .append(Decimal.format(g.quality().volume())).append(',').append(Decimal.format(g.holdMinN()));
            return sb.toString();
        } catch (RuntimeException e) {   // ScenarioException, SimulationException, a bad object file ...: this row fails, the others go on
            // the message alone: a row never shows a Java class name (java.lang.NumberFormatException, Json$JsonException)
            String why = e.getMessage() != null ? e.getMessage() : "internal error (" + e.getClass().getSimpleName() + ")";
            return label + "," + SafeText.csvCell(scenarioName) + ",failed,,,,,,,,,,,,,,,," + SafeText.csvCell(why) + ",,,,";
        }
    }
}
