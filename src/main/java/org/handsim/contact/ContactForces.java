package org.handsim.contact;

/**
 * Contact forces of one finger from its joints: the paper's eq (11) made well-posed (DESIGN.md
 * decision 2, "Which contact forces"), and the torque a set of contact forces puts on a joint,
 * eq (9).
 *
 * <p><b>Why not eq (11) as printed.</b> Eq (11) inverts the cross-product matrix
 * [p_c − p_km]×, which is singular (rank 2) for every p. A point contact i at p_i pushing the
 * object with the force f_i needs, by virtual work, the joint torques
 * <pre>  τ_m = Σ_i t_mi · f_i,   t_mi = z_{m−1} × (p_i − o_{m−1})   for joints m ≤ link(i), else 0,</pre>
 * z_{m−1}, o_{m−1} the axis and origin of joint m (frame {k(m−1)}); t_mi is the direction
 * contact i moves when joint m turns, per radian. A frictionless contact pushes along its
 * normal d_i (f_i = λ_i d_i, λ_i ≥ 0, moment arm a_mi = t_mi · d_i); with Coulomb friction
 * f_i is any vector of its linearised cone K_i (edges from {@code org.handsim.grasp.FrictionCone}),
 * the frictionless contact being the cone of one edge, d_i.
 *
 * <p><b>The joints.</b> Each joint of the finger is either
 * <ul>
 *   <li><em>driven</em> ({@link Problem#driven}): something compliant sets its torque — the
 *       clutch's Belleville springs, a stalled motor — and the contacts must carry it exactly;
 *       or</li>
 *   <li><em>held</em> ({@link Problem#held}): a self-locking worm (or a stop, or a position-held
 *       motor) keeps it from turning, and its torque is the reaction, whatever the contacts put
 *       on it ({@link #torqueOn}).</li>
 * </ul>
 *
 * <p><b>Which forces (the mechanism's compliance).</b> With more contacts or held joints than
 * the balance needs, many forces carry the driven torques. HandSim takes the forces the hand's
 * compliance gives. Links, worms and stops are rigid; every contact is a linear isotropic spring
 * of the same stiffness k (tangential equal to normal), with Coulomb's cone; a driven joint is a
 * torque source (the clutch's springs are 50–500 times softer than a contact's rotational
 * stiffness k·r², so the tiny contact deflections do not change the torque they set). Loads
 * locked in earlier — the forces a contact carried when its link's worm locked
 * ({@link Problem#locked}) — stay, since a held link cannot move to relieve them; only the
 * driven joints turn (by y_m, radians), pressing contact i by Σ_m y_m t_mi. Contact i's force
 * is then its locked force plus k times that displacement, returned onto the cone where it would
 * leave it (sliding, with Coulomb's maximal dissipation), and y makes the driven torques come
 * out right:
 * <pre>  f_i = Π_{K_i}(f⁰_i + Σ_{m driven} y_m t_mi),   Σ_i t_mi · f_i = τ_m  for every driven m</pre>
 * (k drops out: it only scales y). These are the optimality conditions of the least
 * complementary energy of the load increment,
 * <pre>  minimise ½ Σ_i |f_i − f⁰_i|²  subject to  Σ_i t_mi · f_i = τ_m (m driven),  f_i ∈ K_i,</pre>
 * whose dual is solved: φ(y) = ½ Σ_i |Π_i(f⁰_i + T_iᵀy)|² − τᵀy (T_i: contact i's t_mi of the
 * driven joints), convex and piecewise quadratic, by Newton's method regularised by {@link #RHO}
 * times the largest |t|² so that its steps stay finite, then made exact on the final pieces.
 * Without locked loads (f⁰ = 0) this is the least-norm solution; for one contact with its
 * direction of motion t inside the cone the force is along t (the paper's cube: τ_break / |t| =
 * 1.26 / 0.0627 m = 20.09 N), else on the cone's edge nearest t. A held link's contact keeps its
 * locked force (its displacement is 0), whatever the other links do. A contact on the back of a
 * moving link — one that its joints' motion pulls away from the object — gets Π(negative push)
 * = 0.
 *
 * <p><b>Undetermined contacts.</b> A contact no edge of whose cone has a moment arm of
 * {@link #MIN_ARM_M} about a driven joint cannot be weighed by the driven torques: it keeps its
 * locked force (projected onto its cone), 0 without one ({@link #undetermined}), never τ/~0.
 *
 * <p><b>Torques no cone forces carry</b> (a pull, a driven joint no contact loads): phase 1 finds
 * the least-squares torque τ* — the one nearest τ that forces in the cones carry, the projection
 * of τ onto the convex cone of carriable torques, unique — by Lawson–Hanson non-negative least
 * squares on the cone edges' torques; phase 2 the forces above carrying τ*. τ* lies on the
 * boundary of the carriable torques, where the dual's minimum need not be attained: if Newton
 * does not carry τ* to 1e-9 of |τ*|, phase 1's edge forces, which do, moved by a primal
 * active-set method ({@link NearestConeForces}) to the forces above, still carrying τ* exactly.
 * The same happens when τ itself lies on that boundary (a driven torque only a contact at its
 * cone's apex gives, such as τk3 = 0 with every outer contact pressing k3 closed). {@link #residual()} says
 * how far the forces are from the driven torques — nonzero when no forces can carry them (the
 * finger has no static equilibrium in that state).
 *
 * <p>Frames: points, directions and the 48-value frame array ({k0}..{k3}, 12 row-major values
 * each, as {@code FingerKinematics.frames}) must all be in one frame (palm or world).
 *
 * <p>Not thread-safe: one instance per finger (it keeps its scratch arrays and warm-starts from
 * its last solve). A solve allocates nothing once its arrays have grown to the contact count.
 */
