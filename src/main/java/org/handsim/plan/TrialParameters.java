package org.handsim.plan;

import java.io.Serializable;

/**
 * The sampled parameters of one trial (before the approach).
 *
 * @param index        trial index, 0..N−1
 * @param approach     unit vector, world frame: the direction the palm moves in (toward the
 *                     object's centroid); the palm's z axis
 * @param roll         rotation of the palm about the approach, radians in [0, 2π) (see {@link Autograsp#palmRotation})
 * @param spreadCounts spread motor q_M4, integer counts
 * @param wrap         which standoff the trial takes ({@link StandoffRule}): a close palm that the
 *                     fingers wrap round the object from, or the object at the fingertips
 * @param depth        where in that rule's range the standoff falls, uniform in [0, 1)
 */
public record TrialParameters(int index, double[] approach, double roll, int spreadCounts, boolean wrap, double depth) implements Serializable {
    private static final long serialVersionUID = 2L;
}
