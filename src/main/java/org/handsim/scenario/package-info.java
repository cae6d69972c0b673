/**
 * What to simulate, read and written: scenarios and sweeps as JSON, the unit rule of object
 * files, object and hand meshes loaded once (VRML97, OBJ, STL) with their disk cache, the
 * install's folders and the models in the jar ({@link org.handsim.scenario.Home}), and the
 * messages for a missing file. It uses {@code trajectory}, {@code mesh}, {@code vrml},
 * {@code grasp} (the friction bounds), {@code hand}, {@code math}, {@code files},
 * {@code process} and {@code text}; never {@code model} and above.
 */
package org.handsim.scenario;
