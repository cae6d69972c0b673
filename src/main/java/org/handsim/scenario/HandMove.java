package org.handsim.scenario;

import java.util.ArrayList;
import java.util.List;
import org.handsim.text.Decimal;
import org.handsim.text.JsonObject;
import org.handsim.trajectory.Hold;
import org.handsim.trajectory.Trajectory;
import org.handsim.trajectory.Trapezoid;

/**
 * One segment of the hand base's motion (scenario field {@code hand.moves}, DESIGN.md decision 7),
 * played in order as the motors' segments are: {@code "line"} moves the palm by {@code by_m}
 * (world frame, m) on a trapezoid of {@code v_max} (m/s) and {@code a_max} (m/s²);
 * {@code "rotate"} turns it by {@code angle_rad} about {@code axis} (world, through the palm's
 * origin) on a trapezoid of {@code v_max} (rad/s) and {@code a_max} (rad/s²); {@code "hold"}
 * keeps it still for {@code duration_s}.
 *
 * @param type      "line", "rotate" or "hold"
 * @param direction unit direction of the line or axis of the rotation (world), null for a hold
 * @param profile   the distance (m) or angle (rad) covered against time, from 0
 */
public record HandMove(String type, double[] direction, Trajectory profile) {
    /** The segments of {@code hand.moves}; each refused naming its field when it is no motion. */
    static List<HandMove> parse(JsonObject hand) {
        List<HandMove> out = new ArrayList<>();
        if (!hand.has("moves")) return out;
        int n = hand.list("moves").size();
        for (int i = 0; i < n; i++) {
            JsonObject s = hand.objectAt("moves", i);
            String type = s.string("type");
            switch (type) {
                case "line" -> {
                    s.allowOnly("type", "by_m", "v_max", "a_max");
                    double[] by = s.numbers("by_m", 3);
                    double d = Math.sqrt(by[0] * by[0] + by[1] * by[1] + by[2] * by[2]);
                    if (!(d > 0)) throw s.error("by_m", "must not be zero: a line moves the hand");
                    out.add(new HandMove(type, new double[] {by[0] / d, by[1] / d, by[2] / d},
                        new Trapezoid(0, d, s.positive("v_max"), s.positive("a_max"))));
                }
                case "rotate" -> {
                    s.allowOnly("type", "axis", "angle_rad", "v_max", "a_max");
                    double[] ax = s.numbers("axis", 3);
                    double l = Math.sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
                    if (!(l > 0)) throw s.error("axis", "must not be zero");
                    double a = s.number("angle_rad");
                    if (a == 0 || Math.abs(a) > 4 * Math.PI) {
                        throw s.error("angle_rad", "must be non-zero and within ±4π, got " + Decimal.format(a));
                    }
                    double sg = Math.signum(a);
                    out.add(new HandMove(type, new double[] {sg * ax[0] / l + 0.0, sg * ax[1] / l + 0.0, sg * ax[2] / l + 0.0},
                        new Trapezoid(0, Math.abs(a), s.positive("v_max"), s.positive("a_max"))));
                }
                case "hold" -> {
                    s.allowOnly("type", "duration_s");
                    out.add(new HandMove(type, null, new Hold(0, s.positive("duration_s"))));
                }
                default -> throw s.error("type", "must be line, rotate or hold, got \"" + type + "\"");
            }
        }
        return out;
    }

    /** This segment as {@link #parse} reads it. */
    java.util.Map<String, Object> toJson() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("type", type);
        double amount = profile.end();
        java.util.Map<String, Object> seg = profile.segment();
        switch (type) {
            case "line" -> {
                m.put("by_m", new double[] {amount * direction[0], amount * direction[1], amount * direction[2]});
                m.put("v_max", seg.get("v_max"));
                m.put("a_max", seg.get("a_max"));
            }
            case "rotate" -> {
                m.put("axis", direction.clone());
                m.put("angle_rad", amount);
                m.put("v_max", seg.get("v_max"));
                m.put("a_max", seg.get("a_max"));
            }
            default -> m.put("duration_s", profile.duration());
        }
        return m;
    }
}
