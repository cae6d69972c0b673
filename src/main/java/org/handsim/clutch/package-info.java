/**
 * The breakaway clutch of one finger (DESIGN.md decision 1): its states FREE, BLOCKED, BROKEN and
 * STALLED, the transitions between them and the torque through the clutch.
 *
 * <p>May use {@code hand} and {@code kinematics} (docs/DESIGN.md, "Modules").
 */
package org.handsim.clutch;
