package org.handsim.kinematics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.hand.HandDescription;
import org.junit.jupiter.api.Test;

class InverseKinematicsTest {
    private static final HandDescription HAND = HandDescription.barrettHand();
    private static final double[] T2 = HAND.theta2Limits(), T3 = HAND.theta3Limits();

    private static double[] randomJoints(Random rnd, InverseKinematics ik) {
        double[] s = ik.spreadLimits();
        return new double[] {
            s[0] + rnd.nextDouble() * (s[1] - s[0]),
            T2[0] + rnd.nextDouble() * (T2[1] - T2[0]),
            T3[0] + rnd.nextDouble() * (T3[1] - T3[0])};
    }

    private static void assertFinite(IkResult r) {
        for (double v : r.joints()) assertTrue(Double.isFinite(v));
        for (double v : r.fingertip()) assertTrue(Double.isFinite(v));
        assertTrue(Double.isFinite(r.errorM()));
    }

    @Test
    void roundTripTenThousandTargetsPerFinger() {
        for (int k = 1; k <= 3; k++) {
            InverseKinematics ik = InverseKinematics.of(k);
            FingerKinematics fk = ik.forward();
            Random rnd = new Random(1000 + k);
            double maxErr = 0;
            for (int i = 0; i < 10_000; i++) {
                double[] j = randomJoints(rnd, ik);
                double[] target = fk.fingertip(j);
                IkResult r = ik.solve(target);
                assertTrue(r.reachable(), "finger " + k + " target " + java.util.Arrays.toString(target));
                double err = org.handsim.math.Vec3.distance(fk.fingertip(r.joints()), target);
                maxErr = Math.max(maxErr, err);
                assertEquals(err, r.errorM(), 1e-15);
                // the branch inside the limits is unique here: the same joints come back
                assertArrayEquals(j, r.joints(), 1e-6);
            }
            assertTrue(maxErr < 1e-9, "finger " + k + " max IK∘FK error " + maxErr);
        }
    }

    @Test
    void palmFrameRoundTrip() {
        InverseKinematics ik = InverseKinematics.of(1);
        double[] j = {-0.7, 1.1, 0.4};
        double[] f = new double[48];
        ik.forward().framesInPalm(j, f);
        IkResult r = ik.solveInPalm(new double[] {f[39], f[43], f[47]});
        assertTrue(r.reachable());
        assertArrayEquals(j, r.joints(), 1e-9);
        assertArrayEquals(new double[] {f[39], f[43], f[47]}, r.fingertip(), 1e-12);
    }

    @Test
    void everyBranchIsReportedAndEachPlacesTheFingertip() {
        InverseKinematics ik = InverseKinematics.of(2);
        // a curled pose near the spread axis: both spread branches (ψ and ψ + π, r = ±ρ) are
        // within the arm's reach, each with two elbow branches
        double[] target = ik.forward().fingertip(new double[] {0.8, 2.0, 0.7});
        IkResult r = ik.solve(target);
        assertEquals(4, r.branches().size());
        long inside = r.branches().stream().filter(IkSolution::withinLimits).count();
        assertEquals(1, inside);
        for (IkSolution b : r.branches()) {
            assertArrayEquals(target, ik.forward().fingertip(b.joints()), 1e-12);
        }
    }

    /** On the spread axis (x = y = 0) atan2(0, 0) is defined as θk1 = 0: no NaN, exact answer. */
    @Test
    void targetOnTheSpreadAxis() {
        InverseKinematics ik = InverseKinematics.of(2);
        // pick θ2 = 85° and solve A1 + A2 cos φ2 + A3 cos(φ2 + φ3) = 0 for θ3 by bisection
        // (a root near 24°, inside the outer joint's range [0, 48°])
        double t2 = Math.toRadians(85), p2 = t2 + Math.toRadians(2.46);
        double lo = T3[0], hi = T3[1];
        for (int i = 0; i < 200; i++) {
            double mid = 0.5 * (lo + hi);
            double r = 0.05 + 0.07 * Math.cos(p2) + 0.056 * Math.cos(p2 + mid + Math.toRadians(50));
            if (r > 0) lo = mid; else hi = mid; // r falls with θ3 here
        }
        assertTrue(lo > T3[0] + 0.1 && lo < T3[1] - 0.1, "a root inside the range: " + lo);
        double[] target = ik.forward().fingertip(new double[] {0, t2, lo});
        target[0] = 0; // exactly on the axis (the bisection leaves ~1e-18)
        target[1] = 0;
        IkResult r = ik.solve(target);
        assertFinite(r);
        assertTrue(r.reachable(), "error " + r.errorM());
        assertEquals(0.0, r.joints()[0]);
        assertEquals(t2, r.joints()[1], 1e-7);
    }

