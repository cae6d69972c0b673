/**
 * Contact (paper Section IV): from intersection segments to point contacts, and from joint
 * torques to contact forces.
 *
 * <ul>
 *   <li>{@link org.handsim.contact.ContactPatches}: chains the segments of a
 *       {@link org.handsim.collision.CollisionResult} into patches and makes one
 *       {@link org.handsim.contact.PointContact} per patch (centre of the patch's bounding box,
 *       weighted normal of the object's triangles, area estimate, triangles touched; DESIGN.md
 *       decision 3);</li>
 *   <li>{@link org.handsim.contact.ContactForces}: contact forces from the finger's driven and
 *       held joints (eq 11 made well-posed, DESIGN.md decision 2) and eq (9): the forces of the
 *       mechanism's compliance — equal isotropic contact springs in the contacts' linearised
 *       friction cones, loads locked in kept (decision 5) — using
 *       {@link org.handsim.contact.ConeProjection}, the projection onto such a cone.</li>
 * </ul>
 *
 * <p>Typical use after a collision query {@code q.collide(treeA, treeB, pose, result)}:
 * <pre>
 * ContactPatches cp = new ContactPatches();          // object = mesh B by default
 * int n = cp.build(result, meshA, meshB, pose);      // A's frame; normals point out of B
 * cp.center(i, p); cp.normal(i, d); cp.area(i);
 * </pre>
 *
 * <p>May use {@code collision}, {@code mesh} and {@code math} (docs/DESIGN.md, "Modules").
 */
package org.handsim.contact;
