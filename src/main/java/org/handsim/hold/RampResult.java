package org.handsim.hold;

/**
 * One direction of the ramp: the force rose from 0 until the object moved or turned past the
 * ramp's thresholds.
 *
 * @param direction    its name ({@link HoldTest#DIRECTIONS})
 * @param unit         the push's unit direction, world
 * @param forceN       the force when the object crossed a threshold, N; the ramp's largest force
 *                     when it never did ({@code heldAtMax})
 * @param heldAtMax    the object stayed within the thresholds up to the ramp's largest force:
 *                     it holds at least that
 * @param forceAtRestN the force at the last step the object was still at rest (its speed below
 *                     {@link HoldTest#REST_SPEED_M_S}, its spin below {@link HoldTest#REST_SPIN_RAD_S})
 *                     before it crossed: where it began to give way, N
 * @param crossedAtS   when it crossed, s (NaN if it held)
 * @param rotationDeg  its rotation at the end of the ramp, degrees
 * @param displacementM its displacement at the end of the ramp, m
 * @param times        sample times, s
 * @param displacements displacement at each sample, m
 * @param rotations    rotation at each sample, degrees
 */
public record RampResult(String direction, double[] unit, double forceN, boolean heldAtMax, double forceAtRestN, double crossedAtS,
                         double rotationDeg, double displacementM, double[] times, double[] displacements, double[] rotations) {}
