package org.handsim.scenario;

import java.util.ArrayList;
import java.util.List;
import org.handsim.text.JsonObject;

/**
 * A wrench on the free object (scenario field {@code "disturbances"}, DESIGN.md decision 7):
 * force (N) and torque (N·m) in the world frame at the object's centre of mass, applied for
 * {@code from_s} ≤ t &lt; {@code to_s}.
 *
 * @param fromS    start, s, ≥ 0
 * @param toS      end, s, &gt; fromS
 * @param forceN   3 values, world
 * @param torqueNm 3 values, world
 */
public record Disturbance(double fromS, double toS, double[] forceN, double[] torqueNm) {
    /** @return true when the wrench acts at time t */
    public boolean actsAt(double t) { return t >= fromS && t < toS; }

    /** The scenario's {@code disturbances} (empty when absent); each refused naming its field when it is no interval or wrench. */
    static List<Disturbance> parse(JsonObject root, boolean free) {
        List<Disturbance> out = new ArrayList<>();
        if (!root.has("disturbances")) return out;
        int n = root.list("disturbances").size();
        if (n > 0 && !free) throw root.error("disturbances", "push a free object: add \"free\": true to the object, or remove them");
        for (int i = 0; i < n; i++) {
            JsonObject d = root.objectAt("disturbances", i);
            d.allowOnly("from_s", "to_s", "force_N", "torque_N_m");
            double from = d.nonNegative("from_s");
            double to = d.number("to_s");
            if (!(to > from)) {
                throw d.error("to_s", "must be after from_s (" + org.handsim.text.Decimal.format(from) + " s), got "
                    + org.handsim.text.Decimal.format(to) + " s");
            }
            if (!d.has("force_N") && !d.has("torque_N_m")) throw d.error("force_N", "missing: give force_N, torque_N_m or both");
            double[] f = d.has("force_N") ? d.numbers("force_N", 3) : new double[3];
            double[] t = d.has("torque_N_m") ? d.numbers("torque_N_m", 3) : new double[3];
            out.add(new Disturbance(from, to, f, t));
        }
        return out;
    }

    /** This disturbance as {@link #parse} reads it. */
    java.util.Map<String, Object> toJson() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("from_s", fromS);
        m.put("to_s", toS);
        m.put("force_N", forceN.clone());
        m.put("torque_N_m", torqueNm.clone());
        return m;
    }
}
