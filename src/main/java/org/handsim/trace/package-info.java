/**
 * The trace of a run: one row per step of the joints, torques, clutch states and contacts, kept
 * in memory for the charts and written as {@code trace.csv}. The model writes into it, never the
 * other way.
 *
 * <p>May use {@code clutch}, {@code files} and {@code text} (docs/DESIGN.md, "Modules").
 */
package org.handsim.trace;
