package org.handsim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Friction in the simulation (issue 12 item 5): the breakaway depends on the joint torque only,
 * so it is the same for every μ; μ = 0 reproduces the frictionless forces of the code before
 * friction existed; with friction every contact force lies in its cone and the forces carry
 * the transmitted torques.
 */
class FrictionInTheSimulationTest {

    /**
     * The frictionless forces as they were before friction existed (recorded from commit
     * 10c941c, the last one without it): the paper's breakaway force, the sum of every finger's
     * recorded force over the whole trace, and the same for the mug grasp. μ = 0 must give them
     * to the last digit (the frictionless solve is untouched).
     */
    @Test
    void frictionlessReproducesTheForcesOfBeforeFriction() {
        HandModel paper = run("scenarios/paper-breakaway.json", 0);
        assertEquals(21.572305072949526, paper.breakawayForce(3), 1e-12);
        assertEquals(117294.15860633348, forceSum(paper), 1e-7);
        HandModel mug = run("scenarios/mug-grasp.json", 0);
        assertEquals(41.36887472958861, mug.breakawayForce(3), 1e-12);
        assertEquals(191338.75007776765, forceSum(mug), 1e-7);
    }

    @Test
    void theBreakawayDoesNotDependOnFriction() {
        HandModel ref = run("scenarios/paper-breakaway.json", 0);
        for (double mu : new double[] {0.2, 0.5, 1.0}) {
            HandModel m = run("scenarios/paper-breakaway.json", mu);
            assertEquals(ref.breakawayTime(3), m.breakawayTime(3), 1e-12, "mu " + mu);
            assertEquals(1.80, m.breakawayTime(3), 0.02);
            assertEquals(ref.breakawayTorque(3), m.breakawayTorque(3), 1e-12);
            assertEquals(ref.breakawayCounts(3), m.breakawayCounts(3), 1e-9);
        }
    }

    /**
     * With μ = 0.5 on the mug grasp, at the end: each force lies in its contact's friction cone
     * (its tangential part at most μ times its normal part, the circumscribed bound of the
     * linearised cone), has a positive normal part, and the forces of each finger's inner-link
     * contacts put τ_break on joint k2 (the clutch's jammed torque, eq 9).
     */
    @Test
    void forcesWithFrictionLieInTheirConesAndCarryTheTorque() {
        HandModel m = run("scenarios/mug-grasp.json", 0.5);
        int checked = 0;
        for (int k = 1; k <= 3; k++) {
            ContactSet cs = m.contacts(k);
            assertEquals(ClutchState.STALLED, m.state(k));
            // eq (9) with the force vectors: Σ (z1 × (p − o1)) · f over the contacts on links 2 and 3
            double[] fr = m.framesWorld(k);
            double tau2 = 0;
            for (int i = 0; i < cs.size(); i++) {
                if (cs.link(i) < 2) continue;
                double[] p = cs.point(i), f = cs.forceVector(i);
                double zx = fr[12 + 2], zy = fr[12 + 6], zz = fr[12 + 10];
                double rx = p[0] - fr[12 + 3], ry = p[1] - fr[12 + 7], rz = p[2] - fr[12 + 11];
                tau2 += (zy * rz - zz * ry) * f[0] + (zz * rx - zx * rz) * f[1] + (zx * ry - zy * rx) * f[2];
            }
            assertEquals(1.26, tau2, 1e-9, "finger " + k + ": the jammed inner joint's tau_break, carried by the contact forces");
            for (int i = 0; i < cs.size(); i++) {
                if (cs.undetermined(i)) continue;
                double[] f = cs.forceVector(i), n = cs.normal(i);
                double fn = -(f[0] * n[0] + f[1] * n[1] + f[2] * n[2]);    // along the push direction −n
                double ft2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - fn * fn;
                assertTrue(fn >= -1e-9, "normal part " + fn);
                assertTrue(Math.sqrt(Math.max(0, ft2)) <= 0.5 * fn + 1e-9, "tangential " + Math.sqrt(ft2) + " > mu * " + fn);
                assertEquals(Math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]), cs.force(i), 1e-12);
                checked++;
            }
        }
        assertTrue(checked >= 3, "contacts checked: " + checked);
    }

    private static HandModel run(String file, double mu) {
        HandModel m = Simulation.model(Scenario.load(Home.dir().resolve(file)).withFriction(mu), true);
        m.run(null);
        return m;
    }

    private static double forceSum(HandModel m) {
        Recorder r = m.recorder();
        double s = 0;
        for (int row = 0; row < r.rows(); row++) for (int k = 1; k <= 3; k++) s += r.force(k, row);
        return s;
    }
}
