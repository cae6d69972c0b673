package org.handsim.kinematics;

import java.util.ArrayList;
import java.util.List;
import org.handsim.hand.FingerDescription;
import org.handsim.hand.HandDescription;
import org.handsim.math.Vec3;

/**
 * Closed-form inverse kinematics of one finger (paper Section II.B, eqs 5–7), with joint
 * limits, every branch, and the closest reachable point when the target is out of reach.
 *
 * <p><b>Geometry.</b> With α1 = 90°, links 2 and 3 move in the vertical plane through the
 * spread axis at angle θk1. Writing φ2 = θk2 + Φ2 and φ3 = θk3 + Φ3 (the DH angles), the
 * fingertip in {k0} is {@code (r cos θk1, r sin θk1, z)} with
 * {@code r = A1 + A2 cos φ2 + A3 cos(φ2+φ3)}, {@code z = A2 sin φ2 + A3 sin(φ2+φ3)}. So
 * <ul>
 *   <li>eq (5): θk1 = atan2(p_y, p_x), and the second branch θk1 + π with r = −ρ
 *       (ρ = √(p_x² + p_y²)); finger 3 has θ31 ≡ 0 and needs p_y = 0;</li>
 *   <li>eq (6): cos φ3 = ((r − A1)² + p_z² − A2² − A3²) / (2 A2 A3), φ3 = ±acos;</li>
 *   <li>eq (7): φ2 = atan2(p_z, r − A1) − atan2(A3 sin φ3, A2 + A3 cos φ3).</li>
 * </ul>
 * atan2 is used throughout (eq 5 as printed, arctan(p_y/p_x), loses the quadrant).
 *
 * <p><b>Edges handled on purpose.</b> A target on the spread axis (ρ = 0) takes θk1 = 0; an
 * arccos argument a rounding hair outside [−1, 1] (|c| − 1 ≤ 1e−12) is clamped, farther out is
 * out of reach; a stretched finger (θk3 at its limit) and a target behind the palm (below
 * {k0}) fall to the closest-point search.
 *
 * <p><b>Closest reachable point.</b> With the joints inside their limits, the reachable set in
 * the finger plane is the image W of the rectangle [θ2 limits] × [θ3 limits]; since φ3 stays
 * inside (0, π) there, the boundary of W is the image of the rectangle's four edges, four
 * circular arcs. For the spread, the distance from the target at azimuth ψ to the plane at
 * θk1 = ψ + δ splits as (ρ sin δ)² + dist_W((ρ cos δ, p_z))², whose minimum over the allowed
 * θk1 lies at δ = 0, δ = π or an end of the spread range (the interior stationary condition
 * puts the closest point on the spread axis, where every δ is equal). Each candidate is solved
 * exactly; nothing iterates.
 *
 * <p>Thread-safe (no mutable state).
 */
public final class InverseKinematics {
    /** A target within this distance (metres) of a point inside the limits is reachable. */
    public static final double REACH_TOLERANCE_M = 1e-9;
    /** Joint-limit slack (radians) absorbing rounding in the closed form. */
    static final double LIMIT_SLACK = 1e-12;
    /** How far outside [−1, 1] an arccos argument is treated as rounding. */
    static final double ACOS_SLACK = 1e-12;

    private final FingerKinematics fk;
    private final FingerDescription finger;
    private final double a1, a2, a3, phi2, phi3;
    private final double t1lo, t1hi, t2lo, t2hi, t3lo, t3hi;

    public InverseKinematics(HandDescription hand, int k) {
        this.finger = hand.finger(k);
        this.fk = new FingerKinematics(finger);
        this.a1 = finger.dh(0).a();
        this.a2 = finger.dh(1).a();
        this.a3 = finger.dh(2).a();
        this.phi2 = finger.dh(1).thetaOffset();
        this.phi3 = finger.dh(2).thetaOffset();
        double[] spread = hand.spreadLimits();
        if (!finger.hasSpread()) {
            t1lo = t1hi = 0;
        } else if (finger.spreadRadPerCount() < 0) {
            t1lo = -spread[1];
            t1hi = -spread[0];
        } else {
            t1lo = spread[0];
            t1hi = spread[1];
        }
        double[] l2 = hand.theta2Limits(), l3 = hand.theta3Limits();
        t2lo = l2[0]; t2hi = l2[1];
        t3lo = l3[0]; t3hi = l3[1];
    }

    /** Finger k of the BarrettHand. */
    public static InverseKinematics of(int k) {
        return new InverseKinematics(HandDescription.barrettHand(), k);
    }

    public FingerKinematics forward() { return fk; }

    /** Spread limits {lo, hi} of θk1 in radians ({0, 0} for finger 3). */
    public double[] spreadLimits() { return new double[] {t1lo, t1hi}; }

