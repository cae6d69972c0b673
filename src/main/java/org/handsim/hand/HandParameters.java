package org.handsim.hand;

import org.handsim.text.Decimal;

/**
 * Overrides of the hand's own parameters for one scenario ({@code hand.parameters}): each null
 * (or absent) keeps the hand file's value. Ranges ({@link #problem}): what a BarrettHand-like
 * hand can have and the simulation handles, each with its reason.
 *
 * <p><b>Derived values</b> (DESIGN.md decision 1, {@link HandDescription#with}): the clutch
 * stiffness follows from τ_break and the wind-up angle at which the Belleville springs reach it,
 * k_clutch = τ_break / wind-up. The wind-up angle is the documented choice (10° of motor-side
 * inner-joint angle, 1 250 counts), so a τ_break given alone keeps the wind-up and the stiffness
 * follows; a stiffness given instead of the wind-up sets it, wind-up = τ_break / k_clutch. The
 * finger motors' count range follows the inner joint's upper limit through eq (3)
 * (q_max = 125 θk2,max in degrees), the spread's through eqs (1)–(2) (3150 counts per 180°).
 *
 * @param tauBreakNm         breakaway torque τ_break, N·m
 * @param kClutchNmPerRad    clutch stiffness, N·m per radian of inner-joint wind-up
 * @param windupDeg          the wind-up angle at which the clutch reaches τ_break, degrees
 * @param motorVMaxCountsS   the fastest a motor's set-point may move, counts/s
 * @param motorAMaxCountsS2  the largest acceleration of a motor's set-point, counts/s²
 * @param theta2LimitsDeg    inner joint's range {lo, hi}, degrees
 * @param theta3LimitsDeg    outer joint's range {lo, hi}, degrees
 * @param spreadLimitsDeg    spread's range {lo, hi}, degrees
 * @param friction           Coulomb μ of the fingers on the object
 */
