package org.handsim.collision;

/**
 * Conservative k-DOP bounds of a node of a moved tree, without touching its vertices: the
 * {@link TreeQuery.Placement#TRANSFORM} placement (DESIGN.md decision 4, "query in the link's
 * frame").
 *
 * <p><b>Idea.</b> Tree B's k-DOPs are stored in B's own frame; B is placed in A's frame by
 * x ↦ R·x + t. For a direction d of A's frame, max over B's node of d·(R·p + t) =
 * d·t + max u·p with u = Rᵀd. A k-DOP only knows max and min along its own directions eⱼ, but
 * any decomposition u = Σ cⱼ eⱼ gives the upper bound max u·p ≤ Σ cⱼ·(cⱼ &gt; 0 ? maxⱼ : minⱼ)
 * (and the matching lower bound). The decomposition depends only on R, not on the node, so it
 * is chosen once per query: u is written as a non-negative combination of the three signed
 * unit directions ±eⱼ/|eⱼ| spanning the facet of their convex hull that the ray along u
 * leaves through (the decomposition with the least total weight, which is tight when the node
 * is round; the facet of the last call is tried first, as a slowly turning link keeps it).
 * Each node then costs 6 multiply-adds per direction of A, only for the nodes the
 * walk visits (cached per query). For R = identity the decomposition is u = dᵢ itself and the
 * bounds are exact.
 *
 * <p><b>Rounding.</b> The bound must contain the projections of B's vertices as the query
 * actually transforms them (rounded) and must survive the rounding of u, of the decomposition
 * and of the sums. Each direction i gets an outward margin {@code mP_i·ρ + mT_i}, ρ = the
 * largest |coordinate| of the node in B's frame (from its axis slots); mP_i contains three
 * times the computed residual |u − Σ cⱼeⱼ|₁ plus 64ε per unit of |dᵢ|₁ and Σ|cⱼ||eⱼ|₁, mT_i
 * 64ε·|dᵢ|₁·|t|∞: a few times the error bound, about 1e-14 relative — invisible in culling.
 * The bound assumes a rigid transform (rotation entries of magnitude at most 1), as every
 * placement in HandSim is.
 *
 * <p>Not thread-safe: one instance per {@link TreeQuery}.
 */
final class TransformedBounds {
    private int m;
    private final int[] maxSlot = new int[3 * 13], minSlot = new int[3 * 13];
    private final double[] coef = new double[3 * 13], dt = new double[13];
    private final double[] marginP = new double[13], marginT = new double[13];
    private final double[] mu = new double[3];
    // the facet each direction used last time (a rotation that changes a little keeps its facets)
    private final int[] lastFacet = new int[FACET_HINTS];
    /** Length of a facet hint array ({@link #prepare(Kdop, double[], int[])}): one per direction, k ≤ 26. */
    static final int FACET_HINTS = 13;

    /** Forgets the facets of earlier calls (0s: the state of a new instance). */
    void forgetHints() {
        java.util.Arrays.fill(lastFacet, 0);
    }

    /**
     * Prepares the decomposition for placing B's k-DOPs ({@code kdop}) by the row-major
     * rigid transform {@code m12} (B's frame → A's frame).
     */
    void prepare(Kdop kdop, double[] m12) {
        prepare(kdop, m12, lastFacet);
    }

