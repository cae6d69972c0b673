package org.handsim.body;

import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;

/**
 * A rigid body moving freely in space: its {@link MassProperties}, its pose (centre of mass x
 * and orientation q, body → world) and its motion (velocity v of the centre of mass, angular
 * momentum L about it, world frame), advanced by a velocity-level time step into which a
 * contact solve fits (DESIGN.md decision 7).
 *
 * <p><b>The step</b> (size h; force f and torque τ about the centre of mass held over it) is a
 * kick–drift–kick splitting (velocity Verlet; Hairer, Lubich, Wanner, <i>Geometric Numerical
 * Integration</i>, 2nd ed., §I.1.4, §VI.3):
 * <ol>
 *   <li>{@link #beginStep}: half kick, v ← v + h/2·f/m, L ← L + h/2·τ; then the free twist
 *       over the step: u* = v and ω*, the angular velocity of the torque-free rotation over h
 *       (below);</li>
 *   <li>a contact solve replaces (u*, ω*) by the twist (u, w) the contacts allow
 *       ({@link ContactSolver}), with the metric A = diag(m·E, I_w), I_w = R I Rᵀ at the
 *       step's start ({@link #worldInertia});</li>
 *   <li>{@link #endStep}: drift, x ← x + h·u, q ← cay(h·w) ⊗ q; the contacts' impulse enters
 *       the momenta, v ← u, L ← L + I_w(w − ω*); second half kick.</li>
 * </ol>
 * Without contacts (u, w) = (u*, ω*) and the step is exact for a constant force (free fall:
 * x = x₀ + v₀t + ½gt² to rounding, since x advances by h(v + h/2·g)).
 *
 * <p><b>Free rotation</b> (Euler's equations, L̇_b = L_b × I⁻¹L_b in the body frame) is
 * advanced by the implicit midpoint rule on L_b with the orientation moved by the Cayley map of
 * the midpoint angular velocity: L_b' = cay(−hω̂_m)L_b, R' = R·cay(hω̂_m), ω_m = I⁻¹(L_b + L_b')/2
 * (the midpoint equation solved by Newton's method to rounding). So R'L_b' = R L_b: the spatial
 * angular momentum is kept exactly, and the kinetic energy ½L_b·I⁻¹L_b, a quadratic invariant,
 * is kept by the midpoint rule (HLW §IV.2, §VII.5: a Lie–Poisson integrator). The map is
 * symmetric, so Yoshida's triple jump (steps γ₁h, γ₂h, γ₁h, γ₁ = 1/(2 − 2^{1/3}),
 * γ₂ = 1 − 2γ₁; HLW §II.4) makes it fourth order and keeps both invariants; ω* is the angular
 * velocity whose Cayley map over h is that rotation, so with no contact the drift reproduces it.
 *
 * <p>{@link #stepVelocity} and {@link #stepAngularVelocity} are the twist of the last drift,
 * (x' − x)/h: the speed a trace shows (a body resting on a table reads 0 there, while v, the
 * velocity at the step's end, holds half a step of gravity, h/2·g).
 *
 * <p>Not thread-safe; allocation-free per step.
 */
public final class FreeBody {
    private static final double G1 = 1 / (2 - Math.cbrt(2)), G2 = 1 - 2 * G1;

    private final MassProperties props;
    private final double mass;
    private final double[] inertia, inverse, com;
    final double[] x = new double[3];
    final double[] q = {1, 0, 0, 0};
    final double[] v = new double[3];
    final double[] L = new double[3];
    private final double[] stepV = new double[3], stepW = new double[3];
    // the step's start: rotation, world inertia, free angular velocity
    private final double[] r0 = new double[9], iw0 = new double[9], wFree = new double[3];
    private final double[] qs = new double[4], dq = new double[4], lb = new double[3], lm = new double[3], tmp = new double[9];
    private final double[] rot = new double[9], prod = new double[9], twist = new double[6], wOut = new double[3];
    private boolean inStep;

    /**
     * A body at rest with its mesh placed by {@code worldFromMesh} (mesh frame → world).
     */
    public FreeBody(MassProperties props, RigidTransform worldFromMesh) {
        this.props = props;
        this.mass = props.mass();
        this.inertia = props.inertiaRef();
        this.inverse = props.inverseRef();
        this.com = props.comRef();
        double[] m = worldFromMesh.toArray();
        setPose(m);
    }

