package org.handsim.dynamics;

import org.handsim.hand.HandDescription;

/**
 * The dynamics of the three fingers of a hand, the entry point for the simulator, the CLI and
 * the GUI: {@link #finger(int)} gives finger k's {@link ChainDynamics} (active joints only: 3,
 * or 2 for finger 3), and {@link #inverseDynamics(int, double[], double[], double[], double[], double[])}
 * works in the hand's three-joint layout {θk1, θk2, θk3} that the rest of HandSim uses, with
 * τ31 = 0 for the fixed spread of finger 3.
 *
 * <p>Which algorithm: {@link Method#CLOSED_FORM} (default; the generated expressions, the fastest)
 * when the finger has the BarrettHand DH structure, else {@link Method#NEWTON_EULER};
 * {@link Method#LAGRANGE_EULER} and {@link Method#NEWTON_EULER} on request (the CLI's
 * {@code --method}).
 *
 * <p>Holds scratch per finger: one instance per thread.
 */
public final class HandDynamics {
    /** The algorithm behind eq (8). */
    public enum Method {
        /** Generated closed-form Lagrange–Euler expressions ({@link ClosedFormFinger}). */
        CLOSED_FORM,
        /** The general Lagrange–Euler algorithm ({@link LagrangeEuler}, FGL §3.2). */
        LAGRANGE_EULER,
        /** The recursive Newton–Euler algorithm ({@link NewtonEuler}, FGL §3.3). */
        NEWTON_EULER
    }

    private final HandDescription hand;
    private final Method method;
    private final ChainDynamics[] fingers = new ChainDynamics[3];
    private final double[][] qs = new double[3][], qds = new double[3][], qdds = new double[3][], taus = new double[3][];

    private HandDynamics(HandDescription hand, Method method) {
        this.hand = hand;
        this.method = method;
        for (int k = 1; k <= 3; k++) {
            LinkChain c = LinkChain.finger(hand.finger(k));
            ChainDynamics d;
            switch (method) {
                case LAGRANGE_EULER: d = new LagrangeEuler(c); break;
                case NEWTON_EULER: d = new NewtonEuler(c); break;
                default: d = ClosedFormFinger.supports(c) ? new ClosedFormFinger(c) : new NewtonEuler(c);
            }
            fingers[k - 1] = d;
            int n = c.dof();
            qs[k - 1] = new double[n];
            qds[k - 1] = new double[n];
            qdds[k - 1] = new double[n];
            taus[k - 1] = new double[n];
        }
    }

    /** The dynamics of {@code hand} with the given algorithm. */
    public static HandDynamics of(HandDescription hand, Method method) {
        if (hand == null) throw new IllegalArgumentException("hand must not be null");
        if (method == null) throw new IllegalArgumentException("method must not be null");
        return new HandDynamics(hand, method);
    }

    /** The bundled BarrettHand with the closed-form fast path. */
    public static HandDynamics barrettHand() {
        return of(HandDescription.barrettHand(), Method.CLOSED_FORM);
    }

    /** @return the hand */
    public HandDescription hand() {
        return hand;
    }

    /** @return the algorithm requested */
    public Method method() {
        return method;
    }

    /**
     * @param k finger 1, 2 or 3
     * @return finger k's dynamics over its active joints (n = 3, or 2 for finger 3)
     */
    public ChainDynamics finger(int k) {
        if (k < 1 || k > 3) throw new IllegalArgumentException("finger must be 1, 2 or 3, got " + k);
        return fingers[k - 1];
    }

    /**
     * Paper eq (8) in the hand's three-joint layout: {@code τ = D·θ̈ + H + C} for finger k.
     * Matches the simulator's torque-model signature.
     *
     * @param k      finger 1, 2 or 3
     * @param q      {θk1, θk2, θk3}, rad (finger 3: θ31 must be its fixed value 0)
     * @param qd     joint velocities, rad/s (finger 3: first entry 0)
     * @param qdd    joint accelerations, rad/s² (finger 3: first entry 0)
     * @param g      gravity in the finger base frame {k0}, m/s²
     * @param tauOut {τk1, τk2, τk3}, N·m (finger 3: τ31 = 0, the fixed joint is not actuated)
     * @throws IllegalArgumentException if a fixed joint is given a different angle or a motion
     */
    public void inverseDynamics(int k, double[] q, double[] qd, double[] qdd, double[] g, double[] tauOut) {
        ChainDynamics d = finger(k);
        LinkChain c = d.chain();
        Check.vec("tauOut", tauOut, 3);   // the chain would allocate a new one for null
        if (c.dof() == 3) {
            d.inverseDynamics(q, qd, qdd, g, tauOut);   // checks q, qd, qdd and g itself
            return;
        }
        Check.vec("q", q, 3);
        Check.vec("qd", qd, 3);
        Check.vec("qdd", qdd, 3);
        int i = k - 1;
        for (int j = 0; j < 3; j++) {
            int p = c.dofOfLink(j);
            if (p >= 0) {
                qs[i][p] = q[j];
                qds[i][p] = qd[j];
                qdds[i][p] = qdd[j];
            } else if (q[j] != c.fixedValue(j) || qd[j] != 0 || qdd[j] != 0) {
                throw new IllegalArgumentException("finger " + k + " joint " + (j + 1) + " is fixed at " + c.fixedValue(j)
                    + " rad: got q = " + q[j] + ", qd = " + qd[j] + ", qdd = " + qdd[j]);
            }
        }
        d.inverseDynamics(qs[i], qds[i], qdds[i], g, taus[i]);
        for (int j = 0; j < 3; j++) {
            int p = c.dofOfLink(j);
            tauOut[j] = p >= 0 ? taus[i][p] : 0.0;
        }
    }
}
