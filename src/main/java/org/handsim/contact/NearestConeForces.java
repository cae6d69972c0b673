package org.handsim.contact;

import org.handsim.math.Cholesky;

/**
 * The mechanism's forces ({@link ContactForces}, class comment) solved in the primal, exactly:
 * <pre>  minimise ½ Σ_i |f_i − f⁰_i|²  subject to  Σ_i t_mi · f_i = τ_m (m driven),  f_i ∈ K_i,</pre>
 * by a primal active-set method (Nocedal and Wright, <i>Numerical Optimization</i>, 2nd ed.,
 * Algorithm 16.3) started from forces that already carry the torques and lie in the cones.
 *
 * <p><b>Why, beside Newton's method on the dual.</b> When the torques lie on the boundary of what
 * the cones can carry — a driven joint whose torque only a contact at its cone's apex or on one
 * of its faces gives, e.g. τk3 = 0 with every outer contact pressing k3 closed — the dual's
 * minimum is not attained (its multiplier runs off to infinity) and Newton carries the torques
 * only to 1e-9–1e-8 of |τ|. The edge forces of non-negative least squares carry them exactly but
 * are one basic solution of many, blind to the locked loads; this program starts from them and
 * ends at the unique minimiser (the objective is strictly convex in f), still carrying the
 * torques to rounding, since every step stays in the null space of the torque rows.
 *
 * <p><b>Constraints.</b> Each contact's cone in the form the active set needs: a cone of m ≥ 3
 * edges by its facets' inward normals, ν_k · f ≥ 0; a wedge (m = 2) by its plane's normal,
 * ν · f = 0, and the two in-plane normals pointing inwards from its edges; a ray (m = 1, or edges
 * parallel to rounding, as {@link ConeProjection} treats them) by two equalities across it and
 * e · f ≥ 0. Every row is scaled to unit length; the working set keeps only rows independent to
 * {@link Cholesky#PIVOT_TOLERANCE} of the Gram matrix's diagonal (a contact at its apex is pinned by three of
 * its m facets).
 *
 * <p>Not thread-safe; allocates only when a problem is larger than every earlier one.
 */
final class NearestConeForces {
    private static final int EQ = 0, GE = 1;
    /** Iterations allowed per constraint row (each adds or drops one). */
    private static final int ITERATIONS_PER_ROW = 4;

    private int vars, rowCount;
    private double[] rows = new double[0];      // rowCount × vars, unit rows
    private int[] kind = new int[0];
    private boolean[] working = new boolean[0];
    private boolean[] dependent = new boolean[0];  // in the working set's span (to rounding): cannot block
    private int[] ws = new int[0];              // the working set's rows, in order
    private double[] gram = new double[0], mult = new double[0];
    private double[] x = new double[0], target = new double[0], p = new double[0];
    private int[] contactOf = new int[0];       // variable block k → contact index

