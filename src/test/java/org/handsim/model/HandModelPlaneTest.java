package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.handsim.clutch.ClutchState;
import org.handsim.kinematics.Transmission;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Test;

/**
 * The model's clutch, contact-force and breakaway logic against a hand computation, with an
 * analytic object: the half-space z ≥ h above the palm, each link a segment from its joint to
 * the next (so the contact is exactly where the segment crosses the plane).
 *
 * <p>Hand computation: finger 3 closes in the palm's y–z plane; its joint-2 axis is at
 * (0, A1, Dw) = (0, 0.05, 0.084). Link 2's tip is at height Dw + A2 sin φ2, φ2 = θ2 + Φ2. With
 * h = Dw + 0.05 the tip touches when sin φ2 = 0.05/0.07: φ2 = 45.5847°, θ2 = 43.1247°,
 * q_contact = 125·θ2 = 5390.59 counts. The clutch then transmits k_clutch·Δθ2 to the held
 * link; τ_break = 1.26 N·m is reached after Δθ2 = 1.26/7.2192 rad = 10.0000°, i.e. 1250.0
 * counts. The force pushes along +z at the tip, moment arm A2 cos φ2 = 0.048990 m, so the
 * frictionless force at breakaway is 1.26/0.048990 = 25.72 N.
 *
 * <p>With friction μ = 0.5 (8 edges) the least-norm force leans toward the direction the tip
 * moves, t = z × (p − o), |t| = A2 = 0.07 m, φ2 = 45.58° off the plane's normal: beyond the
 * cone's 26.57°, so it slides on the cone edge in the finger's plane, n + μ·(tip's tangential
 * direction): t·edge = A2 (cos φ2 + μ sin φ2) = 0.07 · 1.056997 = 0.0739898 m per newton of
 * normal force, λ = 1.26/0.0739898 = 17.029 N, |f| = λ √(1 + μ²) = 19.039 N.
 */
class HandModelPlaneTest {
    static final double H = 0.084 + 0.05;

    /**
     * Half-space z ≥ H met by the inner link only (a bar over the inner link: the outer link,
     * which rises faster, passes beside it); links as segments o_{j−1} → o_j.
     */
    static final class Plane implements LinkContacts {
        @Override
        public int collide(int finger, int link, double[] m, ContactSet out) {
            if (link != 2) return 0;
            // the link frame's origin is the segment's far end; its near end is A_j back along x
            double a = link == 1 ? 0.05 : link == 2 ? 0.07 : 0.056;
            double ex = m[3], ey = m[7], ez = m[11];
            double sx = ex - a * m[0], sy = ey - a * m[4], sz = ez - a * m[8];
            if (ez < H && sz < H) return 0;
            if (ez >= H && sz >= H) { out.add(link, ex, ey, ez, 0, 0, -1, 0); return 1; }
            double f = (H - sz) / (ez - sz);
            out.add(link, sx + f * (ex - sx), sy + f * (ey - sy), H, 0, 0, -1, 1e-6);
            return 1;
        }
    }

    static Scenario scenario(String motor3, double duration) {
        String json = "{\"name\":\"plane\",\"gravity_m_s2\":[-9.81,0,0],\"dt_s\":0.001,\"duration_s\":" + duration
            + ",\"motors\":{\"M3\":" + motor3 + "},\"outputs\":{\"torques\":false}}";
        return Scenario.parse(Path.of("plane.json"), json);
    }

    @Test
    void withFrictionTheBreakawayIsTheSameAndTheForceSlidesOnTheCone() {
        Scenario s = scenario("[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000}]", 4.0).withFriction(0.5);
        HandModel m = new HandModel(s, new Plane(), TorqueModel.NONE, false);
        m.run(null);
        double qc = 125 * (Math.toDegrees(Math.asin(0.05 / 0.07)) - 2.46);
        assertEquals(qc + 1250.0, m.breakawayCounts(3), 0.05, "breakaway depends on the joint torque, not on friction");
        double phi = Math.asin(0.05 / 0.07);
        double lambda = 1.26 / (0.07 * (Math.cos(phi) + 0.5 * Math.sin(phi)));
        assertEquals(lambda * Math.sqrt(1.25), m.breakawayForce(3), 1e-3);
    }

