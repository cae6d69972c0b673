package org.handsim.plan;

import java.io.Serializable;

/**
 * The sampled parameters of one trial (before the approach).
 *
 * @param index        trial index, 0..N−1
 * @param approach     unit vector, world frame: the direction the palm moves in (toward the
 *                     object's centroid); the palm's z axis
 * @param roll         rotation of the palm about the approach, radians in [0, 2π) (see {@link Autograsp#palmRotation})
 * @param spreadCounts spread motor q_M4, integer counts in [0, 3150]
 * @param standoff     how far the palm is backed off from the first touch, metres
 */
public record TrialParameters(int index, double[] approach, double roll, int spreadCounts, double standoff) implements Serializable {
    private static final long serialVersionUID = 1L;
}
