/**
 * The free object (DESIGN.md decision 7): a rigid body that the hand, supports and gravity move.
 *
 * <ul>
 *   <li>{@link org.handsim.body.MassProperties}: mass, centre of mass and inertia of a closed
 *       mesh (exact polyhedral integrals) or as given, checked to be a physical body;</li>
 *   <li>{@link org.handsim.body.FreeBody}: pose (centre of mass and quaternion) and motion
 *       (velocity, angular momentum), advanced by a kick–drift–kick velocity-level step whose
 *       free rotation is a fourth-order Lie–Poisson integrator (energy and angular momentum
 *       kept to rounding), into which the contact solve fits.</li>
 * </ul>
 *
 * <p>Units SI, frames stated per method (world unless said). Never touches files, the console
 * or Swing.
 *
 * <p>May use {@code contact}, {@code collision}, {@code mesh}, {@code math} and {@code text}
 * (docs/DESIGN.md, "Modules").
 */
package org.handsim.body;
