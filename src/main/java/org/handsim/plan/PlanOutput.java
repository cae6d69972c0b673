package org.handsim.plan;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.function.Consumer;
import org.handsim.hold.HoldSettings;
import org.handsim.files.AtomicFile;
import org.handsim.text.JsonWriter;
import org.handsim.process.Phase;

/**
 * The outputs of a plan (contracts, README), fed one {@link TrialResult} at a time in trial
 * order: {@code plan.csv} is streamed to its temporary file as rows come (renamed when
 * complete), and only what the summary needs is kept — counts, the ten best trials, the ε
 * histogram and the direction map — so memory does not grow with N. {@link #finish} writes
 * {@code plan.json} and {@code best/01.json … best/10.json}, the ten best grasps by ε (ties:
 * the larger minimum hold, then the lower trial index) among those with force closure, as
 * scenarios {@code handsim run} and {@code handsim gui} open as they are — none when no trial
 * reached force closure. Every file is written atomically.
 */
public final class PlanOutput implements Consumer<TrialResult>, AutoCloseable {
    /** How many best grasps are written. */
    public static final int BEST = 10;
    /** Best first: ε, then the minimum hold, descending; then the trial index, ascending. */
    static final Comparator<TrialResult> BETTER_FIRST = Comparator.comparingDouble(TrialResult::epsilon).reversed()
        .thenComparing(Comparator.comparingDouble(TrialResult::holdMinN).reversed())
        .thenComparingInt(TrialResult::index);

    private final Path dir;
    private final Path published;
    private final TrialRunner scenarios;
    private final AtomicFile csv;
    private final Writer w;
    /**
     * With {@code --rank-by hold-margin}: the hold test's smallest margin, descending; then as
     * {@link #BETTER_FIRST}.
     */
    static final Comparator<TrialResult> HELD_FIRST = Comparator.comparingDouble(TrialResult::holdMargin).reversed()
        .thenComparing(BETTER_FIRST);

    private final Comparator<TrialResult> order;
    private final boolean withHold;
    private final PriorityQueue<TrialResult> best;
    private final EpsilonHistogram histogram = new EpsilonHistogram();
    private final DirectionMap directions;
    private final Consumer<Integer> progress;
    private long rows, failed, forceClosure, heldAll;
    private final long[] outcomes = new long[TrialOutcome.values().length];
    private int expected;

    /**
     * @param dir       the plan folder ({@code out/plan-<name>})
     * @param scenarios writes the best trials as scenarios (a runner of the same spec)
     * @param progress  told the number of rows written after each row (may be null)
     */
    public PlanOutput(Path dir, TrialRunner scenarios, Consumer<Integer> progress) throws IOException {
        this(dir, dir, scenarios, progress);
    }

    /**
     * @param dir       where the files are written (a private folder of {@link org.handsim.files.OutputSet})
     * @param published the plan folder they will be read from: the best grasps name the object
     *                  file relative to {@code published/best/}
     * @param scenarios writes the best trials as scenarios (a runner of the same spec)
     * @param progress  told the number of rows written after each row (may be null)
     */
    public PlanOutput(Path dir, Path published, TrialRunner scenarios, Consumer<Integer> progress) throws IOException {
        this.dir = dir;
        this.published = published;
        this.scenarios = scenarios;
        this.progress = progress;
        this.directions = new DirectionMap(scenarios.spec().trials());   // cells sized to the trial count
        PlanHold hold = scenarios.spec().hold();
        this.withHold = hold != null;
        this.order = hold != null && hold.rankByMargin() ? HELD_FIRST : BETTER_FIRST;
        this.best = new PriorityQueue<>(order.reversed());
        this.csv = new AtomicFile(dir.resolve("plan.csv"));
        this.w = csv.writer();
        w.write(withHold ? TrialResult.HEADER + TrialResult.HOLD_HEADER : TrialResult.HEADER);
        w.write('\n');
    }

