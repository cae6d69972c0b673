package org.handsim.kinematics;

import org.handsim.hand.FingerDescription;
import org.handsim.hand.HandDescription;
import org.handsim.math.Vec3;

/**
 * The motor counts whose fingertip comes closest to a target, for a FREE finger. Because one
 * motor drives both joints (θk3 = θk2 / 3, eqs 3–4), a free finger's fingertip traces a curve
 * in its plane, not an area: most targets are not exactly reachable, so path planning asks for
 * the closest point of the curve instead of solving eqs (5)–(7).
 *
 * <p>Method: motor counts are integers, so the search is exact — every q_Mk ∈ [0, 17 500] is
 * evaluated (one sin/cos pair each, about a millisecond). For fingers 1 and 2 the spread is
 * chosen per q in closed form: the in-plane radius r(q) wants the plane through the target
 * (δ = 0) when r ≥ 0 and the opposite plane (δ = π) when r &lt; 0; the spread angle is the
 * allowed θk1 nearest to that, rounded to a whole q_M4 count. Thread-safe.
 */
public final class CoupledReach {
    /** The best counts found and where they put the fingertip. */
    public record Result(int qMk, int qM4, double[] joints, double[] fingertip, double errorM) {
        public Result {
            joints = joints.clone();
            fingertip = fingertip.clone();
        }
    }

    private final HandDescription hand;
    private final FingerDescription finger;
    private final Transmission transmission;
    private final FingerKinematics fk;
    private final InverseKinematics ik;

    public CoupledReach(HandDescription hand, int k) {
        this.hand = hand;
        this.finger = hand.finger(k);
        this.transmission = new Transmission(hand);
        this.fk = new FingerKinematics(finger);
        this.ik = new InverseKinematics(hand, k);
    }

    public static CoupledReach of(int k) {
        return new CoupledReach(HandDescription.barrettHand(), k);
    }

    /** Closest counts for a target in {k0} (metres). */
    public Result closest(double[] target) {
        InverseKinematics.checkTarget(target);
        double px = target[0], py = target[1], pz = target[2];
        double rho = Math.hypot(px, py);
        double psi = rho == 0 ? 0 : Math.atan2(py, px);
        int q4Front = 0, q4Back = 0;
        double cosFront = 1, sinFront = 0, cosBack = -1, sinBack = 0;
        if (finger.hasSpread()) {
            q4Front = spreadCountsNearest(psi);
            q4Back = spreadCountsNearest(InverseKinematics.wrap(psi + Math.PI));
            double d0 = transmission.spreadAngle(finger.finger(), q4Front) - psi;
            double d1 = transmission.spreadAngle(finger.finger(), q4Back) - psi;
            cosFront = Math.cos(d0); sinFront = Math.sin(d0);
            cosBack = Math.cos(d1); sinBack = Math.sin(d1);
        } else {
            // plane y = 0: in-plane x = px, residual |py|
            rho = 1;
            cosFront = px; sinFront = py;
            cosBack = px; sinBack = py;
        }
        double a1 = finger.dh(0).a(), a2 = finger.dh(1).a(), a3 = finger.dh(2).a();
        double phi2 = finger.dh(1).thetaOffset(), phi3 = finger.dh(2).thetaOffset();
        double k2 = transmission.innerRadPerCount(), k3 = transmission.outerRadPerCount(false);
        double bestD2 = Double.POSITIVE_INFINITY;
        int bestQ = 0, bestQ4 = 0;
        for (int q = 0; q <= hand.fingerCountsMax(); q++) {
            double p2 = q * k2 + phi2, p23 = p2 + q * k3 + phi3;
            double r = a1 + a2 * Math.cos(p2) + a3 * Math.cos(p23);
            double z = a2 * Math.sin(p2) + a3 * Math.sin(p23);
            boolean front = r >= 0;
            double c = front ? cosFront : cosBack, s = front ? sinFront : sinBack;
            double ex = r - rho * c, ey = rho * s, ez = z - pz;
            double d2 = ex * ex + ey * ey + ez * ez;
            if (d2 < bestD2) {
                bestD2 = d2;
                bestQ = q;
                bestQ4 = front ? q4Front : q4Back;
            }
        }
        double[] joints = transmission.joints(finger.finger(), bestQ, bestQ4, null);
        double[] tip = fk.fingertip(joints);
        double err = Vec3.distance(tip, target);
        return new Result(bestQ, bestQ4, joints, tip, err);
    }

    /** The whole q_M4 count whose spread angle is nearest to θk1 within the allowed range. */
    private int spreadCountsNearest(double theta1) {
        double[] lim = ik.spreadLimits();
        double t = theta1;
        if (t < lim[0] || t > lim[1]) {
            // outside the range: the limit nearest by angle (not by value: angles wrap)
            double d0 = Math.abs(InverseKinematics.wrap(t - lim[0]));
            double d1 = Math.abs(InverseKinematics.wrap(t - lim[1]));
            t = d0 <= d1 ? lim[0] : lim[1];
        }
        long q = Math.round(transmission.countsForSpread(finger.finger(), t));
        return (int) Math.max(0, Math.min(hand.spreadCountsMax(), q));
    }
}
