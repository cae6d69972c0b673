package org.handsim.kinematics;

/**
 * One analytic branch of the inverse kinematics (eqs 5–7): the joint vector
 * {θk1, θk2, θk3} in radians and whether it lies inside the joint limits.
 */
public record IkSolution(double[] joints, boolean withinLimits) {
    public IkSolution {
        joints = joints.clone();
    }

    @Override
    public double[] joints() { return joints.clone(); }
}