    /**
     * Moves {@code f} (3 per contact; the determined contacts' forces carry the driven torques
     * and lie in their cones) to the minimiser above; undetermined contacts are left as they are.
     *
     * @param n       contacts
     * @param skip    contacts not in the program (undetermined: they keep their forces)
     * @param tvec    9 per contact: t_mi of joints 0..2 (ContactForces' layout)
     * @param joint   the driven joints whose rows are carried, {@code joint[0 .. d)}
     * @param cones   m edges per contact; {@code normals} their facet normals (ConeProjection)
     * @param ref     the locked forces f⁰, 3 per contact
     * @return true when the optimality conditions hold at the end (else {@code f} is left at the
     *         last iterate, which still carries the torques and lies in the cones)
     */
    boolean solve(int n, boolean[] skip, double[] tvec, int[] joint, int d, double[] cones, double[] normals, int m,
                  double[] ref, double[] f) {
        int blocks = 0;
        for (int i = 0; i < n; i++) if (!skip[i]) blocks++;
        vars = 3 * blocks;
        int maxRows = d + blocks * Math.max(m, 3);
        ensure(blocks, maxRows);
        int k = 0;
        for (int i = 0; i < n; i++) {
            if (skip[i]) continue;
            contactOf[k] = i;
            for (int c = 0; c < 3; c++) { x[3 * k + c] = f[3 * i + c]; target[3 * k + c] = ref[3 * i + c]; }
            k++;
        }
        rowCount = 0;
        for (int a = 0; a < d; a++) {
            int r = newRow(EQ);
            for (int b = 0; b < blocks; b++) {
                int o = 9 * contactOf[b] + 3 * joint[a];
                for (int c = 0; c < 3; c++) rows[r * vars + 3 * b + c] = tvec[o + c];
            }
            if (!normalise(r)) rowCount--;
        }
        for (int b = 0; b < blocks; b++) coneRows(b, cones, normals, m, 3 * m * contactOf[b]);

        double scale = 0;
        for (int v = 0; v < vars; v++) scale = Math.max(scale, Math.max(Math.abs(x[v]), Math.abs(target[v])));
        double tol = 1e-12 * (scale + Double.MIN_NORMAL);
        int w = 0;
        for (int r = 0; r < rowCount; r++) {
            working[r] = false;
            dependent[r] = false;
            if (kind[r] == EQ || dot(r, x) <= tol) {
                ws[w] = r;
                if (factor(w + 1)) { working[r] = true; w++; }
            }
        }
        boolean optimal = false;
        for (int it = 0; it < ITERATIONS_PER_ROW * (rowCount + 1); it++) {
            // p: the step to the nearest point of the working set's null space
            double rMax = 0;
            for (int v = 0; v < vars; v++) { p[v] = target[v] - x[v]; rMax = Math.max(rMax, Math.abs(p[v])); }
            if (w > 0) {
                if (!factor(w)) break;
                for (int a = 0; a < w; a++) mult[a] = dot(ws[a], p);
                Cholesky.solve(gram, w, mult);
                for (int a = 0; a < w; a++) {
                    int r = ws[a];
                    for (int v = 0; v < vars; v++) p[v] -= mult[a] * rows[r * vars + v];
                }
            }
            double pMax = 0;
            if (w < vars) for (int v = 0; v < vars; v++) pMax = Math.max(pMax, Math.abs(p[v]));
            // p is the difference of r = f⁰ − x and its projection: zero to that subtraction's rounding
            if (pMax <= tol + 1e-10 * rMax) {
                // at the working set's minimum: x − f⁰ = −Σ μ_r g_r, so a row g·f ≥ 0 holds it with −μ_r ≥ 0
                int drop = -1;
                double worst = tol;
                for (int a = 0; a < w; a++) {
                    if (kind[ws[a]] == GE && mult[a] > worst) { worst = mult[a]; drop = a; }
                }
                if (drop < 0) { optimal = true; break; }
                working[ws[drop]] = false;
                for (int a = drop; a < w - 1; a++) ws[a] = ws[a + 1];
                w--;
                java.util.Arrays.fill(dependent, 0, rowCount, false);
                continue;
            }
            double alpha = 1;
            int block = -1;
            for (int r = 0; r < rowCount; r++) {
                if (working[r] || dependent[r] || kind[r] != GE) continue;
                double gp = dot(r, p);
                if (!(gp < -1e-14 * pMax)) continue;
                double al = Math.max(0, dot(r, x)) / -gp;
                if (al < alpha) { alpha = al; block = r; }
            }
            for (int v = 0; v < vars; v++) x[v] += alpha * p[v];
            if (block >= 0) {
                ws[w] = block;
                if (factor(w + 1)) {
                    working[block] = true;
                    w++;
                    java.util.Arrays.fill(dependent, 0, rowCount, false);
                } else {
                    // a combination of the working rows, which the step keeps at 0: its g · p < 0 is rounding
                    dependent[block] = true;
                }
            }
        }
        for (int b = 0; b < blocks; b++) {
            int i = contactOf[b];
            for (int c = 0; c < 3; c++) f[3 * i + c] = x[3 * b + c];
        }
        return optimal;
    }

