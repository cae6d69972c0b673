/**
 * Grasp analysis beyond the paper (DESIGN.md decisions 5 and 6): Coulomb friction cones
 * ({@link org.handsim.grasp.FrictionCone}), the primitive wrenches of the L1 grasp wrench space
 * ({@link org.handsim.grasp.GraspWrenches}), its convex hull in 6-D (our own Quickhull: no
 * n-dimensional hull exists on Maven Central), force closure, the Ferrari–Canny ε and the
 * volume ({@link org.handsim.grasp.GraspQuality}), and how much load a grasp holds (a linear
 * program on ojAlgo), and the evaluation of a simulated grasp from a copy the model makes
 * ({@link org.handsim.grasp.GraspAssessment}).
 *
 * <p>May use {@code hand} and {@code text} (and ojAlgo; docs/DESIGN.md, "Modules").
 */
package org.handsim.grasp;
