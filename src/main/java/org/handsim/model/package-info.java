/**
 * The simulation model in Easy-Java-Simulations style: state variables, {@code initialise()},
 * {@code step(dt)} and the fixed relations between them ({@link org.handsim.model.HandModel}),
 * its collision back end against the object ({@link org.handsim.model.SceneGeometry}), the
 * hand's clearance, object placement, snapshots for views and the run's summary. It uses every
 * room below it ({@code scenario}, {@code trace}, {@code clutch}, {@code trajectory},
 * {@code grasp}, {@code contact}, {@code collision}, {@code dynamics}, {@code kinematics},
 * {@code mesh}, {@code hand}, {@code math}, {@code process}, {@code text}); nothing below it
 * knows it.
 *
 * <p>Thread rules: a model instance is stepped by one thread at a time; views read
 * {@link org.handsim.model.Snapshot}s, immutable copies taken after a step, and grasp inputs
 * ({@link org.handsim.model.HandModel#graspInput()}).
 */
package org.handsim.model;
