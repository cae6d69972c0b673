package org.handsim.body;

import org.handsim.mesh.TriangleMesh;

/** A closed box centred on its frame, faces outward: a support given by its edge lengths. */
public final class BoxMesh {
    private BoxMesh() {}

    /** The box of edge lengths ex, ey, ez (m): 8 vertices, 12 triangles. */
    public static TriangleMesh of(String name, double ex, double ey, double ez) {
        double x = ex / 2, y = ey / 2, z = ez / 2;
        double[] v = {-x, -y, -z, x, -y, -z, x, y, -z, -x, y, -z, -x, -y, z, x, -y, z, x, y, z, -x, y, z};
        int[] t = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
        return new TriangleMesh(name, v, t);
    }
}
