package org.handsim.bench;

import java.util.Locale;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;

/**
 * What the window's live grasp (gui.LiveGrasp) costs whom, on the three-finger mug grasp
 * (scenarios/mug-grasp.json, μ = 0.5, 8 cone edges): the simulation thread pays for one copy
 * ({@code HandModel.graspInput}) per publication — set against one step of the same run
 * (the whole run's time over its steps) —, the grasp thread for the evaluation of a copy
 * ({@code GraspAssessment.of(Input, …)}), at most 10 times a second.
 */
final class LiveGraspBench implements BenchMain.Suite {
    @Override
    public void run() {
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        long steps = HandModel.totalSteps(s);
        Bench.Result run = Bench.measure("mug-grasp: the whole run (" + steps + " steps)", () -> {
            HandModel m = Simulation.model(s, false);
            m.run(null);
            return m.time();
        }, 3000, 15, 200);
        StringBuilder table = new StringBuilder();
        table.append(String.format(Locale.ROOT, "%n| grasp | contacts | copy (simulation thread) | copy / step | evaluation (grasp thread) |%n"
            + "|---|---:|---:|---:|---:|%n"));
        double stepNs = run.medianNs / steps;
        for (double at : new double[] {2.0, Double.NaN}) {
            HandModel m = Simulation.model(s, false);
            while (m.running() && (Double.isNaN(at) || m.time() < at)) m.step();
            GraspAssessment.Input in = m.graspInput();
            String name = String.format(Locale.ROOT, "mug-grasp at t = %.1f s", m.time());
            Bench.Result copy = Bench.measure(name + ": Input.of", () -> m.graspInput().contacts().size(), 2000, 15, 50);
            Bench.Result eval = Bench.measure(name + ": GraspAssessment.of(Input)", () -> GraspAssessment.of(in, s.friction(), s.coneEdges()).holdMinN(),
                3000, 15, 100);
            table.append(String.format(Locale.ROOT, "| %s | %d | %.2f µs | %.1f %% | %.2f ms |%n", name, in.contacts().size(),
                copy.medianUs(), 100 * copy.medianNs / stepNs, eval.medianMs()));
        }
        System.out.printf(Locale.ROOT, "%none step of mug-grasp: %.2f µs (median run / steps)%n", stepNs / 1e3);
        System.out.print(table);
    }
}
