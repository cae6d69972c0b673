package org.handsim.grasp;

/**
 * The quality of a grasp from its primitive wrenches ({@link GraspWrenches}): the L1 grasp
 * wrench space is their convex hull in 6-D.
 *
 * @param contacts     number of contacts
 * @param wrenches     number of primitive wrenches (contacts × edges)
 * @param forceClosure the origin lies strictly inside the hull
 * @param epsilon      radius of the largest origin-centred ball inside the hull (Ferrari–Canny
 *                     ε, newtons of the scaled wrench) when force closure holds, else 0
 * @param volume       6-D volume of the hull, 0 when it is lower-dimensional (NaN when the
 *                     caller asked for ε only)
 * @param facets       facets of the hull (0 when lower-dimensional; −1 when not computed)
 */
public record GraspQuality(int contacts, int wrenches, boolean forceClosure, double epsilon, double volume, int facets) {

    /** No contacts, or a lower-dimensional wrench space: no force closure, ε = 0, volume 0. */
    public static GraspQuality none(int contacts, int wrenches) {
        return new GraspQuality(contacts, wrenches, false, 0, 0, 0);
    }
}
