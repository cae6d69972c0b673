/**
 * The six-direction hold test (DexGraspBench's, which DexGraspNet, MultiGripperGrasp and GraspGen
 * share): does the object stay in the hand when the world pushes on it?
 *
 * <ul>
 *   <li>{@link org.handsim.hold.LockedGrasp}: a closed grasp with its finger joints locked where
 *       they stopped (the worms are not back-drivable), each flexion joint pressing as the closing
 *       left it, and the object freed there;</li>
 *   <li>{@link org.handsim.hold.HoldTest}: the pushes along ±x, ±y, ±z of the world and the ramp,
 *       on the free object of {@code org.handsim.body};</li>
 *   <li>{@link org.handsim.hold.HoldReport}: a whole test of a scenario (close, lock, push) and
 *       its outputs; {@link org.handsim.hold.ObjectMass}: the object's mass when the scenario
 *       holds it fixed;</li>
 *   <li>{@link org.handsim.hold.HoldSettings}, {@link org.handsim.hold.DirectionResult},
 *       {@link org.handsim.hold.RampResult}: the protocol's values and the answers.</li>
 * </ul>
 *
 * <p>May use every room below it (docs/DESIGN.md, "Modules").
 */
package org.handsim.hold;
