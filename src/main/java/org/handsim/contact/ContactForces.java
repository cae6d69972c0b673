package org.handsim.contact;

/**
 * Contact force magnitudes from joint torques: the paper's eq (11) made well-posed (DESIGN.md
 * decision 2), and the torque a set of contact forces puts on a joint, eq (9).
 *
 * <p><b>Why not eq (11) as printed.</b> Eq (11) inverts the cross-product matrix
 * [p_c − p_km]×, which is singular (rank 2) for every p. A frictionless point contact i at
 * p_i pushing the object along the unit direction d_i with magnitude f_i ≥ 0 needs, by virtual
 * work, the joint torques τ_m = Σ_i a_mi f_i with moment arms
 * <pre>  a_mi = (z_{m−1} × (p_i − o_{m−1})) · d_i   for joints m ≤ link(i), else 0,</pre>
 * z_{m−1}, o_{m−1} the axis and origin of joint m (frame {k(m−1)}). Given the joint torques the
 * contacts must carry, {@link #solve} finds f ≥ 0 minimising |A f − τ| (Lawson–Hanson
 * non-negative least squares, exact for these small systems). A contact whose moment arms are
 * all below {@link #MIN_ARM_M} (its force line passes through every joint axis) cannot be
 * weighed by joint torques: it is reported as <em>undetermined</em> with f = 0, never divided
 * by ~0.
 *
 * <p>Frames: points, directions and the 48-value frame array ({k0}..{k3}, 12 row-major values
 * each, as {@code FingerKinematics.frames}) must all be in one frame (palm or world).
 *
 * <p>Not thread-safe: one instance per model (it keeps its scratch arrays).
 */
public final class ContactForces {
    /**
     * Moment arms (metres) below this count as zero: 0.5 mm. The arm of a contact is only as
     * good as its normal and position, and at the default tessellation those are good to about
     * 1–2° and 0.5 mm (docs/BENCHMARKS.md, chart 2-tessellation): at a 30 mm lever that is an
     * uncertainty of about 0.5–1 mm in the arm, so a smaller arm does not determine the force
     * (f = τ/a would be more than 100 % uncertain, and grow without bound — thousands of newtons
     * for τ_break — as a → 0). Such a contact is reported undetermined with f = 0.
     */
    public static final double MIN_ARM_M = 5e-4;
    private static final int MAX_ITER = 100;

    private double[] arms = new double[0];      // 3 per contact: a_1i, a_2i, a_3i
    private double[] mag = new double[0];
    private boolean[] undetermined = new boolean[0];
    private boolean[] passive = new boolean[0];
    private double[] z = new double[0];
    private int[] idxScratch = new int[0];
    private double[] gScratch = new double[0], bScratch = new double[0], yScratch = new double[0];
    private boolean[] deadScratch = new boolean[0];
    private final double[] res = new double[3];   // τ − A f per joint, in nnls
    private int count;
    private double residual;

    /**
     * Solves for the contact magnitudes.
     *
     * @param frames     48 values: frames {k0}..{k3} (joint m turns about z of frame m−1)
     * @param firstJoint 0-based index of the first joint whose torque is known (joints before
     *                   it are not used: e.g. 1 for the flexion joints only)
     * @param tau        torques the contacts must balance on joints 1..3 (N·m); entries below
     *                   {@code firstJoint} are ignored
     * @param n          number of contacts
     * @param points     3·n contact points (metres)
     * @param dirs       3·n unit directions of the force applied to the object
     * @param links      n link numbers 1..3 (the link each contact is on)
     */
    public void solve(double[] frames, int firstJoint, double[] tau, int n, double[] points, double[] dirs, int[] links) {
        ensure(n);
        count = n;
        for (int i = 0; i < n; i++) {
            double norm2 = 0;
            for (int m = 0; m < 3; m++) {
                double a = 0;
                if (m >= firstJoint && m < links[i]) a = arm(frames, m, points, dirs, i);
                arms[3 * i + m] = a;
                norm2 += a * a;
            }
            undetermined[i] = Math.sqrt(norm2) < MIN_ARM_M;
            mag[i] = 0;
        }
        nnls(firstJoint, tau, n);
        residual = 0;
        for (int m = firstJoint; m < 3; m++) {
            double r = -tau[m];
            for (int i = 0; i < n; i++) r += arms[3 * i + m] * mag[i];
            residual += r * r;
        }
        residual = Math.sqrt(residual);
    }

    /** a = (z_m × (p − o_m)) · d for the joint turning about frame m's z axis. */
    private static double arm(double[] f, int m, double[] p, double[] d, int i) {
        int o = 12 * m;
        double zx = f[o + 2], zy = f[o + 6], zz = f[o + 10];
        double rx = p[3 * i] - f[o + 3], ry = p[3 * i + 1] - f[o + 7], rz = p[3 * i + 2] - f[o + 11];
        double cx = zy * rz - zz * ry, cy = zz * rx - zx * rz, cz = zx * ry - zy * rx;
        return cx * d[3 * i] + cy * d[3 * i + 1] + cz * d[3 * i + 2];
    }

    /**
     * Eq (9) for a frictionless contact: the torque on the joint turning about frame m's z axis
     * from a force f·d at p, {@code (ẑ_m × (p − o_m))ᵀ (f d)} (the n_c term is zero).
     */
    public static double jointTorque(double[] frames, int m, double[] point, double[] dir, double f) {
        return arm(frames, m, point, dir, 0) * f;
    }

