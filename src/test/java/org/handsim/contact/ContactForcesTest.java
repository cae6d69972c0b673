package org.handsim.contact;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.kinematics.FingerKinematics;
import org.junit.jupiter.api.Test;

/**
 * Contact forces from joint torques (eq 11 as least squares, DESIGN.md decision 2) on cases
 * solved by hand.
 */
class ContactForcesTest {
    /** The flexion joints k2, k3 driven at tau[1], tau[2], the spread held, frictionless. */
    static ContactForces.Problem problem(double[] frames, double[] tau, int n, double[] p, double[] d, int[] links) {
        return new ContactForces.Problem().frames(frames).held(0).driven(1, tau[1]).driven(2, tau[2]).contacts(n, p, d, links);
    }

    /** Frames of finger 3 with θ2 = 90° − Φ2 (link 2 straight up in {k0}) and θ3 = 0. */
    private static double[] upright() {
        double[] f = new double[48];
        FingerKinematics.of(3).frames(new double[] {0, Math.toRadians(90 - 2.46), 0}, f);
        return f;
    }

    /**
     * One contact on the inner link, 0.05 m up from the joint-2 axis (which lies along −y at
     * (0.05, 0, 0) in {k0}), pushing the object along −x: the moment arm about joint 2 is
     * (z1 × (p − o1))·d with z1 = (0, −1, 0), p − o1 = (0, 0, 0.05), d = (−1, 0, 0):
     * z1 × r = (−0.05, 0, 0), so a = 0.05 m; for τ2 = 1.26 N·m the force is 1.26/0.05 = 25.2 N.
     * Joint 3 is distal: no arm. Eq (9) gives the torque back.
     */
    @Test
    void singleContactOnTheInnerLinkByHand() {
        double[] f = upright();
        double[] p = {0.05, 0, 0.05}, d = {-1, 0, 0};
        ContactForces cf = new ContactForces();
        cf.solve(problem(f, new double[] {0, 1.26, 0}, 1, p, d, new int[] {2}));
        assertEquals(0.05, cf.arm(0, 1), 1e-15);
        assertEquals(0, cf.arm(0, 2));
        assertEquals(25.2, cf.force(0), 1e-12);
        assertEquals(0, cf.residual(), 1e-12);
        assertFalse(cf.undetermined(0));
        assertEquals(1.26, ContactForces.jointTorque(f, 1, p, d, cf.force(0)), 1e-12);
    }

    /** A torque that would need the contact to pull gives f = 0 (non-negative), the residual says so. */
    @Test
    void contactsCannotPull() {
        double[] f = upright();
        ContactForces cf = new ContactForces();
        cf.solve(problem(f, new double[] {0, -0.5, 0}, 1, new double[] {0.05, 0, 0.05}, new double[] {-1, 0, 0}, new int[] {2}));
        assertEquals(0, cf.force(0));
        assertEquals(0.5, cf.residual(), 1e-12);
    }

    /** A force whose line passes through the joint axis: undetermined, f = 0, never a huge number. */
    @Test
    void zeroMomentArmIsUndetermined() {
        double[] f = upright();
        // at p = o1 + (0,0,0.05), a push along the link (−z) passes through the joint-2 axis
        double[] p = {0.05, 0, 0.05}, d = {0, 0, -1};
        ContactForces cf = new ContactForces();
        cf.solve(problem(f, new double[] {0, 1.26, 0}, 1, p, d, new int[] {2}));
        assertTrue(cf.undetermined(0));
        assertEquals(0, cf.force(0));
        assertTrue(Double.isFinite(cf.residual()));
        // nearly through the axis (arm 1e-9 m): still undetermined rather than 1e9 N
        cf.solve(problem(f, new double[] {0, 1.26, 0}, 1, p, new double[] {-2e-8, 0, -1}, new int[] {2}));
        assertTrue(cf.undetermined(0));
        assertEquals(0, cf.force(0));
    }