    @Test
    void stretchedFingerAtTheOuterJointLimit() {
        InverseKinematics ik = InverseKinematics.of(3);
        for (double t2 : new double[] {0, 0.5, 1.0, 2.0}) {
            double[] target = ik.forward().fingertip(new double[] {0, t2, 0});
            IkResult r = ik.solve(target);
            assertTrue(r.reachable());
            assertEquals(0.0, r.joints()[2], 1e-9, "θ3 stays at its limit 0");
            assertTrue(r.joints()[2] >= 0, "never outside the limit");
        }
    }

    /**
     * The fully stretched pose φ3 = 0 puts the arccos argument of eq (6) at 1 (in rounding,
     * a hair above). The hand's limit θ3 ≥ 0 means φ3 ≥ Φ3 = 50°, so this target is out of reach:
     * the branch is reported (flagged), the answer is the closest point, and nothing is NaN.
     */
    @Test
    void arccosArgumentARoundingHairOutside() {
        InverseKinematics ik = InverseKinematics.of(3);
        double[] target = ik.forward().fingertip(new double[] {0, 0.3, -Math.toRadians(50)});
        double u = Math.hypot(target[0], target[1]) - 0.05, c = (u * u + target[2] * target[2] - 0.07 * 0.07 - 0.056 * 0.056) / (2 * 0.07 * 0.056);
        assertTrue(Math.abs(c - 1) < 1e-12, "the case really is at the arccos edge: c = " + c);
        IkResult r = ik.solve(target);
        assertFinite(r);
        assertFalse(r.reachable());
        assertTrue(r.branches().stream().anyMatch(b -> !b.withinLimits() && Math.abs(b.joints()[2] + Math.toRadians(50)) < 1e-6),
            "the stretched branch is reported, flagged outside the limits");
        // slightly beyond the stretched reach: c = 1 + 1e-13 is still treated as rounding
        double[] beyond = {target[0] * (1 + 1e-14), target[1], target[2] * (1 + 1e-14)};
        IkResult r2 = ik.solve(beyond);
        assertFinite(r2);
        assertFalse(r2.branches().isEmpty());
    }

    @Test
    void targetBehindThePalmGetsTheClosestReachablePoint() {
        InverseKinematics ik = InverseKinematics.of(1);
        double[] target = {0.0, -0.06, -0.05}; // below the base frame: inside/behind the palm
        IkResult r = ik.solve(target);
        assertFinite(r);
        assertFalse(r.reachable());
        assertTrue(r.errorM() > 0.01);
        assertClosestAmongSamples(ik, target, r);
    }

    @Test
    void closestPointIsNoFartherThanAnyOfManySampledReachablePoints() {
        Random rnd = new Random(99);
        for (int k = 1; k <= 3; k++) {
            InverseKinematics ik = InverseKinematics.of(k);
            double[] tips = sampledTips(ik);   // the same samples for every target of this finger: made once
            for (int i = 0; i < 20; i++) {
                double[] target = {(rnd.nextDouble() - 0.5) * 0.5, (rnd.nextDouble() - 0.5) * 0.5, (rnd.nextDouble() - 0.5) * 0.5};
                IkResult r = ik.solve(target);
                assertFinite(r);
                assertClosestAmongSamples(tips, target, r);
            }
        }
    }

