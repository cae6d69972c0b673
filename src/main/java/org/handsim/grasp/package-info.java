/**
 * Grasp analysis beyond the paper (DESIGN.md decisions 5 and 6): Coulomb friction cones
 * ({@link org.handsim.grasp.FrictionCone}), the primitive wrenches of the L1 grasp wrench space
 * ({@link org.handsim.grasp.GraspWrenches}), its convex hull in 6-D (our own Quickhull: no
 * n-dimensional hull exists on Maven Central), force closure, the Ferrari–Canny ε and the
 * volume ({@link org.handsim.grasp.GraspQuality}), and how much load a grasp holds (a linear
 * program on ojAlgo). Uses {@code contact}, {@code kinematics} and {@code hand}; never
 * {@code model} and above.
 */
package org.handsim.grasp;
