package org.handsim.cli;

import org.handsim.hand.HandParameters;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import picocli.CommandLine.Option;

/**
 * The hand's common parameters on the command line ({@code run}, {@code grasp}, {@code plan},
 * {@code sweep}): τ_break and the clutch's wind-up angle, laid over the scenario's
 * {@code hand.parameters} ({@link HandParameters}; the derived stiffness follows). The friction
 * has its own option, {@code --friction}.
 */
public final class HandOptions {
    @Option(names = "--tau-break", paramLabel = "NM", description = {"the clutch's breakaway torque tau_break, N*m", "(hand.parameters.tau_break_Nm; default 1.26)"})
    Double tauBreak;

    @Option(names = "--clutch-windup", paramLabel = "DEG", description = {"the clutch's wind-up angle at tau_break, degrees", "(hand.parameters.windup_deg; default 10)"})
    Double windup;

    /** The options as overrides ({@link HandParameters#NONE} when neither is given). */
    HandParameters parameters() {
        return new HandParameters(tauBreak, null, windup, null, null, null, null, null, null);
    }

    /**
     * {@code s} with the options on top of its own hand parameters.
     *
     * @throws CliError exit 2 naming the option's value when it is out of range
     */
    Scenario apply(Scenario s) {
        check();
        try {
            return s.withHandParameters(parameters());
        } catch (ScenarioException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        }
    }

    /** Exit 2 naming the option when a value is out of its range. */
    void check() {
        String why = parameters().problem();
        if (why == null) return;
        String field = why.substring(0, why.indexOf(':'));
        throw CliError.usage("handsim: " + (field.equals("tau_break_Nm") ? "--tau-break" : "--clutch-windup") + why.substring(why.indexOf(':')));
    }
}