    /** Brute force: 200 000 joint samples inside the limits; none may come closer than the answer. */
    private static void assertClosestAmongSamples(InverseKinematics ik, double[] target, IkResult r) {
        assertClosestAmongSamples(sampledTips(ik), target, r);
    }

    /** The fingertips of 200 000 seeded joint samples inside the limits, x y z after one another. */
    private static double[] sampledTips(InverseKinematics ik) {
        Random rnd = new Random(5);
        double[] tips = new double[3 * 200_000], tip = new double[3];
        for (int i = 0; i < 200_000; i++) {
            ik.forward().fingertip(randomJoints(rnd, ik), tip);
            System.arraycopy(tip, 0, tips, 3 * i, 3);
        }
        return tips;
    }

    private static void assertClosestAmongSamples(double[] tips, double[] target, IkResult r) {
        double best = Double.POSITIVE_INFINITY;
        double[] tip = new double[3];
        for (int i = 0; i < tips.length; i += 3) {
            System.arraycopy(tips, i, tip, 0, 3);
            best = Math.min(best, org.handsim.math.Vec3.distance(tip, target));
        }
        assertTrue(r.errorM() <= best + 1e-12, "IK closest " + r.errorM() + " but a sample reached " + best);
        assertTrue(r.errorM() > best - 0.005 || r.reachable(), "sampling should come near the true minimum");
    }

    @Test
    void farTargetDistanceIsExact() {
        InverseKinematics ik = InverseKinematics.of(3);
        IkResult r = ik.solve(new double[] {1, 0, 0});
        assertFalse(r.reachable());
        // the farthest reach along +x with θ2 = 0 .. is bounded by the stretched reach 0.176
        assertTrue(r.errorM() > 1 - 0.176 && r.errorM() < 1 - 0.12, "error " + r.errorM());
        assertTrue(r.branches().isEmpty());
    }

    @Test
    void fingerThreeOffItsPlaneIsUnreachableWithTheRightDistance() {
        InverseKinematics ik = InverseKinematics.of(3);
        double[] inPlane = ik.forward().fingertip(new double[] {0, 1.0, 0.5});
        IkResult r = ik.solve(new double[] {inPlane[0], 0.01, inPlane[2]});
        assertFalse(r.reachable());
        assertEquals(0.01, r.errorM(), 1e-12);
        assertArrayEquals(new double[] {0, 1.0, 0.5}, r.joints(), 1e-9);
    }

    @Test
    void nonFiniteTargetIsAnArgumentError() {
        InverseKinematics ik = InverseKinematics.of(1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ik.solve(new double[] {0.1, Double.NaN, 0}));
        assertTrue(e.getMessage().contains("y = NaN"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ik.solve(new double[] {Double.POSITIVE_INFINITY, 0, 0}));
    }

    @Test
    void coupledReachFindsTheExactCountsOnItsCurve() {
        for (int k = 1; k <= 3; k++) {
            CoupledReach reach = CoupledReach.of(k);
            Transmission tr = Transmission.barrettHand();
            int q4 = k == 3 ? 0 : 1234;
            for (int q : new int[] {0, 1, 4321, 9000, 17500}) {
                double[] target = FingerKinematics.of(k).fingertip(tr.joints(k, q, q4, null));
                CoupledReach.Result r = reach.closest(target);
                assertEquals(q, r.qMk());
                assertEquals(q4, r.qM4());
                assertEquals(0.0, r.errorM(), 1e-15);
            }
        }
    }

    @Test
    void coupledReachIsTheBestIntegerCount() {
        CoupledReach reach = CoupledReach.of(3);
        Transmission tr = Transmission.barrettHand();
        FingerKinematics fk = FingerKinematics.of(3);
        double[] target = {0.09, 0.0, 0.11};
        CoupledReach.Result r = reach.closest(target);
        for (int q = 0; q <= 17500; q += 7) {
            double d = org.handsim.math.Vec3.distance(fk.fingertip(tr.joints(3, q, 0, null)), target);
            assertTrue(d >= r.errorM() - 1e-15);
        }
        assertTrue(r.errorM() > 0);
    }
}