public final class ContactForces {
    /**
     * Moment arms (metres) below this count as zero: 0.5 mm. The arm of a contact is only as
     * good as its normal and position, and at the default tessellation those are good to about
     * 1–2° and 0.5 mm (docs/BENCHMARKS.md, chart 2-tessellation): at a 30 mm lever that is an
     * uncertainty of about 0.5–1 mm in the arm, so a smaller arm does not determine the force
     * (f = τ/a would be more than 100 % uncertain, and grow without bound — thousands of newtons
     * for τ_break — as a → 0). Such a contact is reported undetermined.
     */
    public static final double MIN_ARM_M = 5e-4;
    /**
     * Regularisation of the dual, relative to the largest |t_mi|² (m²): the torque residual it
     * leaves before the polish is about 1e-10 of the torque; its role is to keep Newton's steps
     * finite when some torque is beyond what the cones can carry.
     */
    public static final double RHO = 1e-10;
    private static final int MAX_ITER = 100;
    private static final int NEWTON_ITER = 60;
    /** Torques carried to this fraction of |τ| count as carried exactly (the polish gives ~1e-16). */
    private static final double EXACT = 1e-9;

    /**
     * What one solve is given: the finger's frames, which joints are driven (and their torques)
     * and which held, its contacts with their cones, and the forces locked in. The caller fills
     * it and may keep it for the next solve (it holds references to the caller's arrays, read
     * during {@link ContactForces#solve}). By default joint 0 (the spread) is held and joints 1, 2
     * are driven at 0 N·m, frictionless, nothing locked.
     */
    public static final class Problem {
        private double[] frames;
        private final boolean[] held = {true, false, false};
        private final double[] torque = new double[3];
        private int count = -1;
        private double[] points, dirs;
        private int[] links;
        private double[] cones;
        private int edges = 1;
        private double[] locked;

        /** Frames {k0}..{k3} of the finger: 48 values, 12 row-major per frame; joint m turns about z of frame m−1. */
        public Problem frames(double[] frames) {
            this.frames = frames;
            return this;
        }

        /** Joint {@code joint} (0-based: 0 = k1, 1 = k2, 2 = k3) is driven at {@code tau} N·m, which the contacts must carry. */
        public Problem driven(int joint, double tau) {
            held[check(joint)] = false;
            torque[joint] = tau;
            return this;
        }

        /** Joint {@code joint} (0-based) is held: it does not turn, its torque is a reaction. */
        public Problem held(int joint) {
            held[check(joint)] = true;
            torque[joint] = 0;
            return this;
        }

        /**
         * The contacts: {@code n} of them, contact i at {@code points[3i..]} (metres), pushing
         * the object along the unit direction {@code dirs[3i..]} (the cone's axis, into the
         * object), on link {@code links[i]} (1..3).
         */
        public Problem contacts(int n, double[] points, double[] dirs, int[] links) {
            this.count = n;
            this.points = points;
            this.dirs = dirs;
            this.links = links;
            return this;
        }

