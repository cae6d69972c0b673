package org.handsim.dynamics;

import java.util.Locale;
import org.handsim.math.Vec3;

/**
 * The stability guard of a free (unactuated, frictionless) chain: after every step the state
 * must be finite and the total energy must not have grown by more than a bound. With zero joint
 * torque and no friction the energy is constant (Fu–Gonzalez–Lee §3.2), so growth is the
 * integrator's error; explicit Euler gains energy on every oscillation and, at a large step,
 * blows up — the guard stops it with the step, the time and the value
 * ({@link IntegrationStoppedException}) instead of letting NaN or nonsense reach the output.
 *
 * <p><b>The bound</b> is {@code FRACTION · S + FLOOR_J} with S the energy scale of the motion:
 * the largest kinetic energy the chain can ever reach from its start,
 * <pre>
 *   S = T(0) + V(0) + Σ_j m_j·|g|·ρ_j  ≥  T(0) + V(0) − min V  ≥  max_t T(t)
 * </pre>
 * where ρ_j = Σ_{i≤j}(|a_i| + |d_i|) + |r̄_j| bounds the distance of link j's centre of mass
 * from the base origin (so V = −Σ m_j gᵀp_j ≥ −Σ m_j |g| ρ_j). A growth of half of everything
 * that can move is far beyond any error an accurate method makes (RK4 at 1 ms: about 1e-10 of
 * S) and is reached within a few steps once a method is unstable. The absolute floor
 * {@link #FLOOR_J} keeps a chain at rest without gravity (S = 0) from tripping on rounding.
 * Energy loss is not guarded: it is bounded by S and not a blow-up.
 *
 * <p>Allocation-free after construction; not thread-safe (scratch).
 */
public final class EnergyGuard {
    /** Allowed growth as a fraction of the energy scale. */
    public static final double FRACTION = 0.5;
    /** Allowed growth in any case, J. */
    public static final double FLOOR_J = 1e-9;

    private final ChainDynamics dynamics;
    private final int dimension, n;
    private final double[] g, q, qd;
    private final double initialEnergy, scale, bound;
    private double maxKinetic;

    /**
     * A guard for motion of {@code ode} (zero torque) from state {@code y0}.
     *
     * @param ode the free chain under gravity (its torque law must be {@link FingerDynamicsOde.Torques#ZERO}
     *            for the bound to hold); the guard uses the ODE's gravity
     * @param y0  the start state (q, q̇), rad and rad/s
     */
    public EnergyGuard(FingerDynamicsOde ode, double[] y0) {
        Check.vec("y0", y0, ode.dimension());
        dynamics = ode.dynamics();
        dimension = ode.dimension();
        n = ode.dof();
        g = ode.gravity();
        for (int i = 0; i < dimension; i++) {
            if (!Double.isFinite(y0[i])) throw new IllegalArgumentException("y0[" + i + "] must be finite, got " + y0[i]);
        }
        q = new double[n];
        qd = new double[n];
        System.arraycopy(y0, 0, q, 0, n);
        System.arraycopy(y0, n, qd, 0, n);
        double kinetic = dynamics.kineticEnergy(q, qd);
        double potential = dynamics.potentialEnergy(q, g);
        initialEnergy = kinetic + potential;
        maxKinetic = kinetic;
        scale = Math.max(0.0, kinetic + potential + potentialDepth(dynamics.chain(), g));
        bound = FRACTION * scale + FLOOR_J;
    }

    /** {@code Σ_j m_j·|g|·ρ_j}: no configuration has a potential energy below its negative, J. */
    static double potentialDepth(LinkChain c, double[] g) {
        double gNorm = Vec3.norm(g);
        double reach = 0, sum = 0;
        for (int j = 0; j < c.links(); j++) {
            reach += Math.abs(c.dh(j).a()) + Math.abs(c.dh(j).d());
            sum += c.link(j).mass() * gNorm * (reach + Vec3.norm(c.link(j).com()));
        }
        return sum;
    }

    /** @return the energy of the start state, J */
    public double initialEnergy() { return initialEnergy; }

    /** @return the energy scale S (the largest kinetic energy reachable), J */
    public double scale() { return scale; }

    /** @return the allowed energy growth FRACTION·S + FLOOR_J, J */
    public double bound() { return bound; }

    /** @return the largest kinetic energy of the states checked so far (and the start), J */
    public double maxKinetic() { return maxKinetic; }

    /**
     * The energy that moves, the denominator of a relative drift: {@code max(|E(0)|, largest
     * kinetic energy so far)}, J (the potential's zero, at the base origin, is arbitrary, so
     * |E(0)| alone can be near zero). EnergyConservationTest uses the same scale.
     */
    public double driftScale() { return Math.max(Math.abs(initialEnergy), maxKinetic); }

    /**
     * Checks the state after step {@code step} (which reached time {@code t}).
     *
     * @return the energy of y, J
     * @throws IntegrationStoppedException if a value of y is not finite or the energy exceeds
     *         the initial energy by more than {@link #bound()}
     */
    public double check(long step, double t, double[] y) {
        for (int i = 0; i < dimension; i++) {
            if (!Double.isFinite(y[i])) {
                String what = i < n ? "q" + (i + 1) : "qd" + (i - n + 1);
                throw new IntegrationStoppedException(IntegrationStoppedException.Reason.NON_FINITE, step, t, y[i], initialEnergy, bound,
                    "state value " + what + " (active joint " + (i % n + 1) + ") is " + y[i]);
            }
        }
        System.arraycopy(y, 0, q, 0, n);
        System.arraycopy(y, n, qd, 0, n);
        double kinetic = dynamics.kineticEnergy(q, qd);
        double e = kinetic + dynamics.potentialEnergy(q, g);
        if (!Double.isFinite(e) || e - initialEnergy > bound) {
            throw new IntegrationStoppedException(IntegrationStoppedException.Reason.ENERGY_GROWTH, step, t, e, initialEnergy, bound,
                String.format(Locale.ROOT, "energy %s J exceeds the initial %s J by more than %.0f %% of the energy scale %s J",
                    IntegrationStoppedException.fmt(e), IntegrationStoppedException.fmt(initialEnergy), 100 * FRACTION,
                    IntegrationStoppedException.fmt(scale)));
        }
        maxKinetic = Math.max(maxKinetic, kinetic);
        return e;
    }

    /** Reports that the integrator refused step {@code step} (to time {@code t}). */
    public IntegrationStoppedException failedStep(long step, double t, String integrator) {
        return new IntegrationStoppedException(IntegrationStoppedException.Reason.STEP_FAILED, step, t, Double.NaN, initialEnergy, bound,
            integrator + " could not take the step (the mass matrix is not positive definite or the step size collapsed)");
    }
}