    /** Places the body so that its mesh is at {@code worldFromMesh} (12 values, row-major); motion unchanged. */
    public void setPose(double[] worldFromMesh) {
        Quaternion.fromMatrix(worldFromMesh, 0, 4, q, 0);
        double[] r = tmp;
        Quaternion.toMatrix(q, 0, r, 0);
        for (int i = 0; i < 3; i++) {
            x[i] = worldFromMesh[4 * i + 3] + r[3 * i] * com[0] + r[3 * i + 1] * com[1] + r[3 * i + 2] * com[2];
        }
    }

    /**
     * Sets the motion: the velocity of the centre of mass (m/s) and the angular velocity
     * (rad/s), both world frame; L = I_w·ω.
     */
    public void setVelocity(double[] velocity, double[] angularVelocity) {
        System.arraycopy(velocity, 0, v, 0, 3);
        System.arraycopy(velocity, 0, stepV, 0, 3);
        System.arraycopy(angularVelocity, 0, stepW, 0, 3);
        worldInertia(tmp);
        mul(tmp, angularVelocity, L);
    }

    // ------------------------------------------------------------------ the step

    /** One contact-free step of h seconds under force f (N) and torque τ (N·m, about the centre of mass), world frame. */
    public void step(double h, double[] force, double[] torque) {
        beginStep(h, force, torque, twist);
        endStep(h, twist, force, torque);
    }

    /**
     * The first half of a step: the half kick, then the free twist over the step into
     * {@code freeTwist} (u*, ω*: m/s, rad/s, world). The world inertia of the step is then
     * {@link #worldInertia}'s.
     */
    public void beginStep(double h, double[] force, double[] torque, double[] freeTwist) {
        checkStep(h);
        double hh = 0.5 * h;
        for (int i = 0; i < 3; i++) {
            v[i] += hh * force[i] / mass;
            L[i] += hh * torque[i];
        }
        Quaternion.toMatrix(q, 0, r0, 0);
        rotateInertia(r0, iw0);
        freeRotation(h);
        freeTwist[0] = v[0]; freeTwist[1] = v[1]; freeTwist[2] = v[2];
        freeTwist[3] = wFree[0]; freeTwist[4] = wFree[1]; freeTwist[5] = wFree[2];
        inStep = true;
    }

    /**
     * The second half of a step: drift with {@code twist} (u, w: m/s, rad/s, world), the twist's
     * change from the free one taken as the contacts' impulse, then the half kick.
     */
    public void endStep(double h, double[] twist, double[] force, double[] torque) {
        if (!inStep) throw new IllegalStateException("endStep without beginStep");
        inStep = false;
        double hh = 0.5 * h;
        for (int i = 0; i < 3; i++) {
            stepV[i] = twist[i];
            stepW[i] = twist[3 + i];
            x[i] += h * twist[i];
        }
        // q <- cay(h w) ⊗ q: the quaternion (1, h w / 2), normalised
        dq[0] = 1; dq[1] = hh * twist[3]; dq[2] = hh * twist[4]; dq[3] = hh * twist[5];
        Quaternion.normalize(dq, 0);
        Quaternion.multiply(dq, 0, q, 0, q, 0);
        Quaternion.normalize(q, 0);
        double dwx = twist[3] - wFree[0], dwy = twist[4] - wFree[1], dwz = twist[5] - wFree[2];
        for (int i = 0; i < 3; i++) {
            v[i] = twist[i] + hh * force[i] / mass;
            L[i] += iw0[3 * i] * dwx + iw0[3 * i + 1] * dwy + iw0[3 * i + 2] * dwz + hh * torque[i];
        }
    }

    private static void checkStep(double h) {
        if (!(h > 0) || !Double.isFinite(h)) throw new IllegalArgumentException("time step must be a finite number above 0, got " + h);
    }

    /**
     * ω* (world): the torque-free rotation over h from (q, L) by three symmetric midpoint–Cayley
     * steps (Yoshida's triple jump), as the angular velocity whose Cayley map over h gives it.
     */
    private void freeRotation(double h) {
        // body-frame angular momentum L_b = Rᵀ L
        double[] r = r0;
        lb[0] = r[0] * L[0] + r[3] * L[1] + r[6] * L[2];
        lb[1] = r[1] * L[0] + r[4] * L[1] + r[7] * L[2];
        lb[2] = r[2] * L[0] + r[5] * L[1] + r[8] * L[2];
        System.arraycopy(q, 0, qs, 0, 4);
        midpointCayley(G1 * h);
        midpointCayley(G2 * h);
        midpointCayley(G1 * h);
        // dq = qs ⊗ q*: the rotation over the step, in the world frame
        double[] c = dq;
        c[0] = q[0]; c[1] = -q[1]; c[2] = -q[2]; c[3] = -q[3];
        Quaternion.multiply(qs, 0, c, 0, c, 0);
        if (c[0] < 0) { c[0] = -c[0]; c[1] = -c[1]; c[2] = -c[2]; c[3] = -c[3]; }
        if (!(c[0] > 1e-3)) {
            throw new IllegalStateException("the body turns by " + Math.toDegrees(2 * Math.acos(Math.min(1, c[0])))
                + "° in one step of " + h + " s: reduce the time step");
        }
        double s = 2 / (h * c[0]);
        wFree[0] = s * c[1]; wFree[1] = s * c[2]; wFree[2] = s * c[3];
    }