    /**
     * Solves for a fingertip target given in the palm frame {P}; the result's fingertip is in {P}.
     */
    public IkResult solveInPalm(double[] targetInPalm) {
        double[] local = fk.baseInPalm().inverse().apply(checkTarget(targetInPalm));
        IkResult r = solve(local);
        return new IkResult(r.reachable(), r.joints(), fk.baseInPalm().apply(r.fingertip()), r.errorM(), r.branches());
    }

    /**
     * Solves for a fingertip target in the finger's base frame {k0} (metres).
     *
     * @throws IllegalArgumentException if the target is not a finite 3-vector
     */
    public IkResult solve(double[] target) {
        checkTarget(target);
        double px = target[0], py = target[1], pz = target[2];
        double rho = Math.hypot(px, py);
        double psi = rho == 0 ? 0 : Math.atan2(py, px);

        List<IkSolution> branches = new ArrayList<>(4);
        if (finger.hasSpread()) {
            addBranches(branches, psi, rho, pz);
            addBranches(branches, wrap(psi + Math.PI), -rho, pz);
        } else if (Math.abs(py) <= REACH_TOLERANCE_M) {
            addBranches(branches, 0, px, pz);
        }
        for (IkSolution b : branches) {
            if (b.withinLimits()) {
                double[] j = b.joints();
                double[] tip = fk.fingertip(j);
                double err = Vec3.distance(tip, target);
                if (err <= REACH_TOLERANCE_M) return new IkResult(true, j, tip, err, branches);
            }
        }
        double[] best = closest(px, py, pz, rho, psi);
        double[] tip = fk.fingertip(best);
        double err = Vec3.distance(tip, target);
        return new IkResult(err <= REACH_TOLERANCE_M, best, tip, err, branches);
    }

    /** Adds the elbow branches of eqs (6)–(7) for the plane at θk1 with signed radius r. */
    private void addBranches(List<IkSolution> out, double theta1, double r, double z) {
        double phi3abs = elbowAbs(r, z);
        if (Double.isNaN(phi3abs)) return;
        for (int sign = 1; sign >= -1; sign -= 2) {
            double[] j = {theta1, 0, 0};
            elbowJoints(r, z, sign * phi3abs, j, 1);
            boolean ok = clampIfClose(j);
            out.add(new IkSolution(j, ok));
            if (phi3abs == 0) break; // the two branches coincide
        }
    }

    /** |φ3| of eq (6) for the point (r, z) of the finger plane (r signed), or NaN when no elbow angle reaches it. */
    private double elbowAbs(double r, double z) {
        double u = r - a1;
        double c = (u * u + z * z - a2 * a2 - a3 * a3) / (2 * a2 * a3);
        return Math.abs(c) > 1 + ACOS_SLACK ? Double.NaN : Math.acos(Math.max(-1, Math.min(1, c)));
    }

    /** The joint angles {θk2, θk3} of the elbow branch φ3 = p3 (eq 7) into out[off], out[off + 1]. */
    private void elbowJoints(double r, double z, double p3, double[] out, int off) {
        double p2 = Math.atan2(z, r - a1) - Math.atan2(a3 * Math.sin(p3), a2 + a3 * Math.cos(p3));
        out[off] = wrap(p2 - phi2);
        out[off + 1] = wrap(p3 - phi3);
    }

    /** Snaps joints lying within LIMIT_SLACK outside a limit onto it; returns true if all within. */
    private boolean clampIfClose(double[] j) {
        return clampOne(j, 0, t1lo, t1hi) & clampOne(j, 1, t2lo, t2hi) & clampOne(j, 2, t3lo, t3hi);
    }

    private static boolean clampOne(double[] j, int i, double lo, double hi) {
        if (j[i] < lo) {
            if (j[i] < lo - LIMIT_SLACK) return false;
            j[i] = lo;
        } else if (j[i] > hi) {
            if (j[i] > hi + LIMIT_SLACK) return false;
            j[i] = hi;
        }
        return true;
    }

    /** Joints (inside the limits) of the reachable point closest to the target. */
    private double[] closest(double px, double py, double pz, double rho, double psi) {
        double[] cand = finger.hasSpread()
            ? new double[] {psi, wrap(psi + Math.PI), t1lo, t1hi}
            : new double[] {0};
        double bestD = Double.POSITIVE_INFINITY;
        double[] best = null;
        double[] planar = new double[2];
        for (double t1 : cand) {
            if (t1 < t1lo - LIMIT_SLACK || t1 > t1hi + LIMIT_SLACK) continue;
            t1 = Math.max(t1lo, Math.min(t1hi, t1));
            double delta = t1 - psi;
            // for finger 3 (t1 = 0) this is the plane y = 0: (px, pz) with residual |py|
            double x = finger.hasSpread() ? rho * Math.cos(delta) : px;
            double off = finger.hasSpread() ? rho * Math.sin(delta) : py;
            double dPlane = planarClosest(x, pz, planar);
            double d = Math.hypot(dPlane, off);
            if (d < bestD) {
                bestD = d;
                best = new double[] {t1, planar[0], planar[1]};
            }
        }
        return best;
    }

