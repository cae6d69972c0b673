/**
 * What to simulate, read and written: scenarios and sweeps as JSON, the unit rule of object
 * files, object and hand meshes loaded once (VRML97, OBJ, STL) with their disk cache, the
 * install's folders and the models in the jar ({@link org.handsim.scenario.Home}), and the
 * messages for a missing file.
 *
 * <p>May use {@code trajectory}, {@code body} (a free object's given inertia checked as it is
 * read), {@code vrml}, {@code mesh}, {@code grasp} (the friction bounds),
 * {@code hand}, {@code math}, {@code files}, {@code process} and {@code text} (docs/DESIGN.md,
 * "Modules").
 */
package org.handsim.scenario;