    /**
     * Below {@link ContactForces#MIN_ARM_M} (0.5 mm) the arm does not determine the force: a
     * push tilted so that its arm about joint 2 is 0.3 mm is undetermined (not 4 200 N); at an
     * arm of 1 mm the force is τ/a exactly. The arm of a push (−s, 0, −1)/√(1+s²) at
     * p − o1 = (0, 0, 0.05) is 0.05·s/√(1+s²).
     */
    @Test
    void armsBelowHalfAMillimetreAreUndeterminedAboveThemTheForceIsTorqueOverArm() {
        double[] f = upright();
        double[] p = {0.05, 0, 0.05};
        ContactForces cf = new ContactForces();
        for (double arm : new double[] {3e-4, 1e-3}) {
            double s = arm / Math.sqrt(0.05 * 0.05 - arm * arm);   // 0.05·s/√(1+s²) = arm
            double n = Math.sqrt(1 + s * s);
            cf.solve(problem(f, new double[] {0, 1.26, 0}, 1, p, new double[] {-s / n, 0, -1 / n}, new int[] {2}));
            assertEquals(arm, Math.abs(cf.arm(0, 1)), 1e-15, "the arm as built");
            if (arm < ContactForces.MIN_ARM_M) {
                assertTrue(cf.undetermined(0), "arm " + arm);
                assertEquals(0, cf.force(0));
            } else {
                assertFalse(cf.undetermined(0), "arm " + arm);
                assertEquals(1.26 / arm, cf.force(0), 1e-9, "f = tau / a");
            }
        }
    }

    /**
     * Two contacts, one per link, torques on both flexion joints: the 2×2 system by hand.
     * Outer link horizontal inward: with θ3 = 90° − Φ3 link 3 points along −x from o2 = (0.05,0,0.07).
     * Contact B on link 3 at 0.03 from o2, pushing −z: arm about joint 3 = 0.03, about joint 2:
     * (z1 × (p − o1))·d with p − o1 = (−0.03, 0, 0.07): z1 × r = (−0.07, 0, −0.03), dot (0,0,−1)
     * → +0.03. Contact A on link 2 as above (arm 0.05 about joint 2). τ2 = 0.05 fA + 0.03 fB,
     * τ3 = 0.03 fB; for fA = 20, fB = 10: τ2 = 1.3, τ3 = 0.3.
     */
    @Test
    void twoContactsTwoJoints() {
        double[] f = new double[48];
        FingerKinematics.of(3).frames(new double[] {0, Math.toRadians(90 - 2.46), Math.toRadians(90 - 50)}, f);
        double[] p = {0.05, 0, 0.05, 0.02, 0, 0.07};
        double[] d = {-1, 0, 0, 0, 0, -1};
        ContactForces cf = new ContactForces();
        cf.solve(problem(f, new double[] {0, 1.3, 0.3}, 2, p, d, new int[] {2, 3}));
        assertEquals(0.03, cf.arm(1, 1), 1e-12);
        assertEquals(0.03, cf.arm(1, 2), 1e-12);
        assertEquals(20, cf.force(0), 1e-9);
        assertEquals(10, cf.force(1), 1e-9);
        assertEquals(0, cf.residual(), 1e-12);
    }

    /**
     * A held joint keeps what was locked into its link, by hand (DESIGN.md, "Which contact
     * forces"): the geometry of {@link #twoContactsTwoJoints} (A on link 2, arm 0.05 m about k2;
     * B on link 3, arms 0.03 m about k2 and k3). The inner joint's worm locked while A pressed
     * with 20 N (1.0 N·m on k2); then k2 is held and k3 driven at 0.3 N·m. A's link cannot move,
     * so A keeps its 20 N; only k3 turns, and B alone carries its 0.3 N·m: fB = 0.3/0.03 = 10 N.
     * The worm's reaction is both contacts' torque on k2: 0.05·20 + 0.03·10 = 1.3 N·m. Without
     * the locked load (the least-norm forces) A would carry nothing and the reaction be 0.3 N·m.
     */
    @Test
    void aHeldLinkKeepsItsLockedLoadAndTheWormReactsToBoth() {
        double[] f = new double[48];
        FingerKinematics.of(3).frames(new double[] {0, Math.toRadians(90 - 2.46), Math.toRadians(90 - 50)}, f);
        double[] p = {0.05, 0, 0.05, 0.02, 0, 0.07};
        double[] d = {-1, 0, 0, 0, 0, -1};
        int[] links = {2, 3};
        ContactForces cf = new ContactForces();
        ContactForces.Problem pr = new ContactForces.Problem().frames(f).held(0).held(1).driven(2, 0.3).contacts(2, p, d, links);
        cf.solve(pr.locked(new double[] {-20, 0, 0, 0, 0, 0}));
        assertEquals(20, cf.force(0), 1e-12);
        assertEquals(10, cf.force(1), 1e-12);
        assertEquals(1.3, cf.torqueOn(1), 1e-12);
        assertEquals(0.3, cf.torqueOn(2), 1e-12);
        assertEquals(0, cf.residual(), 1e-12);
        assertTrue(cf.undetermined(0), "no driven joint weighs A: it keeps its locked force");

        cf.solve(pr.locked(null));
        assertEquals(0, cf.force(0));
        assertEquals(10, cf.force(1), 1e-12);
        assertEquals(0.3, cf.torqueOn(1), 1e-12);
    }

