package org.handsim.vrml;

import java.util.Arrays;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.IndexedLineArray;
import org.jogamp.java3d.PointArray;

/**
 * Turns VRML geometry nodes into {@link TriGeometry} (and line/point geometry), validating
 * indices against their coordinates with errors that point at the offending list element.
 *
 * <ul>
 *   <li><b>IndexedFaceSet</b>: faces separated by −1 (a last face without −1 is accepted);
 *       every index must be −1 or in [0, number of points), otherwise an error names the
 *       element, its value and the valid range. Faces are triangulated by
 *       {@link FaceTriangulator} whatever the {@code convex} flag says (a wrong TRUE is
 *       common in real files and a fan would then add area outside the face); faces with
 *       fewer than three vertices are skipped with a warning. {@code ccw FALSE} reverses
 *       the triangles. Explicit normals (per vertex or per face, indexed or not) are used when
 *       consistent, otherwise (with a warning) generated from {@code creaseAngle}.</li>
 *   <li><b>ElevationGrid</b> (clause 6.17): xDimension × zDimension heights, two triangles per
 *       cell, counter-clockwise seen from +y; the count is checked before anything is
 *       allocated.</li>
 *   <li><b>Extrusion</b> (clause 6.18): the cross-section is scaled, rotated by
 *       {@code orientation} and placed in each spine point's spine-aligned cross-section plane
 *       (Y along the spine tangent, Z normal to the spine's bend, X = Y × Z, with the
 *       standard's rules for end points, closed spines, collinear spines and Z flips); the
 *       caps are triangulated as polygons, oriented to close the body consistently.</li>
 * </ul>
 */
final class GeometryBuilder {
    private final LoadSession session;
    private final FaceTriangulator tri = new FaceTriangulator();

    GeometryBuilder(LoadSession session) {
        this.session = session;
    }

    /** Offset of element {@code k} of the list in field {@code field} (re-reads the file). */
    static int elementOffset(VrmlNode n, String field, int k) {
        int i = n.type.indexOf(field);
        if (i < 0 || n.values[i] == null) return n.offset;
        VrmlLexer lx = new VrmlLexer(n.text, n.valueOffsets[i]);
        lx.accept('[');
        for (int j = 0; j < k; j++) lx.readDouble("an index");
        lx.skip();
        return lx.pos;
    }

    private static void checkIndices(VrmlNode n, String field, int[] idx, int count, String what) {
        for (int k = 0; k < idx.length; k++) {
            int v = idx[k];
            if (v >= count || v < -1) {
                int at = elementOffset(n, field, k);
                if (v < -1) {
                    throw n.text.error(at, field + "[" + k + "] = " + v + " in " + n.describe()
                        + ": negative index (only -1 may appear, to end a face)");
                }
                throw n.text.error(at, field + "[" + k + "] = " + v + " in " + n.describe() + " is out of range: the "
                    + what + " has " + count + (count == 1 ? " entry" : " entries") + (count > 0 ? " (0.." + (count - 1) + ")" : ""));
            }
        }
    }