    /**
     * As {@link #prepare(Kdop, double[])}, trying first the facet each direction used in
     * {@code hints} (the facets of an earlier call for a similar rotation; −1 for none) and
     * writing back the facets used. A wrong hint costs only time: a facet is taken only if the
     * weights on it are all non-negative.
     */
    void prepare(Kdop kdop, double[] m12, int[] hints) {
        m = kdop.directionCount();
        Facets f = kdop.facets();
        double tAbs = Math.max(Math.abs(m12[3]), Math.max(Math.abs(m12[7]), Math.abs(m12[11])));
        for (int i = 0; i < m; i++) {
            double ax = kdop.dx[i], ay = kdop.dy[i], az = kdop.dz[i];
            double ux = m12[0] * ax + m12[4] * ay + m12[8] * az;
            double uy = m12[1] * ax + m12[5] * ay + m12[9] * az;
            double uz = m12[2] * ax + m12[6] * ay + m12[10] * az;
            dt[i] = ax * m12[3] + ay * m12[7] + az * m12[11];
            int h = hints[i];
            int facet = h >= 0 && h < f.count && f.weights(h, ux, uy, uz, mu) ? h : f.decompose(ux, uy, uz, mu);
            hints[i] = facet;
            double rx = ux, ry = uy, rz = uz, cw = 0;
            for (int j = 0; j < 3; j++) {
                int sd = f.tri[3 * facet + j];        // signed direction: 2*dir + (negative ? 1 : 0)
                int dir = sd >> 1;
                double c = (sd & 1) == 0 ? mu[j] : -mu[j];  // coefficient of +e_dir
                coef[3 * i + j] = c;
                maxSlot[3 * i + j] = c > 0 ? 2 * dir + 1 : 2 * dir;
                minSlot[3 * i + j] = c > 0 ? 2 * dir : 2 * dir + 1;
                rx -= c * kdop.dx[dir];
                ry -= c * kdop.dy[dir];
                rz -= c * kdop.dz[dir];
                cw += Math.abs(c) * (Math.abs(kdop.dx[dir]) + Math.abs(kdop.dy[dir]) + Math.abs(kdop.dz[dir]));
            }
            double d1 = Math.abs(ax) + Math.abs(ay) + Math.abs(az);
            marginP[i] = 3 * (Math.abs(rx) + Math.abs(ry) + Math.abs(rz)) + 64 * Predicates.EPSILON * (3 * d1 + cw);
            marginT[i] = 64 * Predicates.EPSILON * d1 * tAbs;
        }
    }

    /** Writes the placed bounds of the k-DOP at {@code src[so..]} (B's frame) to {@code dst[dof..]} (A's frame). */
    void apply(double[] src, int so, double[] dst, int dof) {
        double rho = Math.max(Math.max(Math.max(-src[so], src[so + 1]), Math.max(-src[so + 2], src[so + 3])),
            Math.max(-src[so + 4], src[so + 5]));
        rho = Math.max(rho, 0);
        for (int i = 0, c = 0; i < m; i++, c += 3) {
            double c0 = coef[c], c1 = coef[c + 1], c2 = coef[c + 2];
            double hi = dt[i] + c0 * src[so + maxSlot[c]] + c1 * src[so + maxSlot[c + 1]] + c2 * src[so + maxSlot[c + 2]];
            double lo = dt[i] + c0 * src[so + minSlot[c]] + c1 * src[so + minSlot[c + 1]] + c2 * src[so + minSlot[c + 2]];
            double mg = marginP[i] * rho + marginT[i];
            dst[dof + 2 * i] = lo - mg;
            dst[dof + 2 * i + 1] = hi + mg;
        }
    }

