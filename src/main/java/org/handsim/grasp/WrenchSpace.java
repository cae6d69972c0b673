package org.handsim.grasp;

/**
 * The quality of a grasp from its primitive wrenches: the L1 grasp wrench space (GraspIt!'s) is
 * the convex hull in 6-D of the wrenches {@link GraspWrenches#of} builds (layout: wrench j at
 * {@code w[6j .. 6j+5]}). Two entry points:
 * <ul>
 *   <li>{@link #quality}: the whole hull — force closure, ε, 6-D volume and facet count;</li>
 *   <li>{@link #epsilon}: force closure and ε only (volume NaN, facets −1), the fast path: a
 *       best-first partial hull ({@link ConvexHull#epsilon}) that stops at the facet nearest
 *       the origin once no wrench lies beyond it.</li>
 * </ul>
 *
 * <p><b>Definitions and tolerances</b> (S = the largest absolute wrench coordinate; τ =
 * {@link ConvexHull#DISTANCE_TOLERANCE} · S = 1e-11 · S):
 * <ul>
 *   <li>lower-dimensional (affine rank &lt; 6, e.g. one or two contacts, collinear or coincident
 *       contacts, fewer than 7 distinct wrenches): no force closure, ε = 0, volume 0, facets 0;</li>
 *   <li>force closure: the origin lies strictly inside the hull — its distance to every facet
 *       hyperplane exceeds τ (Ferrari, Canny, "Planning optimal grasps", ICRA 1992; Murray, Li,
 *       Sastry, <i>A Mathematical Introduction to Robotic Manipulation</i>, §5.4);</li>
 *   <li>ε: the radius of the largest origin-centred ball inside the hull = the smallest facet
 *       offset, when force closure holds, else 0 (newtons of the scaled wrench);</li>
 *   <li>volume: the 6-D volume of the hull; facets: facets of the polytope (coplanar simplicial
 *       facets merged, {@link ConvexHull#facetCount()}).</li>
 * </ul>
 * Thread-safe: each thread works in its own reusable hull workspace.
 */
public final class WrenchSpace {
    /** Dimension of a wrench. */
    public static final int DIM = 6;

    private static final ThreadLocal<ConvexHull> HULL = ThreadLocal.withInitial(() -> new ConvexHull(DIM));

    /**
     * Most wrenches (contacts × cone edges, identical ones counted once) whose whole hull
     * {@link #quality} builds: 1 600, 200 contacts of the default 8 edges. Measured on a loaded
     * 2-core machine with 200 random contacts on a sphere (the worst case we know): 930 000
     * facets, 31 s and 300 MB; the facets grow about as the square of the wrenches, so 5 000
     * contacts would take hours. Beyond it {@link #quality} refuses at once
     * ({@link ConvexHull.TooLargeException}); the ε-only path ({@link #epsilon}) builds part of
     * the hull and has only the facet limit ({@link ConvexHull#MAX_FACETS}).
     */
    public static final int MAX_WRENCHES = 1600;
    /**
     * Most wrenches (contacts × edges, repeats included) a caller should build at all: a
     * million, 48 MB of values; repeats are dropped and at most {@link #MAX_WRENCHES} distinct
     * ones are used.
     */
    public static final int MAX_INPUT_WRENCHES = 1_000_000;

    /** This thread's hull workspace: for a progress report ({@link ConvexHull#facetsSoFar}) from another thread. */
    public static ConvexHull threadHull() {
        return HULL.get();
    }

    private WrenchSpace() {}

    /**
     * The whole hull of the wrenches: force closure, ε, volume, facets.
     *
     * @param wrenches 6·count values (newtons; torques already divided by R)
     * @param count    number of wrenches
     * @param contacts number of contacts (reported back; not used in the computation)
     * @throws IllegalArgumentException for too few values or a non-finite value
     */
    public static GraspQuality quality(double[] wrenches, int count, int contacts) {
        return whole(wrenches, count, contacts, true);
    }

    /**
     * As {@link #quality} without the facet count (facets −1): force closure, ε and the volume
     * of the whole hull, the same numbers to the last bit — what the grasp evaluation reports
     * ({@code GraspAssessment}), which shows no facet count; merging the coplanar simplicial
     * facets costs about 8 % of the whole hull on a planner's mug grasp.
     *
     * @throws IllegalArgumentException for too few values or a non-finite value
     */
    public static GraspQuality qualityWithoutFacets(double[] wrenches, int count, int contacts) {
        return whole(wrenches, count, contacts, false);
    }

