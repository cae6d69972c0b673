package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.handsim.clutch.ClutchState;
import org.handsim.grasp.GraspAssessment;
import org.handsim.hand.HandDescription;
import org.handsim.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * The evaluation of a model's grasp against a hand computation, with the analytic half-space of
 * {@link HandModelPlaneTest}: finger 3's inner link touches the plane z = H at its tip, pushing
 * along +z, its moment arm about joint 32 A2 cos φ2 = 0.048990 m (that test's derivation).
 *
 * <p>One contact, and no object geometry, so the torque origin c is the contact point itself
 * ({@link GraspAssessment#of}): a load F·d through c is balanced by the one contact force
 * f = −F d, which must lie in the cone round +z — only d = −z works, with f = (0, 0, F), and it
 * puts τ32 = 0.048990·F on the inner joint (joint 33 is distal, the spread does not exist on
 * finger 3). So the hold is 0 in ±x, ±y, +z and, along −z:
 * <ul>
 *   <li>while the clutch is engaged (BLOCKED): F = τ_break / 0.048990 = 1.26/0.048990 = 25.72 N;</li>
 *   <li>after the breakaway (the inner link held by its worm drive): F = the rated torque of
 *       joint 2 / 0.048990, 2 kg × 9.80665 m/s² × (A2 + A3) = 2.471276 N·m, so 50.445 N.</li>
 * </ul>
 */
class GraspAssessmentTest {
    static final double ARM = 0.07 * Math.cos(Math.asin(0.05 / 0.07));

    static HandModel plane(double until) {
        Scenario s = HandModelPlaneTest.scenario("[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000}]", 4.0);
        HandModel m = new HandModel(s, new HandModelPlaneTest.Plane(), TorqueModel.NONE, false);
        while (m.running() && m.time() < until) m.step();
        return m;
    }

    @Test
    void onePushingContactHoldsOnlyAlongItsPushLimitedByTheClutch() {
        HandModel m = plane(1.3);
        assertEquals(ClutchState.BLOCKED, m.state(3));
        assertTrue(m.clutchEngaged(3));
        GraspAssessment g = GraspAssessment.of(m.graspInput(), 0.5, 8);
        assertEquals(1, g.contacts().size());
        assertFalse(g.quality().forceClosure());
        double[] expected = {0, 0, 0, 0, 0, 1.26 / ARM};
        for (int d = 0; d < 6; d++) assertEquals(expected[d], g.holdN()[d], 1e-6, GraspAssessment.DIRECTIONS.get(d));
        assertEquals(0, g.holdMinN());
        assertEquals(1.3, g.timeS(), 1e-9);
    }

    @Test
    void afterTheBreakawayTheWormHoldsTheInnerLinkUpToTheRating() {
        HandModel m = plane(4.0);
        assertEquals(ClutchState.STALLED, m.state(3));
        assertFalse(m.clutchEngaged(3), "stalled after a breakaway");
        GraspAssessment g = GraspAssessment.of(m.graspInput(), 0.5, 8);
        assertEquals(1, g.contacts().size());
        double rated = 2 * 9.80665 * (0.070 + 0.056);
        assertEquals(rated / ARM, g.holdN()[5], 1e-6);
        assertEquals(0, g.holdN()[4], 1e-9);
    }

    /** The contacts as the simulation has them: world points, the push direction into the object, the force vector. */
    @Test
    void contactsAreTheSimulationsWithTheNormalIntoTheObject() {
        HandModel m = plane(1.3);
        GraspAssessment g = GraspAssessment.of(m.graspInput(), 0.5, 8);
        GraspAssessment.Contact c = g.contacts().get(0);
        ContactSet cs = m.contacts(3);
        assertEquals(3, c.finger());
        assertEquals(2, c.link());
        assertArrayEquals(cs.point(0), c.point());
        assertArrayEquals(new double[] {0, 0, 1}, c.normal());
        assertArrayEquals(cs.forceVector(0), c.forceN());
        assertTrue(c.forceN()[2] > 0, "it pushes into the object");
    }

    /** Without contacts: no closure, ε = volume = 0, every hold 0 — never NaN. */
    @Test
    void noContacts() {
        HandModel m = plane(0.5);
        GraspAssessment g = GraspAssessment.of(m.graspInput(), 0.5, 8);
        assertEquals(List.of(), g.contacts());
        assertFalse(g.quality().forceClosure());
        assertEquals(0, g.quality().epsilon());
        assertEquals(0, g.quality().volume());
        assertArrayEquals(new double[6], g.holdN());
        assertEquals(0, g.holdMinN());
    }

    /**
     * The joint limits of decision 6 from the hand file: 2 kg × 9.80665 m/s² = 19.6133 N at the
     * tip of the stretched finger gives 19.6133 × 0.176 = 3.45194 N·m (spread), × 0.126 =
     * 2.47128 N·m (inner), × 0.056 = 1.09834 N·m (outer); the engaged inner joint τ_break.
     */
    @Test
    void jointLimitsByHand() {
        HandDescription h = HandDescription.barrettHand();
        assertEquals(19.6133, h.fingerRatingN(), 1e-12);
        assertEquals(58.8399, h.handRatingN(), 1e-12);
        assertEquals(3.4519408, GraspAssessment.jointLimit(h, 1, 1, true), 1e-9);
        assertEquals(3.4519408, GraspAssessment.jointLimit(h, 2, 1, false), 1e-9);
        assertTrue(Double.isNaN(GraspAssessment.jointLimit(h, 3, 1, true)), "finger 3 has no spread joint");
        assertEquals(1.26, GraspAssessment.jointLimit(h, 3, 2, true));
        assertEquals(2.4712758, GraspAssessment.jointLimit(h, 3, 2, false), 1e-9);
        assertEquals(1.0983448, GraspAssessment.jointLimit(h, 1, 3, true), 1e-9);
        assertEquals(1.0983448, GraspAssessment.jointLimit(h, 1, 3, false), 1e-9);
    }
}