    /** IndexedFaceSet ⇒ triangles, or null if it has none. */
    TriGeometry indexedFaceSet(VrmlNode g) {
        VrmlNode coord = g.getNode("coord");
        int[] ci = g.getInts("coordIndex");
        if (coord == null) {
            if (ci.length > 0) session.warn(g.text, g.offset, "IndexedFaceSet has a coordIndex but no coord; no geometry");
            return null;
        }
        if (!coord.type.name.equals("Coordinate")) {
            session.warn(g.text, coord.offset, "coord of IndexedFaceSet is a " + coord.type.name + ", not a Coordinate; no geometry");
            return null;
        }
        float[] pts = coord.getFloats("point");
        int np = pts.length / 3;
        checkIndices(g, "coordIndex", ci, np, "Coordinate");
        tri.reset();
        tri.triangulateAll(pts, ci);
        if (tri.shortFaces > 0) {
            session.warn(g.text, g.offsetOf("coordIndex"), tri.shortFaces + " face(s) with fewer than 3 vertices in "
                + g.describe() + " skipped");
        }
        if (tri.fannedConcave > 0) {
            session.warn(g.text, g.offsetOf("coordIndex"), tri.fannedConcave + " face(s) of " + g.describe()
                + " fan-triangulated although not convex (self-intersecting, or more than " + FaceTriangulator.MAX_EAR_CLIP
                + " vertices): the triangles may cover area outside the face");
        }
        int m = tri.count;
        if (m == 0) return null;
        int[] pos = tri.tri;
        int[] cidx = new int[3 * m];
        for (int k = 0; k < 3 * m; k++) cidx[k] = ci[pos[k]];
        TriGeometry t = new TriGeometry();
        t.fpoints = pts;
        t.coordIndex = cidx;
        VrmlNode nn = g.getNode("normal");
        boolean generate = session.normals && (nn == null || !explicitNormals(g, nn, t, pos, tri.face, m));
        if (!g.getBool("ccw")) t.flip();
        if (generate) Normals.generate(t, g.getFloat("creaseAngle"));
        return t;
    }

    private boolean explicitNormals(VrmlNode g, VrmlNode nn, TriGeometry t, int[] pos, int[] face, int m) {
        if (!nn.type.name.equals("Normal")) {
            session.warn(g.text, nn.offset, "normal of IndexedFaceSet is a " + nn.type.name + ", not a Normal; normals generated");
            return false;
        }
        float[] vec = nn.getFloats("vector");
        int count = vec.length / 3;
        int[] ni = g.getInts("normalIndex");
        int[] ci = g.getInts("coordIndex");
        int[] out = new int[3 * m];
        boolean perVertex = g.getBool("normalPerVertex");
        String problem = null;
        if (perVertex) {
            if (ni.length > 0 && ni.length < maxPos(pos, 3 * m) + 1) {
                problem = "normalIndex has " + ni.length + " entries, fewer than coordIndex";
            } else {
                for (int k = 0; k < 3 * m; k++) out[k] = ni.length > 0 ? ni[pos[k]] : ci[pos[k]];
            }
        } else {
            for (int k = 0; k < 3 * m && problem == null; k++) {
                int f = face[k / 3];
                if (ni.length > 0) {
                    if (f >= ni.length) problem = "normalIndex has " + ni.length + " entries, fewer than the faces";
                    else out[k] = ni[f];
                } else {
                    out[k] = f;
                }
            }
        }
        if (problem == null) {
            for (int k = 0; k < 3 * m; k++) {
                if (out[k] < 0 || out[k] >= count) {
                    problem = "normal index " + out[k] + " is out of range (the Normal has " + count + " vectors)";
                    break;
                }
            }
        }
        if (problem != null) {
            session.warn(g.text, g.offset, "explicit normals of " + g.describe() + " ignored: " + problem + "; normals generated");
            return false;
        }
        t.normals = vec;
        t.normalIndex = out;
        return true;
    }

    private static int maxPos(int[] pos, int n) {
        int m = 0;
        for (int k = 0; k < n; k++) m = Math.max(m, pos[k]);
        return m;
    }