    /** Lawson–Hanson NNLS on the rows firstJoint..2 and the determined columns. */
    private void nnls(int r0, double[] tau, int n) {
        for (int i = 0; i < n; i++) passive[i] = false;
        for (int iter = 0; iter < MAX_ITER; iter++) {
            // gradient w = Aᵀ (τ − A f), the residual τ − A f computed once
            for (int m = r0; m < 3; m++) {
                double r = tau[m];
                for (int j = 0; j < n; j++) r -= arms[3 * j + m] * mag[j];
                res[m] = r;
            }
            int best = -1;
            double bestW = 1e-15;
            for (int i = 0; i < n; i++) {
                if (passive[i] || undetermined[i]) continue;
                double g = 0;
                for (int m = r0; m < 3; m++) g += arms[3 * i + m] * res[m];
                if (g > bestW) { bestW = g; best = i; }
            }
            if (best < 0) return;
            passive[best] = true;
            while (true) {
                if (!leastSquaresOnPassive(r0, tau, n)) { passive[best] = false; return; }
                double alpha = 1;
                boolean feasible = true;
                for (int i = 0; i < n; i++) {
                    if (passive[i] && z[i] <= 0) {
                        feasible = false;
                        double a = mag[i] / (mag[i] - z[i]);
                        if (a < alpha) alpha = a;
                    }
                }
                if (feasible) {
                    for (int i = 0; i < n; i++) mag[i] = passive[i] ? z[i] : 0;
                    break;
                }
                for (int i = 0; i < n; i++) {
                    if (passive[i]) {
                        mag[i] += alpha * (z[i] - mag[i]);
                        if (mag[i] <= 1e-15) { mag[i] = 0; passive[i] = false; }
                    }
                }
            }
        }
    }

    /**
     * Unconstrained least squares on the passive columns into z (normal equations, at most a
     * handful of columns; a rank-deficient set is regularised by dropping dependent columns).
     */
    private boolean leastSquaresOnPassive(int r0, double[] tau, int n) {
        int p = 0;
        int[] idx = idxScratch;
        for (int i = 0; i < n; i++) if (passive[i]) idx[p++] = i;
        double[] g = gScratch, b = bScratch;
        for (int a = 0; a < p; a++) {
            for (int c = 0; c < p; c++) {
                double s = 0;
                for (int m = r0; m < 3; m++) s += arms[3 * idx[a] + m] * arms[3 * idx[c] + m];
                g[a * p + c] = s;
            }
            double s = 0;
            for (int m = r0; m < 3; m++) s += arms[3 * idx[a] + m] * tau[m];
            b[a] = s;
        }
        // Cholesky with pivot check: a column dependent on earlier ones gets zero weight
        double scale = 0;
        for (int a = 0; a < p; a++) scale = Math.max(scale, g[a * p + a]);
        boolean[] dead = deadScratch;
        java.util.Arrays.fill(dead, 0, p, false);
        for (int j = 0; j < p; j++) {
            double d = g[j * p + j];
            for (int k = 0; k < j; k++) if (!dead[k]) d -= g[j * p + k] * g[j * p + k];
            if (d <= 1e-12 * scale) { dead[j] = true; g[j * p + j] = 1; continue; }
            double l = Math.sqrt(d);
            g[j * p + j] = l;
            for (int i = j + 1; i < p; i++) {
                double s = g[i * p + j];
                for (int k = 0; k < j; k++) if (!dead[k]) s -= g[i * p + k] * g[j * p + k];
                g[i * p + j] = s / l;
            }
        }
        double[] y = yScratch;
        for (int i = 0; i < p; i++) {
            if (dead[i]) { y[i] = 0; continue; }
            double s = b[i];
            for (int k = 0; k < i; k++) if (!dead[k]) s -= g[i * p + k] * y[k];
            y[i] = s / g[i * p + i];
        }
        for (int i = p - 1; i >= 0; i--) {
            if (dead[i]) { y[i] = 0; continue; }
            double s = y[i];
            for (int k = i + 1; k < p; k++) if (!dead[k]) s -= g[k * p + i] * y[k];
            y[i] = s / g[i * p + i];
        }
        for (int i = 0; i < n; i++) z[i] = 0;
        for (int a = 0; a < p; a++) z[idx[a]] = y[a];
        return true;
    }

    private void ensure(int n) {
        if (mag.length < n) {
            int c = Math.max(n, 2 * mag.length);
            arms = new double[3 * c];
            mag = new double[c];
            undetermined = new boolean[c];
            passive = new boolean[c];
            z = new double[c];
            idxScratch = new int[c];
            gScratch = new double[c * c];
            bScratch = new double[c];
            yScratch = new double[c];
            deadScratch = new boolean[c];
        }
    }

    /** @return the number of contacts of the last solve */
    public int count() { return count; }

    /** @return magnitude f_i ≥ 0 of contact i (newtons) */
    public double force(int i) { return mag[i]; }

    /** @return true if contact i's moment arms are all ~0 (its force is not determined) */
    public boolean undetermined(int i) { return undetermined[i]; }

    /** @return moment arm a_mi of contact i about joint m (0-based), metres */
    public double arm(int i, int m) { return arms[3 * i + m]; }

    /** @return |A f − τ| of the last solve (N·m): nonzero when the contacts cannot carry τ */
    public double residual() { return residual; }
}
