/**
 * The BarrettHand as data: the Denavit–Hartenberg table (paper Tables I–II), the placement of
 * each finger's base frame {k0} in the palm frame {P} (BH8 manual Table 9), the transmission
 * ratios (eqs 1–4, 10), joint limits, the links' mass properties (Table III) and the clutch
 * parameters, loaded and validated from one resource file, {@code barretthand.json}. Every
 * number in that file carries its source beside it. Nothing here computes kinematics.
 *
 * <p>May use {@code math}, {@code files} and {@code text} (docs/DESIGN.md, "Modules").
 */
package org.handsim.hand;
