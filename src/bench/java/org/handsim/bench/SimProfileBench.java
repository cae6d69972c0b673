package org.handsim.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordingFile;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;

/**
 * Suite "sim-profile": where the time of the three-finger mug grasp goes. Runs the scene
 * (scenarios/mug-grasp.json, no trace) over and over for {@value #SECONDS} s under Java Flight
 * Recorder's execution sampler (every 1 ms, after a 3 s warm-up), then sorts the samples by the
 * first of these that is on the sampled stack: the event location (HandModel.touchesAt: the
 * bisection of a first touch, the tunnelling substeps), the collision back end (its tree walks,
 * the tests of near pairs, patches, the displacement bound, the rest of SceneGeometry), the
 * dynamics, the contact forces, the kinematics, the clutch, the trajectories, making the model,
 * the rest of HandModel. Prints each share and its time per run. The recording is kept in
 * build/bench/sim-profile.jfr ({@code jfr print --events jdk.ExecutionSample} reads it).
 *
 * <p>Uses only the API every version of the simulator has (Scenario, Simulation, HandModel), so
 * the same class profiles an earlier build: put that build's jars on the class path instead.
 */
final class SimProfileBench implements BenchMain.Suite {
    static final int SECONDS = 20;

    /** Category and the class/method prefixes that put a sample in it, first match wins. */
    private static final String[][] CATEGORIES = {
        {"event location: first-touch bisection, tunnelling substeps", "org.handsim.model.HandModel.touchesAt"},
        {"collision: tree walk (gathering near pairs)", "org.handsim.collision.TreeQuery.near"},
        {"collision: tree walk (full query)", "org.handsim.collision.TreeQuery.run"},
        {"collision: tests of near pairs", "org.handsim.collision.TreeQuery.testNear"},
        {"collision: patches and point contacts", "org.handsim.contact.ContactPatches"},
        {"collision: displacement bound", "org.handsim.model.SceneGeometry.displacement"},
        {"collision: rest (sphere test, poses)", "org.handsim.model.SceneGeometry", "org.handsim.collision"},
        {"dynamics (eq 8)", "org.handsim.dynamics"},
        {"contact forces (eq 11)", "org.handsim.contact.ContactForces"},
        {"kinematics", "org.handsim.kinematics"},
        {"clutch", "org.handsim.clutch.FingerClutch"},
        {"trajectories", "org.handsim.trajectory"},
        {"making the model", "org.handsim.model.Simulation.model", "org.handsim.model.HandModel.<init>"},
        {"HandModel itself (step, bookkeeping, contact sets)", "org.handsim.model", "org.handsim.trace"},
    };

    @Override
    public void run() throws Exception {
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        double sink = 0;
        long warm = System.nanoTime() + 3_000_000_000L;
        while (System.nanoTime() < warm) sink += once(s);
        Path out = Path.of(System.getProperty("handsim.root", ".")).resolve("build/bench/sim-profile.jfr");
        Files.createDirectories(out.getParent());
        int runs = 0;
        long t0;
        try (Recording rec = new Recording()) {
            rec.enable("jdk.ExecutionSample").withPeriod(Duration.ofMillis(1));
            rec.start();
            t0 = System.nanoTime();
            long end = t0 + SECONDS * 1_000_000_000L;
            while (System.nanoTime() < end) {
                sink += once(s);
                runs++;
            }
            t0 = System.nanoTime() - t0;
            rec.stop();
            rec.dump(out);
        }
        Bench.sink += sink;
        Map<String, Integer> counts = new LinkedHashMap<>();
        for (String[] c : CATEGORIES) counts.put(c[0], 0);
        counts.put("other", 0);
        int total = 0;
        for (RecordedEvent e : RecordingFile.readAllEvents(out)) {
            if (!e.getEventType().getName().equals("jdk.ExecutionSample") || e.getStackTrace() == null) continue;
            List<RecordedFrame> frames = e.getStackTrace().getFrames();
            boolean ours = false;
            for (RecordedFrame f : frames) ours |= f.getMethod().getType().getName().startsWith("org.handsim.model");
            if (!ours) continue;   // JIT, GC and other threads
            total++;
            counts.merge(category(frames), 1, Integer::sum);
        }
        double msPerRun = t0 / 1e6 / runs;
        System.out.printf(Locale.ROOT, "%n%d runs of %s in %d s: %.2f ms per run (wall, with the recorder on); %d samples in the model%n%n",
            runs, s.name(), SECONDS, msPerRun, total);
        System.out.println("| where | share of samples | ms per run |");
        System.out.println("|---|---:|---:|");
        for (Map.Entry<String, Integer> c : counts.entrySet()) {
            if (c.getValue() == 0) continue;
            double share = c.getValue() / (double) Math.max(1, total);
            System.out.printf(Locale.ROOT, "| %s | %.1f %% | %.2f |%n", c.getKey(), 100 * share, share * msPerRun);
        }
        System.out.println("\nrecording: " + out);
    }

    private static double once(Scenario s) {
        HandModel m = Simulation.model(s, false);
        m.run(null);
        return m.maxContactForce(1);
    }

    private static String category(List<RecordedFrame> frames) {
        for (String[] c : CATEGORIES) {
            for (RecordedFrame f : frames) {
                String name = f.getMethod().getType().getName() + "." + f.getMethod().getName();
                for (int i = 1; i < c.length; i++) {
                    if (name.startsWith(c[i])) return c[0];
                }
            }
        }
        return "other";
    }
}
