package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Scenario;
import org.handsim.trajectory.Hold;
import org.handsim.trajectory.Sequence;
import org.handsim.trajectory.Trajectory;
import org.handsim.trajectory.Trapezoid;
import org.junit.jupiter.api.Test;

/**
 * Stability over a long run: 10⁶ steps of a finger closing onto an object, breaking
 * away, opening and re-engaging, again and again. Every cycle must repeat the first exactly:
 * the same contact and breakaway counts, the same states, no NaN, no drift of the clutch.
 */
class LongRunTest {
    @Test
    void millionStepsWithoutDrift() {
        List<Trajectory> cycle = new ArrayList<>();
        double close = new Trapezoid(0, 12000, 6000, 30000).duration();
        for (int c = 0; c < 200; c++) {
            cycle.add(new Trapezoid(0, 12000, 6000, 30000));
            cycle.add(new Hold(12000, 0.3));
            cycle.add(new Trapezoid(12000, 0, 6000, 30000));
            cycle.add(new Hold(0, 0.3));
        }
        Sequence seq = new Sequence(cycle);
        double period = 2 * close + 0.6;
        Scenario s = HandModelPlaneTest.scenario("[]", 1).withMotor(2, seq).withDt(1e-3).withDuration(1000.0);
        HandModel m = new HandModel(s, new HandModelPlaneTest.Plane(), TorqueModel.NONE, false);
        double firstBreak = Double.NaN;
        int breaks = 0, reengages = 0;
        ClutchState prev = ClutchState.FREE;
        double maxTheta2 = 0;
        while (m.running()) {
            m.step();
            ClutchState st = m.state(3);
            if (prev == ClutchState.BLOCKED && st == ClutchState.BROKEN) {
                breaks++;
                if (breaks == 1) firstBreak = m.breakawayCounts(3);
            }
            if (prev != ClutchState.FREE && st == ClutchState.FREE) reengages++;
            prev = st;
            double[] j = m.joints(3);
            assertTrue(Double.isFinite(j[1]) && Double.isFinite(j[2]), "finite at step " + m.stepIndex());
            maxTheta2 = Math.max(maxTheta2, j[1]);
        }
        assertEquals(1_000_000, m.stepIndex());
        int cycles = (int) Math.floor(1000.0 / period);
        assertTrue(breaks >= cycles - 1 && breaks <= cycles + 1, breaks + " breakaways for " + cycles + " cycles");
        assertEquals(breaks, reengages, "every breakaway re-engaged");
        // every cycle breaks at the same count: the first one is exactly the analytic value
        double qc = 125 * (Math.toDegrees(Math.asin(0.05 / 0.07)) - 2.46);
        assertEquals(qc + 1250.0, firstBreak, 0.05);
        assertEquals(Math.toRadians(qc / 125), maxTheta2, 1e-6, "the inner link never passes the contact angle");
        assertEquals(ClutchState.FREE, m.state(3));
    }
}
