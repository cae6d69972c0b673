package org.handsim.contact;

/**
 * Euclidean projection onto a linearised friction cone: the nearest point to a 3-vector v in the
 * polyhedral cone K = {Σ λ_e e_e, λ ≥ 0} spanned by m edges e_0..e_{m−1} that go round the
 * cone's axis in order (as {@code org.handsim.grasp.FrictionCone} makes them), and which piece
 * of K it lands on — the derivative of the projection there, for Newton's method in
 * {@link ContactForces}.
 *
 * <p><b>Method.</b> The projection of v onto a closed convex cone lies in the relative interior
 * of exactly one face: the apex (0), an edge ray, a facet (the 2-D cone between consecutive
 * edges) or the interior. For each face the nearest point of its linear span is computed and
 * kept if it lies in the face; the nearest candidate is the projection (each candidate is a
 * point of K, so none is nearer than the projection, and the projection is a candidate).
 * Facet k (edges e_k, e_{k+1}) has the unit normal ν_k = (e_k × e_{k+1})/|e_k × e_{k+1}|, which
 * points into the cone for m ≥ 3; v is inside K when ν_k · v ≥ 0 for every k. With m = 2 the
 * cone is the flat wedge between its two edges; with m = 1 a ray. Cost O(m), no allocation.
 *
 * <p>A cone whose edges are parallel to rounding (μ below about 1e-16) is the ray of its first
 * edge.
 *
 * <p><b>Piece codes</b> returned by {@link #project}: −1 the apex (Π(v) = 0, derivative 0);
 * 0..m−1 edge k (derivative e eᵀ/|e|²); m..2m−1 facet k − m (derivative I − ν νᵀ); 2m the
 * interior (derivative I). On each piece Π is linear in v.
 *
 * <p>Reference: the projection onto a convex cone and its piecewise-linear structure, e.g.
 * Boyd and Vandenberghe, <i>Convex Optimization</i>, §8.1 (projection on a set) and §2.6
 * (dual cones).
 */
public final class ConeProjection {
    private ConeProjection() {}

    /** The code of the apex piece. */
    public static final int APEX = -1;

    /**
     * The unit facet normals ν_k of a cone, 3·m values into {@code out} from {@code oo} (for
     * m = 1 nothing is written; for m = 2 one normal, of the wedge's plane). A facet whose edges
     * are parallel (μ = 0) gets a zero normal and is never used.
     *
     * @param edges the m edges at {@code edges[eo .. eo + 3m)}
     */
    public static void facetNormals(double[] edges, int eo, int m, double[] out, int oo) {
        int facets = m >= 3 ? m : m == 2 ? 1 : 0;
        for (int k = 0; k < facets; k++) {
            int a = eo + 3 * k, b = eo + 3 * ((k + 1) % m);
            double sx = edges[a + 1] * edges[b + 2] - edges[a + 2] * edges[b + 1];
            double sy = edges[a + 2] * edges[b] - edges[a] * edges[b + 2];
            double sz = edges[a] * edges[b + 1] - edges[a + 1] * edges[b];
            double l = Math.sqrt(sx * sx + sy * sy + sz * sz);
            double inv = l > 0 ? 1 / l : 0;
            out[oo + 3 * k] = sx * inv;
            out[oo + 3 * k + 1] = sy * inv;
            out[oo + 3 * k + 2] = sz * inv;
        }
    }