        /**
         * Coulomb friction: contact i's m cone edges at {@code cones[3m·i ..]}, each with a
         * normal component of 1 along its direction, going round it in order (as
         * {@code org.handsim.grasp.FrictionCone#edges} writes them); null for frictionless.
         */
        public Problem friction(double[] cones, int m) {
            this.cones = cones;
            this.edges = cones == null ? 1 : m;
            return this;
        }

        /** No friction: each contact pushes along its direction only. */
        public Problem frictionless() {
            return friction(null, 1);
        }

        /**
         * The forces locked into the contacts (newtons, 3 per contact, in the contacts' order),
         * or null for none: what each contact carried when its link's worm locked. Matching them
         * to the contacts is the caller's: with a fixed object a link whose joints did not move
         * has the same contacts (HandModel keeps them per link); a caller whose object moves
         * carries them over by its own matching of old contacts to new ones.
         */
        public Problem locked(double[] forces) {
            this.locked = forces;
            return this;
        }

        /** Whether joint {@code joint} (0-based) is held. */
        public boolean isHeld(int joint) { return held[check(joint)]; }

        /** The torque a driven joint must carry (0 for a held one), N·m. */
        public double torque(int joint) { return torque[check(joint)]; }

        private static int check(int joint) {
            if (joint < 0 || joint > 2) throw new IllegalArgumentException("joint must be 0..2, got " + joint);
            return joint;
        }

        private void validate() {
            if (frames == null || frames.length < 48) {
                throw new IllegalArgumentException("frames must hold 48 values, got " + (frames == null ? "none" : frames.length));
            }
            if (count < 0) throw new IllegalArgumentException("no contacts given (Problem.contacts)");
            int n = count;
            if (points.length < 3 * n || dirs.length < 3 * n || links.length < n) {
                throw new IllegalArgumentException(n + " contacts need 3n points and directions and n links, got "
                    + points.length + ", " + dirs.length + ", " + links.length);
            }
            for (int i = 0; i < n; i++) {
                if (links[i] < 1 || links[i] > 3) throw new IllegalArgumentException("contact " + i + ": link must be 1..3, got " + links[i]);
            }
            if (edges < 1) throw new IllegalArgumentException("cone edges must be >= 1, got " + edges);
            if (cones != null && cones.length < 3 * edges * n) {
                throw new IllegalArgumentException(n + " cones of " + edges + " edges need " + 3 * edges * n + " values, got " + cones.length);
            }
            if (locked != null && locked.length < 3 * n) {
                throw new IllegalArgumentException(n + " locked forces need " + 3 * n + " values, got " + locked.length);
            }
            for (int m = 0; m < 3; m++) {
                if (!held[m] && !Double.isFinite(torque[m])) throw new IllegalArgumentException("joint " + m + ": torque " + torque[m]);
            }
        }
    }

    private double[] arms = new double[0];      // 3 per contact: a_mi along the contact's direction
    private boolean[] undetermined = new boolean[0];
    private int[] idxScratch = new int[0];
    private double[] gScratch = new double[0], bScratch = new double[0], yScratch = new double[0];
    private boolean[] deadScratch = new boolean[0];
    private final double[] res = new double[3];
    private final boolean[] driven = new boolean[3];
    private final double[] tau = new double[3];   // the driven joints' torques of the last solve
    private int count;
    private double residual;
    private int edgesPerCone;
    // per contact: torque directions t_mi (9), force vectors, locked forces, the rays of a frictionless solve
    private double[] tvec = new double[0], fvec = new double[0], ref = new double[0], rays = new double[0], facetNormals = new double[0];
    private double[] mag = new double[0];
    private double[] fTrial = new double[0];
    private int[] piece = new int[0], pieceTrial = new int[0];
    private final int[] joint = new int[3];          // active dual rows: joint indices
    private final double[] y = new double[3], yTrial = new double[3], g = new double[3], step = new double[3];
    private final double[] hess = new double[9], tauActive = new double[3], pa = new double[3];
    private double rho, t2Max;                       // ρ and the largest |t_mi|² of the last solve
    private int activeCount;                         // d of the last solve
    private int lastN = -1, lastM, lastD;            // what the pieces in piece[] belong to (warm start)
    private final int[] lastJoint = new int[3];
    private boolean hasLocked;                       // the last solve has forces locked in
    // the least-squares torque when no cone forces carry τ: one column per cone edge
    private double[] edgeArms = new double[0], edgeWeight = new double[0], edgeZ = new double[0];
    private boolean[] edgePassive = new boolean[0], edgeSkip = new boolean[0];
    private final double[] tauStar = new double[3], lsRhs = new double[3], lsResidual = new double[3];   // by joint
    private final NearestConeForces nearest = new NearestConeForces();

