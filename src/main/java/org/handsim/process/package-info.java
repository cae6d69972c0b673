/**
 * The life of a command in its JVM and its timing: the context a command asks about when one JVM
 * runs many (cancellation, terminal, generation), the cleanup on exit, named points of a command's
 * work, memory-bounded caches, steady-state timing and the decimal step clock.
 *
 * <p>May use {@code text} (docs/DESIGN.md, "Modules").
 */
package org.handsim.process;
