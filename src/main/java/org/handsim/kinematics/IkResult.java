package org.handsim.kinematics;

import java.util.List;

/**
 * The answer of {@link InverseKinematics#solve}: never NaN, never an exception for a finite
 * target.
 *
 * @param reachable true if a joint vector inside the limits places the fingertip on the target
 *                  within {@link InverseKinematics#REACH_TOLERANCE_M}
 * @param joints    the chosen joint vector (radians, inside the limits); for an unreachable
 *                  target, the joints of the closest reachable point
 * @param fingertip where those joints put the fingertip (metres, same frame as the target)
 * @param errorM    distance from the fingertip to the target (metres): ~0 if reachable, else the
 *                  distance to the closest reachable point
 * @param branches  every analytic branch of eqs (5)–(7) (in or out of the limits); empty when
 *                  the target is outside the arm's reach even without limits
 */
public record IkResult(boolean reachable, double[] joints, double[] fingertip, double errorM, List<IkSolution> branches) {
    public IkResult {
        joints = joints.clone();
        fingertip = fingertip.clone();
        branches = List.copyOf(branches);
    }

    @Override
    public double[] joints() { return joints.clone(); }

    @Override
    public double[] fingertip() { return fingertip.clone(); }
}
