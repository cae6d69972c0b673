package org.handsim.hold;

import java.util.List;

/**
 * One direction of the hold test: the push along {@code unit} and what the object did.
 *
 * @param direction      its name: {@code -x}, {@code +x}, {@code -y}, {@code +y}, {@code -z}, {@code +z} (world axes)
 * @param unit           the push's unit direction, world
 * @param forceN         the force pushed with, N
 * @param passed         the object moved less than the displacement threshold and turned less
 *                       than the rotation threshold over the whole push
 * @param displacementM  the largest displacement of the centre of mass from its place at release, m
 * @param rotationDeg    the largest rotation from the orientation at release, degrees
 * @param finalDisplacementM the displacement at the end, m
 * @param finalRotationDeg   the rotation at the end, degrees
 * @param margin         1 − the larger of displacement/threshold and rotation/threshold, over the
 *                       push until its verdict was known (the whole push when it passed, up to
 *                       the step that crossed a threshold when it failed): in (0, 1] when it
 *                       passed, ≤ 0 when it failed
 * @param failedAtS      when the object first crossed a threshold, s, or NaN
 * @param contactLostS   from when on the object touched the hand no more (to the end), s, or NaN
 *                       (it touched the hand at the end)
 * @param settledS       when the object was found settled and the rest of the push was not
 *                       simulated ({@link HoldTest}, "Settled"), s, or NaN (simulated to the end)
 * @param settledBoundM  how far it could still have moved in the time not simulated, at most, m (0 if simulated to the end)
 * @param settledBoundDeg how far it could still have turned then, at most, degrees
 * @param contacts       the contacts at the end (the last step simulated)
 * @param simulatedS     how much of the push was simulated step by step, s
 * @param unconvergedSteps the steps whose contact solve ended without settling Coulomb's fixed
 *                       point ({@code ContactSolver.MAX_FIXED_POINT} solves: the normal impulses
 *                       kept changing, by 6e-7 to 0.13 of the largest on a planner grasp measured,
 *                       between contact states that take turns); the step used the last solve
 * @param times          sample times, s (for the chart and the CSV; a sample every
 *                       {@link HoldTest#SAMPLE_S})
 * @param displacements  displacement at each sample, m
 * @param rotations      rotation at each sample, degrees
 */
public record DirectionResult(String direction, double[] unit, double forceN, boolean passed, double displacementM,
                              double rotationDeg, double finalDisplacementM, double finalRotationDeg, double margin,
                              double failedAtS, double contactLostS, double settledS, double settledBoundM,
                              double settledBoundDeg, List<Contact> contacts,
                              double simulatedS, long unconvergedSteps, double[] times, double[] displacements, double[] rotations) {
    /**
     * A contact at the end of the push, world frame.
     *
     * @param body   the hand's body: {@code palm} or {@code finger K link J}
     * @param point  contact point, m
     * @param normal unit normal along which the hand pushes the object (into the object)
     * @param forceN the force the hand applies to the object there (the last step's impulse / dt), N
     * @param gapM   the gap along the normal, m (negative: penetration)
     */
    public record Contact(String body, double[] point, double[] normal, double[] forceN, double gapM) {}
}
