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

    /**
     * The Java3D geometry, or null if there are no triangles. Java3D sizes every by-reference
     * array by one vertex count (it computes bounds over all of them), so the shorter of the
     * point and normal arrays is padded: points with copies of the first point (bounds
     * unchanged), normals with +y. Indices only ever name the real entries.
     */
    IndexedTriangleArray toJava3D() {
        int m = coordIndex.length;
        if (m == 0) return null;
        int np = pointCount();
        int nn = normals == null ? 0 : normals.length / 3;
        int nv = Math.max(1, Math.max(np, nn));
        int format = GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE;
        if (normals != null) format |= GeometryArray.NORMALS;
        IndexedTriangleArray g = new IndexedTriangleArray(nv, format, m);
        setReadCapabilities(g);
        if (fpoints != null) {
            float[] p = fpoints;
            if (np < nv) {
                p = java.util.Arrays.copyOf(fpoints, 3 * nv);
                for (int i = 3 * np; i < 3 * nv; i += 3) { p[i] = p[0]; p[i + 1] = p[1]; p[i + 2] = p[2]; }
            }
            g.setCoordRefFloat(p);
        } else {
            double[] p = dpoints;
            if (np < nv) {
                p = java.util.Arrays.copyOf(dpoints, 3 * nv);
                for (int i = 3 * np; i < 3 * nv; i += 3) { p[i] = p[0]; p[i + 1] = p[1]; p[i + 2] = p[2]; }
            }
            g.setCoordRefDouble(p);
        }
        g.setCoordinateIndices(0, coordIndex);
        if (normals != null) {
            float[] n = normals;
            if (nn < nv) {
                n = java.util.Arrays.copyOf(normals, 3 * nv);
                for (int i = 3 * nn + 1; i < 3 * nv; i += 3) n[i] = 1;
            }
            g.setNormalRefFloat(n);
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
