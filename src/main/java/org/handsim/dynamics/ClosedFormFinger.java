package org.handsim.dynamics;

import org.handsim.hand.DhRow;

/**
 * The fast path of eq (8) for a BarrettHand finger: closed-form D, H, C and τ generated
 * symbolically from the Lagrange–Euler formulas ({@code tools/dynamics/gen_barrett_closed_form.py}
 * writes {@link BarrettFingerKernel}), as the paper did ("the analytical representation of the
 * matrices", Section II.C). Per call: sin and cos of the three DH angles, a few dozen shared
 * monomials and multiply-adds with constants folded from the hand description at construction.
 *
 * <p><b>Which chains.</b> Three revolute links with the finger's DH structure: twists
 * α = (90°, 0, 0) and d = (0, 0, 0) (paper Table I); any lengths, offsets and mass properties
 * (a modified hand description file is fine). {@link #supports(LinkChain)} says whether a chain
 * qualifies; {@link HandDynamics} falls back to {@link NewtonEuler} when it does not.
 * Fixed joints are allowed (finger 3's spread): the kernel is evaluated with the fixed joint
 * at its value and zero velocity and acceleration, and only the active rows and columns are
 * returned — exactly the reduced model, since the other joints' equations do not depend on
 * how a joint with q̇ = q̈ = 0 is held.
 *
 * <p>The kernel is tested against {@link LagrangeEuler} and {@link NewtonEuler} on random
 * states (ClosedFormFingerTest). Units, frames, outputs: {@link ChainDynamics}. Not
 * thread-safe (scratch).
 */
public final class ClosedFormFinger implements ChainDynamics {
    /** Tolerance on the structural DH constants (radians for α, metres for d). */
    private static final double STRUCTURE_TOL = 1e-12;

    private final LinkChain chain;
    private final BarrettFingerKernel kernel;
    private final int dof;
    private final boolean allActive;
    private final double off1, off2, off3;
    private final double[] fixedTheta = new double[3];   // DH angle of a fixed joint
    private final double[] offset = new double[3];
    private final int[] dofOfLink = new int[3];
    // scratch for chains with a fixed joint
    private final double[] d9 = new double[9], v3 = new double[3], hc3 = new double[3];
    private final double[] dReduced;

    /**
     * @throws IllegalArgumentException if the chain is not a BarrettHand-structured finger
     *         (message names the first mismatching DH constant)
     */
    public ClosedFormFinger(LinkChain chain) {
        String why = mismatch(chain);
        if (why != null) throw new IllegalArgumentException("closed-form finger dynamics needs the BarrettHand finger structure: " + why);
        this.chain = chain;
        dof = chain.dof();
        allActive = dof == 3;
        dReduced = new double[dof * dof];
        double[] p = new double[48];
        for (int j = 0; j < 3; j++) {
            chain.pseudoInertia(j, p, 16 * j);
            dofOfLink[j] = chain.dofOfLink(j);
            offset[j] = chain.dh(j).thetaOffset();
            fixedTheta[j] = chain.fixedValue(j) + offset[j];
        }
        kernel = new BarrettFingerKernel(chain.dh(0).a(), chain.dh(1).a(), chain.dh(2).a(), p);
        off1 = chain.dh(0).thetaOffset();
        off2 = chain.dh(1).thetaOffset();
        off3 = chain.dh(2).thetaOffset();
    }

    /** @return whether {@code chain} has the BarrettHand finger structure the closed form assumes */
    public static boolean supports(LinkChain chain) {
        return mismatch(chain) == null;
    }

    private static String mismatch(LinkChain chain) {
        if (chain.links() != 3) return "3 links, got " + chain.links();
        double[] alpha = {Math.PI / 2, 0, 0};
        for (int j = 0; j < 3; j++) {
            DhRow r = chain.dh(j);
            if (Math.abs(r.alpha() - alpha[j]) > STRUCTURE_TOL) return "dh[" + j + "].alpha = " + alpha[j] + " rad, got " + r.alpha();
            if (Math.abs(r.d()) > STRUCTURE_TOL) return "dh[" + j + "].d = 0 m, got " + r.d();
        }
        return null;
    }

    @Override
    public LinkChain chain() {
        return chain;
    }

    @Override
    public double[] inverseDynamics(double[] q, double[] qd, double[] qdd, double[] g, double[] tauOut) {
        tauOut = Check.out("tauOut", tauOut, dof, q, qd, qdd, g);
        Check.vec("q", q, dof);
        Check.vec("qd", qd, dof);
        Check.vec("qdd", qdd, dof);
        Check.vec("g", g, 3);
        if (allActive) {
            kernel.inverseDynamics(q[0] + off1, q[1] + off2, q[2] + off3, qd[0], qd[1], qd[2],
                qdd[0], qdd[1], qdd[2], g[0], g[1], g[2], tauOut);
        } else {
            kernel.inverseDynamics(theta(0, q), theta(1, q), theta(2, q), rate(0, qd), rate(1, qd), rate(2, qd),
                rate(0, qdd), rate(1, qdd), rate(2, qdd), g[0], g[1], g[2], v3);
            gather(v3, tauOut);
        }
        return tauOut;
    }

