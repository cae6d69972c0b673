package org.handsim.bench;

import java.nio.file.Path;
import java.util.Locale;
import org.handsim.dynamics.HandDynamics;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.SceneGeometry;
import org.handsim.model.Simulation;

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
 * A second table prices friction: the default setting with the scenes' μ = 0.5 (the
 * mechanism's forces in the friction cones) against μ = 0 (the frictionless contacts),
 * measured alternately in five rounds, the best round's median of each: measured one after the
 * other, whichever runs first after the warm-up came out up to 2× slower.
 */
final class SimBench implements BenchMain.Suite {
    @Override
    public void run() {
        StringBuilder table = new StringBuilder();
        table.append("| scene | setting | wall per run | ns/step | x real time | finger updates | fingers idle | collision queries | skipped"
            + " | dynamics calls | skipped | sphere apart | tree walks | coherent queries | triangle tests |\n");
        table.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
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
        // before the main table: its "lazy off" runs leave the JIT's code slower for what follows
        String friction = frictionCost();
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
        System.out.println();
        System.out.print(friction);
        System.out.println();
        System.out.print(allocation());
    }

    /**
     * Bytes the step allocates: a model run once (its scratch arrays grow to the scene's contact
     * counts), reset with {@code initialise()} and run again, the second run's allocation by the
     * thread (com.sun.management.ThreadMXBean). An odd few hundred bytes seen in some runs were
     * the JIT's (deoptimisation): the same second run interpreted ({@code -Xint}) allocated none.
     */
    private static String allocation() {
        com.sun.management.ThreadMXBean tb = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        StringBuilder t = new StringBuilder("| scene | mu | steps | bytes allocated by the second run |\n|---|---:|---:|---:|\n");
        for (Path file : new Path[] {Home.paperScenario(), Home.scenarios().resolve("mug-grasp.json")}) {
            for (double mu : new double[] {0.5, 0}) {
                Scenario s = Scenario.load(file).withFriction(mu);
                HandModel m = Simulation.model(s, false);
                m.run(null);
                m.initialise();
                long id = Thread.currentThread().getId();
                long b0 = tb.getThreadAllocatedBytes(id);
                m.run(null);
                long bytes = tb.getThreadAllocatedBytes(id) - b0;
                t.append(String.format(Locale.ROOT, "| %s | %s | %d | %d |%n", s.name(), mu, m.stepIndex(), bytes));
            }
        }
        return t.toString();
    }

    /** μ = 0.5 against μ = 0, alternating rounds, the best median of each. */
    private static String frictionCost() {
        StringBuilder t = new StringBuilder("| scene | mu = 0.5 (forces in the cones) | mu = 0 (frictionless) | ratio |\n|---|---:|---:|---:|\n");
        for (Path file : new Path[] {Home.paperScenario(), Home.scenarios().resolve("mug-grasp.json")}) {
            Scenario s = Scenario.load(file);
            double best05 = Double.POSITIVE_INFINITY, best0 = Double.POSITIVE_INFINITY;
            for (int round = 0; round < 5; round++) {
                for (double mu : new double[] {0.5, 0}) {
                    Scenario run = s.withFriction(mu);
                    Bench.Result r = Bench.measure(String.format(Locale.ROOT, "%s, mu = %s, round %d", s.name(), mu, round + 1), () -> {
                        HandModel m = Simulation.model(run, false);
                        m.run(null);
                        return m.maxContactForce(3);
                    }, 1000, 5, 200);
                    if (mu == 0) best0 = Math.min(best0, r.medianMs()); else best05 = Math.min(best05, r.medianMs());
                }
            }
            t.append(String.format(Locale.ROOT, "| %s | %.1f ms | %.1f ms | %.2f |%n", s.name(), best05, best0, best05 / best0));
        }
        return t.toString();
    }
}
