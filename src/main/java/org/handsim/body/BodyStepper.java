package org.handsim.body;

import java.util.Arrays;

/**
 * One time step of the free object with its contacts (DESIGN.md decision 7): the half kick of
 * {@link FreeBody}, one {@link ContactProblem} over the object's twist and the followers'
 * velocities solved by {@link ContactSolver}, the drift and second half kick; each contact's
 * impulse is written back into the {@link BodyContacts} (impulse / h = the contact force).
 *
 * <p><b>Rows of a contact</b> at p with normal n (into the object), tangents t₁, t₂: the object's
 * point moves with u + w × (p − x), so row d (d = n, t₁, t₂) is (dᵀ, ((p − x) × d)ᵀ) on the
 * twist, and −d·(z_j × (p − o_j)) on each follower j that moves the other body. The bias is
 * the other body's velocity along d, plus on the normal the gap's stabilisation
 * v̂ = −g/h for g ≥ 0 (close at most the gap in one step: touching, never passing) and
 * v̂ = −β·g/h for g &lt; 0 (a penetration pushed out at the fraction β = {@value #PUSH_OUT} per
 * step, Baumgarte's stabilisation; a full push-out would launch the object).
 *
 * <p><b>Followers</b> (a finger link that presses on the object): a rotation about a world axis
 * z through o with inertia D about it (kg·m²) and a torque τ (N·m, positive closing, about z),
 * starting each step at rest (the finger has no dynamics of its own: the worm holds it), so its
 * free velocity is hτ/D; a one-sided bound keeps its velocity ≥ 0 — the worm does not let the
 * object push it open. Against an object that holds, the link presses with impulse hτ through
 * its contacts; when the object gives way, the link follows it closing.
 *
 * <p><b>A follower's spring and its worm's hold.</b> A follower may press with a torque that falls
 * as it closes, τ − k·Δθ (an elastic preload let go, stiffness k in N·m/rad): taken at the
 * step's end, Δθ = h·v, its momentum balance is (D + h²k)·v = hτ + contact impulses, so the
 * metric is D + h²k and the free velocity hτ/(D + h²k) — the implicit step of a spring, stable at
 * any stiffness (taken at the step's start instead, a link of 2.6e-5 kg·m² on a 250 N·m/rad
 * preload, ωh ≈ 3 at 1 ms, rings and chatters). The worm's bound is v ≥ b: b = 0 holds the joint
 * where it is, and b = β·δ/h (β = {@value #PUSH_OUT}) takes back an opening δ it let through —
 * the bound, regularised like every constraint, yields by ε·W·γ per step under load, which left
 * alone is a creep that never stops.
 *
 * <p>Not thread-safe; allocation-free per step once grown.
 */
public final class BodyStepper {
    /** The fraction of a penetration pushed out per step (Baumgarte's β). */
    public static final double PUSH_OUT = 0.2;

    private final FreeBody body;
    private final ContactProblem problem = new ContactProblem();
    private final ContactSolver solver = new ContactSolver();
    private final double[] free = new double[6], twist = new double[6], iw = new double[9], x = new double[3];
    private int followers;
    private double[] fAxis = new double[12], fOrigin = new double[12], fInertia = new double[4], fTorque = new double[4];
    private double[] fVelocity = new double[4], fStiffness = new double[4], fWormBias = new double[4];
    private boolean[] fWorm = new boolean[4];
    private double[] fWormImpulse = new double[4];
    private final double[] t1 = new double[3], t2 = new double[3], rel = new double[3];
    private double time;
    private Tunnelling tunnelling;

    /** Steps {@code body}. */
    public BodyStepper(FreeBody body) {
        this.body = body;
    }

    /** @return the body it steps */
    public FreeBody body() { return body; }

    /** @return the problem of the last step (its constraints are the contacts, then the followers' bounds) */
    public ContactProblem problem() { return problem; }

    /** @return the solver of the last step */
    public ContactSolver solver() { return solver; }

    /**
     * Watches every step from now on for tunnelling: a point of the object moving more than
     * {@code marginM} (the contact margin) in one step ({@link Tunnelling}).
     *
     * @param reachM the object's reach from its centre of mass ({@link Tunnelling#reach})
     */
    public void watchTunnelling(double marginM, double reachM) {
        tunnelling = new Tunnelling(marginM, reachM);
    }

    /** @return what {@link #watchTunnelling} has seen so far, or null if it was not called */
    public Tunnelling tunnelling() { return tunnelling; }

    /** Sets the clock (s): the time the next step starts at; each step advances it by its h. */
    public void setTime(double timeS) { time = timeS; }

    /** @return the clock, s: the end of the last step */
    public double time() { return time; }

