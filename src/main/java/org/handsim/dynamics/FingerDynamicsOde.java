package org.handsim.dynamics;

/**
 * The equations of motion of a chain as an {@link Ode}: state {@code y = (q, q̇)} (2n values,
 * rad and rad/s), derivative {@code ẏ = (q̇, q̈)} with q̈ from {@link ForwardDynamics} (paper
 * eq 8 solved for Θ̈), under the joint torques of a {@link Torques} law and gravity g in the
 * base frame.
 *
 * <p>Allocation-free per evaluation; not thread-safe (scratch).
 */
public final class FingerDynamicsOde implements Ode {
    /** Joint torques as a function of time and state (a controller, a clutch spring, zero). */
    @FunctionalInterface
    public interface Torques {
        /** No actuation: the chain moves freely under gravity. */
        Torques ZERO = (t, q, qd, tau) -> java.util.Arrays.fill(tau, 0.0);

        /**
         * Writes τ(t, q, q̇), N·m, into {@code tauOut} (n values; do not keep the arrays).
         */
        void torques(double t, double[] q, double[] qd, double[] tauOut);
    }

    private final ForwardDynamics forward;
    private final int n;
    private final double[] gravity = new double[3];
    private final Torques torques;
    private final double[] q, qd, tau, qdd;

    /**
     * @param dynamics the D, H, C source (e.g. {@link ClosedFormFinger})
     * @param g        gravity in the base frame, m/s² (copied)
     * @param torques  the joint torque law ({@link Torques#ZERO} for free motion)
     */
    public FingerDynamicsOde(ChainDynamics dynamics, double[] g, Torques torques) {
        Check.vec("g", g, 3);
        if (torques == null) throw new IllegalArgumentException("torques must not be null (use Torques.ZERO)");
        forward = new ForwardDynamics(dynamics);
        n = dynamics.dof();
        System.arraycopy(g, 0, gravity, 0, 3);
        this.torques = torques;
        q = new double[n];
        qd = new double[n];
        tau = new double[n];
        qdd = new double[n];
    }

    @Override
    public int dimension() {
        return 2 * n;
    }

    /** @return the number of joints n (the state has 2n values) */
    public int dof() {
        return n;
    }

    /** @return gravity in the base frame, m/s² (a copy) */
    public double[] gravity() {
        return gravity.clone();
    }

    /** @return the dynamics behind this ODE */
    public ChainDynamics dynamics() {
        return forward.dynamics();
    }

    @Override
    public boolean derivative(double t, double[] y, double[] yDot) {
        System.arraycopy(y, 0, q, 0, n);
        System.arraycopy(y, n, qd, 0, n);
        torques.torques(t, q, qd, tau);
        if (!forward.accelerations(q, qd, tau, gravity, qdd)) return false;
        System.arraycopy(qd, 0, yDot, 0, n);
        System.arraycopy(qdd, 0, yDot, n, n);
        return true;
    }

    /**
     * Total mechanical energy of a state, kinetic plus potential ({@link ChainDynamics}), J:
     * conserved under zero torque; the simulator's energy guard.
     */
    public double energy(double[] y) {
        System.arraycopy(y, 0, q, 0, n);
        System.arraycopy(y, n, qd, 0, n);
        ChainDynamics d = forward.dynamics();
        return d.kineticEnergy(q, qd) + d.potentialEnergy(q, gravity);
    }
}