    /**
     * Solves for the contact forces of {@code p} (class comment): afterwards {@link #force},
     * {@link #forceVector}, {@link #jointTorque}, {@link #torqueOn} and {@link #residual} give
     * the answer.
     *
     * @throws IllegalArgumentException naming the value when the problem is malformed
     */
    public void solve(Problem p) {
        p.validate();
        int n = p.count, m = p.edges;
        ensure(n);
        ensureCones(n, m);
        count = n;
        edgesPerCone = m;
        for (int jm = 0; jm < 3; jm++) {
            driven[jm] = !p.held[jm];
            tau[jm] = driven[jm] ? p.torque[jm] : 0;
        }
        double[] cones = p.cones;
        if (cones == null) {
            // frictionless: the cone of one edge, the contact's direction
            System.arraycopy(p.dirs, 0, rays, 0, 3 * n);
            cones = rays;
        }
        double[] frames = p.frames, points = p.points, dirs = p.dirs;
        boolean anyLocked = false;
        for (int i = 0; i < n; i++) {
            double px = points[3 * i], py = points[3 * i + 1], pz = points[3 * i + 2];
            for (int jm = 0; jm < 3; jm++) {
                int o = 9 * i + 3 * jm;
                if (jm < p.links[i]) {
                    int f = 12 * jm;
                    double zx = frames[f + 2], zy = frames[f + 6], zz = frames[f + 10];
                    double rx = px - frames[f + 3], ry = py - frames[f + 7], rz = pz - frames[f + 11];
                    tvec[o] = zy * rz - zz * ry; tvec[o + 1] = zz * rx - zx * rz; tvec[o + 2] = zx * ry - zy * rx;
                    arms[3 * i + jm] = tvec[o] * dirs[3 * i] + tvec[o + 1] * dirs[3 * i + 1] + tvec[o + 2] * dirs[3 * i + 2];
                } else {
                    tvec[o] = 0; tvec[o + 1] = 0; tvec[o + 2] = 0;
                    arms[3 * i + jm] = 0;
                }
            }
            // undetermined: no edge of the cone has a moment arm (torque per newton) about a driven joint
            double bestArm2 = 0;
            for (int e = 0; e < m; e++) {
                int c = 3 * m * i + 3 * e;
                double a2 = 0;
                for (int jm = 0; jm < 3; jm++) {
                    if (!driven[jm]) continue;
                    int o = 9 * i + 3 * jm;
                    double a = tvec[o] * cones[c] + tvec[o + 1] * cones[c + 1] + tvec[o + 2] * cones[c + 2];
                    a2 += a * a;
                }
                bestArm2 = Math.max(bestArm2, a2);
            }
            undetermined[i] = Math.sqrt(bestArm2) < MIN_ARM_M;
            ConeProjection.facetNormals(cones, 3 * m * i, m, facetNormals, 3 * m * i);
            for (int c = 0; c < 3; c++) {
                double f0 = p.locked == null ? 0 : p.locked[3 * i + c];
                ref[3 * i + c] = f0;
                anyLocked |= f0 != 0;
            }
            if (undetermined[i]) {
                // weighed by no driven torque: it keeps what was locked into it
                piece[i] = ConeProjection.project(cones, 3 * m * i, facetNormals, 3 * m * i, m,
                    ref[3 * i], ref[3 * i + 1], ref[3 * i + 2], fvec, 3 * i);
            } else {
                fvec[3 * i] = 0; fvec[3 * i + 1] = 0; fvec[3 * i + 2] = 0;
            }
        }
        hasLocked = anyLocked;
        newtonOnTheDual(n, cones, m);
        for (int i = 0; i < n; i++) {
            mag[i] = Math.sqrt(fvec[3 * i] * fvec[3 * i] + fvec[3 * i + 1] * fvec[3 * i + 1] + fvec[3 * i + 2] * fvec[3 * i + 2]);
        }
        double worst = 0;
        for (int jm = 0; jm < 3; jm++) {
            if (driven[jm]) worst = Math.max(worst, Math.abs(tau[jm] - torqueOn(jm)));
        }
        residual = worst;
    }

