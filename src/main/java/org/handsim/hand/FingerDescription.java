package org.handsim.hand;

import org.handsim.math.RigidTransform;

/**
 * One finger k ∈ {1, 2, 3}: its DH rows (paper Table I), the pose of its base frame {k0} in the
 * palm frame {P}, the spread coupling, and the mass properties of its three links.
 *
 * @param finger            1, 2 or 3
 * @param dh                three DH rows, joints k1, k2, k3
 * @param baseInPalm        {@code P ← k0}: maps points in {k0} to the palm frame
 * @param hasSpread         false for finger 3 (Table I, r = 0): θ31 ≡ 0 and its dynamics has two joints
 * @param spreadRadPerCount θk1 per spread-motor count, radians (eqs 1, 2): −2/35°, +2/35°, 0
 * @param links             mass properties of links 1, 2, 3 (Table III; identical for all fingers)
 */
public record FingerDescription(int finger, DhRow[] dh, RigidTransform baseInPalm, boolean hasSpread,
                                double spreadRadPerCount, LinkInertia[] links) {
    public FingerDescription {
        dh = dh.clone();
        links = links.clone();
    }

    /** @return the number of joints the dynamics integrates: 3, or 2 for finger 3 */
    public int activeJoints() {
        return hasSpread ? 3 : 2;
    }

    @Override
    public DhRow[] dh() { return dh.clone(); }

    /** @return DH row j (0-based: 0 = joint k1). */
    public DhRow dh(int j) { return dh[j]; }

    @Override
    public LinkInertia[] links() { return links.clone(); }

    /** @return link j's mass properties (0-based: 0 = link 1). */
    public LinkInertia link(int j) { return links[j]; }
}
