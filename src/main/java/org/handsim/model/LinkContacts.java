package org.handsim.model;

/**
 * The collision side of the model: where the links of a placed finger touch the object.
 * Implemented by {@link SceneGeometry} on k-DOP trees; tests may supply analytic shapes.
 */
public interface LinkContacts {
    /**
     * Finds the point contacts of link {@code link} (1..3) of finger {@code finger} (1..3), placed
     * in the world by the 12-value row-major transform {@code worldFromLink}, with the object;
     * appends them to {@code out}.
     *
     * @return the number of contacts appended
     */
    int collide(int finger, int link, double[] worldFromLink, ContactSet out);

    /**
     * Whether link {@code link} of finger {@code finger}, placed by {@code worldFromLink}, touches
     * the object: exactly {@code collide(...) > 0}, which the default computes; an implementation
     * may stop at the first touching pair (the event bisection asks only this).
     */
    default boolean touches(int finger, int link, double[] worldFromLink) {
        return collide(finger, link, worldFromLink, new ContactSet()) > 0;
    }

    /**
     * What the back end did so far, by name (lower case, for {@code summary.json}'s counters);
     * empty by default.
     */
    default java.util.Map<String, Long> counters() {
        return java.util.Map.of();
    }

    /**
     * The object's thinnest width in metres (an estimate from above is fine; the tunnelling
     * guard substeps so that no link point moves more than half of it per check).
     */
    default double minThickness() {
        return Double.POSITIVE_INFINITY;
    }

    /**
     * The thinnest finger link's width in metres (an estimate from above), 0 when unknown. A link
     * crossing the object overlaps it over a motion at least as long as the link's own width, so
     * the tunnelling guard never needs finer substeps than half of it: a flat object (a 1 000-gon
     * sheet, width 0) would otherwise ask for 100 000 substeps a step.
     */
    default double minLinkThickness() {
        return 0;
    }

    /**
     * The object's torque origin and characteristic length for grasp analysis: its
     * centroid c in the world (metres, {@code TriangleMesh.centroid}) and R, the largest
     * distance from c to a vertex (GraspIt!'s convention), as {cx, cy, cz, R}; null when the
     * back end has no object geometry (analytic test shapes).
     */
    default double[] centroidAndRadius() {
        return null;
    }
}