    /** The cone rows of variable block b (class comment). */
    private void coneRows(int b, double[] cones, double[] normals, int m, int eo) {
        int facets = m >= 3 ? m : m == 2 ? 1 : 0;
        boolean ray = facets == 0 || (normals[eo] == 0 && normals[eo + 1] == 0 && normals[eo + 2] == 0);
        if (ray) {
            double ex = cones[eo], ey = cones[eo + 1], ez = cones[eo + 2];
            // two directions across the ray: e × (the axis e is least along), then e × that
            double ax = Math.abs(ex), ay = Math.abs(ey), az = Math.abs(ez);
            double ux, uy, uz;
            if (ax <= ay && ax <= az) { ux = 0; uy = ez; uz = -ey; }
            else if (ay <= az) { ux = -ez; uy = 0; uz = ex; }
            else { ux = ey; uy = -ex; uz = 0; }
            coneRow(b, EQ, ux, uy, uz);
            coneRow(b, EQ, ey * uz - ez * uy, ez * ux - ex * uz, ex * uy - ey * ux);
            coneRow(b, GE, ex, ey, ez);
        } else if (m == 2) {
            double nx = normals[eo], ny = normals[eo + 1], nz = normals[eo + 2];
            int e0 = eo, e1 = eo + 3;
            coneRow(b, EQ, nx, ny, nz);
            // ν × e0 points from e0 towards e1, e1 × ν from e1 towards e0
            coneRow(b, GE, ny * cones[e0 + 2] - nz * cones[e0 + 1], nz * cones[e0] - nx * cones[e0 + 2], nx * cones[e0 + 1] - ny * cones[e0]);
            coneRow(b, GE, cones[e1 + 1] * nz - cones[e1 + 2] * ny, cones[e1 + 2] * nx - cones[e1] * nz, cones[e1] * ny - cones[e1 + 1] * nx);
        } else {
            for (int k = 0; k < m; k++) {
                int o = eo + 3 * k;
                if (normals[o] == 0 && normals[o + 1] == 0 && normals[o + 2] == 0) continue;
                coneRow(b, GE, normals[o], normals[o + 1], normals[o + 2]);
            }
        }
    }

    private void coneRow(int b, int type, double gx, double gy, double gz) {
        int r = newRow(type);
        rows[r * vars + 3 * b] = gx;
        rows[r * vars + 3 * b + 1] = gy;
        rows[r * vars + 3 * b + 2] = gz;
        if (!normalise(r)) rowCount--;
    }

    private int newRow(int type) {
        int r = rowCount++;
        kind[r] = type;
        java.util.Arrays.fill(rows, r * vars, (r + 1) * vars, 0);
        return r;
    }

    private boolean normalise(int r) {
        double s = 0;
        for (int v = 0; v < vars; v++) s += rows[r * vars + v] * rows[r * vars + v];
        if (!(s > 0)) return false;
        double inv = 1 / Math.sqrt(s);
        for (int v = 0; v < vars; v++) rows[r * vars + v] *= inv;
        return true;
    }

    private double dot(int r, double[] z) {
        double s = 0;
        for (int v = 0; v < vars; v++) s += rows[r * vars + v] * z[v];
        return s;
    }

    /** The Gram matrix of the first w working rows, factorised; false if they are dependent. */
    private boolean factor(int w) {
        for (int a = 0; a < w; a++) {
            for (int c = 0; c <= a; c++) {
                double s = 0;
                int ra = ws[a] * vars, rc = ws[c] * vars;
                for (int v = 0; v < vars; v++) s += rows[ra + v] * rows[rc + v];
                gram[a * w + c] = s;
                gram[c * w + a] = s;
            }
        }
        return Cholesky.decompose(gram, w);
    }

    private void ensure(int blocks, int maxRows) {
        int v = 3 * blocks;
        if (x.length < v) {
            x = new double[v];
            target = new double[v];
            p = new double[v];
            contactOf = new int[blocks];
        }
        if (rows.length < maxRows * v) rows = new double[maxRows * v];
        if (kind.length < maxRows) {
            kind = new int[maxRows];
            working = new boolean[maxRows];
            dependent = new boolean[maxRows];
            ws = new int[maxRows];
            mult = new double[maxRows];
        }
        if (gram.length < maxRows * maxRows) gram = new double[maxRows * maxRows];
    }
}
