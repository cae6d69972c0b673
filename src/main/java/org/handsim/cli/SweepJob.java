package org.handsim.cli;

import java.io.Writer;
import java.nio.file.Path;
import java.util.Locale;
import org.handsim.plan.IndexedJob;
import org.handsim.scenario.Sweep;
import org.handsim.files.AtomicFile;
import org.handsim.files.OutputSet;
import org.handsim.process.Phase;
import org.handsim.text.SafeText;

/**
 * The runs of a sweep file as an {@link IndexedJob}, run by any engine ({@code handsim sweep
 * --engine local|spark}): run i of the file gives its {@code summary.csv} row. The job carries
 * the sweep file's path; a worker that did not get the loaded file (a Spark executor) loads it
 * once.
 */
final class SweepJob implements IndexedJob<String> {
    private static final long serialVersionUID = 1L;
    /** A sweep's folder holds one file, its table. */
    static final OutputSet.Layout LAYOUT = new OutputSet.Layout("summary.csv", "summary\\.csv");
    private final String file;
    private final Double friction;
    private final Integer edges;
    private final org.handsim.hand.HandParameters hand;
    private transient volatile Sweep sweep;

    /** @param sweep the loaded file; friction, edges the command's overrides (null: each scenario's) */
    SweepJob(Path file, Sweep sweep, Double friction, Integer edges, org.handsim.hand.HandParameters hand) {
        this.file = file.toAbsolutePath().normalize().toString();
        this.hand = hand;
        this.sweep = sweep;
        this.friction = friction;
        this.edges = edges;
    }

    @Override
    public String run(int index) {
        Sweep s = sweep;
        if (s == null) {
            synchronized (this) {
                if (sweep == null) sweep = Sweep.load(Path.of(file));
                s = sweep;
            }
        }
        return SweepCommand.runOne(s.runs().get(index), friction, edges, hand);
    }

    /** {@code handsim sweep} on the command's engine: the table streamed in the file's order, progress on standard error. */
    static int run(SweepCommand c, Sweep sweep, int defaultThreads) throws Exception {
        EngineChoice eng = EngineChoice.of(c.engine, c.master, c.threads, defaultThreads);
        int runs = sweep.runs().size();
        Path dir = c.out != null ? Args.outputPath("--out", c.out) : Path.of("out", sweep.name());
        long t0 = System.nanoTime();
        int[] failed = {0}, done = {0};
        java.io.PrintWriter err = c.spec.commandLine().getErr();
        try (OutputSet set = Args.outputSet(err, "--out", dir, LAYOUT)) {
            Phase.reach("opened");
            try (AtomicFile f = new AtomicFile(set.dir().resolve("summary.csv"))) {
                Writer w = f.writer();
                w.write(SweepCommand.HEADER);
                w.write('\n');
                eng.announce(err, "sweep " + sweep.name());
                try {
                    eng.engine().run(new SweepJob(c.file, sweep, c.friction, c.edges, c.hand.parameters()), runs, eng.settings("handsim sweep " + sweep.name()), row -> {
                        try {
                            if (row.contains(",failed,")) failed[0]++;
                            w.write(row);
                            w.write('\n');
                        } catch (java.io.IOException e) {
                            throw new java.io.UncheckedIOException(e);
                        }
                        err.println(String.format(Locale.ROOT, "[%d/%d] %s (%.1f s)", ++done[0], runs, SafeText.line(sweep.runs().get(done[0] - 1).label()),
                            (System.nanoTime() - t0) / 1e9));
                        err.flush();
                        if (done[0] == 1) Phase.reach("first-row");
                        if (done[0] == (runs + 1) / 2) Phase.reach("half-rows");
                        if (done[0] == runs) Phase.reach("last-row");
                    });
                } catch (java.io.UncheckedIOException e) {
                    throw e.getCause();
                } catch (Exception e) {
                    throw eng.failed("sweep " + sweep.name(), e);
                }
                f.commit();
            }
            Phase.reach("table");
            set.publish();
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        c.spec.commandLine().getOut().println(String.format(Locale.ROOT, "%s: %d runs (%d failed) on %s in %.2f s; wrote %s",
            sweep.name(), runs, failed[0], eng.where(), wall, dir.resolve("summary.csv")));
        return failed[0] == 0 ? 0 : 1;
    }
}
