package org.handsim.grasp;

import java.util.ArrayList;
import java.util.List;
import org.ojalgo.optimisation.Optimisation;
import org.ojalgo.optimisation.linear.LinearSolver;
import org.ojalgo.structure.Mutate2D;

/**
 * How much load a grasp holds (DESIGN.md decision 6): for a disturbance force F·d on
 * the object through the torque origin c, the largest F for which contact forces inside the
 * linearised friction cones balance it — force and torque about c —
 * <pre>  Σ_i f_i + F d = 0,   Σ_i (p_i − c) × f_i = 0,   f_i = Σ_e λ_ie e_ie,  λ_ie ≥ 0,</pre>
 * while every joint's torque stays within what that joint can resist,
 * <pre>  −L_j ≤ Σ_{i loads j} (z_j × (p_i − o_j)) · f_i ≤ L_j,</pre>
 * (eq 9 with the force's full direction: the torque joint j must supply for the finger to apply
 * f_i), and F ≤ F_cap. A linear program, solved by ojAlgo's revised (phased dual/primal) simplex
 * through its double-valued {@link LinearSolver.Builder} — the solver {@code ExpressionsBasedModel}
 * uses, without that model's BigDecimal coefficients and presolve, which cost 6× the solve here
 * (docs/BENCHMARKS.md, "The hold LP"); Murray, Li, Sastry, <i>A Mathematical Introduction to
 * Robotic Manipulation</i>, §5.3–5.5, for contact models and internal forces.
 *
 * <p><b>Outcomes</b> ({@link Result#outcome()}), never NaN or infinity:
 * <ul>
 *   <li>{@link Outcome#HELD}: the LP's optimum F &lt; F_cap;</li>
 *   <li>{@link Outcome#CAPPED}: the joints' limits allow F_cap or more — also when they allow any
 *       load (contacts whose forces load no limited joint, e.g. on a link fixed to the palm, or
 *       pushing through every joint axis: the LP without the cap is unbounded). The caller
 *       documents F_cap (the simulator uses the hand's rated payload);</li>
 *   <li>{@link Outcome#NO_CONTACTS}: F = 0;</li>
 *   <li>{@link Outcome#SOLVER_FAILED}: the solver reported neither optimum nor a known state
 *       (not seen in the tests): F = 0, the safe answer.</li>
 * </ul>
 * F = 0 with {@code HELD} means no load at all in that direction can be balanced (e.g.
 * frictionless contacts against a tangential load). The LP is always feasible (all forces 0,
 * F = 0), so "infeasible" cannot happen.
 *
 * <p>Scaling: the torque-balance rows are divided by the characteristic length R (as the grasp
 * wrench space's torques, {@link GraspWrenches}), so every row is in newtons; this conditions
 * the LP and does not change its solution.
 *
 * <p>Use: build once per grasp ({@link #addJoint}, {@link #addContact}), then {@link #hold}
 * per direction. Not thread-safe.
 */
public final class HoldCapacity {
    /** The six world directions of {@link #holdSix()}: +x, −x, +y, −y, +z, −z. */
    public static final double[][] SIX_DIRECTIONS = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

    /** How the LP ended. */
    public enum Outcome { HELD, CAPPED, NO_CONTACTS, SOLVER_FAILED }

    /**
     * The answer for one direction.
     *
     * @param forceN       the largest load F, newtons (0 ≤ F ≤ F_cap)
     * @param outcome      how the LP ended
     * @param contactForces the contact forces f_i at the optimum, 3 per contact, newtons (zeros
     *                     unless {@code HELD} or {@code CAPPED})
     * @param jointTorques the torque each joint carries at the optimum, N·m, in the order the
     *                     joints were added
     */
    public record Result(double forceN, Outcome outcome, double[] contactForces, double[] jointTorques) {}

    /**
     * The solver's options, one per thread: ojAlgo's {@code build()} makes new ones every time,
     * and making them (number formats) cost 14 % of the six LPs.
     */
    private static final ThreadLocal<Optimisation.Options> OPTIONS = ThreadLocal.withInitial(Optimisation.Options::new);

