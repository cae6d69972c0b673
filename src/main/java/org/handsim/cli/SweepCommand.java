package org.handsim.cli;

import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.Callable;
import org.handsim.sim.GraspAssessment;
import org.handsim.sim.HandModel;
import org.handsim.sim.Scenario;
import org.handsim.sim.ScenarioException;
import org.handsim.sim.Simulation;
import org.handsim.sim.SimulationException;
import org.handsim.sim.Sweep;
import org.handsim.util.AtomicFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim sweep}: many scenarios in parallel in one JVM, one summary table. */
@Command(name = "sweep", mixinStandardHelpOptions = true,
    description = {"Runs every run of SWEEP.json in parallel on all cores and writes one table,",
        "out/<sweep name>/summary.csv (header: " + SweepCommand.HEADER + ").",
        "A run that fails is a row with status 'failed' and its error; the others go on."})
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

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        Sweep sweep;
        try {
            sweep = Sweep.load(file);
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage());
        }
        GraspCommand.checkFriction(friction, edges);
        int n = threads != null ? threads : sweep.threads();
        if (n < 1) throw CliError.usage("handsim: --threads must be >= 1, got " + n);
        if (!engine.equals("local")) return SweepJob.runOnEngine(this, sweep, n, engine, master);
        if (master != null) throw CliError.usage("handsim: --master needs --engine spark");
        List<Sweep.Run> runs = sweep.runs();
        ExecutorService pool = Executors.newFixedThreadPool(n);
        AtomicInteger done = new AtomicInteger();
        long t0 = System.nanoTime();
        List<Future<String>> rows = new ArrayList<>();
        for (Sweep.Run run : runs) {
            rows.add(pool.submit(() -> {
                String row = runOne(run, friction, edges);
                int d = done.incrementAndGet();
                synchronized (err) {
                    err.println(String.format(Locale.ROOT, "[%d/%d] %s (%.1f s)", d, runs.size(), run.label(), (System.nanoTime() - t0) / 1e9));
                    err.flush();
                }
                return row;
            }));
        }
        pool.shutdown();
        Path dir = out != null ? out : Path.of("out", sweep.name());
        int failed = 0;
        try (AtomicFile f = new AtomicFile(dir.resolve("summary.csv"))) {
            Writer w = f.writer();
            w.write(HEADER);
            w.write('\n');
            for (Future<String> r : rows) {
                String row = r.get();
                if (row.contains(",failed,")) failed++;
                w.write(row);
                w.write('\n');
            }
            f.commit();
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        spec.commandLine().getOut().println(String.format(Locale.ROOT, "%s: %d runs (%d failed) on %d threads in %.2f s; wrote %s",
            sweep.name(), runs.size(), failed, n, wall, dir.resolve("summary.csv")));
        return failed == 0 ? 0 : 1;
    }

    static String runOne(Sweep.Run run, Double friction, Integer edges) {
        String label = csvText(run.label());
        String scenarioName = "";
        try {
            Scenario s = GraspCommand.withFriction(run.scenario().get(), friction, edges);
            scenarioName = s.name();
            HandModel m = Simulation.model(s, false);
            long t = System.nanoTime();
            m.run(null);
            double wall = (System.nanoTime() - t) / 1e9;
            StringBuilder sb = new StringBuilder();
            sb.append(label).append(',').append(csvText(scenarioName)).append(",ok,").append(m.time()).append(',')
                .append(m.stepIndex()).append(',').append(wall);
            for (int k = 1; k <= 3; k++) {
                sb.append(',').append(m.state(k)).append(',').append(num(m.breakawayTime(k))).append(',')
                    .append(num(m.breakawayForce(k))).append(',').append(m.maxContactForce(k));
            }
            GraspAssessment g = GraspAssessment.of(m, s.friction(), s.coneEdges());
            sb.append(",,").append(g.quality().forceClosure()).append(',').append(g.quality().epsilon()).append(',')
                .append(g.quality().volume()).append(',').append(g.holdMinN());
            return sb.toString();
        } catch (ScenarioException | SimulationException | IllegalArgumentException e) {
            return label + "," + csvText(scenarioName) + ",failed,,,,,,,,,,,,,,,," + csvText(e.getMessage()) + ",,,,";
        }
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "" : Double.toString(v);
    }

    /** Quotes a text field for CSV when it holds a comma, quote or newline. */
    static String csvText(String s) {
        if (s == null) return "";
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0) return s;
        return "\"" + s.replace("\"", "\"\"").replace("\n", " ") + "\"";
    }
}
