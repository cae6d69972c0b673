package org.handsim.grasp;

/** Test access to a built hull's facet hyperplanes. */
final class HullAccess {
    private HullAccess() {}

    /** Every facet of the last build as {n_1..n_d, b} with n·x ≤ b inside. */
    static double[][] planes(ConvexHull h) {
        return h.facetPlanes();
    }
}