    @Override
    public double[] massMatrix(double[] q, double[] dOut) {
        dOut = Check.out("dOut", dOut, dof * dof, q, null, null, null);
        Check.vec("q", q, dof);
        if (allActive) {
            kernel.massMatrix(q[0] + off1, q[1] + off2, q[2] + off3, dOut);
        } else {
            kernel.massMatrix(theta(0, q), theta(1, q), theta(2, q), d9);
            gatherMatrix(d9, dOut);
        }
        return dOut;
    }

    @Override
    public double[] coriolisCentrifugal(double[] q, double[] qd, double[] hOut) {
        hOut = Check.out("hOut", hOut, dof, q, qd, null, null);
        Check.vec("q", q, dof);
        Check.vec("qd", qd, dof);
        if (allActive) {
            kernel.coriolisCentrifugal(q[0] + off1, q[1] + off2, q[2] + off3, qd[0], qd[1], qd[2], hOut);
        } else {
            kernel.coriolisCentrifugal(theta(0, q), theta(1, q), theta(2, q), rate(0, qd), rate(1, qd), rate(2, qd), v3);
            gather(v3, hOut);
        }
        return hOut;
    }

    @Override
    public double[] gravityTorque(double[] q, double[] g, double[] cOut) {
        cOut = Check.out("cOut", cOut, dof, q, g, null, null);
        Check.vec("q", q, dof);
        Check.vec("g", g, 3);
        if (allActive) {
            kernel.gravityTorque(q[0] + off1, q[1] + off2, q[2] + off3, g[0], g[1], g[2], cOut);
        } else {
            kernel.gravityTorque(theta(0, q), theta(1, q), theta(2, q), g[0], g[1], g[2], v3);
            gather(v3, cOut);
        }
        return cOut;
    }

    @Override
    public void terms(double[] q, double[] qd, double[] g, double[] dOut, double[] hOut, double[] cOut) {
        Check.outNonNull("dOut", dOut, dof * dof, q, qd, g);
        Check.outNonNull("hOut", hOut, dof, q, qd, g);
        Check.outNonNull("cOut", cOut, dof, q, qd, g);
        Check.vec("q", q, dof);
        Check.vec("qd", qd, dof);
        Check.vec("g", g, 3);
        if (allActive) {
            kernel.terms(q[0] + off1, q[1] + off2, q[2] + off3, qd[0], qd[1], qd[2], g[0], g[1], g[2], dOut, hOut, cOut);
        } else {
            kernel.terms(theta(0, q), theta(1, q), theta(2, q), rate(0, qd), rate(1, qd), rate(2, qd),
                g[0], g[1], g[2], d9, v3, hc3);
            gatherMatrix(d9, dOut);
            gather(v3, hOut);
            gather(hc3, cOut);
        }
    }

    @Override
    public double kineticEnergy(double[] q, double[] qd) {
        Check.vec("qd", qd, dof);
        double[] d = allActive ? d9 : dReduced;
        massMatrix(q, d);
        double s = 0;
        for (int i = 0; i < dof; i++) {
            double r = 0;
            for (int k = 0; k < dof; k++) r += d[i * dof + k] * qd[k];
            s += qd[i] * r;
        }
        return 0.5 * s;
    }

    @Override
    public double potentialEnergy(double[] q, double[] g) {
        Check.vec("q", q, dof);
        Check.vec("g", g, 3);
        return kernel.potentialEnergy(theta(0, q), theta(1, q), theta(2, q), g[0], g[1], g[2]);
    }

    // ------------------------------------------------------------------ mapping active <-> all joints

    private double theta(int j, double[] q) {
        int p = dofOfLink[j];
        return p >= 0 ? q[p] + offset[j] : fixedTheta[j];
    }

    private double rate(int j, double[] v) {
        int p = dofOfLink[j];
        return p >= 0 ? v[p] : 0.0;
    }

    private void gather(double[] all, double[] out) {
        for (int j = 0; j < 3; j++) {
            int p = dofOfLink[j];
            if (p >= 0) out[p] = all[j];
        }
    }

    private void gatherMatrix(double[] all, double[] out) {
        for (int i = 0; i < 3; i++) {
            int pi = dofOfLink[i];
            if (pi < 0) continue;
            for (int k = 0; k < 3; k++) {
                int pk = dofOfLink[k];
                if (pk >= 0) out[pi * dof + pk] = all[3 * i + k];
            }
        }
    }
}
