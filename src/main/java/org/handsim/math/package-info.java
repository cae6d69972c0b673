/**
 * Small numeric building blocks shared by every layer: 3-vectors on {@code double[]},
 * rigid transforms, and the dense symmetric solves the dynamics needs.
 *
 * <p>Naming (docs/STYLE.md, item 2): a method that returns a new object says nothing
 * ({@code compose}); a method that writes into a caller-supplied array takes it as its last
 * argument ({@code apply(p, out)}), and states whether {@code out} may alias an input.
 * Nothing here allocates in the methods marked "allocation-free".
 *
 * <p>May use {@code text} (docs/DESIGN.md, "Modules").
 */
package org.handsim.math;
