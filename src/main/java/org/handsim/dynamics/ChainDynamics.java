package org.handsim.dynamics;

/**
 * Inverse dynamics of one serial chain, paper eq (8):
 * <pre>
 *   τ = D(Θ)·Θ̈ + H(Θ, Θ̇) + C(Θ)
 * </pre>
 * with D the n×n inertia (mass) matrix, H the Coriolis and centrifugal torques and C the
 * gravity torques (Fu–Gonzalez–Lee §3.2 writes the same as τ = D(q)q̈ + h(q, q̇) + c(q)).
 * Three implementations compute the same quantities by different routes:
 * {@link LagrangeEuler} (the reference, FGL §3.2), {@link NewtonEuler} (the independent
 * cross-check, FGL §3.3) and {@link ClosedFormFinger} (generated closed-form expressions for
 * the BarrettHand finger, the fast path of the simulator's step).
 *
 * <p><b>Units and frames.</b> Joint angles q in radians (the joint variables of the chain,
 * without the DH offsets), q̇ in rad/s, q̈ in rad/s², torques in N·m, D in kg·m², energy in J.
 * Gravity {@code g} is the gravitational acceleration vector (3 values, m/s²) in the chain's
 * base frame {0} ({k0} for a finger), e.g. {@code (0, 0, −9.81)} when z0 points up. Vectors
 * have {@link #dof()} entries (active joints only, {@link LinkChain}); matrices are dof×dof,
 * row-major in a flat array.
 *
 * <p><b>Outputs</b> (docs/STYLE.md, item 3): each method writes into the output array it is given and
 * returns it; {@code null} allocates a new one (convenient, not for hot loops). An output must
 * not be the same array as an input ({@link IllegalArgumentException}). With non-null outputs
 * every method is allocation-free.
 *
 * <p><b>Threads.</b> Implementations keep preallocated scratch: one instance per thread.
 */
public interface ChainDynamics {
    /** @return the chain these dynamics describe */
    LinkChain chain();

    /** @return the number of active joints n (vector length; D is n×n) */
    default int dof() {
        return chain().dof();
    }

    /**
     * Joint torques for a motion, paper eq (8): {@code τ = D(q)·q̈ + H(q, q̇) + C(q)}.
     *
     * @param q      joint angles, rad
     * @param qd     joint velocities, rad/s
     * @param qdd    joint accelerations, rad/s²
     * @param g      gravity in the base frame, m/s² (3 values)
     * @param tauOut joint torques, N·m (or null)
     * @return tauOut
     */
    double[] inverseDynamics(double[] q, double[] qd, double[] qdd, double[] g, double[] tauOut);

    /**
     * The inertia matrix D(q) of eq (8), kg·m², symmetric positive definite, row-major n×n.
     *
     * @return dOut (or a new array if null)
     */
    double[] massMatrix(double[] q, double[] dOut);

    /**
     * The Coriolis and centrifugal torques H(q, q̇) of eq (8), N·m: the torque that q̇ alone
     * demands (τ with q̈ = 0 and g = 0); quadratic in q̇.
     *
     * @return hOut (or a new array if null)
     */
    double[] coriolisCentrifugal(double[] q, double[] qd, double[] hOut);

    /**
     * The gravity torques C(q) of eq (8), N·m: the torque that holds the chain still against
     * {@code g} (τ with q̇ = q̈ = 0).
     *
     * @return cOut (or a new array if null)
     */
    double[] gravityTorque(double[] q, double[] g, double[] cOut);

    /**
     * D, H and C together (the GUI and charts show all three; forward dynamics needs all
     * three), sharing the work of one evaluation. All outputs must be non-null.
     */
    void terms(double[] q, double[] qd, double[] g, double[] dOut, double[] hOut, double[] cOut);

    /** Kinetic energy {@code ½·q̇ᵀ·D(q)·q̇} (FGL §3.2), J. */
    double kineticEnergy(double[] q, double[] qd);

    /**
     * Potential energy {@code V = −Σ_j m_j·gᵀ·p_j} (FGL §3.2), J, with p_j the centre of
     * mass of link j in the base frame: zero at the base origin, so that C = ∂V/∂q.
     * Fixed links count too (their constant share does not change energy differences).
     */
    double potentialEnergy(double[] q, double[] g);
}