    /**
     * {@link #apply} for two k-DOPs at once ({@code src[s1..]} to {@code dst[d1..]} and
     * {@code src[s2..]} to {@code dst[d2..]}), bit-identical to two calls: the tree walk places
     * both children of a node together, and the decomposition's slots and weights are then
     * read once for the two.
     */
    void apply2(double[] src, int s1, int s2, double[] dst, int d1, int d2) {
        double rho1 = Math.max(Math.max(Math.max(-src[s1], src[s1 + 1]), Math.max(-src[s1 + 2], src[s1 + 3])),
            Math.max(-src[s1 + 4], src[s1 + 5]));
        double rho2 = Math.max(Math.max(Math.max(-src[s2], src[s2 + 1]), Math.max(-src[s2 + 2], src[s2 + 3])),
            Math.max(-src[s2 + 4], src[s2 + 5]));
        rho1 = Math.max(rho1, 0);
        rho2 = Math.max(rho2, 0);
        final double[] cf = coef, dti = dt, mp = marginP, mt = marginT;
        final int[] hiS = maxSlot, loS = minSlot;
        for (int i = 0, c = 0; i < m; i++, c += 3) {
            double c0 = cf[c], c1 = cf[c + 1], c2 = cf[c + 2], t = dti[i], mpi = mp[i], mti = mt[i];
            int h0 = hiS[c], h1 = hiS[c + 1], h2 = hiS[c + 2], l0 = loS[c], l1 = loS[c + 1], l2 = loS[c + 2];
            double hi1 = t + c0 * src[s1 + h0] + c1 * src[s1 + h1] + c2 * src[s1 + h2];
            double lo1 = t + c0 * src[s1 + l0] + c1 * src[s1 + l1] + c2 * src[s1 + l2];
            double hi2 = t + c0 * src[s2 + h0] + c1 * src[s2 + h1] + c2 * src[s2 + h2];
            double lo2 = t + c0 * src[s2 + l0] + c1 * src[s2 + l1] + c2 * src[s2 + l2];
            double mg1 = mpi * rho1 + mti, mg2 = mpi * rho2 + mti;
            dst[d1 + 2 * i] = lo1 - mg1;
            dst[d1 + 2 * i + 1] = hi1 + mg1;
            dst[d2 + 2 * i] = lo2 - mg2;
            dst[d2 + 2 * i + 1] = hi2 + mg2;
        }
    }

    /**
     * The facets of the convex hull of the signed unit directions ±eⱼ/|eⱼ| of one direction
     * set, each with the inverse of the 3×3 matrix of its (unnormalised, signed) directions.
     * Built once per k by trying every triple (at most 26·25·24/6 = 2 600).
     */
    static final class Facets {
        final int count;
        final int[] tri;          // 3 signed directions per facet
        final double[] plane;     // outward normal scaled so that normal·vertex = 1
        final double[] inv;       // 9 per facet: inverse of [e_a e_b e_c] (columns), row-major

        Facets(double[] dx, double[] dy, double[] dz) {
            int n = 2 * dx.length;
            double[] ux = new double[n], uy = new double[n], uz = new double[n];
            double[] ex = new double[n], ey = new double[n], ez = new double[n];
            for (int i = 0; i < n; i++) {
                int d = i >> 1;
                double s = (i & 1) == 0 ? 1 : -1;
                ex[i] = s * dx[d];
                ey[i] = s * dy[d];
                ez[i] = s * dz[d];
                double len = Math.sqrt(ex[i] * ex[i] + ey[i] * ey[i] + ez[i] * ez[i]);
                ux[i] = ex[i] / len;
                uy[i] = ey[i] / len;
                uz[i] = ez[i] / len;
            }
            int[] t = new int[3 * n * n];
            double[] pl = new double[3 * n * n];
            double[] iv = new double[9 * n * n];
            int c = 0;
            for (int a = 0; a < n; a++) {
                for (int b = a + 1; b < n; b++) {
                    for (int e = b + 1; e < n; e++) {
                        double bx = ux[b] - ux[a], by = uy[b] - uy[a], bz = uz[b] - uz[a];
                        double cx = ux[e] - ux[a], cy = uy[e] - uy[a], cz = uz[e] - uz[a];
                        double nx = by * cz - bz * cy, ny = bz * cx - bx * cz, nz = bx * cy - by * cx;
                        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
                        if (len < 1e-9) continue;
                        nx /= len; ny /= len; nz /= len;
                        double off = nx * ux[a] + ny * uy[a] + nz * uz[a];
                        if (Math.abs(off) < 1e-9) continue;  // plane through the origin
                        if (off < 0) { nx = -nx; ny = -ny; nz = -nz; off = -off; }
                        boolean hull = true;
                        for (int o = 0; o < n && hull; o++) {
                            if (nx * ux[o] + ny * uy[o] + nz * uz[o] > off + 1e-9) hull = false;
                        }
                        if (!hull) continue;
                        // inverse of the matrix with columns e_a, e_b, e_e
                        double m00 = ex[a], m01 = ex[b], m02 = ex[e];
                        double m10 = ey[a], m11 = ey[b], m12 = ey[e];
                        double m20 = ez[a], m21 = ez[b], m22 = ez[e];
                        double det = m00 * (m11 * m22 - m12 * m21) - m01 * (m10 * m22 - m12 * m20) + m02 * (m10 * m21 - m11 * m20);
                        if (Math.abs(det) < 1e-12) continue;
                        t[3 * c] = a; t[3 * c + 1] = b; t[3 * c + 2] = e;
                        pl[3 * c] = nx / off; pl[3 * c + 1] = ny / off; pl[3 * c + 2] = nz / off;
                        int o9 = 9 * c;
                        iv[o9] = (m11 * m22 - m12 * m21) / det;
                        iv[o9 + 1] = (m02 * m21 - m01 * m22) / det;
                        iv[o9 + 2] = (m01 * m12 - m02 * m11) / det;
                        iv[o9 + 3] = (m12 * m20 - m10 * m22) / det;
                        iv[o9 + 4] = (m00 * m22 - m02 * m20) / det;
                        iv[o9 + 5] = (m02 * m10 - m00 * m12) / det;
                        iv[o9 + 6] = (m10 * m21 - m11 * m20) / det;
                        iv[o9 + 7] = (m01 * m20 - m00 * m21) / det;
                        iv[o9 + 8] = (m00 * m11 - m01 * m10) / det;
                        c++;
                    }
                }
            }
            count = c;
            tri = java.util.Arrays.copyOf(t, 3 * c);
            plane = java.util.Arrays.copyOf(pl, 3 * c);
            inv = java.util.Arrays.copyOf(iv, 9 * c);
        }