    /**
     * Two contacts on one driven joint share a load increment by their stiffness, not by the
     * smallest norm, by hand. Link 3 horizontal (as {@link #twoContactsTwoJoints}), k2 held: B
     * at 0.03 m and C at 0.015 m from joint k3, both pushing −z (arms 0.03 and 0.015 m). When k2
     * locked, B carried 10 N and C nothing (0.3 N·m on k3). k3's torque then rises to 0.45 N·m:
     * k3 turns by y, pressing B by 0.03·y and C by 0.015·y; with equal contact stiffness k the
     * increment 0.15 N·m = k·y·(0.03² + 0.015²) gives k·y = 133.3 N/m·m, so B gains 4 N and C
     * 2 N: 14 N and 2 N (the least-norm forces, proportional to the arms, would be 12 N and
     * 6 N). When k3's torque falls to 0.1 N·m instead, C would be pulled (0.015·k·y &lt; 0): it
     * leaves, and B alone carries 0.1/0.03 = 3.333 N.
     */
    @Test
    void aLoadIncrementIsSharedByTheContactsStiffness() {
        double[] f = new double[48];
        FingerKinematics.of(3).frames(new double[] {0, Math.toRadians(90 - 2.46), Math.toRadians(90 - 50)}, f);
        // link 3 points along −x from o2 = (0.05, 0, 0.07)
        double[] p = {0.02, 0, 0.07, 0.035, 0, 0.07};
        double[] d = {0, 0, -1, 0, 0, -1};
        int[] links = {3, 3};
        double[] locked = {0, 0, -10, 0, 0, 0};
        ContactForces cf = new ContactForces();
        ContactForces.Problem pr = new ContactForces.Problem().frames(f).held(0).held(1).contacts(2, p, d, links).locked(locked);
        assertEquals(0.03, ContactForces.jointTorque(f, 2, new double[] {0.02, 0, 0.07}, new double[] {0, 0, -1}, 1), 1e-12);
        cf.solve(pr.driven(2, 0.3));
        assertEquals(10, cf.force(0), 1e-12);
        assertEquals(0, cf.force(1), 1e-12);
        cf.solve(pr.driven(2, 0.45));
        assertEquals(14, cf.force(0), 1e-12);
        assertEquals(2, cf.force(1), 1e-12);
        assertEquals(0, cf.residual(), 1e-12);
        cf.solve(pr.driven(2, 0.1));
        assertEquals(0.1 / 0.03, cf.force(0), 1e-12);
        assertEquals(0, cf.force(1));
        assertEquals(0, cf.residual(), 1e-12);
        cf.solve(pr.driven(2, 0.45).locked(null));
        assertEquals(12, cf.force(0), 1e-12);
        assertEquals(6, cf.force(1), 1e-12);
    }

    /** Many identical contacts: the least-squares answer carries the torque, none negative. */
    @Test
    void redundantContactsStayNonNegative() {
        double[] f = upright();
        int n = 5;
        double[] p = new double[3 * n], d = new double[3 * n];
        int[] links = new int[n];
        for (int i = 0; i < n; i++) {
            p[3 * i] = 0.05; p[3 * i + 2] = 0.02 + 0.01 * i;
            d[3 * i] = -1;
            links[i] = 2;
        }
        ContactForces cf = new ContactForces();
        cf.solve(problem(f, new double[] {0, 1.0, 0}, n, p, d, links));
        double tau = 0;
        for (int i = 0; i < n; i++) {
            assertTrue(cf.force(i) >= 0);
            tau += cf.force(i) * cf.arm(i, 1);
        }
        assertEquals(1.0, tau, 1e-12);
    }
}