    /** Forgets the followers (call before adding this step's). */
    public void clearFollowers() { followers = 0; }

    /**
     * Adds a follower for the next step.
     *
     * @param axis     unit rotation axis, world (closing is positive about it)
     * @param origin   a point on the axis, world, m
     * @param inertia  D &gt; 0, kg·m², about the axis
     * @param torqueNm τ, N·m, positive closing
     * @return its index (for {@link BodyContacts#dependsOn})
     */
    public int addFollower(double[] axis, double[] origin, double inertia, double torqueNm) {
        return addFollower(axis, origin, inertia, torqueNm, true);
    }

    /**
     * {@link #addFollower(double[], double[], double, double)}, with or without the worm: a
     * follower not {@code wormHeld} has no bound on its velocity, so an object that pushes it
     * with more than τ drives it open (a joint that gives way at a torque, as an engaged clutch
     * does at its breakaway torque when τ is that).
     */
    public int addFollower(double[] axis, double[] origin, double inertia, double torqueNm, boolean wormHeld) {
        return addFollower(axis, origin, inertia, torqueNm, 0, wormHeld, 0);
    }

    /**
     * {@link #addFollower(double[], double[], double, double, boolean)} whose torque falls by
     * {@code stiffness}·Δθ as it closes by Δθ within the step (implicit; N·m/rad, ≥ 0), and
     * whose worm bound is v ≥ {@code wormBias} (rad/s, ≥ 0: what it takes back of an opening).
     */
    public int addFollower(double[] axis, double[] origin, double inertia, double torqueNm, double stiffness, boolean wormHeld,
                           double wormBias) {
        if (followers == fInertia.length) {
            int cap = 2 * followers;
            fAxis = Arrays.copyOf(fAxis, 3 * cap);
            fOrigin = Arrays.copyOf(fOrigin, 3 * cap);
            fInertia = Arrays.copyOf(fInertia, cap);
            fTorque = Arrays.copyOf(fTorque, cap);
            fVelocity = Arrays.copyOf(fVelocity, cap);
            fWorm = Arrays.copyOf(fWorm, cap);
            fWormImpulse = Arrays.copyOf(fWormImpulse, cap);
            fStiffness = Arrays.copyOf(fStiffness, cap);
            fWormBias = Arrays.copyOf(fWormBias, cap);
        }
        int j = followers++;
        System.arraycopy(axis, 0, fAxis, 3 * j, 3);
        System.arraycopy(origin, 0, fOrigin, 3 * j, 3);
        fInertia[j] = inertia;
        fTorque[j] = torqueNm;
        fWorm[j] = wormHeld;
        fStiffness[j] = stiffness;
        fWormBias[j] = wormBias;
        return j;
    }

    /** @return follower j's velocity over the last step, rad/s (≥ 0: closing) */
    public double followerVelocity(int j) { return fVelocity[j]; }

    /** Follower j's worm reaction over the last step, N·m·s (the impulse holding it against opening; 0 without the worm). */
    public double wormImpulse(int j) { return fWormImpulse[j]; }

