/**
 * The trace of a run: one row per step of the joints, torques, clutch states and contacts, kept
 * in memory for the charts and written as {@code trace.csv}. It uses {@code clutch} (the state
 * names), {@code files} and {@code text}; the model writes into it, never the other way.
 */
package org.handsim.trace;
