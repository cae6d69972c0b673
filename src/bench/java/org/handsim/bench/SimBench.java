package org.handsim.bench;

import java.nio.file.Path;
import java.util.Locale;
import org.handsim.sim.HandModel;
import org.handsim.sim.Home;
import org.handsim.sim.Scenario;
import org.handsim.sim.Simulation;

/**
 * The whole model in the process — trajectories, clutch, kinematics, collision and contacts,
 * dynamics — on the paper's experiment (scenarios/paper-breakaway.json, 8 947 steps) and the
 * three-finger mug grasp (scenarios/mug-grasp.json, 4 700 steps), dt = 1 ms, no trace: the
 * savings table of docs/BENCHMARKS.md. Three settings per scene: the default (work saving on),
 * lazy off (every finger collided and run through the dynamics every step) and torques off
 * (no dynamics: the clutch does not need it). The results of the three are checked equal.
 * A fourth row runs the default setting frictionless (μ = 0, the contact-force solve of before
 * friction existed): the cost of the friction cones' least-norm forces (its forces differ).
 */
final class SimBench implements BenchMain.Suite {
    @Override
    public void run() {
        StringBuilder table = new StringBuilder();
        table.append("| scene | setting | wall per run | ns/step | x real time | finger updates | fingers idle | collision queries | skipped | dynamics calls | skipped |\n");
        table.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        // the JIT takes several seconds to settle on the whole model (measured: the first 2 s
        // warm-up of one setting left it 2-4x slow): run both contact-force paths first
        for (Path file : new Path[] {Home.paperScenario(), Home.scenarios().resolve("mug-grasp.json")}) {
            for (Scenario w : new Scenario[] {Scenario.load(file), Scenario.load(file).withFriction(0)}) {
                long end = System.nanoTime() + 3_000_000_000L;
                while (System.nanoTime() < end) {
                    HandModel m = Simulation.model(w, false);
                    m.run(null);
                    Bench.sink += m.maxContactForce(3);
                }
            }
        }
        for (Path file : new Path[] {Home.paperScenario(), Home.scenarios().resolve("mug-grasp.json")}) {
            Scenario s = Scenario.load(file);
            double reference = Double.NaN;
            for (String setting : new String[] {"default (lazy)", "torques off", "lazy off", "frictionless (mu = 0)"}) {
                Scenario run = setting.equals("torques off") ? s.withTorques(false)
                    : setting.startsWith("frictionless") ? s.withFriction(0) : s;
                boolean lazy = !setting.equals("lazy off");
                HandModel[] last = new HandModel[1];
                Bench.Result r = Bench.measure(String.format(Locale.ROOT, "%s, %s (one run)", s.name(), setting), () -> {
                    HandModel m = Simulation.model(run, false).lazy(lazy);
                    m.run(null);
                    last[0] = m;
                    return m.maxContactForce(1) + m.maxContactForce(3);
                }, 2000, 11, 200);
                HandModel m = last[0];
                double result = m.maxContactForce(1) + m.maxContactForce(3) + m.breakawayTime(3);
                if (Double.isNaN(reference)) reference = result;
                if (!setting.startsWith("frictionless") && Math.abs(result - reference) > 1e-9 * Math.abs(reference)) {
                    throw new AssertionError(s.name() + ", " + setting + ": results differ from the default: " + result + " vs " + reference);
                }
                double perStep = r.medianNs / m.stepIndex();
                table.append(String.format(Locale.ROOT, "| %s | %s | %.1f ms | %.0f | %.0f | %d | %d | %d | %d | %d | %d |%n",
                    s.name(), setting, r.medianMs(), perStep, m.time() / (r.medianNs / 1e9),
                    m.counter(HandModel.Counter.FINGER_UPDATES), m.counter(HandModel.Counter.FINGERS_IDLE),
                    m.counter(HandModel.Counter.COLLISION_QUERIES), m.counter(HandModel.Counter.COLLISIONS_SKIPPED),
                    m.counter(HandModel.Counter.DYNAMICS_CALLS), m.counter(HandModel.Counter.DYNAMICS_SKIPPED)));
            }
        }
        System.out.println();
        System.out.print(table);
    }
}
