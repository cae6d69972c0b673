package org.handsim.vrml;

import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.IndexedGeometryArray;
import org.jogamp.java3d.IndexedTriangleArray;

/**
 * Triangles as the loader builds them before they become Java3D geometry: points (float or
 * double), three point indices per triangle (counter-clockwise seen from the front), and
 * optionally normals with their own indices (per corner).
 *
 * <p>{@link #toJava3D()} makes one {@link IndexedTriangleArray} that holds the point and normal
 * arrays <em>by reference</em> (no copy) and copies only the index arrays, so building Java3D
 * geometry costs little more than the parse. The read capabilities the tessellation walk needs
 * are set, so the walk also works on a live or compiled scene.
 */
final class TriGeometry {
    float[] fpoints;
    double[] dpoints;
    int[] coordIndex;
    float[] normals;
    int[] normalIndex;

    int pointCount() {
        return (fpoints != null ? fpoints.length : dpoints.length) / 3;
    }

    int triangleCount() {
        return coordIndex.length / 3;
    }

    /** Reverses every triangle (for ccw FALSE); normals indices follow. */
    void flip() {
        for (int t = 0; t < coordIndex.length; t += 3) {
            int s = coordIndex[t + 1]; coordIndex[t + 1] = coordIndex[t + 2]; coordIndex[t + 2] = s;
            if (normalIndex != null) {
                s = normalIndex[t + 1]; normalIndex[t + 1] = normalIndex[t + 2]; normalIndex[t + 2] = s;
            }
        }
    }

    /** The Java3D geometry, or null if there are no triangles. */
    IndexedTriangleArray toJava3D() {
        int m = coordIndex.length;
        if (m == 0) return null;
        int np = pointCount();
        int nn = normals == null ? 0 : normals.length / 3;
        int format = GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE;
        if (normals != null) format |= GeometryArray.NORMALS;
        IndexedTriangleArray g = new IndexedTriangleArray(Math.max(1, Math.max(np, nn)), format, m);
        setReadCapabilities(g);
        if (fpoints != null) g.setCoordRefFloat(fpoints); else g.setCoordRefDouble(dpoints);
        g.setCoordinateIndices(0, coordIndex);
        if (normals != null) {
            g.setNormalRefFloat(normals);
            g.setNormalIndices(0, normalIndex);
        }
        return g;
    }

    /** The capabilities the tessellation walk needs to read geometry back. */
    static void setReadCapabilities(GeometryArray g) {
        g.setCapability(GeometryArray.ALLOW_COORDINATE_READ);
        g.setCapability(GeometryArray.ALLOW_COUNT_READ);
        g.setCapability(GeometryArray.ALLOW_FORMAT_READ);
        g.setCapability(GeometryArray.ALLOW_REF_DATA_READ);
        if (g instanceof IndexedGeometryArray) g.setCapability(IndexedGeometryArray.ALLOW_COORDINATE_INDEX_READ);
    }
}