    @Test
    void contactBreakawayAndForceMatchTheHandComputation() {
        Scenario s = scenario("[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000}]", 4.0).withFriction(0);
        HandModel m = new HandModel(s, new Plane(), TorqueModel.NONE, true);
        m.run(null);
        double qc = 125 * (Math.toDegrees(Math.asin(0.05 / 0.07)) - 2.46);
        assertEquals(qc, m.contactCounts(3), 1e-4, "first touch located inside the step");
        assertEquals(qc + 1250.0, m.breakawayCounts(3), 0.05, "τ_break after 10° of clutch wind-up");
        double armAtTip = 0.07 * Math.cos(Math.asin(0.05 / 0.07));
        assertEquals(1.26 / armAtTip, m.breakawayForce(3), 1e-3);
        assertEquals(1.26, m.breakawayTorque(3), 1e-12);
        // after the breakaway the outer link turns at 4/375 deg per count up to its 48° limit
        // (the hand file's joint_limits_deg.theta3), where the finger stalls
        assertEquals(ClutchState.STALLED, m.state(3));
        assertEquals(Math.toRadians(48), m.joints(3)[2], 1e-12);
        Recorder r = m.recorder();
        Transmission tr = Transmission.barrettHand();
        int rows = r.rows();
        boolean sawBroken = false;
        for (int row = 1; row < rows; row++) {
            if (r.state(3, row) == ClutchState.BROKEN && r.state(3, row - 1) == ClutchState.BROKEN) {
                sawBroken = true;
                double dq = r.get(3, Recorder.Q, row) - r.get(3, Recorder.Q, row - 1);
                double dth = r.get(3, Recorder.TH3, row) - r.get(3, Recorder.TH3, row - 1);
                assertEquals(tr.outerRadPerCount(true), dth / dq, 1e-12);
                assertEquals(r.get(3, Recorder.TH2, row - 1), r.get(3, Recorder.TH2, row));
            }
        }
        assertTrue(sawBroken);
    }

    @Test
    void freeFingerWithoutObjectEndsAtTheIssuesAngles() {
        Scenario s = scenario("[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000}]", 4.0);
        HandModel m = new HandModel(s, null, TorqueModel.NONE, false);
        m.run(null);
        assertEquals(Math.toRadians(140), m.joints(3)[1], 1e-12);
        assertEquals(Math.toRadians(140.0 / 3), m.joints(3)[2], 1e-12);
        assertEquals(ClutchState.FREE, m.state(3));
    }

    @Test
    void openingReengagesAtTheBreakawayCount() {
        Scenario s = scenario("[{\"type\":\"trapezoid\",\"to\":9000,\"v_max\":5000,\"a_max\":25000},"
            + "{\"type\":\"hold\",\"duration_s\":0.2},{\"type\":\"trapezoid\",\"to\":0,\"v_max\":5000,\"a_max\":25000}]", 5.0);
        HandModel m = new HandModel(s, new Plane(), TorqueModel.NONE, true);
        m.run(null);
        double qb = m.breakawayCounts(3);
        assertTrue(qb > 6000 && qb < 7000, "qb " + qb);
        double qc = m.contactCounts(3);
        Recorder r = m.recorder();
        int reengage = -1, free = -1;
        for (int row = 1; row < r.rows(); row++) {
            if (r.state(3, row - 1) == ClutchState.BROKEN && r.state(3, row) == ClutchState.BLOCKED) reengage = row;
            if (r.state(3, row - 1) == ClutchState.BLOCKED && r.state(3, row) == ClutchState.FREE) free = row;
        }
        // the clutch grips again on the step that passes q_break, springs still wound ...
        assertTrue(reengage > 0);
        assertTrue(r.get(3, Recorder.Q, reengage) <= qb && r.get(3, Recorder.Q, reengage - 1) > qb,
            "re-engaged on the step that passed q_break");
        // ... and the links follow the motor again once it has unwound them, below q_contact
        assertTrue(free > reengage);
        assertTrue(r.get(3, Recorder.Q, free) < qc && r.get(3, Recorder.Q, free - 1) >= qc);
        for (int row = 1; row < r.rows(); row++) {
            assertEquals(r.get(3, Recorder.TH3, row - 1), r.get(3, Recorder.TH3, row), 0.2 * Math.PI / 180,
                "the outer joint never jumps (row " + row + ")");
        }
        assertEquals(ClutchState.FREE, m.state(3));
        assertEquals(0, m.joints(3)[1], 1e-12);
    }
}
