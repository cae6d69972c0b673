package org.handsim.contact;

import java.util.Arrays;

/**
 * One point contact made from one contact patch (DESIGN.md decision 3): an immutable value.
 * Frames and sign conventions as in {@link ContactPatches}: everything in mesh A's frame,
 * metres; the normal is a unit vector pointing out of mesh B (into A).
 */
public final class PointContact {
    private final double[] center;
    private final double[] normal;
    private final double area;
    private final int pairs;
    private final int[] trianglesA, trianglesB;
    private final ContactPatches.NormalSource normalSource;

    PointContact(double[] center, double[] normal, double area, int pairs, int[] trianglesA, int[] trianglesB,
                 ContactPatches.NormalSource normalSource) {
        this.center = center;
        this.normal = normal;
        this.area = area;
        this.pairs = pairs;
        this.trianglesA = trianglesA;
        this.trianglesB = trianglesB;
        this.normalSource = normalSource;
    }

    /** @return the centre of the patch's bounding box, A's frame, metres (a copy) */
    public double[] center() { return center.clone(); }

    /** @return the unit contact normal, out of B into A, A's frame (a copy) */
    public double[] normal() { return normal.clone(); }

    /** @return the patch area estimate, m² */
    public double area() { return area; }

    /** @return the number of intersecting triangle pairs in the patch */
    public int pairCount() { return pairs; }

    /** @return the distinct triangles of A in the patch, ascending (a copy) */
    public int[] trianglesA() { return trianglesA.clone(); }

    /** @return the distinct triangles of B in the patch, ascending (a copy) */
    public int[] trianglesB() { return trianglesB.clone(); }

    /** @return where the normal came from (the object's triangles, or a documented fallback) */
    public ContactPatches.NormalSource normalSource() { return normalSource; }

    @Override
    public String toString() {
        return "PointContact[center=" + Arrays.toString(center) + ", normal=" + Arrays.toString(normal) + ", area=" + area
            + ", pairs=" + pairs + ", " + normalSource + "]";
    }
}