    /** ElevationGrid ⇒ triangles, or null if it has no cell. */
    TriGeometry elevationGrid(VrmlNode g) {
        int xd = g.getInt("xDimension"), zd = g.getInt("zDimension");
        float[] h = g.getFloats("height");
        if (xd < 0 || zd < 0) {
            throw g.text.error(g.offsetOf(xd < 0 ? "xDimension" : "zDimension"), "ElevationGrid dimensions must not be negative, got "
                + xd + " x " + zd);
        }
        long need = (long) xd * zd;
        if (h.length < need) {
            throw g.text.error(g.offsetOf("height"), "ElevationGrid height has " + h.length + " values but xDimension x zDimension = "
                + xd + " x " + zd + " = " + need);
        }
        if (h.length > need) session.warn(g.text, g.offsetOf("height"), "ElevationGrid height has " + (h.length - need) + " values more than needed; ignored");
        if (xd < 2 || zd < 2) return null;
        double dx = g.getFloat("xSpacing"), dz = g.getFloat("zSpacing");
        float[] p = new float[(int) (3 * need)];
        for (int j = 0; j < zd; j++) {
            for (int i = 0; i < xd; i++) {
                int v = i + j * xd;
                p[3 * v] = (float) (i * dx);
                p[3 * v + 1] = h[v];
                p[3 * v + 2] = (float) (j * dz);
            }
        }
        int cells = (xd - 1) * (zd - 1);
        int[] ci = new int[6 * cells];
        int o = 0;
        for (int j = 0; j + 1 < zd; j++) {
            for (int i = 0; i + 1 < xd; i++) {
                int a = i + j * xd, b = i + (j + 1) * xd, c = i + 1 + (j + 1) * xd, d = i + 1 + j * xd;
                ci[o++] = a; ci[o++] = b; ci[o++] = c;
                ci[o++] = a; ci[o++] = c; ci[o++] = d;
            }
        }
        TriGeometry t = new TriGeometry();
        t.fpoints = p;
        t.coordIndex = ci;
        if (!g.getBool("ccw")) t.flip();
        if (session.normals) Normals.generate(t, g.getFloat("creaseAngle"));
        return t;
    }

    /** Extrusion ⇒ triangles, or null if degenerate (fewer than 2 spine or cross-section points). */
    TriGeometry extrusion(VrmlNode g) {
        float[] spine = g.getFloats("spine");
        float[] cs = g.getFloats("crossSection");
        float[] sc = g.getFloats("scale");
        float[] or = g.getFloats("orientation");
        int ns = spine.length / 3, nc = cs.length / 2;
        if (ns < 2 || nc < 2) return null;
        if ((long) ns * nc > session.maxGeneratedPoints) {
            throw g.text.error(g.offset, "Extrusion would generate " + ((long) ns * nc) + " points (" + ns + " spine x " + nc
                + " cross-section), more than the limit of " + session.maxGeneratedPoints);
        }
        boolean closedSpine = ns > 2 && spine[0] == spine[3 * ns - 3] && spine[1] == spine[3 * ns - 2] && spine[2] == spine[3 * ns - 1];
        boolean closedCs = nc > 2 && cs[0] == cs[2 * nc - 2] && cs[1] == cs[2 * nc - 1];
        double[][] frame = spineFrames(spine, ns, closedSpine);
        // a closed cross-section or spine shares its seam: the last ring point/ring is the first
        int ncr = closedCs ? nc - 1 : nc, nsr = closedSpine ? ns - 1 : ns;
        float[] p = new float[3 * nsr * ncr];
        double[] m = new double[9];
        for (int i = 0; i < nsr; i++) {
            double[] f = frame[i];
            int si = Math.min(i, sc.length / 2 - 1), oi = Math.min(i, or.length / 4 - 1);
            double sx = si >= 0 ? sc[2 * si] : 1, sz = si >= 0 ? sc[2 * si + 1] : 1;
            if (oi >= 0) rotation(or[4 * oi], or[4 * oi + 1], or[4 * oi + 2], or[4 * oi + 3], m);
            else rotation(0, 0, 1, 0, m);
            for (int k = 0; k < ncr; k++) {
                double lx = cs[2 * k] * sx, lz = cs[2 * k + 1] * sz;
                // orientation rotation of (lx, 0, lz)
                double rx = m[0] * lx + m[2] * lz, ry = m[3] * lx + m[5] * lz, rz = m[6] * lx + m[8] * lz;
                int v = i * ncr + k;
                for (int a = 0; a < 3; a++) {
                    p[3 * v + a] = (float) (spine[3 * i + a] + rx * f[a] + ry * f[3 + a] + rz * f[6 + a]);
                }
            }
        }
        int body = 2 * (ns - 1) * (nc - 1);
        int capN = ncr;
        boolean begin = g.getBool("beginCap") && !closedSpine && capN >= 3;
        boolean end = g.getBool("endCap") && !closedSpine && capN >= 3;
        int[] ci = new int[3 * (body + (begin ? capN - 2 : 0) + (end ? capN - 2 : 0))];
        int o = 0;
        for (int i = 0; i + 1 < ns; i++) {
            int r0 = i * ncr, r1 = (i + 1 == nsr ? 0 : i + 1) * ncr;
            for (int k = 0; k + 1 < nc; k++) {
                int k1 = k + 1 == ncr ? 0 : k + 1;
                int a = r0 + k, b = r0 + k1, c = r1 + k1, d = r1 + k;
                ci[o++] = a; ci[o++] = b; ci[o++] = c;
                ci[o++] = a; ci[o++] = c; ci[o++] = d;
            }
        }
        if (begin) o = cap(p, 0, capN, true, ci, o);
        if (end) o = cap(p, (ns - 1) * ncr, capN, false, ci, o);
        TriGeometry t = new TriGeometry();
        t.fpoints = p;
        t.coordIndex = o == ci.length ? ci : Arrays.copyOf(ci, o);
        if (!g.getBool("ccw")) t.flip();
        if (session.normals) Normals.generate(t, g.getFloat("creaseAngle"));
        return t;
    }

