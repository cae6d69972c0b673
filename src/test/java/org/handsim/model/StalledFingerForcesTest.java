package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.clutch.ClutchState;
import org.handsim.dynamics.HandDynamics;
import org.handsim.scenario.Scenario;
import org.handsim.trajectory.Trapezoid;
import org.junit.jupiter.api.Test;

/**
 * A finger that stalls before any breakaway is blocked by the contacts on its outer link, so
 * their forces carry the torque the stalled motor winds into the outer joint k3 (DESIGN.md,
 * "Which torques the contacts carry"): the scene of the README's window screenshot
 * (docs/gui-screenshot.txt) — the millimetre mug placed clear on the palm axis by
 * {@link ObjectPlacer}, the paper's hand with gravity along −x, all three fingers closing on
 * trapezoids to 17 500 counts — at t = 2.4 s, where every finger is STALLED with one contact on
 * link 3 near the mug's rim. The contacts must not also be asked to put 0 N·m on the inner
 * joint k2, which no push on the outer link can do (it loads k2 with ~0.1 m of lever): k2's
 * torque is its worm's reaction, whatever it takes.
 */
class StalledFingerForcesTest {

    /** The screenshot's scene with Coulomb coefficient μ. */
    static Scenario screenshotScene(double mu) {
        Scenario s = Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json"));
        Path stl = TestPaths.root().resolve("vrml/objects/mug_mm.stl");
        ObjectPlacer.Placed p = ObjectPlacer.place(s, stl, Scenario.DEFAULT_DIVISIONS, 1, Scenario.Units.MM);
        assertTrue(p.clear());
        s = s.withObject(p.placement());
        for (int m = 0; m < 3; m++) s = s.withMotor(m, new Trapezoid(0, 17500, 5000, 25000));
        return s.withFriction(mu);
    }

    /**
     * For μ = 0.5 (the scenario's) and μ = 0: each finger STALLED before any breakaway, its
     * contacts on link 3 with forces, and the torques those forces put on joints k3 and k2
     * recomputed here by eq (9) from the force vectors and the world frames, Σ (z × (p − o))·f.
     * For both they carry the blocked joint's torque τk3 − τ_dyn,k3 exactly (τ_dyn from the
     * finger's inverse dynamics at rest: gravity only), and k2's, the worm's reaction, is what the
     * model reports as the joint's carried torque (less τ_dyn,k2); each force lies in its cone.
     * The worm's reaction has no cap (Barrett documents no strength of the worm drive): with μ = 0
     * a push along the normal that carries k3's torque puts more than the 2 kg rating's 2.471 N·m
     * on k2, and the run's warnings say so for each finger.
     */
    @Test
    void aStalledFingersContactsCarryItsOuterJointsTorque() {
        HandDynamics dyn = HandDynamics.barrettHand();
        for (double mu : new double[] {0.5, 0}) {
            Scenario s = screenshotScene(mu);
            HandModel m = Simulation.model(s, false);
            while (m.running() && m.time() < 2.4 - 1e-9) m.step();
            for (int k = 1; k <= 3; k++) {
                String at = "mu " + mu + " finger " + k;
                assertEquals(ClutchState.STALLED, m.state(k), at);
                assertTrue(m.clutchEngaged(k), at + ": stalled before any breakaway");
                assertTrue(Double.isNaN(m.breakawayTime(k)), at);
                ContactSet cs = m.contacts(k);
                assertTrue(cs.size() >= 1, at);
                double[] fr = m.framesWorld(k);
                // gravity in {k0}: R_world<-k0ᵀ g
                double[] g = s.gravity(), gk0 = new double[3];
                for (int r = 0; r < 3; r++) gk0[r] = fr[r] * g[0] + fr[4 + r] * g[1] + fr[8 + r] * g[2];
                double[] tauDyn = new double[3];
                dyn.inverseDynamics(k, m.joints(k), new double[3], new double[3], gk0, tauDyn);
                double blocked = m.torques(k)[2] - tauDyn[2];
                assertTrue(blocked > 0.5, at + ": the motor has wound the outer joint: " + blocked);
                double tau3 = 0, tau2 = 0;
                for (int i = 0; i < cs.size(); i++) {
                    tau2 += FrictionInTheSimulationTest.eq9(fr, 12, cs.point(i), cs.forceVector(i));
                    assertEquals(3, cs.link(i), at + ": the outer link is what blocks the finger");
                    assertFalse(cs.undetermined(i), at);
                    double[] p = cs.point(i), f = cs.forceVector(i), n = cs.normal(i);
                    int o = 24;                                  // frame {k2}: joint k3 turns about its z
                    double zx = fr[o + 2], zy = fr[o + 6], zz = fr[o + 10];
                    double rx = p[0] - fr[o + 3], ry = p[1] - fr[o + 7], rz = p[2] - fr[o + 11];
                    tau3 += (zy * rz - zz * ry) * f[0] + (zz * rx - zx * rz) * f[1] + (zx * ry - zy * rx) * f[2];
                    double fn = -(f[0] * n[0] + f[1] * n[1] + f[2] * n[2]);
                    double f2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
                    assertTrue(fn > 1, at + ": pushes into the mug: " + fn + " N");
                    double ft = Math.sqrt(Math.max(0, f2 - fn * fn));
                    // √(|f|² − fn²) rounds to about √ε·|f| (1.5e-8 |f|) when the force is along the normal
                    assertTrue(ft <= mu * fn + 1e-7 * fn, at + ": tangential " + ft + " N within mu × " + fn + " N");
                    assertEquals(Math.sqrt(f2), cs.force(i), 1e-12, at);
                }
                double rated = m.hand().fingerRatingN() * m.hand().leverToTip(2);
                assertEquals(0, m.torqueResidual(k), 1e-9, at + ": a static equilibrium");
                assertEquals(blocked, tau3, 1e-9 * blocked, at + ": eq (9) on k3 from the contact forces");
                assertEquals(tauDyn[1] + tau2, m.carriedTorque(k, 2), 1e-9, at + ": the worm's reaction on k2, reported");
                assertEquals(Math.abs(m.carriedTorque(k, 2)), m.maxWormReaction(k), 1e-12, at);
                if (mu == 0) {
                    assertTrue(Math.abs(m.carriedTorque(k, 2)) > rated, at + ": above the rating's torque: " + m.carriedTorque(k, 2));
                    String prefix = "finger " + k + ": the torque of joint " + k + "2 as a force at the fingertip above Barrett's rating";
                    assertTrue(m.warnings().stream().anyMatch(w -> w.startsWith(prefix)), at + ": " + m.warnings());
                }
            }
        }
    }
}