    /** The whole hull's quality; the merged facet count when {@code facets}, else −1. */
    private static GraspQuality whole(double[] wrenches, int count, int contacts, boolean facets) {
        check(wrenches, count, contacts);
        double[] w = distinct(wrenches, count);
        int n = w == wrenches ? count : w.length / DIM;
        if (n > MAX_WRENCHES) {
            int edges = contacts > 0 ? count / contacts : count;
            String advice = contacts > 0 && contacts <= MAX_WRENCHES
                ? "use fewer contacts, or at most " + MAX_WRENCHES / contacts + " cone edges (--edges) for " + contacts + " contacts"
                : "use fewer contacts: at most " + MAX_WRENCHES / FrictionCone.DEFAULT_EDGES + " at the default "
                    + FrictionCone.DEFAULT_EDGES + " cone edges";
            throw new ConvexHull.TooLargeException(contacts + " contacts x " + edges + " cone edges give " + n + " distinct wrenches, more"
                + " than the limit of " + MAX_WRENCHES + " for the whole grasp wrench space (its facets grow about as the square of the"
                + " wrenches: 1 600 take 30 s and 300 MB); " + advice);
        }
        ConvexHull hull = HULL.get();
        if (!hull.build(w, n)) return GraspQuality.none(contacts, count);
        double b = hull.minOffset();
        boolean closure = b > hull.tolerance();
        return new GraspQuality(contacts, count, closure, closure ? b : 0, hull.volume(), facets ? hull.facetCount() : -1);
    }

    /**
     * Force closure and ε only (volume NaN, facets −1): the fast path, equal to
     * {@link #quality}'s force closure and ε.
     *
     * @param wrenches 6·count values (newtons; torques already divided by R)
     * @param count    number of wrenches
     * @param contacts number of contacts (reported back)
     * @throws IllegalArgumentException for too few values or a non-finite value
     */
    public static GraspQuality epsilon(double[] wrenches, int count, int contacts) {
        check(wrenches, count, contacts);
        double[] w = distinct(wrenches, count);
        ConvexHull hull = HULL.get();
        double b = hull.epsilon(w, w == wrenches ? count : w.length / DIM);
        if (Double.isNaN(b)) return new GraspQuality(contacts, count, false, 0, Double.NaN, -1);
        boolean closure = b > hull.tolerance();
        return new GraspQuality(contacts, count, closure, closure ? b : 0, Double.NaN, -1);
    }

    /**
     * Above this many wrenches, repeated ones are dropped before the hull is built: they add
     * nothing to it, and the checks Quickhull runs after a step spoiled by rounding cost facets ×
     * points (5 000 rows of 150 distinct contacts, 40 000 wrenches, did not finish in 3 minutes;
     * their 1 200 distinct wrenches take seconds). Below it, the wrenches are used as given (the
     * planner's grasps: a few dozen, no allocation).
     */
    static final int DEDUPLICATE_ABOVE = 512;

    /**
     * The wrenches without repeats (identical in all six coordinates; first occurrences in their
     * order): {@code w} itself when there are none or {@code count} ≤ {@link #DEDUPLICATE_ABOVE},
     * else a new array of 6 × distinct values.
     */
    static double[] distinct(double[] w, int count) {
        if (count <= DEDUPLICATE_ABOVE) return w;
        Integer[] order = new Integer[count];
        for (int i = 0; i < count; i++) order[i] = i;
        java.util.Arrays.sort(order, (a, b) -> compare(w, a, b));
        boolean[] repeat = new boolean[count];
        int repeats = 0;
        for (int k = 1; k < count; k++) {
            if (compare(w, order[k - 1], order[k]) == 0) {
                // of equal wrenches, keep the first in the input: the sort is stable
                repeat[order[k]] = true;
                repeats++;
            }
        }
        if (repeats == 0) return w;
        double[] out = new double[DIM * (count - repeats)];
        int n = 0;
        for (int i = 0; i < count; i++) {
            if (!repeat[i]) System.arraycopy(w, DIM * i, out, DIM * n++, DIM);
        }
        return out;
    }

    private static int compare(double[] w, int a, int b) {
        for (int k = 0; k < DIM; k++) {
            int c = Double.compare(w[DIM * a + k], w[DIM * b + k]);
            if (c != 0) return c;
        }
        return 0;
    }

    private static void check(double[] wrenches, int count, int contacts) {
        if (count < 0 || wrenches.length < DIM * count) {
            throw new IllegalArgumentException("need 6*count = " + DIM * count + " wrench values, got " + wrenches.length);
        }
        if (contacts < 0) throw new IllegalArgumentException("contacts must be >= 0, got " + contacts);
    }
}
