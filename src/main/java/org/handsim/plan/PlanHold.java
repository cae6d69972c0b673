package org.handsim.plan;

import java.io.Serializable;
import org.handsim.hold.HoldSettings;

/**
 * The hold test of {@code handsim plan --hold-test}: each trial's grasp is locked, its object
 * freed and pushed along the six world directions ({@link org.handsim.hold.HoldTest}, verdicts
 * only: a failed push stops where it crossed a threshold).
 *
 * @param settings     the pushes (force, time, step, thresholds)
 * @param massKg       the object's mass, kg, or NaN (its closed mesh at the density, else the default)
 * @param densityKgM3  its density, kg/m³, or NaN
 * @param rankByMargin rank the trials by the hold test's smallest margin (then ε) instead of ε
 */
public record PlanHold(HoldSettings settings, double massKg, double densityKgM3, boolean rankByMargin) implements Serializable {
    private static final long serialVersionUID = 1L;
}