        /**
         * Writes u's weights on facet f's three directions into {@code out}; true if none is
         * negative, i.e. the ray along u leaves the hull through f (the answer of
         * {@link #decompose}, up to a tie on a shared edge, where either facet is exact).
         */
        boolean weights(int f, double x, double y, double z, double[] out) {
            int o = 9 * f;
            double a = inv[o] * x + inv[o + 1] * y + inv[o + 2] * z;
            double b = inv[o + 3] * x + inv[o + 4] * y + inv[o + 5] * z;
            double c = inv[o + 6] * x + inv[o + 7] * y + inv[o + 8] * z;
            out[0] = a; out[1] = b; out[2] = c;
            return a >= 0 && b >= 0 && c >= 0;
        }

        /**
         * Writes the non-negative weights of u on the facet the ray along u leaves the hull
         * through into {@code out}; returns the facet.
         */
        int decompose(double x, double y, double z, double[] out) {
            double best = Double.NEGATIVE_INFINITY;
            for (int f = 0; f < count; f++) {
                double s = plane[3 * f] * x + plane[3 * f + 1] * y + plane[3 * f + 2] * z;
                if (s > best) best = s;
            }
            double len = Math.abs(x) + Math.abs(y) + Math.abs(z);
            double tol = 1e-9 * len;
            int chosen = -1;
            double chosenMin = Double.NEGATIVE_INFINITY;
            for (int f = 0; f < count; f++) {
                double s = plane[3 * f] * x + plane[3 * f + 1] * y + plane[3 * f + 2] * z;
                if (s < best - tol) continue;
                int o = 9 * f;
                double a = inv[o] * x + inv[o + 1] * y + inv[o + 2] * z;
                double b = inv[o + 3] * x + inv[o + 4] * y + inv[o + 5] * z;
                double c = inv[o + 6] * x + inv[o + 7] * y + inv[o + 8] * z;
                double mn = Math.min(a, Math.min(b, c));
                if (mn > chosenMin) {
                    chosenMin = mn;
                    chosen = f;
                    out[0] = a; out[1] = b; out[2] = c;
                    if (mn >= 0) break;
                }
            }
            // Tiny negative weights (u on a facet edge) are harmless: the bound uses signed
            // coefficients and the residual margin covers the rounding.
            return chosen;
        }
    }
}