    /**
     * Closest point of the joint-limited planar workspace W to (x, z) in the finger plane (x the
     * signed distance from the spread axis). Writes {θ2, θ3} into {@code out}; returns the
     * distance (0 when inside W).
     */
    double planarClosest(double x, double z, double[] out) {
        double phi3abs = elbowAbs(x, z);
        if (!Double.isNaN(phi3abs)) {
            for (int sign = 1; sign >= -1; sign -= 2) {
                elbowJoints(x, z, sign * phi3abs, out, 0);
                double t2 = out[0], t3 = out[1];
                if (t2 >= t2lo - LIMIT_SLACK && t2 <= t2hi + LIMIT_SLACK && t3 >= t3lo - LIMIT_SLACK && t3 <= t3hi + LIMIT_SLACK) {
                    out[0] = Math.max(t2lo, Math.min(t2hi, t2));
                    out[1] = Math.max(t3lo, Math.min(t3hi, t3));
                    return 0;
                }
            }
        }
        double best = Double.POSITIVE_INFINITY;
        double[] arc = new double[2];
        // (a) θ2 at a limit, θ3 varies: circle of radius A3 about the elbow
        for (double t2 : new double[] {t2lo, t2hi}) {
            double p2 = t2 + phi2;
            double cx = a1 + a2 * Math.cos(p2), cz = a2 * Math.sin(p2);
            double d = arcClosest(x, z, cx, cz, a3, p2 + t3lo + phi3, p2 + t3hi + phi3, arc);
            if (d < best) {
                best = d;
                out[0] = t2;
                out[1] = arc[0] - p2 - phi3;
            }
        }
        // (b) θ3 at a limit, θ2 varies: circle of radius |A2 + A3 e^{iφ3}| about the joint-2 axis
        for (double t3 : new double[] {t3lo, t3hi}) {
            double p3 = t3 + phi3;
            double lx = a2 + a3 * Math.cos(p3), lz = a3 * Math.sin(p3);
            double radius = Math.hypot(lx, lz), beta = Math.atan2(lz, lx);
            double d = arcClosest(x, z, a1, 0, radius, t2lo + phi2 + beta, t2hi + phi2 + beta, arc);
            if (d < best) {
                best = d;
                out[0] = arc[0] - beta - phi2;
                out[1] = t3;
            }
        }
        out[0] = Math.max(t2lo, Math.min(t2hi, out[0]));
        out[1] = Math.max(t3lo, Math.min(t3hi, out[1]));
        return best;
    }

    /**
     * Closest point to (x, z) on the arc of the circle (cx, cz, radius) with angles in [g0, g1]
     * (g1 − g0 &lt; 2π). Writes the angle of the closest point into {@code angleOut[0]}.
     */
    static double arcClosest(double x, double z, double cx, double cz, double radius, double g0, double g1, double[] angleOut) {
        double dx = x - cx, dz = z - cz;
        double gp = Math.atan2(dz, dx);
        double rel = gp - g0;
        rel -= 2 * Math.PI * Math.floor(rel / (2 * Math.PI));
        double g;
        if (rel <= g1 - g0) {
            g = g0 + rel;
        } else {
            double d0 = Math.hypot(x - cx - radius * Math.cos(g0), z - cz - radius * Math.sin(g0));
            double d1 = Math.hypot(x - cx - radius * Math.cos(g1), z - cz - radius * Math.sin(g1));
            g = d0 <= d1 ? g0 : g1;
        }
        angleOut[0] = g;
        return Math.hypot(x - cx - radius * Math.cos(g), z - cz - radius * Math.sin(g));
    }

    /** Wraps an angle into (−π, π]. */
    static double wrap(double a) {
        double w = Math.IEEEremainder(a, 2 * Math.PI);
        return w <= -Math.PI ? w + 2 * Math.PI : w;
    }

    /** @throws IllegalArgumentException naming the coordinate, unless {@code t} is a finite 3-vector */
    static double[] checkTarget(double[] t) {
        if (t == null || t.length != 3) throw new IllegalArgumentException("target must have 3 coordinates");
        for (int i = 0; i < 3; i++) {
            if (!Double.isFinite(t[i])) {
                throw new IllegalArgumentException("target coordinate " + "xyz".charAt(i) + " = " + t[i] + " is not finite");
            }
        }
        return t;
    }
}