    /** One implicit-midpoint step of h on (qs, lb), the orientation moved by the Cayley map. */
    private void midpointCayley(double h) {
        double[] j = inverse;
        double hh = 0.5 * h;
        lm[0] = lb[0]; lm[1] = lb[1]; lm[2] = lb[2];
        double scale = Math.sqrt(lb[0] * lb[0] + lb[1] * lb[1] + lb[2] * lb[2]);
        for (int it = 0; it < 30 && scale > 0; it++) {
            double wx = j[0] * lm[0] + j[1] * lm[1] + j[2] * lm[2];
            double wy = j[3] * lm[0] + j[4] * lm[1] + j[5] * lm[2];
            double wz = j[6] * lm[0] + j[7] * lm[1] + j[8] * lm[2];
            // F = lm − lb − h/2·(lm × w)
            double fx = lm[0] - lb[0] - hh * (lm[1] * wz - lm[2] * wy);
            double fy = lm[1] - lb[1] - hh * (lm[2] * wx - lm[0] * wz);
            double fz = lm[2] - lb[2] - hh * (lm[0] * wy - lm[1] * wx);
            // dF = E − h/2·([lm]× J⁻¹ − [w]×)
            double[] a = tmp;
            for (int c = 0; c < 3; c++) {
                double jx = j[c], jy = j[3 + c], jz = j[6 + c];          // column c of J⁻¹
                double px = lm[1] * jz - lm[2] * jy, py = lm[2] * jx - lm[0] * jz, pz = lm[0] * jy - lm[1] * jx;
                a[c] = -hh * px; a[3 + c] = -hh * py; a[6 + c] = -hh * pz;
            }
            // − h/2·(−[w]×) = + h/2·[w]×
            a[1] += hh * -wz; a[2] += hh * wy;
            a[3] += hh * wz;  a[5] += hh * -wx;
            a[6] += hh * -wy; a[7] += hh * wx;
            a[0] += 1; a[4] += 1; a[8] += 1;
            double dx, dy, dz;
            double c00 = a[4] * a[8] - a[5] * a[7], c01 = a[5] * a[6] - a[3] * a[8], c02 = a[3] * a[7] - a[4] * a[6];
            double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
            dx = (c00 * fx + (a[2] * a[7] - a[1] * a[8]) * fy + (a[1] * a[5] - a[2] * a[4]) * fz) / det;
            dy = (c01 * fx + (a[0] * a[8] - a[2] * a[6]) * fy + (a[2] * a[3] - a[0] * a[5]) * fz) / det;
            dz = (c02 * fx + (a[1] * a[6] - a[0] * a[7]) * fy + (a[0] * a[4] - a[1] * a[3]) * fz) / det;
            lm[0] -= dx; lm[1] -= dy; lm[2] -= dz;
            if (Math.abs(dx) + Math.abs(dy) + Math.abs(dz) <= 1e-15 * scale) break;
        }
        double wx = j[0] * lm[0] + j[1] * lm[1] + j[2] * lm[2];
        double wy = j[3] * lm[0] + j[4] * lm[1] + j[5] * lm[2];
        double wz = j[6] * lm[0] + j[7] * lm[1] + j[8] * lm[2];
        // R ← R·cay(h ω̂_b): qs ← qs ⊗ (1, h ω_b / 2)
        dq[0] = 1; dq[1] = hh * wx; dq[2] = hh * wy; dq[3] = hh * wz;
        Quaternion.normalize(dq, 0);
        Quaternion.multiply(qs, 0, dq, 0, qs, 0);
        Quaternion.normalize(qs, 0);
        lb[0] = 2 * lm[0] - lb[0]; lb[1] = 2 * lm[1] - lb[1]; lb[2] = 2 * lm[2] - lb[2];
    }

    // ------------------------------------------------------------------ state

