package org.handsim.clutch;

/**
 * The state of a finger's breakaway clutch and links (DESIGN.md decision 1).
 * <ul>
 *   <li>{@link #FREE}: coupled, θk2 = q_Mk/125°, θk3 = q_Mk/375° (eqs 3, 4);</li>
 *   <li>{@link #BLOCKED}: closing and the inner link touches: θk2, θk3 hold while the motor
 *       winds the Belleville springs, τk2 = τ_dyn + k_clutch·(q_Mk − q_Mk,contact)/125°;</li>
 *   <li>{@link #BROKEN}: the torque through the clutch, τk2, exceeded τ_break: the clutch
 *       free-wheels, the worm holds θk2, θk3 turns at 4/375° per count (eq 10, written from the
 *       outer joint's angle at the breakaway so that it does not jump);</li>
 *   <li>{@link #STALLED}: the outer link is blocked (or the outer joint is at its limit): the
 *       finger stops and the motor stalls.</li>
 * </ul>
 * Opening re-engages the clutch at q_Mk,break: BROKEN → BLOCKED (the springs are still wound
 * by q_Mk,break − q_Mk,contact, so the links stay put), then BLOCKED → FREE below q_Mk,contact.
 */
public enum ClutchState {
    FREE, BLOCKED, BROKEN, STALLED
}
