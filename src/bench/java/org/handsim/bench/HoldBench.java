package org.handsim.bench;

import java.util.Locale;
import org.handsim.grasp.HoldCapacity;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;

/**
 * The hold LP and the whole grasp evaluation on the three-finger mug grasp
 * (scenarios/mug-grasp.json, μ = 0.5, 8 cone edges): at t = 2.0 s (three inner-link contacts,
 * the clutches engaged) and at the end (six contacts, the outer links wrapped). Rows: one LP
 * (one direction, +z), the six directions, and {@code GraspAssessment.of} (contacts, the whole
 * wrench-space hull for force closure, ε and volume, and the six LPs).
 */
final class HoldBench implements BenchMain.Suite {
    @Override
    public void run() {
        StringBuilder table = new StringBuilder();
        table.append("| grasp | contacts | one LP (+z) | six LPs | GraspAssessment.of |\n|---|---:|---:|---:|---:|\n");
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        for (double at : new double[] {2.0, Double.NaN}) {
            HandModel m = Simulation.model(s, false);
            while (m.running() && (Double.isNaN(at) || m.time() < at)) m.step();
            GraspAssessment g = GraspAssessment.of(m.graspInput(), s.friction(), s.coneEdges());
            double[] cr = m.objectCentroidAndRadius();
            double[] c = {cr[0], cr[1], cr[2]};
            String name = String.format(Locale.ROOT, "mug-grasp at t = %.1f s", m.time());
            Bench.Result one = Bench.measure(name + ": one LP", () -> {
                HoldCapacity hc = GraspAssessment.hold(m.graspInput(), g.contacts(), s.friction(), s.coneEdges(), c, cr[3]);
                return hc.hold(HoldCapacity.SIX_DIRECTIONS[4]).forceN();
            }, 3000, 15, 100);
            Bench.Result six = Bench.measure(name + ": six LPs", () -> {
                HoldCapacity hc = GraspAssessment.hold(m.graspInput(), g.contacts(), s.friction(), s.coneEdges(), c, cr[3]);
                return hc.holdSix()[0];
            }, 3000, 15, 100);
            Bench.Result all = Bench.measure(name + ": GraspAssessment.of", () -> GraspAssessment.of(m.graspInput(), s.friction(), s.coneEdges()).holdMinN(),
                3000, 15, 100);
            table.append(String.format(Locale.ROOT, "| %s | %d | %.2f ms | %.2f ms | %.2f ms |%n",
                name, g.contacts().size(), one.medianMs(), six.medianMs(), all.medianMs()));
        }
        System.out.println();
        System.out.print(table);
    }
}
