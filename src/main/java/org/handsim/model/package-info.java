/**
 * The simulation model in Easy-Java-Simulations style: state variables, {@code initialise()},
 * {@code step(dt)} and the fixed relations between them ({@link org.handsim.sim.HandModel}),
 * the clutch state machine of each finger ({@link org.handsim.sim.FingerClutch}, DESIGN.md
 * decision 1), scenarios read from JSON, the recorder and the output files, and the evaluation
 * of a model's grasp ({@link org.handsim.sim.GraspAssessment}: quality and hold, with each
 * joint's limit in its clutch state; DESIGN.md decisions 5 and 6).
 *
 * <p>Thread rules: a model instance is stepped by one thread at a time; views read
 * {@link org.handsim.sim.Snapshot}s, immutable copies taken after a step.
 */
package org.handsim.sim;
