package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * Friction in the simulation: the breakaway depends on the torque through the clutch only, so it
 * is the same for every μ; μ = 0 is the frictionless solve; with friction every contact force lies
 * in its cone and the forces carry the torques the drive sets.
 */
class FrictionInTheSimulationTest {

    /**
     * μ = 0 is the frictionless solve (non-negative least squares along the normals): on the
     * paper's experiment, while the finger is BLOCKED, the one contact's force is the one that
     * puts the spring's torque on k2 along its push direction, τ/a with a = (z × (p − o))·d
     * (eq 9 by hand), at every recorded step.
     */
    @Test
    void frictionlessIsTorqueOverTheNormalsArm() {
        HandModel m = Simulation.model(Scenario.load(Home.paperScenario()).withFriction(0), false);
        int checked = 0;
        while (m.running() && m.time() < 1.79) {
            m.step();
            if (m.state(3) != ClutchState.BLOCKED) continue;
            ContactSet cs = m.contacts(3);
            assertEquals(1, cs.size());
            double[] fr = m.framesWorld(3), p = cs.point(0), n = cs.normal(0);
            double zx = fr[12 + 2], zy = fr[12 + 6], zz = fr[12 + 10];
            double rx = p[0] - fr[12 + 3], ry = p[1] - fr[12 + 7], rz = p[2] - fr[12 + 11];
            double arm = -((zy * rz - zz * ry) * n[0] + (zz * rx - zx * rz) * n[1] + (zx * ry - zy * rx) * n[2]);
            assertEquals(m.torques(3)[1] / arm, cs.force(0), 1e-9, "t = " + m.time());
            checked++;
        }
        assertTrue(checked > 200, "BLOCKED steps checked: " + checked);
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
     * linearised cone), has a positive normal part, and the forces carry the outer joint's stall
     * torque exactly (eq 9 recomputed here from the force vectors), while the torque they put on
     * the inner joint k2 — held by its worm since the breakaway — is the worm's reaction, which
     * the model reports ({@link HandModel#carriedTorque}): the load locked in at the breakaway
     * (τ_break less gravity's share, kept by the inner contact) plus what the outer contact adds
     * (DESIGN.md, "Which contact forces").
     */
    @Test
    void forcesWithFrictionLieInTheirConesAndCarryTheTorque() {
        HandModel m = run("scenarios/mug-grasp.json", 0.5);
        int checked = 0;
        for (int k = 1; k <= 3; k++) {
            ContactSet cs = m.contacts(k);
            assertEquals(ClutchState.STALLED, m.state(k));
            assertTrue(m.torqueResidual(k) <= 1e-9, "finger " + k + ": residual " + m.torqueResidual(k));
            // eq (9) with the force vectors: Σ (z × (p − o)) · f over the contacts on the links each joint carries
            double[] fr = m.framesWorld(k);
            double tau2 = 0, tau3 = 0;
            for (int i = 0; i < cs.size(); i++) {
                double[] p = cs.point(i), f = cs.forceVector(i);
                if (cs.link(i) >= 2) tau2 += eq9(fr, 12, p, f);
                if (cs.link(i) == 3) tau3 += eq9(fr, 24, p, f);
            }
            assertEquals(1.26, tau3, 1e-9, "finger " + k + ": the stalled outer joint's torque, carried by the contact forces");
            double tauDyn2 = m.carriedTorque(k, 2) - tau2;
            assertTrue(Math.abs(tauDyn2) < 0.1, "finger " + k + ": gravity's share on k2 " + tauDyn2);
            assertTrue(tau2 > 1.26 + 0.5, "finger " + k + ": the held inner joint's reaction " + tau2 + " above the preload");
            assertEquals(m.carriedTorque(k, 2), m.maxWormReaction(k), 1e-12, "finger " + k + ": the largest worm reaction is the final one");
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

    /** Eq (9): the torque of force f at p on the joint turning about the z axis of the frame at {@code o}. */
    static double eq9(double[] fr, int o, double[] p, double[] f) {
        double zx = fr[o + 2], zy = fr[o + 6], zz = fr[o + 10];
        double rx = p[0] - fr[o + 3], ry = p[1] - fr[o + 7], rz = p[2] - fr[o + 11];
        return (zy * rz - zz * ry) * f[0] + (zz * rx - zx * rz) * f[1] + (zx * ry - zy * rx) * f[2];
    }

    private static HandModel run(String file, double mu) {
        HandModel m = Simulation.model(Scenario.load(Home.dir().resolve(file)).withFriction(mu), true);
        m.run(null);
        return m;
    }
}
