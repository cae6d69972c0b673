package org.handsim.kinematics;

import org.handsim.hand.FingerDescription;
import org.handsim.hand.HandDescription;

/**
 * Motor encoder counts ⇄ joint angles (paper eqs 1–4, 10), the one place where counts and
 * degrees become radians.
 *
 * <ul>
 *   <li>eq (1), (2): θ11 = −2/35°·q_M4, θ21 = +2/35°·q_M4 (finger 3: θ31 = 0);</li>
 *   <li>eq (3): θk2 = q_Mk / 125 (degrees);</li>
 *   <li>eq (4): θk3 = q_Mk / 375 (degrees), the coupled (free) finger;</li>
 *   <li>eq (10), after breakaway at q_Mk,break: θk3 = 4/375·q_Mk − 3/375·q_Mk,break (degrees).</li>
 * </ul>
 * Worked example: q_Mk = 17 500 gives θk2 = 140° and θk3 = 46.67°; q_M4 = 3 150 gives 180° of
 * spread. Counts are range-checked (q_Mk ∈ [0, 17 500], q_M4 ∈ [0, 3 150]); a count outside,
 * or not finite, is an {@link IllegalArgumentException} naming the value.
 *
 * <p>Immutable and thread-safe.
 */
public final class Transmission {
    private final HandDescription hand;

    public Transmission(HandDescription hand) {
        this.hand = hand;
    }

    /** The BarrettHand's transmission. */
    public static Transmission barrettHand() {
        return new Transmission(HandDescription.barrettHand());
    }

    public HandDescription hand() { return hand; }

    private double checkFingerCounts(String name, double q) {
        if (!Double.isFinite(q) || q < 0 || q > hand.fingerCountsMax()) {
            throw new IllegalArgumentException(name + " = " + q + " counts is outside [0, " + hand.fingerCountsMax() + "]");
        }
        return q;
    }

    private double checkSpreadCounts(double q) {
        if (!Double.isFinite(q) || q < 0 || q > hand.spreadCountsMax()) {
            throw new IllegalArgumentException("qM4 = " + q + " counts is outside [0, " + hand.spreadCountsMax() + "]");
        }
        return q;
    }

    /** θk2 in degrees for q_Mk counts, eq (3): exactly q/125. */
    public double innerDegrees(double qMk) {
        return checkFingerCounts("qMk", qMk) / hand.innerCountsPerDeg();
    }

    /** θk3 in degrees for the coupled finger, eq (4): exactly q/375. */
    public double outerDegrees(double qMk) {
        return checkFingerCounts("qMk", qMk) / hand.outerCountsPerDeg();
    }

    /** θk2 in radians, eq (3). */
    public double innerAngle(double qMk) {
        return Math.toRadians(innerDegrees(qMk));
    }

    /** θk3 in radians for the coupled (FREE) finger, eq (4). */
    public double outerAngle(double qMk) {
        return Math.toRadians(outerDegrees(qMk));
    }

    /**
     * θk3 in radians after breakaway, eq (10): (4·q_Mk − 3·q_Mk,break)/375 degrees. At
     * q_Mk = q_Mk,break it equals eq (4), so the outer joint does not jump at the breakaway.
     */
    public double outerAngleBroken(double qMk, double qMkBreak) {
        checkFingerCounts("qMk", qMk);
        checkFingerCounts("qMk,break", qMkBreak);
        return Math.toRadians((4 * qMk - 3 * qMkBreak) / hand.outerCountsPerDeg());
    }

    /** dθk3/dq_Mk in rad/count: 1/375° coupled (eq 4), 4/375° broken (eq 10). */
    public double outerRadPerCount(boolean broken) {
        return Math.toRadians((broken ? 4.0 : 1.0) / hand.outerCountsPerDeg());
    }

    /** dθk2/dq_Mk in rad/count (eq 3). */
    public double innerRadPerCount() {
        return Math.toRadians(1.0 / hand.innerCountsPerDeg());
    }

    /** θk1 in radians for the spread motor's q_M4 counts, eqs (1), (2); 0 for finger 3. */
    public double spreadAngle(int finger, double qM4) {
        checkSpreadCounts(qM4);
        FingerDescription f = hand.finger(finger);
        return f.spreadRadPerCount() * qM4;
    }

    /**
     * The joint vector {θk1, θk2, θk3} (radians) of a FREE (coupled) finger.
     *
     * @param out a 3-array to fill, or null for a new one
     */
    public double[] joints(int finger, double qMk, double qM4, double[] out) {
        double[] j = out != null ? out : new double[3];
        j[0] = spreadAngle(finger, qM4);
        j[1] = innerAngle(qMk);
        j[2] = outerAngle(qMk);
        return j;
    }

    /** Motor counts (not rounded) for an inner-joint angle in radians (inverse of eq 3). */
    public double countsForInner(double theta2) {
        return Math.toDegrees(theta2) * hand.innerCountsPerDeg();
    }

    /** Motor counts (not rounded) for an outer-joint angle of a FREE finger (inverse of eq 4). */
    public double countsForOuter(double theta3) {
        return Math.toDegrees(theta3) * hand.outerCountsPerDeg();
    }

    /**
     * Spread counts for θk1 in radians (inverse of eqs 1, 2).
     *
     * @throws IllegalArgumentException for finger 3, which has no spread
     */
    public double countsForSpread(int finger, double theta1) {
        FingerDescription f = hand.finger(finger);
        if (!f.hasSpread()) throw new IllegalArgumentException("finger 3 has no spread joint");
        return theta1 / f.spreadRadPerCount();
    }
}