    /**
     * Writes Π_K(v) into {@code out[oo .. oo+2]} and returns the code of its piece (above).
     *
     * @param edges   the m edges at {@code edges[eo ..]}
     * @param normals the facet normals from {@link #facetNormals} at {@code normals[no ..]}
     */
    public static int project(double[] edges, int eo, double[] normals, int no, int m,
                              double vx, double vy, double vz, double[] out, int oo) {
        int facets = m >= 3 ? m : m == 2 ? 1 : 0;
        // edges parallel to rounding (μ so small that n + μ t = n): the cone is the ray of e_0
        boolean ray = facets > 0 && normals[no] == 0 && normals[no + 1] == 0 && normals[no + 2] == 0;
        if (m >= 3 && !ray) {
            boolean inside = true;
            for (int k = 0; k < m && inside; k++) {
                int f = no + 3 * k;
                inside = normals[f] * vx + normals[f + 1] * vy + normals[f + 2] * vz >= 0;
            }
            if (inside) {
                out[oo] = vx; out[oo + 1] = vy; out[oo + 2] = vz;
                return 2 * m;
            }
        }
        double v2 = vx * vx + vy * vy + vz * vz;
        double best = v2;
        int code = APEX;
        double px = 0, py = 0, pz = 0;
        for (int k = 0; k < m; k++) {
            int e = eo + 3 * k;
            double ex = edges[e], ey = edges[e + 1], ez = edges[e + 2];
            double e2 = ex * ex + ey * ey + ez * ez;
            double t = (vx * ex + vy * ey + vz * ez) / e2;
            if (!(t > 0)) continue;
            double d2 = v2 - t * t * e2;
            if (d2 < best) {
                best = d2;
                code = k;
                px = t * ex; py = t * ey; pz = t * ez;
            }
        }
        for (int k = 0; k < facets; k++) {
            int f = no + 3 * k;
            double nx = normals[f], ny = normals[f + 1], nz = normals[f + 2];
            if (nx == 0 && ny == 0 && nz == 0) continue;
            double h = nx * vx + ny * vy + nz * vz;
            if (m >= 3 && h >= 0) continue;          // v on the inner side: this facet is not nearest
            double d2 = h * h;
            if (!(d2 < best)) continue;
            double qx = vx - h * nx, qy = vy - h * ny, qz = vz - h * nz;
            int a = eo + 3 * k, b = eo + 3 * ((k + 1) % m);
            // q between e_a and e_b: (e_a × q)·ν ≥ 0 and (q × e_b)·ν ≥ 0
            double c1 = (edges[a + 1] * qz - edges[a + 2] * qy) * nx + (edges[a + 2] * qx - edges[a] * qz) * ny
                + (edges[a] * qy - edges[a + 1] * qx) * nz;
            double c2 = (qy * edges[b + 2] - qz * edges[b + 1]) * nx + (qz * edges[b] - qx * edges[b + 2]) * ny
                + (qx * edges[b + 1] - qy * edges[b]) * nz;
            if (c1 >= 0 && c2 >= 0) {
                best = d2;
                code = m + k;
                px = qx; py = qy; pz = qz;
            }
        }
        out[oo] = px; out[oo + 1] = py; out[oo + 2] = pz;
        return code;
    }

    /**
     * Applies the derivative of the projection on piece {@code code} to the vector a: writes
     * DΠ·a into {@code out[oo .. oo+2]} (DΠ is symmetric).
     */
    public static void derivative(int code, double[] edges, int eo, double[] normals, int no, int m,
                                  double ax, double ay, double az, double[] out, int oo) {
        if (code == APEX) {
            out[oo] = 0; out[oo + 1] = 0; out[oo + 2] = 0;
        } else if (code < m) {
            int e = eo + 3 * code;
            double ex = edges[e], ey = edges[e + 1], ez = edges[e + 2];
            double t = (ax * ex + ay * ey + az * ez) / (ex * ex + ey * ey + ez * ez);
            out[oo] = t * ex; out[oo + 1] = t * ey; out[oo + 2] = t * ez;
        } else if (code < 2 * m) {
            int f = no + 3 * (code - m);
            double h = normals[f] * ax + normals[f + 1] * ay + normals[f + 2] * az;
            out[oo] = ax - h * normals[f]; out[oo + 1] = ay - h * normals[f + 1]; out[oo + 2] = az - h * normals[f + 2];
        } else {
            out[oo] = ax; out[oo + 1] = ay; out[oo + 2] = az;
        }
    }
}