    private final double mu;
    private final int edges;
    private final double[] center;
    private final double radius;
    private final double capN;
    private final List<double[]> joints = new ArrayList<>();      // {zx, zy, zz, ox, oy, oz, L}
    private final List<double[]> contacts = new ArrayList<>();    // {px, py, pz, nx, ny, nz}
    private final List<int[]> loads = new ArrayList<>();          // the joints each contact loads
    // the LP's coefficients, made at the first hold() after the last change (null: to be made)
    private double[] wrenches;
    private double[][] balance, torquePerEdge;
    private boolean[] jointUsed;

    /**
     * @param mu     Coulomb coefficient μ ≥ 0 of every contact
     * @param edges  edges m ≥ 1 of the linearised cones ({@link FrictionCone})
     * @param center the torque origin c (the point the disturbance acts through), metres
     * @param radius characteristic length R &gt; 0 for the scaling of the torque rows, metres
     * @param capN   the largest load ever reported, F_cap &gt; 0, newtons (finite)
     */
    public HoldCapacity(double mu, int edges, double[] center, double radius, double capN) {
        this.mu = FrictionCone.checkMu(mu);
        this.edges = FrictionCone.checkEdges(edges);
        if (center.length != 3 || !finite(center)) throw new IllegalArgumentException("center must be 3 finite numbers");
        if (!(radius > 0) || !Double.isFinite(radius)) throw new IllegalArgumentException("radius must be a finite number > 0, got " + radius);
        if (!(capN > 0) || !Double.isFinite(capN)) throw new IllegalArgumentException("load cap must be a finite number > 0, got " + capN);
        this.center = center.clone();
        this.radius = radius;
        this.capN = capN;
    }

    /**
     * Adds a joint: it turns about the unit axis z through the point o and resists torques up to
     * |τ| ≤ L.
     *
     * @return its index, for {@link #addContact}
     */
    public int addJoint(double[] axis, double[] origin, double limitNm) {
        if (!(limitNm >= 0) || !Double.isFinite(limitNm)) {
            throw new IllegalArgumentException("joint torque limit must be a finite number >= 0, got " + limitNm);
        }
        double l = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        if (!(l > 0) || !finite(axis) || !finite(origin)) throw new IllegalArgumentException("joint axis and origin must be finite, the axis non-zero");
        joints.add(new double[] {axis[0] / l, axis[1] / l, axis[2] / l, origin[0], origin[1], origin[2], limitNm});
        wrenches = null;
        return joints.size() - 1;
    }

    /**
     * Adds a contact at p whose normal n points into the object (the direction the finger
     * pushes), on a link whose force loads the given joints (none: a link fixed to the palm).
     */
    public void addContact(double[] point, double[] normal, int... jointIndices) {
        if (!finite(point) || !finite(normal)) throw new IllegalArgumentException("contact point and normal must be finite");
        for (int j : jointIndices) {
            if (j < 0 || j >= joints.size()) throw new IllegalArgumentException("no joint " + j + " (" + joints.size() + " added)");
        }
        contacts.add(new double[] {point[0], point[1], point[2], normal[0], normal[1], normal[2]});
        loads.add(jointIndices.clone());
        wrenches = null;
    }

    /** @return the number of contacts added */
    public int contactCount() { return contacts.size(); }

    /** The largest load in each of {@link #SIX_DIRECTIONS}, newtons. */
    public double[] holdSix() {
        double[] out = new double[6];
        for (int d = 0; d < 6; d++) out[d] = hold(SIX_DIRECTIONS[d]).forceN();
        return out;
    }

