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
 * <p><b>With Coulomb friction</b> ({@link #solveWithFriction}, DESIGN.md "Contact forces with
 * friction") a contact force f_i is any vector in contact i's linearised friction cone K_i (its
 * edges given by the caller, {@code org.handsim.grasp.FrictionCone}), and joint m feels
 * τ_m = Σ_i t_mi · f_i with t_mi = z_{m−1} × (p_i − o_{m−1}) (eq 9 with the force's full
 * direction). Eq (11) then has many solutions; HandSim reports the <em>least-norm</em> one,
 * <pre>  minimise Σ |f_i|²  subject to  Σ_i t_mi · f_i = τ_m,  f_i ∈ K_i,</pre>
 * (if no forces in the cones carry τ exactly: the least-norm forces of the least-squares
 * torque). By duality its solution is f_i = Π_{K_i}(Σ_m y_m t_mi), the projection onto the cone
 * ({@link ConeProjection}) of the displacement a small joint rotation y imposes at the contact:
 * the forces of equal isotropic contact springs the held links press into the object where they
 * stick, turned onto the cone's boundary (sliding, Coulomb's maximal dissipation) where that
 * displacement leaves the cone. For a single contact that is f along t (the direction the
 * link moves) when t lies in the cone, else on the cone edge nearest t. The 1–3 multipliers y
 * are found by Newton's method on the dual (a smooth concave function, piecewise quadratic),
 * regularised by {@link #RHO} times the largest |t|² so that its steps stay finite, then
 * polished on the final pieces to satisfy the torques exactly. Torques the cones cannot carry
 * get the least-squares torque — the one nearest τ that forces in the cones carry, found by
 * non-negative least squares on the cone edges — and the least-norm forces carrying it
 * ({@link #leastSquaresTorque}). μ = 0 is the frictionless {@link #solve} (the cones are
 * rays), which callers use then: its forces are today's.
 *
 * <p><b>A held joint</b> ({@link #solveHeld}): a joint whose torque is not set by the drive but
 * is the reaction of what holds it (the BarrettHand's inner joint, held by its self-locking
 * worm after a breakaway) is free within [lo, hi]; the others are carried exactly. Either way
 * {@link #residual()} says how far the forces are from doing that — nonzero when no forces in
 * the cones can (the finger has no static equilibrium in that state).
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
    /**
     * Regularisation of the friction solve, relative to the largest |t_mi|² (m²): the torque
     * residual it leaves before the polish is about 1e-10 of the torque; its role is to keep
     * Newton's steps finite when some torque is beyond what the cones can carry.
     */
    public static final double RHO = 1e-10;
    private static final int NEWTON_ITER = 60;
    /** Torques carried to this fraction of |τ| count as carried exactly (the polish gives ~1e-16). */
    private static final double EXACT = 1e-9;

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
    // with friction: torque directions t_mi (9 per contact), force vectors, cone pieces, facet normals
    private boolean friction;
    private int edgesPerCone;
    private double[] tvec = new double[0], fvec = new double[0], dirCopy = new double[0], facetNormals = new double[0];
    private double[] fTrial = new double[0];
    private int[] piece = new int[0], pieceTrial = new int[0];
    private final int[] joint = new int[3];          // active dual rows: joint indices
    private final double[] y = new double[3], yTrial = new double[3], g = new double[3], step = new double[3];
    private final double[] hess = new double[9], tauActive = new double[3], pa = new double[3];
    private double rho, t2Max;                       // ρ and the largest |t_mi|² of the last friction solve
    private int activeCount;                         // d of the last friction solve
    private int lastN = -1, lastM, lastD;            // what the pieces in piece[] belong to (warm start)
    private final int[] lastJoint = new int[3];
    // the least-squares torque when no cone forces carry τ: one column per cone edge
    private double[] edgeArms = new double[0], edgeWeight = new double[0], edgeZ = new double[0];
    private boolean[] edgePassive = new boolean[0], edgeSkip = new boolean[0];
    private final double[] tauStar = new double[3];
    // a held joint (solveHeld): the torques of the solve, the reaction, scratch
    private final double[] tauHeld = new double[3];
    private double held = Double.NaN;

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
        friction = false;
        held = Double.NaN;
        System.arraycopy(dirs, 0, dirCopy, 0, 3 * n);
        for (int i = 0; i < n; i++) {
            double norm2 = 0;
            for (int m = 0; m < 3; m++) {
                // every joint of the contact's chain (jointTorque reports them all); the solve uses firstJoint..2
                double a = 0;
                if (m < links[i]) a = arm(frames, m, points, dirs, i);
                arms[3 * i + m] = a;
                if (m >= firstJoint) norm2 += a * a;
            }
            undetermined[i] = Math.sqrt(norm2) < MIN_ARM_M;
            mag[i] = 0;
        }
        nnls(firstJoint, tau, n);
        residual = largestResidual(firstJoint, tau, n);
    }

    /**
     * Contact forces with Coulomb friction: the least-norm forces inside the contacts' linearised
     * friction cones that carry the joint torques (class comment). Same arguments as
     * {@link #solve}, plus the cones.
     *
     * @param cones 3·m·n values: contact i's m cone edges at {@code cones[3m·i ..]}, each with
     *              a normal component of 1 along {@code dirs[i]} (as
     *              {@code org.handsim.grasp.FrictionCone#edges} writes them), going round the
     *              normal in order
     * @param m     edges per cone (≥ 1)
     */
    public void solveWithFriction(double[] frames, int firstJoint, double[] tau, int n, double[] points, double[] dirs, int[] links,
                                  double[] cones, int m) {
        if (m < 1) throw new IllegalArgumentException("cone edges must be >= 1, got " + m);
        ensure(n);
        ensureCones(n, m);
        count = n;
        friction = true;
        held = Double.NaN;
        edgesPerCone = m;
        System.arraycopy(dirs, 0, dirCopy, 0, 3 * n);
        for (int i = 0; i < n; i++) {
            double px = points[3 * i], py = points[3 * i + 1], pz = points[3 * i + 2];
            for (int jm = 0; jm < 3; jm++) {
                int o = 9 * i + 3 * jm;
                // every joint of the contact's chain (jointTorque reports them all); the solve uses firstJoint..2
                if (jm < links[i]) {
                    int f = 12 * jm;
                    double zx = frames[f + 2], zy = frames[f + 6], zz = frames[f + 10];
                    double rx = px - frames[f + 3], ry = py - frames[f + 7], rz = pz - frames[f + 11];
                    tvec[o] = zy * rz - zz * ry; tvec[o + 1] = zz * rx - zx * rz; tvec[o + 2] = zx * ry - zy * rx;
                    // the moment arm of the normal (arm(): the same products in the same order)
                    arms[3 * i + jm] = tvec[o] * dirs[3 * i] + tvec[o + 1] * dirs[3 * i + 1] + tvec[o + 2] * dirs[3 * i + 2];
                } else {
                    tvec[o] = 0; tvec[o + 1] = 0; tvec[o + 2] = 0;
                    arms[3 * i + jm] = 0;
                }
            }
            // undetermined: no edge of the cone has a moment arm (torque per newton of normal force)
            double bestArm2 = 0;
            for (int e = 0; e < m; e++) {
                int c = 3 * m * i + 3 * e;
                double a2 = 0;
                for (int jm = firstJoint; jm < 3; jm++) {
                    int o = 9 * i + 3 * jm;
                    double a = tvec[o] * cones[c] + tvec[o + 1] * cones[c + 1] + tvec[o + 2] * cones[c + 2];
                    a2 += a * a;
                }
                bestArm2 = Math.max(bestArm2, a2);
            }
            undetermined[i] = Math.sqrt(bestArm2) < MIN_ARM_M;
            ConeProjection.facetNormals(cones, 3 * m * i, m, facetNormals, 3 * m * i);
            mag[i] = 0;
            fvec[3 * i] = 0; fvec[3 * i + 1] = 0; fvec[3 * i + 2] = 0;
        }
        newtonOnTheDual(firstJoint, tau, n, cones, m);
        residual = largestResidual(firstJoint, tau, n);
    }

    /** max over joints r0..2 of |τ_m − Σ_i (torque of contact i on m)|, N·m. */
    private double largestResidual(int r0, double[] tau, int n) {
        double worst = 0;
        for (int jm = r0; jm < 3; jm++) {
            double r = tau[jm];
            for (int i = 0; i < n; i++) r -= jointTorque(i, jm);
            worst = Math.max(worst, Math.abs(r));
        }
        return worst;
    }

    /**
     * Contact forces for a finger whose joint {@code firstJoint} is <em>held</em> and whose later
     * joints are <em>driven</em> (DESIGN.md, "Which torques the contacts carry"): a driven joint's
     * torque {@code tau[m]} must be carried exactly, while the held joint's torque is a reaction
     * of whatever holds it (the BarrettHand's inner joint: its self-locking worm), free within
     * [{@code lo}, {@code hi}], what that holder resists. Without friction the non-negative
     * least squares of {@link #solve}, with it the least-norm forces of
     * {@link #solveWithFriction} (when {@code cones} is not null), each under these rows:
     * <ol>
     *   <li>solve for the driven joints alone; the held joint's reaction s is what those forces
     *       put on it (eq 9);</li>
     *   <li>if s lies outside [lo, hi], solve again with the held joint driven at the bound
     *       nearer s.</li>
     * </ol>
     * That is the optimum of the problem with the interval: the best value with the held torque
     * fixed at σ is a convex function of σ (a partial minimum of a convex problem), smallest at
     * σ = s, so over [lo, hi] it is smallest at the bound nearer s — for the least-norm forces and,
     * when the torques cannot be carried, for the least-squares torque alike. {@link #residual()}
     * then includes how far the reaction lies outside [lo, hi], and {@link #heldTorque()} is the
     * reaction.
     *
     * @param frames     48 values: frames {k0}..{k3}
     * @param firstJoint the held joint (0-based); the joints after it are driven
     * @param tau        torques of the driven joints, N·m (entry {@code firstJoint} is not read)
     * @param lo         least torque the held joint's holder puts on it, N·m
     * @param hi         largest, N·m (≥ lo)
     * @param cones      the contacts' cone edges as for {@link #solveWithFriction}, or null
     *                   without friction
     * @param m          edges per cone (ignored without friction)
     */
    public void solveHeld(double[] frames, int firstJoint, double[] tau, double lo, double hi, int n, double[] points, double[] dirs,
                          int[] links, double[] cones, int m) {
        if (!(lo <= hi)) throw new IllegalArgumentException("held joint's bounds must have lo <= hi, got [" + lo + ", " + hi + "]");
        if (firstJoint < 0 || firstJoint > 2) throw new IllegalArgumentException("held joint must be 0..2, got " + firstJoint);
        for (int jm = 0; jm < 3; jm++) tauHeld[jm] = jm == firstJoint ? 0 : tau[jm];
        solveRows(frames, firstJoint + 1, tauHeld, n, points, dirs, links, cones, m);
        double s = torqueOn(firstJoint, n);
        double bound = s < lo ? lo : s > hi ? hi : s;
        if (bound != s) {
            tauHeld[firstJoint] = bound;
            solveRows(frames, firstJoint, tauHeld, n, points, dirs, links, cones, m);
            s = torqueOn(firstJoint, n);
            residual = largestResidual(firstJoint + 1, tauHeld, n);
        }
        held = s;
        residual = Math.max(residual, Math.max(0, Math.max(lo - s, s - hi)));
    }

    private void solveRows(double[] frames, int r0, double[] t, int n, double[] points, double[] dirs, int[] links, double[] cones, int m) {
        if (cones == null) solve(frames, r0, t, n, points, dirs, links);
        else solveWithFriction(frames, r0, t, n, points, dirs, links, cones, m);
    }

    /** Eq (9): the torque the last solve's forces put on joint jm, N·m. */
    private double torqueOn(int jm, int n) {
        double sum = 0;
        for (int i = 0; i < n; i++) sum += jointTorque(i, jm);
        return sum;
    }

    /**
     * Newton's method on the regularised dual of the least-norm problem (class comment):
     * minimise φ(y) = ½ Σ_i |Π_i(T_i y)|² + ½ ρ |y|² − τᵀy over the multipliers y of the joints
     * that some determined contact loads (T_i: the 3×d matrix of contact i's t_mi); then the
     * polish: on the pieces found, solve Σ T_iᵀ DΠ_i T_i y = τ without ρ and keep it if the
     * pieces stay the same (the torques are then carried exactly).
     */
    private void newtonOnTheDual(int r0, double[] tau, int n, double[] cones, int m) {
        int d = 0;
        double s = 0;
        for (int jm = r0; jm < 3; jm++) {
            boolean used = false;
            for (int i = 0; i < n; i++) {
                if (undetermined[i]) continue;
                int o = 9 * i + 3 * jm;
                double t2 = tvec[o] * tvec[o] + tvec[o + 1] * tvec[o + 1] + tvec[o + 2] * tvec[o + 2];
                if (t2 > 0) { used = true; s = Math.max(s, t2); }
            }
            if (used) { tauActive[d] = tau[jm]; joint[d++] = jm; }
        }
        activeCount = d;
        if (d == 0) {
            for (int i = 0; i < n; i++) { mag[i] = 0; piece[i] = ConeProjection.APEX; }
            lastN = -1;
            return;
        }
        rho = RHO * s;
        t2Max = s;
        // warm start: the pieces of the last solve (a held grasp keeps them while its torques
        // grow). Any y with Σ T_iᵀ Π_i(T_i y) = τ is optimal (the KKT conditions of a convex
        // problem), so if the exact solve on those pieces lands on the same pieces, it is the answer.
        if (lastN == n && lastM == m && lastD == d && sameJoints(d) && exactOnPieces(n, m, d, cones)) {
            finish(n);
            return;
        }
        newtonFromTheInterior(n, m, d, cones);
        // the polish failed to carry τ: if no cone forces can, the least-squares torque (below)
        if (!carriesTauActive(n, d, EXACT)) leastSquaresTorque(r0, tau, n, m, d, cones);
        finish(n);
    }

    /**
     * Newton's method on the regularised dual for the torques {@code tauActive}, from y =
     * (Σ TᵀT + ρI)⁻¹ τ (every contact inside its cone), then the polish on the final pieces.
     * Leaves the forces in {@code fvec} and their pieces in {@code piece}.
     */
    private void newtonFromTheInterior(int n, int m, int d, double[] cones) {
        // start: every contact inside its cone, y = (Σ TᵀT + ρI)⁻¹ τ
        for (int i = 0; i < n; i++) piece[i] = 2 * m;
        hessian(n, m, d, cones, piece, true);
        for (int a = 0; a < d; a++) y[a] = tauActive[a];
        if (!org.handsim.math.Cholesky.decompose(hess, d)) java.util.Arrays.fill(y, 0, d, 0);
        else org.handsim.math.Cholesky.solve(hess, d, y);
        double phi = evaluate(y, n, m, d, cones, fvec, piece, g);
        double tauMax = 0;
        for (int a = 0; a < d; a++) tauMax = Math.max(tauMax, Math.abs(tauActive[a]));
        for (int it = 0; it < NEWTON_ITER; it++) {
            double gMax = 0, yMax = 0;
            for (int a = 0; a < d; a++) { gMax = Math.max(gMax, Math.abs(g[a])); yMax = Math.max(yMax, Math.abs(y[a])); }
            if (gMax <= 1e-13 * (tauMax + t2Max * yMax) + Double.MIN_NORMAL) break;     // stationary to rounding
            hessian(n, m, d, cones, piece, true);
            if (!org.handsim.math.Cholesky.decompose(hess, d)) break;
            for (int a = 0; a < d; a++) step[a] = -g[a];
            org.handsim.math.Cholesky.solve(hess, d, step);
            double slope = 0;
            for (int a = 0; a < d; a++) slope += g[a] * step[a];
            if (!(slope < 0)) break;                       // at the minimum to rounding
            double t = 1, phiTrial = 0;
            boolean accepted = false;
            for (int ls = 0; ls < 50; ls++) {
                for (int a = 0; a < d; a++) yTrial[a] = y[a] + t * step[a];
                phiTrial = evaluate(yTrial, n, m, d, cones, fTrial, pieceTrial, res);
                if (phiTrial <= phi + 1e-4 * t * slope) { accepted = true; break; }
                t *= 0.5;
            }
            if (!accepted) break;
            boolean samePieces = t == 1;
            for (int i = 0; i < n && samePieces; i++) samePieces = pieceTrial[i] == piece[i];
            System.arraycopy(yTrial, 0, y, 0, d);
            System.arraycopy(fTrial, 0, fvec, 0, 3 * n);
            System.arraycopy(pieceTrial, 0, piece, 0, n);
            System.arraycopy(res, 0, g, 0, d);
            phi = phiTrial;
            if (samePieces) break;                        // a full step inside one quadratic piece: its minimum
        }
        // polish: the exact torques on the final pieces, if the system is regular there
        exactOnPieces(n, m, d, cones);
    }

    /** Whether the forces in {@code fvec} carry {@code tauActive} to {@code tol} × |τ| (2-norm). */
    private boolean carriesTauActive(int n, int d, double tol) {
        double r2 = 0, t2 = 0;
        for (int a = 0; a < d; a++) {
            double r = tauActive[a];
            for (int i = 0; i < n; i++) {
                int o = 9 * i + 3 * joint[a];
                r -= tvec[o] * fvec[3 * i] + tvec[o + 1] * fvec[3 * i + 1] + tvec[o + 2] * fvec[3 * i + 2];
            }
            r2 += r * r;
            t2 += tauActive[a] * tauActive[a];
        }
        return r2 <= tol * tol * t2;
    }

    /**
     * Torques no forces in the cones carry (class comment): the regularised dual's minimum then
     * lies at |y| ~ |residual|/ρ, where the forces are the tiny difference of huge projections
     * and Newton's steps stall — on one contact that must push both joints k2 and k3 it ended at
     * the apex, f = 0, although cone forces reduce the torque error. So, in two phases:
     * (1) the least-squares torque τ* = argmin |τ − Σ T_iᵀ f_i| over forces in the cones, by
     * non-negative least squares on the cone edges' torques (Lawson–Hanson; τ* is unique, the
     * projection of τ onto the convex cone of carriable torques), kept only if it beats what
     * Newton found; (2) the least-norm forces that carry τ* exactly, by Newton's method on τ*.
     * τ* lies on the boundary of the carriable torques, where the dual's minimum need not be
     * attained; if Newton does not carry τ* to {@link #EXACT}, the edge forces of phase 1, which
     * carry it exactly — the least-norm ones when a single cone edge makes τ* (the generic case),
     * else one basic solution of several.
     */
    private void leastSquaresTorque(int r0, double[] tau, int n, int m, int d, double[] cones) {
        int cols = n * m;
        ensureEdges(cols);
        for (int i = 0; i < n; i++) {
            for (int e = 0; e < m; e++) {
                int c = i * m + e, ce = 3 * m * i + 3 * e;
                edgeSkip[c] = undetermined[i];
                edgeWeight[c] = 0;
                for (int jm = 0; jm < 3; jm++) {
                    int o = 9 * i + 3 * jm;
                    edgeArms[3 * c + jm] = jm < r0 ? 0 : tvec[o] * cones[ce] + tvec[o + 1] * cones[ce + 1] + tvec[o + 2] * cones[ce + 2];
                }
            }
        }
        nnls(edgeArms, r0, tau, cols, edgeSkip, edgeWeight, edgePassive, edgeZ);
        double before = 0, after = 0, scale = 0;
        for (int a = 0; a < d; a++) {
            int jm = joint[a];
            double carried = 0, star = 0;
            for (int i = 0; i < n; i++) carried += jointTorque(i, jm);
            for (int c = 0; c < cols; c++) star += edgeArms[3 * c + jm] * edgeWeight[c];
            before += (tau[jm] - carried) * (tau[jm] - carried);
            after += (tau[jm] - star) * (tau[jm] - star);
            scale += tau[jm] * tau[jm];
            tauStar[a] = star;
        }
        // Newton's answer is within EXACT·|τ| of the least-squares torque: keep it
        if (!(Math.sqrt(after) < Math.sqrt(before) - EXACT * Math.sqrt(scale))) return;
        System.arraycopy(tauStar, 0, tauActive, 0, d);
        newtonFromTheInterior(n, m, d, cones);
        if (carriesTauActive(n, d, EXACT)) return;
        for (int i = 0; i < n; i++) {
            double fx = 0, fy = 0, fz = 0;
            for (int e = 0; e < m; e++) {
                double w = edgeWeight[i * m + e];
                int ce = 3 * m * i + 3 * e;
                fx += w * cones[ce]; fy += w * cones[ce + 1]; fz += w * cones[ce + 2];
            }
            fvec[3 * i] = fx; fvec[3 * i + 1] = fy; fvec[3 * i + 2] = fz;
            piece[i] = ConeProjection.APEX;               // no warm start from these
        }
    }

    private void ensureEdges(int cols) {
        if (edgeWeight.length < cols) {
            int c = Math.max(cols, 2 * edgeWeight.length);
            edgeArms = new double[3 * c];
            edgeWeight = new double[c];
            edgeZ = new double[c];
            edgePassive = new boolean[c];
            edgeSkip = new boolean[c];
        }
        if (idxScratch.length < cols) {
            idxScratch = new int[cols];
            bScratch = new double[cols];
            yScratch = new double[cols];
            deadScratch = new boolean[cols];
        }
        if (gScratch.length < cols * cols) gScratch = new double[cols * cols];
    }

    /**
     * Solves Σ T_iᵀ DΠ_i T_i y = τ on the current pieces (no regularisation); if the system is
     * regular and the projections at that y stay on the same pieces, takes y and its forces.
     */
    private boolean exactOnPieces(int n, int m, int d, double[] cones) {
        hessian(n, m, d, cones, piece, false);
        if (!org.handsim.math.Cholesky.decompose(hess, d)) return false;
        for (int a = 0; a < d; a++) yTrial[a] = tauActive[a];
        org.handsim.math.Cholesky.solve(hess, d, yTrial);
        evaluate(yTrial, n, m, d, cones, fTrial, pieceTrial, res);
        for (int i = 0; i < n; i++) if (pieceTrial[i] != piece[i]) return false;
        System.arraycopy(yTrial, 0, y, 0, d);
        System.arraycopy(fTrial, 0, fvec, 0, 3 * n);
        return true;
    }

    private boolean sameJoints(int d) {
        for (int a = 0; a < d; a++) if (lastJoint[a] != joint[a]) return false;
        return true;
    }

    /** Magnitudes, and what the next solve may warm-start from. */
    private void finish(int n) {
        for (int i = 0; i < n; i++) {
            mag[i] = Math.sqrt(fvec[3 * i] * fvec[3 * i] + fvec[3 * i + 1] * fvec[3 * i + 1] + fvec[3 * i + 2] * fvec[3 * i + 2]);
        }
        lastN = n;
        lastM = edgesPerCone;
        int d = 0;
        while (d < 3 && d < lastJoint.length) { lastJoint[d] = joint[d]; d++; }
        lastD = activeCount;
    }

    /**
     * φ(y) of {@link #newtonOnTheDual}; writes the forces Π_i(T_i y), their pieces and the
     * gradient Σ T_iᵀ f_i + ρ y − τ.
     */
    private double evaluate(double[] yy, int n, int m, int d, double[] cones, double[] f, int[] pieces, double[] grad) {
        double phi = 0;
        for (int a = 0; a < d; a++) grad[a] = rho * yy[a] - tauActive[a];
        for (int i = 0; i < n; i++) {
            if (undetermined[i]) {
                f[3 * i] = 0; f[3 * i + 1] = 0; f[3 * i + 2] = 0;
                pieces[i] = ConeProjection.APEX;
                continue;
            }
            double vx = 0, vy = 0, vz = 0;
            for (int a = 0; a < d; a++) {
                int o = 9 * i + 3 * joint[a];
                vx += yy[a] * tvec[o]; vy += yy[a] * tvec[o + 1]; vz += yy[a] * tvec[o + 2];
            }
            pieces[i] = ConeProjection.project(cones, 3 * m * i, facetNormals, 3 * m * i, m, vx, vy, vz, f, 3 * i);
            double fx = f[3 * i], fy = f[3 * i + 1], fz = f[3 * i + 2];
            phi += 0.5 * (fx * fx + fy * fy + fz * fz);
            for (int a = 0; a < d; a++) {
                int o = 9 * i + 3 * joint[a];
                grad[a] += tvec[o] * fx + tvec[o + 1] * fy + tvec[o + 2] * fz;
            }
        }
        for (int a = 0; a < d; a++) phi += yy[a] * (0.5 * rho * yy[a] - tauActive[a]);
        return phi;
    }

    /** H = Σ_i T_iᵀ DΠ_i T_i (+ ρ I when {@code regularised}) into {@code hess} (d×d). */
    private void hessian(int n, int m, int d, double[] cones, int[] pieces, boolean regularised) {
        for (int a = 0; a < d * d; a++) hess[a] = 0;
        for (int i = 0; i < n; i++) {
            if (undetermined[i] || pieces[i] == ConeProjection.APEX) continue;
            for (int c = 0; c < d; c++) {
                int oc = 9 * i + 3 * joint[c];
                ConeProjection.derivative(pieces[i], cones, 3 * m * i, facetNormals, 3 * m * i, m,
                    tvec[oc], tvec[oc + 1], tvec[oc + 2], pa, 0);
                for (int r = 0; r < d; r++) {
                    int or = 9 * i + 3 * joint[r];
                    hess[r * d + c] += tvec[or] * pa[0] + tvec[or + 1] * pa[1] + tvec[or + 2] * pa[2];
                }
            }
        }
        if (regularised) for (int a = 0; a < d; a++) hess[a * d + a] += rho;
    }

    private void ensureCones(int n, int m) {
        if (tvec.length < 9 * n) {
            int c = Math.max(n, 2 * tvec.length / 9);
            tvec = new double[9 * c];
            fvec = new double[3 * c];
            fTrial = new double[3 * c];
            piece = new int[c];
            lastN = -1;
            pieceTrial = new int[c];
        }
        if (facetNormals.length < 3 * m * n) facetNormals = new double[Math.max(3 * m * n, 2 * facetNormals.length)];
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

    /** Lawson–Hanson NNLS on the rows firstJoint..2 and the determined contacts' arms. */
    private void nnls(int r0, double[] tau, int n) {
        nnls(arms, r0, tau, n, undetermined, mag, passive, z);
    }

    /**
     * Lawson–Hanson non-negative least squares: x ≥ 0 minimising |A x − τ| over the rows
     * r0..2, A's column c at {@code a[3c .. 3c+2]} (one value per joint), columns with
     * {@code skip[c]} held at 0. {@code x} must be zero on entry; {@code passive} and {@code zz}
     * are scratch of at least {@code cols} entries.
     */
    private void nnls(double[] a, int r0, double[] tau, int cols, boolean[] skip, double[] x, boolean[] passive, double[] zz) {
        for (int i = 0; i < cols; i++) passive[i] = false;
        for (int iter = 0; iter < MAX_ITER; iter++) {
            // gradient w = Aᵀ (τ − A x), the residual τ − A x computed once
            for (int m = r0; m < 3; m++) {
                double r = tau[m];
                for (int j = 0; j < cols; j++) r -= a[3 * j + m] * x[j];
                res[m] = r;
            }
            int best = -1;
            double bestW = 1e-15;
            for (int i = 0; i < cols; i++) {
                if (passive[i] || skip[i]) continue;
                double g = 0;
                for (int m = r0; m < 3; m++) g += a[3 * i + m] * res[m];
                if (g > bestW) { bestW = g; best = i; }
            }
            if (best < 0) return;
            passive[best] = true;
            while (true) {
                if (!leastSquaresOnPassive(a, r0, tau, cols, passive, zz)) { passive[best] = false; return; }
                double alpha = 1;
                boolean feasible = true;
                for (int i = 0; i < cols; i++) {
                    if (passive[i] && zz[i] <= 0) {
                        feasible = false;
                        double al = x[i] / (x[i] - zz[i]);
                        if (al < alpha) alpha = al;
                    }
                }
                if (feasible) {
                    for (int i = 0; i < cols; i++) x[i] = passive[i] ? zz[i] : 0;
                    break;
                }
                for (int i = 0; i < cols; i++) {
                    if (passive[i]) {
                        x[i] += alpha * (zz[i] - x[i]);
                        if (x[i] <= 1e-15) { x[i] = 0; passive[i] = false; }
                    }
                }
            }
        }
    }

    /**
     * Unconstrained least squares on the passive columns into zz (normal equations, at most a
     * handful of columns; a rank-deficient set is regularised by dropping dependent columns).
     */
    private boolean leastSquaresOnPassive(double[] a, int r0, double[] tau, int cols, boolean[] passive, double[] zz) {
        int p = 0;
        int[] idx = idxScratch;
        for (int i = 0; i < cols; i++) if (passive[i]) idx[p++] = i;
        double[] g = gScratch, b = bScratch;
        for (int u = 0; u < p; u++) {
            for (int c = 0; c < p; c++) {
                double sum = 0;
                for (int m = r0; m < 3; m++) sum += a[3 * idx[u] + m] * a[3 * idx[c] + m];
                g[u * p + c] = sum;
            }
            double sum = 0;
            for (int m = r0; m < 3; m++) sum += a[3 * idx[u] + m] * tau[m];
            b[u] = sum;
        }
        // Cholesky with pivot check: a column dependent on earlier ones gets zero weight
        double scale = 0;
        for (int u = 0; u < p; u++) scale = Math.max(scale, g[u * p + u]);
        boolean[] dead = deadScratch;
        java.util.Arrays.fill(dead, 0, p, false);
        for (int j = 0; j < p; j++) {
            double d = g[j * p + j];
            for (int k = 0; k < j; k++) if (!dead[k]) d -= g[j * p + k] * g[j * p + k];
            if (d <= 1e-12 * scale) { dead[j] = true; g[j * p + j] = 1; continue; }
            double l = Math.sqrt(d);
            g[j * p + j] = l;
            for (int i = j + 1; i < p; i++) {
                double sum = g[i * p + j];
                for (int k = 0; k < j; k++) if (!dead[k]) sum -= g[i * p + k] * g[j * p + k];
                g[i * p + j] = sum / l;
            }
        }
        double[] yy = yScratch;
        for (int i = 0; i < p; i++) {
            if (dead[i]) { yy[i] = 0; continue; }
            double sum = b[i];
            for (int k = 0; k < i; k++) if (!dead[k]) sum -= g[i * p + k] * yy[k];
            yy[i] = sum / g[i * p + i];
        }
        for (int i = p - 1; i >= 0; i--) {
            if (dead[i]) { yy[i] = 0; continue; }
            double sum = yy[i];
            for (int k = i + 1; k < p; k++) if (!dead[k]) sum -= g[k * p + i] * yy[k];
            yy[i] = sum / g[i * p + i];
        }
        for (int i = 0; i < cols; i++) zz[i] = 0;
        for (int u = 0; u < p; u++) zz[idx[u]] = yy[u];
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
            dirCopy = new double[3 * c];
        }
    }

    /** @return the number of contacts of the last solve */
    public int count() { return count; }

    /** @return magnitude |f_i| ≥ 0 of contact i's force (newtons) */
    public double force(int i) { return mag[i]; }

    /**
     * Contact i's force on the object (newtons, the frame of the inputs) into
     * {@code out[off .. off+2]}: f_i·d_i without friction, the cone solve's vector with it.
     */
    public void forceVector(int i, double[] out, int off) {
        if (friction) {
            out[off] = fvec[3 * i]; out[off + 1] = fvec[3 * i + 1]; out[off + 2] = fvec[3 * i + 2];
        } else {
            out[off] = mag[i] * dirCopy[3 * i]; out[off + 1] = mag[i] * dirCopy[3 * i + 1]; out[off + 2] = mag[i] * dirCopy[3 * i + 2];
        }
    }

    /**
     * Eq (9): the torque contact i's force puts on joint m (0-based), N·m: a_mi·f_i without
     * friction (the same product as before friction existed), t_mi·f_i with it.
     */
    public double jointTorque(int i, int m) {
        if (!friction) return arms[3 * i + m] * mag[i];
        int o = 9 * i + 3 * m;
        return tvec[o] * fvec[3 * i] + tvec[o + 1] * fvec[3 * i + 1] + tvec[o + 2] * fvec[3 * i + 2];
    }

    /** @return true if contact i's moment arms are all ~0 (its force is not determined) */
    public boolean undetermined(int i) { return undetermined[i]; }

    /** @return moment arm a_mi of contact i about joint m (0-based) along its normal d_i, metres */
    public double arm(int i, int m) { return arms[3 * i + m]; }

    /**
     * How far the last solve's forces are from carrying the joint torques, N·m: the largest
     * |τ_m − Σ_i t_mi·f_i| over the joints it was given (eq 9 with the forces found), and after
     * {@link #solveHeld} also how far the held joint's reaction lies outside its bounds. 0 up to
     * rounding when the contacts carry the torques; nonzero when no forces in the cones can
     * (the finger has no static equilibrium in that state).
     */
    public double residual() { return residual; }

    /** The held joint's reaction after {@link #solveHeld} (N·m, eq 9 with the forces found); NaN after the other solves. */
    public double heldTorque() { return held; }
}