public record HandParameters(Double tauBreakNm, Double kClutchNmPerRad, Double windupDeg, Double motorVMaxCountsS,
                             Double motorAMaxCountsS2, double[] theta2LimitsDeg, double[] theta3LimitsDeg, double[] spreadLimitsDeg,
                             Double friction) implements java.io.Serializable {
    private static final long serialVersionUID = 1L;

    /** No override. */
    public static final HandParameters NONE = new HandParameters(null, null, null, null, null, null, null, null, null);

    /** The fields of {@code hand.parameters}, in the order they are written. */
    public static final java.util.List<String> FIELDS = java.util.List.of("tau_break_Nm", "k_clutch_Nm_per_rad", "windup_deg",
        "motor_v_max_counts_s", "motor_a_max_counts_s2", "theta2_limits_deg", "theta3_limits_deg", "spread_limits_deg", "friction");

    /** τ_break range, N·m: a twentieth of the BarrettHand's 1.26 up to twice the worm-held inner joint's rated 2.47. */
    public static final double TAU_MIN = 0.05, TAU_MAX = 5;
    /** Wind-up range, degrees: at 0.1° the spring is nearly rigid (a breakaway within 12 counts); beyond 90° it is no clutch spring. */
    public static final double WINDUP_MIN = 0.1, WINDUP_MAX = 90;
    /** Motor speed range, counts/s: the hand file's bound of a valid trajectory is the largest. */
    public static final double V_MAX = 1e5, A_MAX = 1e7;

    /** The problem with a value, or null: "must be in [lo, hi] UNIT (why), got V". */
    static String range(double v, double lo, double hi, String unit, String why) {
        if (v >= lo && v <= hi) return null;
        return "must be in [" + Decimal.format(lo) + ", " + Decimal.format(hi) + "] " + unit + " (" + why + "), got " + Decimal.format(v);
    }

    /**
     * The first problem of these overrides as "FIELD: message", or null. Checked: each value
     * within its range, a joint range's lower limit below its upper, the stiffness and the wind-up
     * not both given.
     */
    public String problem() {
        if (kClutchNmPerRad != null && windupDeg != null) {
            return "k_clutch_Nm_per_rad: give the clutch stiffness or the wind-up angle (windup_deg), not both: one follows from the other and tau_break_Nm";
        }
        String p;
        if (tauBreakNm != null && (p = range(tauBreakNm, TAU_MIN, TAU_MAX, "N*m", "a twentieth of the BarrettHand's 1.26 to twice the inner worm's rated 2.47")) != null) return "tau_break_Nm: " + p;
        if (kClutchNmPerRad != null) {
            double tau = tauBreakNm != null ? tauBreakNm : 1.26;
            double windup = Math.toDegrees(tau / kClutchNmPerRad);
            if (!(kClutchNmPerRad > 0) || !(windup >= WINDUP_MIN && windup <= WINDUP_MAX)) {
                return "k_clutch_Nm_per_rad: must give a wind-up tau_break / k between " + Decimal.format(WINDUP_MIN) + " and "
                    + Decimal.format(WINDUP_MAX) + " degrees, got " + Decimal.format(kClutchNmPerRad);
            }
        }
        if (windupDeg != null && (p = range(windupDeg, WINDUP_MIN, WINDUP_MAX, "degrees", "nearly rigid to no clutch spring")) != null) return "windup_deg: " + p;
        if (motorVMaxCountsS != null && (p = positive(motorVMaxCountsS, V_MAX, "counts/s")) != null) return "motor_v_max_counts_s: " + p;
        if (motorAMaxCountsS2 != null && (p = positive(motorAMaxCountsS2, A_MAX, "counts/s^2")) != null) return "motor_a_max_counts_s2: " + p;
        if (theta2LimitsDeg != null && (p = limits(theta2LimitsDeg, 0, 180)) != null) return "theta2_limits_deg: " + p;
        if (theta3LimitsDeg != null && (p = limits(theta3LimitsDeg, 0, 90)) != null) return "theta3_limits_deg: " + p;
        if (spreadLimitsDeg != null && (p = limits(spreadLimitsDeg, 0, 180)) != null) return "spread_limits_deg: " + p;
        if (friction != null && (p = range(friction, 0, 10, "", "measured coefficients stay below 2")) != null) return "friction: " + p;
        return null;
    }

    private static String positive(double v, double max, String unit) {
        if (v > 0 && v <= max) return null;
        return "must be > 0 and at most " + Decimal.format(max) + " " + unit + ", got " + Decimal.format(v);
    }

    private static String limits(double[] l, double lo, double hi) {
        if (l.length != 2) return "needs 2 numbers {lower, upper}, got " + l.length;
        String p = range(l[0], lo, hi, "degrees", "the joint's mechanical range");
        if (p == null) p = range(l[1], lo, hi, "degrees", "the joint's mechanical range");
        if (p != null) return p;
        if (!(l[0] < l[1])) return "the lower limit must be below the upper, got " + Decimal.format(l[0]) + ", " + Decimal.format(l[1]);
        return null;
    }

    /** The overrides as {@code hand.parameters} writes them (only those given), for saving a scenario. */
    public java.util.Map<String, Object> toJson() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        Object[] v = {tauBreakNm, kClutchNmPerRad, windupDeg, motorVMaxCountsS, motorAMaxCountsS2, theta2LimitsDeg, theta3LimitsDeg, spreadLimitsDeg, friction};
        for (int i = 0; i < v.length; i++) if (v[i] != null) m.put(FIELDS.get(i), v[i]);
        return m;
    }

    /** These overrides with {@code o}'s non-null values on top (the command line's over the scenario's). */
    public HandParameters and(HandParameters o) {
        return new HandParameters(o.tauBreakNm != null ? o.tauBreakNm : tauBreakNm,
            o.kClutchNmPerRad != null ? o.kClutchNmPerRad : o.windupDeg != null ? null : kClutchNmPerRad,
            o.windupDeg != null ? o.windupDeg : o.kClutchNmPerRad != null ? null : windupDeg,
            o.motorVMaxCountsS != null ? o.motorVMaxCountsS : motorVMaxCountsS, o.motorAMaxCountsS2 != null ? o.motorAMaxCountsS2 : motorAMaxCountsS2,
            o.theta2LimitsDeg != null ? o.theta2LimitsDeg : theta2LimitsDeg, o.theta3LimitsDeg != null ? o.theta3LimitsDeg : theta3LimitsDeg,
            o.spreadLimitsDeg != null ? o.spreadLimitsDeg : spreadLimitsDeg, o.friction != null ? o.friction : friction);
    }

    /** True when nothing is overridden. */
    public boolean isEmpty() { return toJson().isEmpty(); }
}
