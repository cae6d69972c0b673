package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.handsim.TestPaths;
import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Scenario;
import org.handsim.trajectory.Hold;
import org.handsim.trajectory.Sequence;
import org.handsim.trajectory.Trapezoid;
import org.junit.jupiter.api.Test;

/**
 * Blocking means pushing back (DESIGN.md decision 1): finger 2 closes to θ22 = 48°, the spread
 * turns while it waits, and the finger then closes on. A cylinder (vrml/objects/cylinder.wrl at
 * scale 0.5: radius 15 mm, 60 mm long) lies along finger 2's inner link, beside it on the side the
 * spread turns it to and behind it: placed, for the pose of 600 spread counts and θ22 = 48°, 5 mm
 * out along the link from its middle and 23 mm from it along a direction four parts behind the
 * closing motion to one part along the spread's. The spread drives the inner link's back edge into
 * the cylinder: the contact's push direction opposes the spread's motion there, not the closing,
 * which pulls the link away from it (its push direction is 110.6° from the closing motion).
 *
 * <p>Expected: the spread stops at its first opposing contact and stays there; finger 2 is never
 * BLOCKED by that contact and never breaks away — it closes on, free, and leaves the cylinder;
 * no warning. (A model in which any contact on the inner link blocks it winds the clutch up
 * against a contact that carries nothing and breaks away, while the spread drives on through the
 * object: what this test fails.)
 */
class SpreadBlockingTest {
    /** The cylinder's centre and rotation vector in the palm frame (= world): see the class comment. */
    static final double[] CYLINDER = {0.08181, -0.07343, 0.10064}, ROTATION = {0.570190, 0.388749, 0};

    static Scenario scene() {
        Scenario s = Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json"));
        Path cyl = TestPaths.root().resolve("vrml/objects/cylinder.wrl");
        s = s.withObject(Scenario.ObjectPlacement.of(cyl, CYLINDER, ROTATION, 0.5, Scenario.DEFAULT_DIVISIONS, Scenario.Units.M));
        return s.withMotor(2, new Trapezoid(0, 0, 1, 1))           // finger 3 stays open
            // finger 2 closes to θ22 = 48°, waits, then closes on to 80°
            .withMotor(1, new Sequence(List.of(new Trapezoid(0, 6000, 4000, 20000), new Hold(6000, 2.0), new Trapezoid(6000, 10000, 1000, 5000))))
            // the spread waits 1.5 s, then turns to 1 200 counts (68.6°)
            .withMotor(3, new Sequence(List.of(new Hold(0, 1.5), new Trapezoid(0, 1200, 400, 2000))))
            .withDuration(8.5);
    }

    @Test
    void theSpreadStopsAtItsFirstOpposingContactAndTheFingerClosesOn() {
        Scenario s = scene();
        HandModel m = Simulation.model(s, false);
        assertTrue(m.startWarnings().isEmpty(), m.startWarnings().toString());
        double stopTheta = Double.NaN;
        boolean touched = false, left = false;
        while (m.running()) {
            m.step();
            assertEquals(ClutchState.FREE, m.state(2), "t = " + m.time() + ": finger 2 is never blocked");
            if (!m.spreadStopped()) continue;
            double th21 = m.joints(2)[0];
            if (Double.isNaN(stopTheta)) {
                stopTheta = th21;
                checkTheStop(m);
            }
            assertEquals(stopTheta, th21, "t = " + m.time() + ": the spread stays where the contact stopped it");
            touched |= m.contacts(2).size() > 0;
            left |= touched && m.contacts(2).size() == 0;
        }
        assertFalse(Double.isNaN(stopTheta), "the spread stopped");
        assertTrue(touched && left, "finger 2 closed on past the cylinder");
        assertTrue(Double.isNaN(m.breakawayTime(2)), "no breakaway");
        assertTrue(m.joints(2)[1] > Math.toRadians(79), "finger 2 closed to its set-point: " + Math.toDegrees(m.joints(2)[1]));
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
        assertTrue(m.spreadCounts() < 1200 - 100, "stopped well short of its set-point: " + m.spreadCounts());
    }

    /**
     * At the step the spread stopped: finger 2 touches the cylinder at the stop, each contact's
     * push direction d opposes the spread's motion there (v_s · d > 0, v_s = z0 × (p − o0)) and
     * lies more than 90° from the link's closing motion (v_c · d < 0, v_c = z1 × (p − o1)); a
     * billionth of a count before the stop the link does not touch (the first contact).
     */
    private static void checkTheStop(HandModel m) {
        ContactSet cs = m.contacts(2);
        assertTrue(cs.size() > 0, "contacts at the stop");
        double[] fr = m.framesWorld(2);
        for (int i = 0; i < cs.size(); i++) {
            assertEquals(2, cs.link(i), "the inner link");
            double[] p = cs.point(i), n = cs.normal(i);
            double[] d = {-n[0], -n[1], -n[2]};                   // the push, into the cylinder
            double spread = dot(cross(fr, 0, p), d), closing = dot(cross(fr, 12, p), d);
            assertTrue(spread > 0, "the spread pushes into the cylinder: " + spread);
            double angle = Math.toDegrees(Math.acos(closing / norm(cross(fr, 12, p))));
            assertTrue(angle > 105, "the push direction is behind the closing motion: " + angle + " degrees");
            assertEquals(0, cs.force(i), "a free finger's contact carries nothing");
        }
        // just before the stop: no contact (the stop is the first)
        double before = m.spreadStopCounts() - 1e-6;
        double[] joints = m.joints(2);
        joints[0] = m.hand().finger(2).spreadRadPerCount() * before;
        SceneGeometry g = new SceneGeometry(m.scenario().object(), SceneGeometry.DEFAULT_K);
        assertFalse(touches(g, m, joints), "no contact a millionth of a count before the stop");
        joints[0] = m.hand().finger(2).spreadRadPerCount() * m.spreadStopCounts();
        assertTrue(touches(g, m, joints), "a contact at the stop");
    }

    /** Whether finger 2 at {@code joints} touches the object (its own collision, the hand's base at the palm: the hand is at the world's origin). */
    private static boolean touches(SceneGeometry g, HandModel m, double[] joints) {
        double[] base = new double[12], fr = new double[48], link = new double[12];
        m.hand().finger(2).baseInPalm().copyTo(base, 0);
        org.handsim.kinematics.FingerKinematics.of(2).framesFrom(base, joints, fr);
        for (int j = 1; j <= 3; j++) {
            System.arraycopy(fr, 12 * j, link, 0, 12);
            if (g.touches(2, j, link)) return true;
        }
        return false;
    }

    /** z × (p − o) for the frame at {@code o} (its z axis and origin). */
    private static double[] cross(double[] fr, int o, double[] p) {
        double zx = fr[o + 2], zy = fr[o + 6], zz = fr[o + 10];
        double rx = p[0] - fr[o + 3], ry = p[1] - fr[o + 7], rz = p[2] - fr[o + 11];
        return new double[] {zy * rz - zz * ry, zz * rx - zx * rz, zx * ry - zy * rx};
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    private static double norm(double[] a) { return Math.sqrt(dot(a, a)); }
}
