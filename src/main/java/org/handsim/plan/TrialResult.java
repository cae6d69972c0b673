package org.handsim.plan;

import java.io.Serializable;
import org.handsim.text.Decimal;
import org.handsim.text.SafeText;

/**
 * One row of {@code plan.csv} (the contract, README): the trial's parameters, where the hand
 * ended, and the grasp's evaluation. A failed trial keeps its parameters and carries the
 * one-line error; its other fields are empty in the table.
 *
 * @param palmPosition the palm position the fingers closed from, metres (null if the trial failed before)
 * @param palmRotation its axis-angle rotation, radians (null likewise)
 * @param outcome      how the grasp ended, for the plan's diagnosis when no trial reaches force
 *                     closure ({@link TrialOutcome}; null for a failed trial); not in plan.csv
 * @param holdPassed   the hold test's six verdicts, in {@link org.handsim.hold.HoldTest#DIRECTIONS}' order
 *                     (−x, +x, −y, +y, −z, +z), or null (no hold test, or the trial failed)
 * @param holdMargin   the hold test's smallest margin over the six ({@link org.handsim.hold.DirectionResult#margin}),
 *                     or NaN
 */
public record TrialResult(int index, boolean ok, double[] approach, double roll, int spreadCounts, double standoff,
                          int contacts, boolean forceClosure, double epsilon, double volume, double holdMinN,
                          String[] finalStates, double simTimeS, double wallS, String error,
                          double[] palmPosition, double[] palmRotation, TrialOutcome outcome, boolean[] holdPassed,
                          double holdMargin) implements Serializable {
    private static final long serialVersionUID = 3L;

    /** A row without the hold test. */
    public TrialResult(int index, boolean ok, double[] approach, double roll, int spreadCounts, double standoff,
                       int contacts, boolean forceClosure, double epsilon, double volume, double holdMinN,
                       String[] finalStates, double simTimeS, double wallS, String error,
                       double[] palmPosition, double[] palmRotation, TrialOutcome outcome) {
        this(index, ok, approach, roll, spreadCounts, standoff, contacts, forceClosure, epsilon, volume, holdMinN, finalStates, simTimeS,
            wallS, error, palmPosition, palmRotation, outcome, null, Double.NaN);
    }

    /** The hold test's columns, after {@link #HEADER}'s, in a plan run with {@code --hold-test} (contract). */
    public static final String HOLD_HEADER = ",hold_-x,hold_+x,hold_-y,hold_+y,hold_-z,hold_+z,hold_margin";

    /** This row with the hold test's answer. */
    public TrialResult withHold(boolean[] passed, double margin) {
        return new TrialResult(index, ok, approach, roll, spreadCounts, standoff, contacts, forceClosure, epsilon, volume, holdMinN,
            finalStates, simTimeS, wallS, error, palmPosition, palmRotation, outcome, passed, margin);
    }

    /** The header of plan.csv (contract). */
    public static final String HEADER = "trial,status,approach_x,approach_y,approach_z,roll_rad,spread_counts,standoff_m,"
        + "contacts,force_closure,epsilon,volume,hold_min_N,final_state1,final_state2,final_state3,sim_time_s,wall_s,error";

    /** A failed trial: its parameters, its standoff (NaN, an empty cell, if it failed before that) and the error (one line). */
    public static TrialResult failed(TrialParameters p, double standoff, double wallS, String error) {
        String e = error == null ? "" : error.replace('\n', ' ').replace('\r', ' ');
        return new TrialResult(p.index(), false, p.approach(), p.roll(), p.spreadCounts(), standoff, 0, false, 0, 0, 0,
            null, 0, wallS, e, null, null, null);
    }

    /**
     * The CSV row (no line end) with the hold test's columns ({@link #HOLD_HEADER}; empty cells
     * for a trial without its answer) when {@code withHold}.
     */
    public String csvRow(boolean withHold) {
        if (!withHold) return csvRow();
        StringBuilder sb = new StringBuilder(csvRow());
        if (holdPassed == null) {
            sb.append(",,,,,,,");
        } else {
            for (boolean b : holdPassed) sb.append(',').append(b);
            sb.append(',').append(Decimal.orEmpty(holdMargin));
        }
        return sb.toString();
    }

    /** The CSV row (no line end). Numbers in text.Decimal's form (shortest round trip, integers as integers). */
    public String csvRow() {
        StringBuilder sb = new StringBuilder(256);
        sb.append(index).append(',').append(ok ? "ok" : "failed");
        for (double v : approach) sb.append(',').append(Decimal.orEmpty(v));
        sb.append(',').append(Decimal.orEmpty(roll)).append(',').append(spreadCounts).append(',').append(Decimal.orEmpty(standoff));
        if (ok) {
            sb.append(',').append(contacts).append(',').append(forceClosure).append(',').append(Decimal.orEmpty(epsilon))
                .append(',').append(Decimal.orEmpty(volume)).append(',').append(Decimal.orEmpty(holdMinN));
            for (String s : finalStates) sb.append(',').append(s);
            sb.append(',').append(Decimal.orEmpty(simTimeS));
        } else {
            sb.append(",,,,,,,,,");
        }
        sb.append(',').append(Decimal.orEmpty(wallS)).append(',').append(SafeText.csvCell(error));
        return sb.toString();
    }
}
