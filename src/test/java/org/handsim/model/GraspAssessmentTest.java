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
 *   <li>after the breakaway (the inner link held by its worm drive, whose strength Barrett does
 *       not document: no limit): the hand's rated load, the report's ceiling, 58.84 N
 *       ({@code CAPPED}: at least that).</li>
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
    void afterTheBreakawayTheWormHoldsTheInnerLinkWithoutALimit() {
        HandModel m = plane(4.0);
        assertEquals(ClutchState.STALLED, m.state(3));
        assertFalse(m.clutchEngaged(3), "stalled after a breakaway");
        GraspAssessment g = GraspAssessment.of(m.graspInput(), 0.5, 8);
        assertEquals(1, g.contacts().size());
        assertEquals(2 * 9.80665 * 3, g.holdN()[5], 1e-9);
        assertEquals(0, g.holdN()[4], 1e-9);
        assertEquals(58.8399, g.holdCapN(), 1e-12);
        assertTrue(Double.isNaN(g.jointLimitsNm()[2][1]), "the worm-held inner joint: no limit");
        assertEquals(1.26, GraspAssessment.of(plane(1.3).graspInput(), 0.5, 8).jointLimitsNm()[2][1], "the engaged clutch: tau_break");
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
     * The joint limits of decision 6, the simulation's: the engaged inner joint τ_break; no
     * known limit (NaN) for a joint a worm holds, the spread and finger 3's missing spread. The
     * rating from the hand file, 2 kg × 9.80665 m/s² = 19.6133 N at the tip of the stretched
     * finger (3 × 19.6133 = 58.8399 N for the hand), and the levers to the tip that turn a joint
     * torque into a fingertip-equivalent force: A1 + A2 + A3 = 0.050 + 0.070 + 0.056 = 0.176 m,
     * A2 + A3 = 0.126 m, A3 = 0.056 m (Table II).
     */
    @Test
    void jointLimitsAndRatingByHand() {
        HandDescription h = HandDescription.barrettHand();
        assertEquals(19.6133, h.fingerRatingN(), 1e-12);
        assertEquals(58.8399, h.handRatingN(), 1e-12);
        assertEquals(2, h.fingerRatingKg());
        assertEquals(0.176, h.leverToTip(1), 1e-12);
        assertEquals(0.126, h.leverToTip(2), 1e-12);
        assertEquals(0.056, h.leverToTip(3), 1e-12);
        for (int k = 1; k <= 3; k++) {
            for (boolean engaged : new boolean[] {true, false}) {
                assertTrue(Double.isNaN(GraspAssessment.jointLimit(h, k, 1, engaged)), "spread");
                assertTrue(Double.isNaN(GraspAssessment.jointLimit(h, k, 3, engaged)), "outer joint: its worm");
            }
            assertEquals(1.26, GraspAssessment.jointLimit(h, k, 2, true));
            assertTrue(Double.isNaN(GraspAssessment.jointLimit(h, k, 2, false)), "inner joint after a breakaway: its worm");
        }
    }
}