    /**
     * Advances the body by h under force f and torque τ (world, at the centre of mass) with the
     * contacts given (their impulses written back).
     *
     * @return how the solve ended
     */
    public ContactSolver.Outcome step(double h, double[] force, double[] torque, BodyContacts contacts) {
        body.beginStep(h, force, torque, free);
        int nc = contacts.n;
        if (nc == 0 && followers == 0) {
            body.endStep(h, free, force, torque);
            watch(h, free);
            return ContactSolver.Outcome.CONVERGED;
        }
        int nv = 6 + followers;
        problem.begin(nv);
        body.worldInertia(iw);
        problem.setObject(body.mass(), iw, free);
        for (int j = 0; j < followers; j++) {
            double d = fInertia[j] + h * h * fStiffness[j];
            problem.setScalar(6 + j, d, h * fTorque[j] / d);
        }
        body.position(x);
        double[] jac = problem.jacobian(), bias = problem.bias();
        for (int i = 0; i < nc; i++) {
            int c = problem.addConstraint(contacts.mu[i]);
            jac = problem.jacobian();
            bias = problem.bias();
            double nx = contacts.normal[3 * i], ny = contacts.normal[3 * i + 1], nz = contacts.normal[3 * i + 2];
            tangents(nx, ny, nz, t1, t2);
            double rx = contacts.point[3 * i] - x[0], ry = contacts.point[3 * i + 1] - x[1], rz = contacts.point[3 * i + 2] - x[2];
            double ox = contacts.other[3 * i], oy = contacts.other[3 * i + 1], oz = contacts.other[3 * i + 2];
            row(jac, (3 * c) * nv, rx, ry, rz, nx, ny, nz);
            row(jac, (3 * c + 1) * nv, rx, ry, rz, t1[0], t1[1], t1[2]);
            row(jac, (3 * c + 2) * nv, rx, ry, rz, t2[0], t2[1], t2[2]);
            double g = contacts.gap[i];
            bias[3 * c] = ox * nx + oy * ny + oz * nz + (g >= 0 ? -g / h : -PUSH_OUT * g / h);
            bias[3 * c + 1] = ox * t1[0] + oy * t1[1] + oz * t1[2];
            bias[3 * c + 2] = ox * t2[0] + oy * t2[1] + oz * t2[2];
            for (int k = 0; k < BodyContacts.MAX_JOINTS; k++) {
                int j = contacts.joints[BodyContacts.MAX_JOINTS * i + k];
                if (j < 0) break;
                // the link's point moves with z × (p − o) per unit joint velocity: minus that on the relative velocity
                double px = contacts.point[3 * i] - fOrigin[3 * j], py = contacts.point[3 * i + 1] - fOrigin[3 * j + 1],
                    pz = contacts.point[3 * i + 2] - fOrigin[3 * j + 2];
                double zx = fAxis[3 * j], zy = fAxis[3 * j + 1], zz = fAxis[3 * j + 2];
                rel[0] = zy * pz - zz * py; rel[1] = zz * px - zx * pz; rel[2] = zx * py - zy * px;
                int col = 6 + j;
                jac[(3 * c) * nv + col] = -(rel[0] * nx + rel[1] * ny + rel[2] * nz);
                jac[(3 * c + 1) * nv + col] = -(rel[0] * t1[0] + rel[1] * t1[1] + rel[2] * t1[2]);
                jac[(3 * c + 2) * nv + col] = -(rel[0] * t2[0] + rel[1] * t2[1] + rel[2] * t2[2]);
            }
        }
        int firstWorm = nc;   // the contacts are constraints 0..nc-1, the worms follow
        for (int j = 0; j < followers; j++) {
            if (!fWorm[j]) continue;
            int c = problem.addConstraint(0);
            problem.jacobian()[(3 * c) * nv + 6 + j] = 1;   // the worm: velocity ≥ its bias
            problem.bias()[3 * c] = fWormBias[j];
        }
        ContactSolver.Outcome out = solver.solveCoulomb(problem);
        solver.velocities(twist, 6);
        for (int j = 0, w = firstWorm; j < followers; j++) {
            fVelocity[j] = solver.velocity(6 + j);
            fWormImpulse[j] = fWorm[j] ? solver.impulse(w++, 0) : 0;
        }
        for (int i = 0; i < nc; i++) {
            double nx = contacts.normal[3 * i], ny = contacts.normal[3 * i + 1], nz = contacts.normal[3 * i + 2];
            tangents(nx, ny, nz, t1, t2);
            double gn = solver.impulse(i, 0), g1 = solver.impulse(i, 1), g2 = solver.impulse(i, 2);
            for (int k = 0; k < 3; k++) {
                contacts.impulse[3 * i + k] = gn * contacts.normal[3 * i + k] + g1 * t1[k] + g2 * t2[k];
            }
        }
        body.endStep(h, twist, force, torque);
        watch(h, twist);
        return out;
    }

    /** Advances the clock by h and shows the step's twist to the tunnelling watch. */
    private void watch(double h, double[] tw) {
        time += h;
        if (tunnelling != null) tunnelling.observe(time, h, tw[0], tw[1], tw[2], tw[3], tw[4], tw[5]);
    }

    /** Row (dᵀ, (r × d)ᵀ) into jac[o..o+5]. */
    private static void row(double[] jac, int o, double rx, double ry, double rz, double dx, double dy, double dz) {
        jac[o] = dx; jac[o + 1] = dy; jac[o + 2] = dz;
        jac[o + 3] = ry * dz - rz * dy;
        jac[o + 4] = rz * dx - rx * dz;
        jac[o + 5] = rx * dy - ry * dx;
    }

    /** An orthonormal pair t₁, t₂ with t₁ × t₂ = n (n unit): t₁ = n × a/|n × a|, a = e_x unless n is near it. */
    static void tangents(double nx, double ny, double nz, double[] t1, double[] t2) {
        double ax, ay, az;
        if (Math.abs(nx) < 0.9) { ax = 0; ay = nz; az = -ny; } else { ax = -nz; ay = 0; az = nx; }
        double l = Math.sqrt(ax * ax + ay * ay + az * az);
        t1[0] = ax / l; t1[1] = ay / l; t1[2] = az / l;
        t2[0] = ny * t1[2] - nz * t1[1];
        t2[1] = nz * t1[0] - nx * t1[2];
        t2[2] = nx * t1[1] - ny * t1[0];
    }
}