    /**
     * Newton's method on the dual (class comment): minimise φ(y) over the multipliers y of the
     * driven joints that some determined contact loads; then the polish: on the pieces found,
     * solve Σ T_i DΠ_i (f⁰_i + T_iᵀ y) = τ without ρ and keep it if the pieces stay the same
     * (the torques are then carried exactly).
     */
    private void newtonOnTheDual(int n, double[] cones, int m) {
        int d = 0;
        double s = 0;
        for (int jm = 0; jm < 3; jm++) {
            if (!driven[jm]) continue;
            boolean used = false;
            for (int i = 0; i < n; i++) {
                if (undetermined[i]) continue;
                int o = 9 * i + 3 * jm;
                double t2 = tvec[o] * tvec[o] + tvec[o + 1] * tvec[o + 1] + tvec[o + 2] * tvec[o + 2];
                if (t2 > 0) { used = true; s = Math.max(s, t2); }
            }
            if (used) {
                // what the undetermined contacts' locked forces already put on the joint
                double carried = 0;
                for (int i = 0; i < n; i++) if (undetermined[i]) carried += jointTorque(i, jm);
                tauActive[d] = tau[jm] - carried;
                joint[d++] = jm;
            }
        }
        activeCount = d;
        if (d == 0) {
            lastN = -1;
            return;
        }
        rho = RHO * s;
        t2Max = s;
        // warm start: the pieces of the last solve (a held grasp keeps them while its torques
        // grow). Any y with Σ T_i Π_i(f⁰_i + T_iᵀ y) = τ is optimal (the KKT conditions of a
        // convex problem), so if the exact solve on those pieces lands on the same pieces, it is the answer.
        if (lastN == n && lastM == m && lastD == d && sameJoints(d) && exactOnPieces(n, m, d, cones)) {
            finish(n, m);
            return;
        }
        newtonFromTheInterior(n, m, d, cones);
        // the polish failed to carry τ: if no cone forces can, the least-squares torque (below)
        if (!carriesTauActive(n, d, EXACT)) leastSquaresTorque(n, m, d, cones);
        finish(n, m);
    }

