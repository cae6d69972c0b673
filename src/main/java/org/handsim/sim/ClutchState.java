package org.handsim.sim;

/**
 * The state of a finger's breakaway clutch and links (DESIGN.md decision 1).
 * <ul>
 *   <li>{@link #FREE}: coupled, θk2 = q_Mk/125°, θk3 = q_Mk/375° (eqs 3, 4);</li>
 *   <li>{@link #BLOCKED}: closing and the inner link touches: θk2, θk3 hold while the motor
 *       winds the Belleville springs, τk2 = τ_dyn + k_clutch·(q_Mk − q_Mk,contact)/125°;</li>
 *   <li>{@link #BROKEN}: τk2 exceeded τ_break: θk2 stays, θk3 = 4/375·q_Mk − 3/375·q_Mk,break
 *       (eq 10);</li>
 *   <li>{@link #STALLED}: the outer link is blocked (or the outer joint is at its limit): the
 *       finger stops and the motor stalls.</li>
 * </ul>
 * Opening re-engages: from BLOCKED below q_Mk,contact, from BROKEN at q_Mk,break.
 */
public enum ClutchState {
    FREE, BLOCKED, BROKEN, STALLED
}
