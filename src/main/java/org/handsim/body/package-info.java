/**
 * The free object (DESIGN.md decision 7): a rigid body that the hand, supports and gravity move.
 *
 * <ul>
 *   <li>{@link org.handsim.body.MassProperties}: mass, centre of mass and inertia of a closed
 *       mesh (exact polyhedral integrals) or as given, checked to be a physical body;</li>
 *   <li>{@link org.handsim.body.FreeBody}: pose (centre of mass and quaternion) and motion
 *       (velocity, angular momentum), advanced by a kick–drift–kick velocity-level step whose
 *       free rotation is a fourth-order Lie–Poisson integrator (energy and angular momentum
 *       kept to rounding), into which the contact solve fits;</li>
 *   <li>{@link org.handsim.body.ContactProblem}, {@link org.handsim.body.ContactSolver}: the
 *       step's convex problem (no penetration with the gap stabilised, velocities in Coulomb's
 *       exact cones) and its Newton solver; {@link org.handsim.body.PolyhedralContactSolver}, the
 *       same problem on pyramids through ojAlgo, the reference it is measured against;</li>
 *   <li>{@link org.handsim.body.BodyContacts}, {@link org.handsim.body.BodyStepper}: one step's
 *       contact points, and the step with them (finger links that press as followers);
 *       {@link org.handsim.body.Tunnelling}, the steps in which a point of the object moved
 *       more than the contact margin;</li>
 *   <li>{@link org.handsim.body.ProximityContacts}, {@link org.handsim.body.MeshTopology}: contact
 *       points from proximity within a margin, at most 9 spanning each patch;</li>
 *   <li>{@link org.handsim.body.BodyScene}: the object among static supports;
 *       {@link org.handsim.body.BoxMesh}, a support given by its edge lengths.</li>
 * </ul>
 *
 * <p>Units SI, frames stated per method (world unless said). Never touches files, the console
 * or Swing.
 *
 * <p>May use {@code contact}, {@code collision}, {@code mesh}, {@code math} and {@code text}
 * (docs/DESIGN.md, "Modules").
 */
package org.handsim.body;
