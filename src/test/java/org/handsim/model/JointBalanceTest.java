package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.clutch.ClutchState;
import org.handsim.dynamics.HandDynamics;
import org.handsim.hand.HandDescription;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.plan.PlanSpec;
import org.handsim.plan.PlanTesting;
import org.handsim.plan.TrialParameters;
import org.handsim.plan.TrialResult;
import org.handsim.plan.TrialRunner;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * Every joint's torque balances in every step (DESIGN.md, "Which contact forces"): the torque a
 * joint carries as the model reports it ({@link HandModel#carriedTorque}: the drive's torque, or
 * the reaction of the worm or motor that holds it) equals τ_dyn + Jᵀf recomputed here without the
 * model's own code — the frames from the joint angles by forward kinematics, τ_dyn by the
 * recursive Newton–Euler algorithm (the model uses the generated closed form), Jᵀf as
 * Σ (z_{j−1} × (p − o_{j−1})) · f over the contacts on the links joint j carries — to 1e-9 N·m;
 * and where the drive sets a joint's torque (k2 while the clutch drives the inner link, k3 but
 * at its stop), the joint carries exactly that torque. On the paper's run, the mug grasp (μ = 0.5
 * and frictionless) and 20 seeded mug grasps of the planner, run to their ends with torques.
 */
class JointBalanceTest {
    static final double TOL = 1e-9;

    /** Counts of what was checked: joint-steps, of them held joints with a nonzero reaction. */
    static final class Counts {
        long joints, heldReactions, driven;
        double worst, worstDriven, largestReaction;
    }

    static Counts check(Scenario s) {
        HandDescription hand = HandDescription.barrettHand();
        HandDynamics ne = HandDynamics.of(hand, HandDynamics.Method.NEWTON_EULER);
        HandModel m = Simulation.model(s.withTorques(true), false);
        Counts c = new Counts();
        double[][] base = new double[3][12];
        for (int k = 1; k <= 3; k++) s.worldFromPalm().compose(hand.finger(k).baseInPalm()).copyTo(base[k - 1], 0);
        double theta3Max = hand.theta3Limits()[1];
        do {
            for (int k = 1; k <= 3; k++) {
                double[] fr = new double[48], q = m.joints(k);
                FingerKinematics.of(k).framesFrom(base[k - 1], q, fr);
                double[] g = s.gravity(), gk0 = new double[3], tauDyn = new double[3];
                for (int r = 0; r < 3; r++) gk0[r] = fr[r] * g[0] + fr[4 + r] * g[1] + fr[8 + r] * g[2];
                ne.inverseDynamics(k, q, m.velocities(k), m.accelerations(k), gk0, tauDyn);
                ContactSet cs = m.contacts(k);
                ClutchState st = m.state(k);
                for (int j = k == 3 ? 2 : 1; j <= 3; j++) {
                    double jtf = 0;
                    for (int i = 0; i < cs.size(); i++) {
                        if (cs.link(i) >= j) jtf += FrictionInTheSimulationTest.eq9(fr, 12 * (j - 1), cs.point(i), cs.forceVector(i));
                    }
                    String at = s.name() + " t = " + m.time() + " finger " + k + " joint " + j + " " + st;
                    double carried = m.carriedTorque(k, j);
                    assertEquals(tauDyn[j - 1] + jtf, carried, TOL, at + ": τ − τ_dyn − Jᵀf");
                    c.worst = Math.max(c.worst, Math.abs(carried - tauDyn[j - 1] - jtf));
                    c.joints++;
                    boolean driven = j == 2 ? !(st == ClutchState.BROKEN || st == ClutchState.STALLED)
                        : j == 3 && !(st == ClutchState.STALLED && q[2] >= theta3Max - 1e-12);
                    if (driven) {
                        assertEquals(m.torques(k)[j - 1], carried, TOL, at + ": the drive's torque is carried");
                        c.worstDriven = Math.max(c.worstDriven, Math.abs(m.torques(k)[j - 1] - carried));
                        c.driven++;
                    } else if (j >= 2 && Math.abs(jtf) > 1e-6) {
                        c.heldReactions++;
                        c.largestReaction = Math.max(c.largestReaction, Math.abs(carried));
                    }
                }
            }
            if (!m.running()) break;
            m.step();
        } while (true);
        System.out.printf("%s mu %s: %d joint-steps, largest |τ − τ_dyn − Jᵀf| %.3g N·m, driven joints %d (largest |τ_drive − τ| %.3g),"
            + " held reactions %d (largest %.4g N·m)%n", s.name(), s.friction(), c.joints, c.worst, c.driven, c.worstDriven,
            c.heldReactions, c.largestReaction);
        return c;
    }

    @Test
    void thePaperRunAndTheMugGraspBalanceEveryJointInEveryStep() {
        for (String file : new String[] {"scenarios/paper-breakaway.json", "scenarios/mug-grasp.json"}) {
            for (double mu : new double[] {0.5, 0}) {
                Counts c = check(Scenario.load(Home.dir().resolve(file)).withFriction(mu));
                assertTrue(c.heldReactions > 500, file + " mu " + mu + ": held joints' reactions checked: " + c.heldReactions);
                assertTrue(c.driven > 5000, file + " mu " + mu + ": driven joints checked: " + c.driven);
            }
        }
    }

    /** 20 seeded grasps of the planner on the mug (seed 7), each the scenario best/NN.json would be, run to its end. */
    @Test
    void twentySeededGraspsBalanceEveryJointInEveryStep() {
        PlanSpec spec = PlanTesting.mugPlan(20, 7);
        TrialRunner r = new TrialRunner(spec);
        int ran = 0;
        long held = 0;
        for (int i = 0; i < 20; i++) {
            TrialParameters p = r.parameters(i);
            TrialResult res = r.run(i);
            assertTrue(res.ok(), res.error());
            Scenario s = Scenario.parse(java.nio.file.Path.of(spec.templateFile()),
                r.scenarioJson(p, res.standoff(), res.palmPosition(), res.palmRotation(), "trial" + i, false, null));
            held += check(s).heldReactions;
            ran++;
        }
        assertEquals(20, ran);
        assertTrue(held > 20, "held joints' reactions checked: " + held);
    }
}
