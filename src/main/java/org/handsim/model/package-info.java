/**
 * The simulation model in Easy-Java-Simulations style: state variables, {@code initialise()},
 * {@code step(dt)} and the fixed relations between them ({@link org.handsim.model.HandModel}),
 * its collision back end against the object ({@link org.handsim.model.SceneGeometry}), the
 * hand's clearance, object placement, snapshots for views and the run's summary. Nothing
 * below it knows it.
 *
 * <p>Thread rules: a model instance is stepped by one thread at a time; views read
 * {@link org.handsim.model.Snapshot}s, immutable copies taken after a step, and grasp inputs
 * ({@link org.handsim.model.HandModel#graspInput()}).
 *
 * <p>May use every room below it (docs/DESIGN.md, "Modules").
 */
package org.handsim.model;
