package org.handsim.model;

/** The dynamics side of the model: inverse dynamics of one finger, paper eq (8). */
public interface TorqueModel {
    /**
     * τ = D(Θ)Θ̈ + H(Θ, Θ̇) + C(Θ) for finger k.
     *
     * @param finger 1..3
     * @param q      joint angles {θk1, θk2, θk3}, rad
     * @param qd     joint velocities, rad/s
     * @param qdd    joint accelerations, rad/s²
     * @param gravity gravity in the finger base frame {k0}, m/s²
     * @param tauOut joint torques {τk1, τk2, τk3}, N·m (τ31 = 0: finger 3's spread is fixed)
     */
    void inverseDynamics(int finger, double[] q, double[] qd, double[] qdd, double[] gravity, double[] tauOut);

    /** No dynamics: all torques zero (the kinematic model). */
    TorqueModel NONE = (k, q, qd, qdd, g, tau) -> { tau[0] = 0; tau[1] = 0; tau[2] = 0; };
}
