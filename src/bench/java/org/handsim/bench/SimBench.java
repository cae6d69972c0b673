package org.handsim.bench;

import java.util.Locale;
import org.handsim.sim.HandModel;
import org.handsim.sim.Home;
import org.handsim.sim.Scenario;
import org.handsim.sim.Simulation;

/**
 * Steps per second of the paper's experiment (scenarios/paper-breakaway.json, dt = 1 ms,
 * 8 947 steps): the whole model in the process — trajectories, clutch, kinematics, collision
 * and contacts, dynamics — with the trace recorded, as the default (work saving on) and with
 * every finger fully computed every step (lazy off: collision and contacts every step).
 */
final class SimBench implements BenchMain.Suite {
    @Override
    public void run() {
        Scenario s = Scenario.load(Home.paperScenario());
        for (boolean lazy : new boolean[] {true, false}) {
            for (boolean record : new boolean[] {false, true}) {
                long[] steps = {0};
                Bench.Result r = Bench.measure(String.format(Locale.ROOT, "paper experiment, lazy %s, trace %s (one run)", lazy, record), () -> {
                    HandModel m = Simulation.model(s, record).lazy(lazy);
                    m.run(null);
                    steps[0] = m.stepIndex();
                    return m.breakawayTime(3);
                }, 3000, 15, 200);
                double perStep = r.medianNs / steps[0];
                System.out.println(String.format(Locale.ROOT, "    -> %.0f ns/step, %.0f steps/s, %.0fx real time",
                    perStep, 1e9 / perStep, 1e9 / perStep * s.dt()));
            }
        }
    }
}
