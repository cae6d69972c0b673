package org.handsim.hand;

import org.handsim.text.Decimal;

/**
 * The ranges of the physical quantities HandSim reads from people (options, CSV rows, scenario
 * fields), each with its reason. A value outside is refused where it enters, naming the field and
 * the value; inside, every computation (energies go with the square of a speed, torques with a
 * mass times an acceleration) stays many orders of magnitude from overflow, so a result is never
 * an infinity that only the JSON writer would notice.
 *
 * <table>
 *   <caption>Ranges (each component, in absolute value)</caption>
 *   <tr><th>quantity</th><th>limit</th><th>why</th></tr>
 *   <tr><td>gravity</td><td>100 m/s²</td><td>ten times the Earth's; at about 25 times it the
 *       fingers' own weight alone turns an inner joint's clutch past τ_break</td></tr>
 *   <tr><td>joint angle</td><td>1000 rad</td><td>160 turns, as a rotation vector's components
 *       ({@code math.RigidTransform.MAX_ROTATION_RAD})</td></tr>
 *   <tr><td>joint velocity</td><td>1000 rad/s</td><td>the BarrettHand's fingers turn at a few
 *       rad/s</td></tr>
 *   <tr><td>joint acceleration</td><td>1e6 rad/s²</td><td>a step of a few rad/s in a
 *       millisecond is 1e3–1e4</td></tr>
 *   <tr><td>motor speed (trapezoid {@code v_max})</td><td>1e7 counts/s</td><td>about 1 400 rad/s
 *       of an inner joint (7 162 counts/rad); the motors close a finger in about a second,
 *       2e4 counts/s</td></tr>
 *   <tr><td>motor acceleration (trapezoid {@code a_max})</td><td>1e10 counts/s²</td><td>about
 *       1.4e6 rad/s² of an inner joint; the paper's profile ramps at 2e4 counts/s²</td></tr>
 *   <tr><td>target, position</td><td>1e6 m</td><td>{@code math.RigidTransform.MAX_POSITION_M}:
 *       a finger reaches 0.2 m</td></tr>
 * </table>
 */
public final class InputRanges {
    private InputRanges() {}

    /**
     * A range ±{@code max} of one kind of value.
     *
     * @param unit its unit in messages
     * @param why  the reason, in messages
     */
    public record Range(double max, String unit, String why) {
        /** Null when |v| ≤ max, else "V is beyond +-MAX UNIT (WHY)". */
        public String problem(double v) {
            if (Math.abs(v) <= max) return null;
            return Decimal.format(v) + " is beyond +-" + Decimal.format(max) + " " + unit + " (" + why + ")";
        }

        /** The first CSV column out of range as "column NAME = problem", or null ({@code columns[i]} names {@code v[i]}). */
        public String problem(String[] columns, double[] v) {
            for (int i = 0; i < v.length; i++) {
                String p = problem(v[i]);
                if (p != null) return "column " + columns[i] + " = " + p;
            }
            return null;
        }

        /** The first component out of range as "NAME[i]: problem", or null. */
        public String problem(String name, double[] v) {
            for (int i = 0; i < v.length; i++) {
                String p = problem(v[i]);
                if (p != null) return name + "[" + i + "]: " + p;
            }
            return null;
        }
    }

    public static final Range GRAVITY = new Range(100, "m/s^2", "ten times the Earth's gravity: a physical bound for a hand on a bench");
    public static final Range JOINT_ANGLE = new Range(1000, "rad", "160 turns");
    public static final Range JOINT_SPEED = new Range(1000, "rad/s", "the fingers turn at a few rad/s");
    public static final Range JOINT_ACCELERATION = new Range(1e6, "rad/s^2", "a few rad/s gained in a millisecond is 1e3 to 1e4");
    public static final Range POSITION = new Range(1e6, "m", "a finger reaches 0.2 m");
    public static final Range MOTOR_SPEED = new Range(1e7, "counts/s", "the inner joint at 1 400 rad/s; the motors close a finger"
        + " in about a second, 2e4 counts/s");
    public static final Range MOTOR_ACCELERATION = new Range(1e10, "counts/s^2", "the inner joint at 1.4e6 rad/s^2; the paper's"
        + " profile ramps at 2e4 counts/s^2");
}