    /**
     * Newton's method on the regularised dual for the torques {@code tauActive}, from the y of
     * every contact inside its cone, (Σ T Tᵀ + ρI) y = τ − Σ T f⁰; then the polish on the final
     * pieces. Leaves the forces in {@code fvec} and their pieces in {@code piece}.
     */
    private void newtonFromTheInterior(int n, int m, int d, double[] cones) {
        for (int i = 0; i < n; i++) if (!undetermined[i]) piece[i] = 2 * m;
        hessian(n, m, d, cones, piece, true);
        rightHandSide(n, m, d, cones, piece, y);
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
            copyDetermined(fTrial, pieceTrial, n);
            System.arraycopy(res, 0, g, 0, d);
            phi = phiTrial;
            if (samePieces) break;                        // a full step inside one quadratic piece: its minimum
        }
        exactOnPieces(n, m, d, cones);
    }

    /** The determined contacts' forces and pieces from a trial (the undetermined keep theirs). */
    private void copyDetermined(double[] f, int[] pieces, int n) {
        for (int i = 0; i < n; i++) {
            if (undetermined[i]) continue;
            fvec[3 * i] = f[3 * i]; fvec[3 * i + 1] = f[3 * i + 1]; fvec[3 * i + 2] = f[3 * i + 2];
            piece[i] = pieces[i];
        }
    }

    /** Whether the forces in {@code fvec} carry {@code tauActive} to {@code tol} × |τ| (2-norm). */
    private boolean carriesTauActive(int n, int d, double tol) {
        double r2 = 0, t2 = 0;
        for (int a = 0; a < d; a++) {
            double r = tauActive[a];
            for (int i = 0; i < n; i++) {
                if (undetermined[i]) continue;
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
     * (1) the least-squares torque τ* = argmin |τ − Σ T_i f_i| over forces in the cones, by
     * non-negative least squares on the cone edges' torques (Lawson–Hanson; τ* is unique, the
     * projection of τ onto the convex cone of carriable torques), kept only if it beats what
     * Newton found; (2) the forces that carry τ* exactly, by Newton's method on τ*. If Newton does
     * not carry τ* to {@link #EXACT} (τ* on the boundary, where the dual's minimum is not
     * attained), the edge forces of phase 1, which carry it exactly but are one basic solution of
     * many, blind to the locked loads, moved by {@link NearestConeForces} to the unique minimiser.
     */
    private void leastSquaresTorque(int n, int m, int d, double[] cones) {
        int cols = n * m;
        ensureEdges(cols);
        for (int i = 0; i < n; i++) {
            for (int e = 0; e < m; e++) {
                int c = i * m + e, ce = 3 * m * i + 3 * e;
                edgeSkip[c] = undetermined[i];
                edgeWeight[c] = 0;
                for (int jm = 0; jm < 3; jm++) {
                    int o = 9 * i + 3 * jm;
                    edgeArms[3 * c + jm] = tvec[o] * cones[ce] + tvec[o + 1] * cones[ce + 1] + tvec[o + 2] * cones[ce + 2];
                }
            }
        }
        for (int jm = 0; jm < 3; jm++) lsRhs[jm] = 0;
        for (int a = 0; a < d; a++) lsRhs[joint[a]] = tauActive[a];
        nnls(edgeArms, lsRhs, cols, edgeSkip, edgeWeight, edgePassive, edgeZ, d);
        double before = 0, after = 0, scale = 0;
        for (int a = 0; a < d; a++) {
            int jm = joint[a];
            double carried = 0, star = 0;
            for (int i = 0; i < n; i++) if (!undetermined[i]) carried += jointTorque(i, jm);
            for (int c = 0; c < cols; c++) star += edgeArms[3 * c + jm] * edgeWeight[c];
            before += (tauActive[a] - carried) * (tauActive[a] - carried);
            after += (tauActive[a] - star) * (tauActive[a] - star);
            scale += tauActive[a] * tauActive[a];
            tauStar[a] = star;
        }
        // Newton's answer is within EXACT·|τ| of the least-squares torque: keep it
        if (!(Math.sqrt(after) < Math.sqrt(before) - EXACT * Math.sqrt(scale))) return;
        System.arraycopy(tauStar, 0, tauActive, 0, d);
        newtonFromTheInterior(n, m, d, cones);
        if (carriesTauActive(n, d, EXACT)) return;
        for (int i = 0; i < n; i++) {
            if (undetermined[i]) continue;
            double fx = 0, fy = 0, fz = 0;
            for (int e = 0; e < m; e++) {
                double w = edgeWeight[i * m + e];
                int ce = 3 * m * i + 3 * e;
                fx += w * cones[ce]; fy += w * cones[ce + 1]; fz += w * cones[ce + 2];
            }
            fvec[3 * i] = fx; fvec[3 * i + 1] = fy; fvec[3 * i + 2] = fz;
            piece[i] = ConeProjection.APEX;               // no warm start from these
        }
        // from those edge forces, which carry τ* exactly, to the mechanism's forces carrying it
        nearest.solve(n, undetermined, tvec, joint, d, cones, facetNormals, m, ref, fvec);
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
     * Solves Σ T_i DΠ_i T_iᵀ y = τ − Σ T_i DΠ_i f⁰_i on the current pieces (no regularisation);
     * if the system is regular and the projections at that y stay on the same pieces, takes y and
     * its forces.
     */
    private boolean exactOnPieces(int n, int m, int d, double[] cones) {
        hessian(n, m, d, cones, piece, false);
        if (!org.handsim.math.Cholesky.decompose(hess, d)) return false;
        rightHandSide(n, m, d, cones, piece, yTrial);
        org.handsim.math.Cholesky.solve(hess, d, yTrial);
        evaluate(yTrial, n, m, d, cones, fTrial, pieceTrial, res);
        for (int i = 0; i < n; i++) if (!undetermined[i] && pieceTrial[i] != piece[i]) return false;
        System.arraycopy(yTrial, 0, y, 0, d);
        copyDetermined(fTrial, pieceTrial, n);
        return true;
    }

    /** τ − Σ_i T_i DΠ_i f⁰_i on the given pieces into {@code out} (the linear system's right-hand side). */
    private void rightHandSide(int n, int m, int d, double[] cones, int[] pieces, double[] out) {
        for (int a = 0; a < d; a++) out[a] = tauActive[a];
        if (!hasLocked) return;
        for (int i = 0; i < n; i++) {
            if (undetermined[i] || pieces[i] == ConeProjection.APEX) continue;
            ConeProjection.derivative(pieces[i], cones, 3 * m * i, facetNormals, 3 * m * i, m,
                ref[3 * i], ref[3 * i + 1], ref[3 * i + 2], pa, 0);
            for (int a = 0; a < d; a++) {
                int o = 9 * i + 3 * joint[a];
                out[a] -= tvec[o] * pa[0] + tvec[o + 1] * pa[1] + tvec[o + 2] * pa[2];
            }
        }
    }

    private boolean sameJoints(int d) {
        for (int a = 0; a < d; a++) if (lastJoint[a] != joint[a]) return false;
        return true;
    }

    /** What the next solve may warm-start from. */
    private void finish(int n, int m) {
        lastN = n;
        lastM = m;
        for (int a = 0; a < activeCount; a++) lastJoint[a] = joint[a];
        lastD = activeCount;
    }

    /**
     * φ(y) of {@link #newtonOnTheDual}; writes the determined contacts' forces Π_i(f⁰_i + T_iᵀ y),
     * their pieces and the gradient Σ T_i f_i + ρ y − τ.
     */
    private double evaluate(double[] yy, int n, int m, int d, double[] cones, double[] f, int[] pieces, double[] grad) {
        double phi = 0;
        for (int a = 0; a < d; a++) grad[a] = rho * yy[a] - tauActive[a];
        for (int i = 0; i < n; i++) {
            if (undetermined[i]) continue;
            double vx = ref[3 * i], vy = ref[3 * i + 1], vz = ref[3 * i + 2];
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

    /** H = Σ_i T_i DΠ_i T_iᵀ (+ ρ I when {@code regularised}) into {@code hess} (d×d). */
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

    /**
     * Lawson–Hanson non-negative least squares: x ≥ 0 minimising |A x − b| over the active rows
     * {@code joint[0..rows)}, A's column c at {@code a[3c .. 3c+2]} (one value per joint),
     * columns with {@code skip[c]} held at 0. {@code x} must be zero on entry; {@code passive}
     * and {@code zz} are scratch of at least {@code cols} entries; b is indexed by joint.
     */
    private void nnls(double[] a, double[] b, int cols, boolean[] skip, double[] x, boolean[] passive, double[] zz, int rows) {
        double[] r = lsResidual;
        for (int i = 0; i < cols; i++) passive[i] = false;
        for (int iter = 0; iter < MAX_ITER; iter++) {
            for (int q = 0; q < rows; q++) {
                int m = joint[q];
                double v = b[m];
                for (int j = 0; j < cols; j++) v -= a[3 * j + m] * x[j];
                r[m] = v;
            }
            int best = -1;
            double bestW = 1e-15;
            for (int i = 0; i < cols; i++) {
                if (passive[i] || skip[i]) continue;
                double w = 0;
                for (int q = 0; q < rows; q++) w += a[3 * i + joint[q]] * r[joint[q]];
                if (w > bestW) { bestW = w; best = i; }
            }
            if (best < 0) return;
            passive[best] = true;
            while (true) {
                leastSquaresOnPassive(a, b, cols, passive, zz, rows);
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
    private void leastSquaresOnPassive(double[] a, double[] b, int cols, boolean[] passive, double[] zz, int rows) {
        int p = 0;
        int[] idx = idxScratch;
        for (int i = 0; i < cols; i++) if (passive[i]) idx[p++] = i;
        double[] gm = gScratch, rhs = bScratch;
        for (int u = 0; u < p; u++) {
            for (int c = 0; c < p; c++) {
                double sum = 0;
                for (int q = 0; q < rows; q++) sum += a[3 * idx[u] + joint[q]] * a[3 * idx[c] + joint[q]];
                gm[u * p + c] = sum;
            }
            double sum = 0;
            for (int q = 0; q < rows; q++) sum += a[3 * idx[u] + joint[q]] * b[joint[q]];
            rhs[u] = sum;
        }
        // Cholesky with pivot check: a column dependent on earlier ones gets zero weight
        double scale = 0;
        for (int u = 0; u < p; u++) scale = Math.max(scale, gm[u * p + u]);
        boolean[] dead = deadScratch;
        java.util.Arrays.fill(dead, 0, p, false);
        for (int j = 0; j < p; j++) {
            double dj = gm[j * p + j];
            for (int k = 0; k < j; k++) if (!dead[k]) dj -= gm[j * p + k] * gm[j * p + k];
            if (dj <= 1e-12 * scale) { dead[j] = true; gm[j * p + j] = 1; continue; }
            double l = Math.sqrt(dj);
            gm[j * p + j] = l;
            for (int i = j + 1; i < p; i++) {
                double sum = gm[i * p + j];
                for (int k = 0; k < j; k++) if (!dead[k]) sum -= gm[i * p + k] * gm[j * p + k];
                gm[i * p + j] = sum / l;
            }
        }
        double[] yy = yScratch;
        for (int i = 0; i < p; i++) {
            if (dead[i]) { yy[i] = 0; continue; }
            double sum = rhs[i];
            for (int k = 0; k < i; k++) if (!dead[k]) sum -= gm[i * p + k] * yy[k];
            yy[i] = sum / gm[i * p + i];
        }
        for (int i = p - 1; i >= 0; i--) {
            if (dead[i]) { yy[i] = 0; continue; }
            double sum = yy[i];
            for (int k = i + 1; k < p; k++) if (!dead[k]) sum -= gm[k * p + i] * yy[k];
            yy[i] = sum / gm[i * p + i];
        }
        for (int i = 0; i < cols; i++) zz[i] = 0;
        for (int u = 0; u < p; u++) zz[idx[u]] = yy[u];
    }

    private void ensure(int n) {
        if (mag.length < n) {
            int c = Math.max(n, 2 * mag.length);
            arms = new double[3 * c];
            mag = new double[c];
            undetermined = new boolean[c];
            idxScratch = new int[c];
            gScratch = new double[c * c];
            bScratch = new double[c];
            yScratch = new double[c];
            deadScratch = new boolean[c];
        }
    }

    private void ensureCones(int n, int m) {
        if (tvec.length < 9 * n) {
            int c = Math.max(n, 2 * tvec.length / 9);
            tvec = new double[9 * c];
            fvec = new double[3 * c];
            ref = new double[3 * c];
            rays = new double[3 * c];
            fTrial = new double[3 * c];
            piece = new int[c];
            lastN = -1;
            pieceTrial = new int[c];
        }
        if (facetNormals.length < 3 * m * n) facetNormals = new double[Math.max(3 * m * n, 2 * facetNormals.length)];
    }

    /**
     * Eq (9) for a frictionless contact: the torque on the joint turning about frame m's z axis
     * from a force f·d at p, {@code (ẑ_m × (p − o_m))ᵀ (f d)} (the n_c term is zero).
     */
    public static double jointTorque(double[] frames, int m, double[] point, double[] dir, double f) {
        int o = 12 * m;
        double zx = frames[o + 2], zy = frames[o + 6], zz = frames[o + 10];
        double rx = point[0] - frames[o + 3], ry = point[1] - frames[o + 7], rz = point[2] - frames[o + 11];
        double cx = zy * rz - zz * ry, cy = zz * rx - zx * rz, cz = zx * ry - zy * rx;
        return (cx * dir[0] + cy * dir[1] + cz * dir[2]) * f;
    }

    /** @return the number of contacts of the last solve */
    public int count() { return count; }

    /** @return magnitude |f_i| ≥ 0 of contact i's force (newtons) */
    public double force(int i) { return mag[i]; }

    /** Contact i's force on the object (newtons, the frame of the inputs) into {@code out[off .. off+2]}. */
    public void forceVector(int i, double[] out, int off) {
        out[off] = fvec[3 * i]; out[off + 1] = fvec[3 * i + 1]; out[off + 2] = fvec[3 * i + 2];
    }

    /** Eq (9): the torque contact i's force puts on joint m (0-based), t_mi · f_i, N·m (0 for a joint beyond its link). */
    public double jointTorque(int i, int m) {
        int o = 9 * i + 3 * m;
        return tvec[o] * fvec[3 * i] + tvec[o + 1] * fvec[3 * i + 1] + tvec[o + 2] * fvec[3 * i + 2];
    }

    /**
     * Eq (9) summed: the torque all the contacts' forces put on joint m (0-based), N·m — for a
     * held joint the reaction of what holds it, for a driven one its torque when the forces carry
     * it ({@link #residual()} 0).
     */
    public double torqueOn(int m) {
        double sum = 0;
        for (int i = 0; i < count; i++) sum += jointTorque(i, m);
        return sum;
    }

    /**
     * @return true if no edge of contact i's cone has a moment arm of {@link #MIN_ARM_M} about a
     *         driven joint: the driven torques do not weigh it, and it carries its locked force
     *         (projected onto its cone), 0 without one
     */
    public boolean undetermined(int i) { return undetermined[i]; }

    /** @return moment arm a_mi = t_mi · d_i of contact i about joint m (0-based) along its direction, metres */
    public double arm(int i, int m) { return arms[3 * i + m]; }

    /**
     * How far the last solve's forces are from carrying the driven joints' torques, N·m: the
     * largest |τ_m − Σ_i t_mi · f_i| over the driven joints (eq 9 with the forces found). 0 up to
     * rounding when the contacts carry them; nonzero when no forces in the cones can (the finger
     * has no static equilibrium in that state).
     */
    public double residual() { return residual; }
}
