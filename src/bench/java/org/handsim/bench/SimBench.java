package org.handsim.bench;

import java.nio.file.Path;
import java.util.Locale;
import org.handsim.dynamics.HandDynamics;
import org.handsim.sim.HandModel;
import org.handsim.sim.Home;
import org.handsim.sim.Scenario;
import org.handsim.sim.SceneGeometry;

/**
 * The whole model in the process — trajectories, clutch, kinematics, collision and contacts,
 * dynamics — on the paper's experiment (scenarios/paper-breakaway.json, 8 947 steps) and the
 * three-finger mug grasp (scenarios/mug-grasp.json, 4 700 steps), dt = 1 ms, no trace: the
 * savings table of docs/BENCHMARKS.md. Five settings per scene: the default (work saving and
 * coherent collision on), coherence off (every collision query that passes the sphere test
 * walks the trees), torques off (no dynamics: the clutch does not need it), lazy off (every
 * finger collided and run through the dynamics every step) and both off (the full computation).
 * The results of all are checked equal. The last columns are the collision back end's counters
 * (SceneGeometry.Counter).
 */
final class SimBench implements BenchMain.Suite {
    @Override
    public void run() {
        StringBuilder table = new StringBuilder();
        table.append("| scene | setting | wall per run | ns/step | x real time | finger updates | fingers idle | collision queries | skipped"
            + " | dynamics calls | skipped | sphere apart | tree walks | coherent queries | triangle tests |\n");
        table.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (Path file : new Path[] {Home.paperScenario(), Home.scenarios().resolve("mug-grasp.json")}) {
            Scenario s = Scenario.load(file);
            double reference = Double.NaN;
            for (String setting : new String[] {"default", "coherence off", "torques off", "lazy off", "lazy and coherence off"}) {
                Scenario run = setting.equals("torques off") ? s.withTorques(false) : s;
                boolean lazy = !setting.startsWith("lazy");
                boolean coherent = !setting.contains("coherence off");
                HandModel[] last = new HandModel[1];
                SceneGeometry[] geometry = new SceneGeometry[1];
                Bench.Result r = Bench.measure(String.format(Locale.ROOT, "%s, %s (one run)", s.name(), setting), () -> {
                    SceneGeometry g = new SceneGeometry(run.object(), SceneGeometry.DEFAULT_K).coherent(coherent);
                    HandModel m = new HandModel(run, g, HandDynamics.barrettHand()::inverseDynamics, false).lazy(lazy);
                    m.run(null);
                    last[0] = m;
                    geometry[0] = g;
                    return m.maxContactForce(1) + m.maxContactForce(3);
                }, 2000, 11, 200);
                HandModel m = last[0];
                SceneGeometry g = geometry[0];
                double result = m.maxContactForce(1) + m.maxContactForce(3) + m.breakawayTime(3);
                if (Double.isNaN(reference)) reference = result;
                if (Math.abs(result - reference) > 1e-9 * Math.abs(reference)) {
                    throw new AssertionError(s.name() + ", " + setting + ": results differ from the default: " + result + " vs " + reference);
                }
                double perStep = r.medianNs / m.stepIndex();
                table.append(String.format(Locale.ROOT, "| %s | %s | %.2f ms | %.0f | %.0f | %d | %d | %d | %d | %d | %d | %d | %d | %d | %d |%n",
                    s.name(), setting, r.medianMs(), perStep, m.time() / (r.medianNs / 1e9),
                    m.counter(HandModel.Counter.FINGER_UPDATES), m.counter(HandModel.Counter.FINGERS_IDLE),
                    m.counter(HandModel.Counter.COLLISION_QUERIES), m.counter(HandModel.Counter.COLLISIONS_SKIPPED),
                    m.counter(HandModel.Counter.DYNAMICS_CALLS), m.counter(HandModel.Counter.DYNAMICS_SKIPPED),
                    g.counter(SceneGeometry.Counter.SPHERE_APART), g.counter(SceneGeometry.Counter.TREE_WALKS),
                    g.counter(SceneGeometry.Counter.COHERENT_QUERIES), g.counter(SceneGeometry.Counter.TRIANGLE_TESTS)));
            }
        }
        System.out.println();
        System.out.print(table);
    }
}