    /** R I Rᵀ for rotation r (9 values) into out. */
    private void rotateInertia(double[] r, double[] out) {
        double[] t = prod;
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
                t[3 * i + k] = r[3 * i] * inertia[k] + r[3 * i + 1] * inertia[3 + k] + r[3 * i + 2] * inertia[6 + k];
            }
        }
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) out[3 * i + k] = t[3 * i] * r[3 * k] + t[3 * i + 1] * r[3 * k + 1] + t[3 * i + 2] * r[3 * k + 2];
        }
    }

    private static void mul(double[] m, double[] a, double[] out) {
        double x0 = a[0], x1 = a[1], x2 = a[2];
        out[0] = m[0] * x0 + m[1] * x1 + m[2] * x2;
        out[1] = m[3] * x0 + m[4] * x1 + m[5] * x2;
        out[2] = m[6] * x0 + m[7] * x1 + m[8] * x2;
    }

    /** The inertia about the centre of mass in world axes, R I Rᵀ (kg·m², 9 values), at the current orientation — or, between {@link #beginStep} and {@link #endStep}, the step's. */
    public void worldInertia(double[] out) {
        if (inStep) {
            System.arraycopy(iw0, 0, out, 0, 9);
            return;
        }
        Quaternion.toMatrix(q, 0, rot, 0);
        rotateInertia(rot, out);
    }

    /** @return the mass properties */
    public MassProperties massProperties() { return props; }

    /** @return the mass, kg */
    public double mass() { return mass; }

    /** The centre of mass, world, m, into out[0..2]; returns out. */
    public double[] position(double[] out) { System.arraycopy(x, 0, out, 0, 3); return out; }

    /** The orientation (w, x, y, z), body → world, into out[0..3]; returns out. */
    public double[] orientation(double[] out) { System.arraycopy(q, 0, out, 0, 4); return out; }

    /** The velocity of the centre of mass at the end of the last step, world, m/s, into out; returns out. */
    public double[] velocity(double[] out) { System.arraycopy(v, 0, out, 0, 3); return out; }

    /** The angular momentum about the centre of mass, world, kg·m²/s, into out; returns out. */
    public double[] angularMomentum(double[] out) { System.arraycopy(L, 0, out, 0, 3); return out; }

    /** The angular velocity I_w⁻¹L at the current orientation, world, rad/s, into out; returns out. */
    public double[] angularVelocity(double[] out) {
        double[] r = rot;
        Quaternion.toMatrix(q, 0, r, 0);
        double bx = r[0] * L[0] + r[3] * L[1] + r[6] * L[2];
        double by = r[1] * L[0] + r[4] * L[1] + r[7] * L[2];
        double bz = r[2] * L[0] + r[5] * L[1] + r[8] * L[2];
        double[] j = inverse;
        double wx = j[0] * bx + j[1] * by + j[2] * bz, wy = j[3] * bx + j[4] * by + j[5] * bz, wz = j[6] * bx + j[7] * by + j[8] * bz;
        out[0] = r[0] * wx + r[1] * wy + r[2] * wz;
        out[1] = r[3] * wx + r[4] * wy + r[5] * wz;
        out[2] = r[6] * wx + r[7] * wy + r[8] * wz;
        return out;
    }

    /** The velocity of the centre of mass over the last step, (x' − x)/h, world, m/s, into out; returns out. */
    public double[] stepVelocity(double[] out) { System.arraycopy(stepV, 0, out, 0, 3); return out; }

    /** The angular velocity of the last step's drift, world, rad/s, into out; returns out. */
    public double[] stepAngularVelocity(double[] out) { System.arraycopy(stepW, 0, out, 0, 3); return out; }

    /** @return the kinetic energy ½m|v|² + ½ L·I_w⁻¹L, J */
    public double kineticEnergy() {
        double[] w = angularVelocity(wOut);
        return 0.5 * mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.5 * (L[0] * w[0] + L[1] * w[1] + L[2] * w[2]);
    }

    /** The mesh's pose, mesh frame → world (12 values, row-major), into out[off..off+11]; returns out. */
    public double[] worldFromMesh(double[] out, int off) {
        double[] r = rot;
        Quaternion.toMatrix(q, 0, r, 0);
        for (int i = 0; i < 3; i++) {
            out[off + 4 * i] = r[3 * i];
            out[off + 4 * i + 1] = r[3 * i + 1];
            out[off + 4 * i + 2] = r[3 * i + 2];
            out[off + 4 * i + 3] = x[i] - (r[3 * i] * com[0] + r[3 * i + 1] * com[1] + r[3 * i + 2] * com[2]);
        }
        return out;
    }
}
