package org.handsim.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.handsim.plan.Autograsp;
import org.handsim.plan.PlanSpec;
import org.handsim.plan.TrialParameters;
import org.handsim.plan.TrialResult;
import org.handsim.plan.TrialRunner;
import org.handsim.model.HandClearance;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;

/**
 * Planning trials on one core: the mug (vrml/objects/mug.wrl, 720
 * triangles) and a 19 880-triangle sphere ({@code generate_models.py --big 20000}, generated
 * into a temporary folder when absent). Per object: the whole trial (approach, closing,
 * evaluation) over a fixed set of trial indices of a 1 000-trial plan (seed 1), and the approach
 * alone on the same indices; trials per second per core = 1 / the mean trial time.
 */
final class PlanBench implements BenchMain.Suite {
    static final int TRIALS = 1000, SAMPLE = 100;

    @Override
    public void run() throws Exception {
        StringBuilder table = new StringBuilder();
        table.append("| object | triangles | trial (" + SAMPLE + " fixed trials, median of batch means) | approach | closing + evaluation | trials/s per core | sim time per trial | force closure |\n");
        table.append("|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (Path f : new Path[] {Home.dir().resolve("vrml/objects/mug.wrl"), bigSphere()}) {
            PlanSpec spec = PlanSpec.forTarget(f, TRIALS, 1, 0.5, 8);
            TrialRunner runner = new TrialRunner(spec);
            Scenario t = Scenario.parse(Path.of(spec.templateFile()), spec.templateJson());
            HandClearance hc = new HandClearance(t.object());
            int[] next = {0};
            double[] sim = {0}, fc = {0};
            Bench.Result trial = Bench.measure(String.format(Locale.ROOT, "plan trial, %s", f.getFileName()), () -> {
                int i = (next[0]++ % SAMPLE) * (TRIALS / SAMPLE);
                TrialResult r = runner.run(i);
                if (!r.ok()) throw new AssertionError("trial " + i + " failed: " + r.error());
                sim[0] += r.simTimeS();
                fc[0] += r.forceClosure() ? 1 : 0;
                return r.epsilon() + r.simTimeS();
            }, 3000, 11, 500);
            int[] next2 = {0};
            Bench.Result approach = Bench.measure(String.format(Locale.ROOT, "plan approach only, %s", f.getFileName()), () -> {
                int i = (next2[0]++ % SAMPLE) * (TRIALS / SAMPLE);
                TrialParameters p = runner.parameters(i);
                // the approach's cost is the touch search; the standoff (the trial's own rule) only backs off from it
                Autograsp.Approach a = Autograsp.approach(hc, p.approach(), p.roll(), p.spreadCounts(), new double[3], 0);
                return a.distance();
            }, 2000, 11, 300);
            long calls = next[0];
            table.append(String.format(Locale.ROOT, "| %s | %d | %.2f ms | %.2f ms | %.2f ms | %.0f | %.2f s | %.0f %% |%n",
                f.getFileName(), org.handsim.scenario.SceneMeshes.mesh(f, Scenario.DEFAULT_DIVISIONS, 1.0).triangleCount(),
                trial.medianMs(), approach.medianMs(), trial.medianMs() - approach.medianMs(), 1e3 / trial.medianMs(),
                sim[0] / calls, 100 * fc[0] / calls));
        }
        System.out.println();
        System.out.print(table);
    }

    /** vrml/objects/sphere_big.wrl if it exists, else generated into a temporary folder (python3). */
    static Path bigSphere() throws IOException, InterruptedException {
        Path f = Home.dir().resolve("vrml/objects/sphere_big.wrl");
        if (Files.isRegularFile(f)) return f;
        Path dir = Path.of(System.getProperty("java.io.tmpdir"), "handsim-bench-big");
        Path g = dir.resolve("objects/sphere_big.wrl");
        if (!Files.isRegularFile(g)) {
            Process p = new ProcessBuilder("python3", Home.dir().resolve("vrml/tools/generate_models.py").toString(),
                "--big", "20000", "--out", dir.toString()).inheritIO().start();
            if (p.waitFor() != 0) throw new IOException("generate_models.py --big 20000 failed");
        }
        return g;
    }
}