    @Override
    public void accept(TrialResult r) {
        if (r.index() != expected) {
            throw new IllegalStateException("trial " + r.index() + " delivered where trial " + expected + " was expected");
        }
        expected++;
        try {
            w.write(r.csvRow(withHold));
            w.write('\n');
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        rows++;
        if (!r.ok()) {
            failed++;
        } else {
            if (r.forceClosure()) forceClosure++;
            if (r.holdPassed() != null) {
                boolean all = true;
                for (boolean b : r.holdPassed()) all &= b;
                if (all) heldAll++;
            }
            if (r.outcome() != null) outcomes[r.outcome().ordinal()]++;
            histogram.add(r.forceClosure(), r.epsilon());
            directions.add(r.approach(), r.forceClosure() ? r.epsilon() : 0);
            if (r.forceClosure()) {   // a grasp without force closure is no "best" grasp
                best.add(r);
                if (best.size() > BEST) best.poll();
            }
        }
        if (progress != null) progress.accept((int) rows);
    }

    /**
     * Commits plan.csv and writes plan.json and best/.
     *
     * @param wallS  wall time of the whole plan, seconds
     * @param engine the engine's name
     * @return plan.json's content
     */
    public Map<String, Object> finish(double wallS, String engine) throws IOException {
        PlanSpec spec = scenarios.spec();
        if (rows != spec.trials()) throw new IllegalStateException(rows + " rows for " + spec.trials() + " trials");
        csv.commit();
        Phase.reach("table");
        List<TrialResult> top = bestFirst();
        Path bestDir = dir.resolve("best");
        Files.createDirectories(bestDir);
        if (dir.equals(published)) {   // written in place: the previous plan's best grasps go first
            try (DirectoryStream<Path> old = Files.newDirectoryStream(bestDir, "[0-9][0-9].json")) {
                for (Path p : old) Files.delete(p);
            }
        }
        String objectFile = published.resolve("best").toAbsolutePath().normalize().relativize(objectFile(spec)).toString();
        for (int i = 0; i < top.size(); i++) {
            TrialResult r = top.get(i);
            String nn = String.format("%02d", i + 1);
            Path file = bestDir.resolve(nn + ".json");
            TrialParameters p = new TrialParameters(r.index(), r.approach(), r.roll(), r.spreadCounts(), false, 0);
            AtomicFile.writeString(file, scenarios.scenarioJson(p, r.standoff(), r.palmPosition(), r.palmRotation(),
                "plan-" + spec.name() + "-best" + nn, true, objectFile));
        }
        Phase.reach("best");
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("target", spec.target());
        json.put("trials", spec.trials());
        json.put("force_closure", forceClosure);
        json.put("best_epsilon", top.isEmpty() ? 0.0 : top.get(0).epsilon());
        json.put("wall_time_s", wallS);
        json.put("trials_per_s", wallS > 0 ? spec.trials() / wallS : 0.0);
        json.put("engine", engine);
        json.put("seed", spec.seed());
        if (withHold) {
            HoldSettings hs = spec.hold().settings();
            Map<String, Object> h = new LinkedHashMap<>();
            h.put("force_N", Double.isNaN(hs.forceN()) ? null : (Object) hs.forceN());
            h.put("duration_s", hs.durationS());
            h.put("dt_s", hs.dtS());
            h.put("max_displacement_m", hs.maxDisplacementM());
            h.put("max_rotation_deg", hs.maxRotationDeg());
            h.put("held_all_six", heldAll);
            h.put("ranked_by", spec.hold().rankByMargin() ? "hold_margin" : "epsilon");
            json.put("hold_test", h);
        }
        AtomicFile.writeString(dir.resolve("plan.json"), JsonWriter.pretty(json));
        return json;
    }

    private static Path objectFile(PlanSpec spec) {
        @SuppressWarnings("unchecked")
        Map<String, Object> o = (Map<String, Object>) spec.template().get("object");
        return Path.of((String) o.get("file")).toAbsolutePath().normalize();
    }

    /** Trials per {@link TrialOutcome} (index: ordinal), of the trials that did not fail. */
    public long[] outcomes() { return outcomes.clone(); }

    /** The best trials with force closure so far, best first (at most {@link #BEST}). */
    public List<TrialResult> bestFirst() {
        List<TrialResult> l = new ArrayList<>(best);
        l.sort(order);
        return l;
    }

    public EpsilonHistogram histogram() { return histogram; }
    public DirectionMap directions() { return directions; }
    public long rows() { return rows; }
    public long failed() { return failed; }
    public long forceClosure() { return forceClosure; }
    /** Trials whose grasp held in all six directions of the hold test (0 without it). */
    public long heldAll() { return heldAll; }

    /** Deletes the temporary table unless {@link #finish} committed it. */
    @Override
    public void close() throws IOException {
        csv.close();
    }
}
