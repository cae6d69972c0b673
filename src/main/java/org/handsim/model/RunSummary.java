package org.handsim.model;

import org.handsim.text.Decimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The figures of one finished run, as written to {@code summary.json} (a contract: README,
 * "Outputs"). Keys: {@code scenario, sim_time_s, steps, dt_s, wall_time_s, steps_per_s,
 * realtime_factor, fingers[{finger, final_state, breakaway_time_s|null, breakaway_torque_Nm|null,
 * breakaway_force_N|null, contact_counts|null, breakaway_counts|null, final_joints_rad,
 * max_contact_force_N, torque_residual_Nm, max_worm_reaction_Nm|null}], lazy, counters{...}};
 * {@code torque_residual_Nm} is the largest {@link HandModel#torqueResidual} of the run,
 * {@code max_worm_reaction_Nm} the largest torque the inner joint's worm held
 * ({@link HandModel#maxWormReaction}; null if it never held the joint). A run with a free object
 * (DESIGN.md decision 7) adds, after {@code fingers}: {@code released_at_s} (null if it was
 * never released), {@code max_displacement_m} and {@code max_rotation_deg} (its largest
 * displacement and rotation relative to the palm), {@code slipped_at_s} (when it first moved
 * more than 5 mm relative to the palm, or null), {@code dropped_at_s} (when it lost every
 * contact with the hand and moved away, or null) and its tunnelling ({@code tunnelling_steps},
 * {@code tunnelling_at_s} and {@code tunnelling_speed_m_s}: how many steps moved a point of it
 * more than the contact margin, the first one's end time and speed bound, or null), then
 * {@code unconverged_steps} (steps whose Coulomb fixed point did not settle; each used its last
 * exact solve).
 */
public final class RunSummary {
    private RunSummary() {}

    private static Object orNull(double v) {
        return Double.isNaN(v) ? null : v;
    }

    /** The summary of a model that has run, with the wall time it took. */
    public static Map<String, Object> of(HandModel m, double wallSeconds) {
        Map<String, Object> s = new LinkedHashMap<>();
        s.put("scenario", m.scenario().name());
        s.put("sim_time_s", m.time());
        s.put("steps", m.stepIndex());
        s.put("dt_s", m.scenario().dt());
        java.util.Map<String, Object> hp = m.hand().parametersJson();
        hp.put("friction", m.scenario().friction());
        s.put("hand_parameters", hp);
        s.put("wall_time_s", wallSeconds);
        s.put("steps_per_s", wallSeconds > 0 ? m.stepIndex() / wallSeconds : null);
        s.put("realtime_factor", wallSeconds > 0 ? m.time() / wallSeconds : null);
        List<Object> fingers = new ArrayList<>();
        for (int k = 1; k <= 3; k++) {
            Map<String, Object> f = new LinkedHashMap<>();
            f.put("finger", k);
            f.put("final_state", m.state(k).name());
            f.put("breakaway_time_s", orNull(m.breakawayTime(k)));
            f.put("breakaway_torque_Nm", orNull(m.breakawayTorque(k)));
            f.put("breakaway_force_N", orNull(m.breakawayForce(k)));
            f.put("contact_counts", orNull(m.contactCounts(k)));
            f.put("breakaway_counts", orNull(m.breakawayCounts(k)));
            f.put("final_joints_rad", Decimal.clean(m.joints(k)));   // README: |x| < 1e-12 written as 0
            f.put("max_contact_force_N", m.maxContactForce(k));
            f.put("torque_residual_Nm", m.maxTorqueResidual(k));
            f.put("max_worm_reaction_Nm", orNull(m.maxWormReaction(k)));
            fingers.add(f);
        }
        s.put("fingers", fingers);
        if (m.objectFree()) {
            s.put("released_at_s", orNull(m.objectReleasedAt()));
            s.put("max_displacement_m", m.objectMaxDisplacement());
            s.put("max_rotation_deg", m.objectMaxRotation());
            s.put("slipped_at_s", orNull(m.objectSlippedAt()));
            s.put("dropped_at_s", orNull(m.objectDroppedAt()));
            org.handsim.body.Tunnelling tu = m.objectTunnelling();
            s.put("tunnelling_steps", tu == null ? 0 : tu.steps());
            s.put("tunnelling_at_s", tu == null ? null : orNull(tu.firstTimeS()));
            s.put("tunnelling_speed_m_s", tu == null ? null : orNull(tu.firstSpeedMS()));
            s.put("unconverged_steps", m.objectUnconvergedSteps());
        }
        Map<String, Object> c = new LinkedHashMap<>();
        for (HandModel.Counter counter : HandModel.Counter.values()) c.put(counter.name().toLowerCase(), m.counter(counter));
        c.putAll(m.collisionCounters());
        s.put("lazy", m.isLazy());
        s.put("counters", c);
        return s;
    }
}
