package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.handsim.clutch.ClutchState;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Test;

/**
 * Where no contact forces carry the joint torques the drive sets, the model says so rather than
 * report forces that silently fail to balance (DESIGN.md, "Which contact forces"): the residual
 * (trace, summary, {@code handsim grasp}) and one warning per finger and stretch of steps.
 *
 * <p>The case, with an analytic object: a frictionless wall that finger 3's fingertip meets
 * while the finger closes, whose push direction d the closing motion of the tip drives into
 * (u · d &gt; 0, u = dθ2/dq · t2 + dθ3/dq · t3, t_m = z_{m−1} × (p − o_{m−1})) but the outer
 * joint's own motion pulls out of (t3 · d &lt; 0): d = (t̂2 − (t̂2 · t̂3 + 0.2) t̂3)/|…| at the
 * pose θ32 = 60°, θ33 = 20°, so d · t̂3 ∝ −0.2. The wall blocks the closing there: the finger
 * stalls (its outer link blocked), the stalled motor winds the outer joint up to its stall
 * torque, and a push along d can only turn that joint back (its torque on k3 is negative) — no
 * static equilibrium, residual = the stall torque the wall cannot carry.
 */
class NoEquilibriumTest {
    static final double TH2 = Math.toRadians(60), TH3 = Math.toRadians(20);

    /** The wall: link 3's tip, once past the plane through its position at (TH2, TH3) normal to d, touches it there. */
    static final class TipWall implements LinkContacts {
        final double[] tip = new double[3], d = new double[3];

        TipWall() {
            double[] f = new double[48], base = new double[12];       // the hand at the world's origin: {30} where the palm puts it
            org.handsim.hand.HandDescription.barrettHand().finger(3).baseInPalm().copyTo(base, 0);
            FingerKinematics.of(3).framesFrom(base, new double[] {0, TH2, TH3}, f);
            for (int c = 0; c < 3; c++) tip[c] = f[36 + 4 * c + 3];
            double[] t2 = cross(f, 12, tip), t3 = cross(f, 24, tip);
            unit(t2);
            unit(t3);
            double c23 = t2[0] * t3[0] + t2[1] * t3[1] + t2[2] * t3[2];
            for (int c = 0; c < 3; c++) d[c] = t2[c] - (c23 + 0.2) * t3[c];
            unit(d);
        }

        @Override
        public int collide(int finger, int link, double[] m, ContactSet out) {
            if (finger != 3 || link != 3) return 0;
            double ex = m[3], ey = m[7], ez = m[11];
            double s = (ex - tip[0]) * d[0] + (ey - tip[1]) * d[1] + (ez - tip[2]) * d[2];
            if (s < 0) return 0;
            out.add(link, ex, ey, ez, -d[0], -d[1], -d[2], 1e-6);
            return 1;
        }

        static double[] cross(double[] fr, int o, double[] p) {
            double zx = fr[o + 2], zy = fr[o + 6], zz = fr[o + 10];
            double rx = p[0] - fr[o + 3], ry = p[1] - fr[o + 7], rz = p[2] - fr[o + 11];
            return new double[] {zy * rz - zz * ry, zz * rx - zx * rz, zx * ry - zy * rx};
        }

        static void unit(double[] v) {
            double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            for (int c = 0; c < 3; c++) v[c] /= l;
        }
    }

    @Test
    void aTorqueNoForceCarriesIsTheResidualAndOneWarningPerStretch() {
        Scenario s = HandModelPlaneTest.scenario("[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000}]", 4.0)
            .withFriction(0);
        HandModel m = new HandModel(s, new TipWall(), TorqueModel.NONE, true);
        m.run(null);
        assertEquals(ClutchState.STALLED, m.state(3));
        assertTrue(m.clutchEngaged(3), "stalled before any breakaway");
        assertEquals(Math.toRadians(60), m.joints(3)[1], 1e-6, "stopped where the wall is");
        assertEquals(1.26, m.torqueResidual(3), 1e-9, "the stall torque no push along d carries");
        assertEquals(0, m.contacts(3).force(0), "a push would turn the outer joint back");
        assertEquals(1.26, m.maxTorqueResidual(3), 1e-9);
        List<String> w = m.warnings();
        assertEquals(1, w.size(), w.toString());
        assertTrue(w.get(0).startsWith("finger 3: the contact forces cannot carry its joint torques from t = "), w.get(0));
        assertTrue(w.get(0).endsWith("s to 4 s (largest residual 1.26 N*m): no static equilibrium in that state"), w.get(0));
        Recorder r = m.recorder();
        assertEquals(1.26, r.residual(3, r.rows() - 1), 1e-9, "the trace's residual3_Nm");
    }
}
