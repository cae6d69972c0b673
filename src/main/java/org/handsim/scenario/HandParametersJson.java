package org.handsim.scenario;

import org.handsim.hand.HandParameters;
import org.handsim.text.JsonObject;

/**
 * A scenario's {@code hand.parameters} read into {@link HandParameters}: every field optional, each
 * checked against its range with an error naming the field ({@code paper.json: field
 * hand.parameters.tau_break_Nm: must be in [0.05, 5] N*m ..., got 9}).
 */
final class HandParametersJson {
    private HandParametersJson() {}

    static HandParameters parse(JsonObject p) {
        p.allowOnly(HandParameters.FIELDS.toArray(new String[0]));
        HandParameters h = new HandParameters(num(p, "tau_break_Nm"), num(p, "k_clutch_Nm_per_rad"), num(p, "windup_deg"),
            num(p, "motor_v_max_counts_s"), num(p, "motor_a_max_counts_s2"), pair(p, "theta2_limits_deg"), pair(p, "theta3_limits_deg"),
            pair(p, "spread_limits_deg"), num(p, "friction"));
        String why = h.problem();
        if (why != null) throw p.error(why.substring(0, why.indexOf(':')), why.substring(why.indexOf(':') + 2));
        return h;
    }

    private static Double num(JsonObject p, String f) {
        return p.has(f) ? p.number(f) : null;
    }

    private static double[] pair(JsonObject p, String f) {
        return p.has(f) ? p.numbers(f, 2) : null;
    }
}