    /**
     * A cap on the ring starting at vertex {@code base}. The body uses each begin-ring edge
     * k→k+1 and each end-ring edge k+1→k, so the begin cap runs the ring backwards and the end
     * cap forwards: then every cap edge meets its body edge in the opposite direction.
     */
    private int cap(float[] p, int base, int capN, boolean reverse, int[] ci, int o) {
        int[] ring = new int[capN];
        for (int k = 0; k < capN; k++) ring[k] = base + (reverse ? capN - 1 - k : k);
        tri.reset();
        tri.polygon(p, ring, 0, capN, 0);
        for (int k = 0; k < 3 * tri.count; k++) ci[o++] = ring[tri.tri[k]];
        return o;
    }

    /** Spine-aligned cross-section planes: per spine point {X, Y, Z} as 9 numbers. */
    private static double[][] spineFrames(float[] s, int ns, boolean closed) {
        double[][] ys = new double[ns][];
        double[][] zs = new double[ns][];
        for (int i = 0; i < ns; i++) {
            double[] y;
            if (i == 0) y = closed ? sub(s, 1, ns - 2) : sub(s, 1, 0);
            else if (i == ns - 1) y = closed ? sub(s, 1, ns - 2) : sub(s, ns - 1, ns - 2);
            else y = sub(s, i + 1, i - 1);
            ys[i] = normalize(y);
            double[] z = null;
            if (i > 0 && i < ns - 1) {
                z = cross(sub(s, i + 1, i), sub(s, i - 1, i));
            } else if (closed) {
                z = cross(sub(s, 1, 0), sub(s, ns - 2, 0));
            }
            zs[i] = z == null ? null : normalize(z);
        }
        if (!closed && ns > 2) {
            zs[0] = zs[1];
            zs[ns - 1] = zs[ns - 2];
        }
        // Y: fill zero-length tangents from neighbours
        fillGaps(ys);
        boolean anyZ = false;
        for (double[] z : zs) if (z != null) anyZ = true;
        double[][] out = new double[ns][];
        if (!anyZ) {
            // collinear spine: rotate the Y=0 plane by the rotation taking +y to the spine direction
            double[] y = ys[0] != null ? ys[0] : new double[] {0, 1, 0};
            double[] r = rotationBetween(new double[] {0, 1, 0}, y);
            double[] x = apply(r, new double[] {1, 0, 0}), z = apply(r, new double[] {0, 0, 1});
            for (int i = 0; i < ns; i++) out[i] = concat(x, y, z);
            return out;
        }
        fillGaps(zs);
        for (int i = 1; i < ns; i++) {
            if (dot(zs[i], zs[i - 1]) < 0) zs[i] = new double[] {-zs[i][0], -zs[i][1], -zs[i][2]};
        }
        for (int i = 0; i < ns; i++) {
            double[] y = ys[i] != null ? ys[i] : new double[] {0, 1, 0};
            double[] x = normalize(cross(y, zs[i]));
            if (x == null) x = new double[] {1, 0, 0};
            double[] z = normalize(cross(x, y));
            out[i] = concat(x, y, z);
        }
        return out;
    }