    /**
     * The largest load F through c along the unit direction d (normalised here) that the grasp
     * holds, with the contact forces and joint torques that hold it.
     */
    public Result hold(double[] direction) {
        double dl = Math.sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
        if (!(dl > 0) || !finite(direction)) throw new IllegalArgumentException("load direction must be a finite non-zero vector");
        int n = contacts.size(), nj = joints.size(), m = edges;
        if (n == 0) return new Result(0, Outcome.NO_CONTACTS, new double[0], new double[nj]);
        if (wrenches == null) coefficients();
        // x = (F, λ): minimise −F; the balance rows as equalities, each used joint's range as two
        // inequalities (τ ≤ L, −τ ≤ L), 0 ≤ F ≤ F_cap, λ ≥ 0 (the builder's default bound)
        int nv = 1 + n * m, used = 0;
        for (int j = 0; j < nj; j++) if (jointUsed[j]) used++;
        double[] objective = new double[nv];
        objective[0] = -1;
        LinearSolver.Builder lp = LinearSolver.newBuilder(objective);
        Mutate2D eq = lp.equalities(new double[6]);
        for (int r = 0; r < 6; r++) {
            if (r < 3 && direction[r] != 0) eq.set(r, 0, direction[r] / dl);
            for (int v = 0; v < n * m; v++) if (balance[r][v] != 0) eq.set(r, 1 + v, balance[r][v]);
        }
        double[] limits = new double[2 * used];
        int q = 0;
        for (int j = 0; j < nj; j++) if (jointUsed[j]) { limits[q] = limits[q + 1] = joints.get(j)[6]; q += 2; }
        Mutate2D in = used > 0 ? lp.inequalities(limits) : null;   // (ojAlgo 57.1 refuses an empty block)
        q = 0;
        for (int j = 0; j < nj && used > 0; j++) {
            if (!jointUsed[j]) continue;
            for (int v = 0; v < n * m; v++) {
                double t = torquePerEdge[j][v];
                if (t != 0) { in.set(q, 1 + v, t); in.set(q + 1, 1 + v, -t); }
            }
            q += 2;
        }
        lp.range(0, 0, capN);
        Optimisation.Result r = lp.build(OPTIONS.get()).solve();
        if (!r.getState().isOptimal()) return new Result(0, Outcome.SOLVER_FAILED, new double[3 * n], new double[nj]);
        double f = Math.max(0, Math.min(capN, r.doubleValue(0)));
        double[] forces = new double[3 * n];
        double[] w = new double[n * m];
        for (int v = 0; v < n * m; v++) w[v] = Math.max(0, r.doubleValue(1 + v));
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < m; k++) {
                int o = 6 * (i * m + k);
                for (int c = 0; c < 3; c++) forces[3 * i + c] += w[i * m + k] * wrenches[o + c];
            }
        }
        double[] torques = new double[nj];
        for (int j = 0; j < nj; j++) for (int v = 0; v < n * m; v++) torques[j] += torquePerEdge[j][v] * w[v];
        Outcome outcome = f >= capN * (1 - 1e-9) ? Outcome.CAPPED : Outcome.HELD;
        return new Result(f, outcome, forces, torques);
    }

    /**
     * The LP's coefficients, which do not depend on the load's direction: the balance rows, the
     * edge wrenches of {@link GraspWrenches#of} (force; torque about c divided by R), and each
     * joint's torque per edge weight.
     */
    private void coefficients() {
        int n = contacts.size(), nj = joints.size(), m = edges;
        double[] points = new double[3 * n], normals = new double[3 * n];
        for (int i = 0; i < n; i++) {
            double[] c = contacts.get(i);
            System.arraycopy(c, 0, points, 3 * i, 3);
            System.arraycopy(c, 3, normals, 3 * i, 3);
        }
        // the edge wrenches of the grasp wrench space: (f, (p − c) × f / R) per cone edge
        double[] w = GraspWrenches.of(n, points, normals, mu, m, center, radius);
        balance = new double[6][n * m];
        for (int v = 0; v < n * m; v++) {
            for (int r = 0; r < 6; r++) balance[r][v] = w[6 * v + r];
        }
        torquePerEdge = new double[nj][n * m];
        jointUsed = new boolean[nj];
        for (int j = 0; j < nj; j++) {
            double[] jt = joints.get(j);
            for (int i = 0; i < n; i++) {
                if (!contains(loads.get(i), j)) continue;
                double[] c = contacts.get(i);
                double rx = c[0] - jt[3], ry = c[1] - jt[4], rz = c[2] - jt[5];
                double tx = jt[1] * rz - jt[2] * ry, ty = jt[2] * rx - jt[0] * rz, tz = jt[0] * ry - jt[1] * rx;
                for (int k = 0; k < m; k++) {
                    int o = 6 * (i * m + k);
                    torquePerEdge[j][i * m + k] = tx * w[o] + ty * w[o + 1] + tz * w[o + 2];
                    jointUsed[j] |= torquePerEdge[j][i * m + k] != 0;
                }
            }
        }
        wrenches = w;
    }

    private static boolean contains(int[] a, int x) {
        for (int v : a) if (v == x) return true;
        return false;
    }

    private static boolean finite(double[] v) {
        for (double x : v) if (!Double.isFinite(x)) return false;
        return true;
    }
}
