/**
 * Forward and inverse kinematics of the BarrettHand's fingers (paper Section II.A–B) and the
 * motor transmissions (eqs 1–4 and 10).
 *
 * <p>Joint vector of finger k: {@code {θk1, θk2, θk3}} in radians, the transmission's joint
 * angles; the DH angle of joint j is the joint angle plus the constant offset of Table II
 * (Φ2, Φ3). θ31 ≡ 0 (finger 3 has no spread). Positions in metres, in the finger's base frame
 * {k0} unless a method says palm frame {P}.
 *
 * <p>May use {@code hand} and {@code math} (docs/DESIGN.md, "Modules").
 */
package org.handsim.kinematics;