    private static void fillGaps(double[][] v) {
        for (int i = 1; i < v.length; i++) if (v[i] == null) v[i] = v[i - 1];
        for (int i = v.length - 2; i >= 0; i--) if (v[i] == null) v[i] = v[i + 1];
    }

    private static double[] sub(float[] s, int i, int j) {
        return new double[] {s[3 * i] - s[3 * j], s[3 * i + 1] - s[3 * j + 1], s[3 * i + 2] - s[3 * j + 2]};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** Unit vector, or null for a (near) zero vector. */
    private static double[] normalize(double[] a) {
        double l = Math.sqrt(dot(a, a));
        if (!(l > 1e-12)) return null;
        return new double[] {a[0] / l, a[1] / l, a[2] / l};
    }

    private static double[] concat(double[] x, double[] y, double[] z) {
        return new double[] {x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]};
    }

    /** Row-major 3×3 rotation about axis (x, y, z) by angle a (Rodrigues); identity for a zero axis. */
    static void rotation(double x, double y, double z, double a, double[] m) {
        double l = Math.sqrt(x * x + y * y + z * z);
        if (!(l > 0)) { x = 0; y = 0; z = 1; a = 0; } else { x /= l; y /= l; z /= l; }
        double c = Math.cos(a), s = Math.sin(a), t = 1 - c;
        m[0] = t * x * x + c;     m[1] = t * x * y - s * z; m[2] = t * x * z + s * y;
        m[3] = t * x * y + s * z; m[4] = t * y * y + c;     m[5] = t * y * z - s * x;
        m[6] = t * x * z - s * y; m[7] = t * y * z + s * x; m[8] = t * z * z + c;
    }

    private static double[] rotationBetween(double[] from, double[] to) {
        double[] axis = cross(from, to);
        double s = Math.sqrt(dot(axis, axis)), c = dot(from, to);
        double[] m = new double[9];
        if (s < 1e-12) {
            if (c > 0) rotation(0, 0, 1, 0, m); else rotation(1, 0, 0, Math.PI, m);
        } else {
            rotation(axis[0], axis[1], axis[2], Math.atan2(s, c), m);
        }
        return m;
    }

    private static double[] apply(double[] m, double[] v) {
        return new double[] {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
    }

    /** IndexedLineSet ⇒ line segments (kept for the view; the tessellation walk skips lines). */
    GeometryArray indexedLineSet(VrmlNode g) {
        VrmlNode coord = g.getNode("coord");
        if (coord == null || !coord.type.name.equals("Coordinate")) return null;
        float[] pts = coord.getFloats("point");
        int[] ci = g.getInts("coordIndex");
        checkIndices(g, "coordIndex", ci, pts.length / 3, "Coordinate");
        int[] seg = new int[16];
        int n = 0;
        for (int k = 0; k + 1 < ci.length; k++) {
            if (ci[k] >= 0 && ci[k + 1] >= 0) {
                if (n + 2 > seg.length) seg = Arrays.copyOf(seg, seg.length * 2);
                seg[n++] = ci[k];
                seg[n++] = ci[k + 1];
            }
        }
        if (n == 0 || pts.length == 0) return null;
        IndexedLineArray a = new IndexedLineArray(pts.length / 3, GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE, n);
        TriGeometry.setReadCapabilities(a);
        a.setCoordRefFloat(pts);
        a.setCoordinateIndices(0, Arrays.copyOf(seg, n));
        return a;
    }

    /** PointSet ⇒ points (kept for the view; the tessellation walk skips points). */
    GeometryArray pointSet(VrmlNode g) {
        VrmlNode coord = g.getNode("coord");
        if (coord == null || !coord.type.name.equals("Coordinate")) return null;
        float[] pts = coord.getFloats("point");
        if (pts.length == 0) return null;
        PointArray a = new PointArray(pts.length / 3, GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE);
        TriGeometry.setReadCapabilities(a);
        a.setCoordRefFloat(pts);
        return a;
    }
}
