package org.handsim.dynamics;

import org.handsim.math.Quaternion;

/**
 * The orientation of a torque-free rigid body by Euler's equations I ω̇ = −ω × Iω in the body
 * frame with the quaternion rate q̇ = ½ q ⊗ (0, ω), integrated by Dormand–Prince 5(4) at 1e-13.
 * It shares nothing with the free body's own step (a symplectic splitting), so it is the
 * independent reference for a free tumble, in the tests and in the time-step study alike.
 */
public final class TorqueFreeRotation {
    private TorqueFreeRotation() {}

    /**
     * @param inertia the 3×3 inertia about the centre of mass in body axes, row-major
     * @param inverseInertia its inverse, row-major
     * @param w0Body the angular velocity at the start, body frame, rad/s
     * @param q0 the orientation at the start, (w, x, y, z)
     * @param t the time to integrate to, s
     * @return the unit quaternion at {@code t}
     */
    public static double[] orientationAfter(double[] inertia, double[] inverseInertia, double[] w0Body, double[] q0, double t) {
        double[] in = inertia, inv = inverseInertia;
        Ode euler = new Ode() {
            @Override
            public int dimension() { return 7; }

            @Override
            public boolean derivative(double time, double[] y, double[] d) {
                double wx = y[0], wy = y[1], wz = y[2];
                double lx = in[0] * wx + in[1] * wy + in[2] * wz, ly = in[3] * wx + in[4] * wy + in[5] * wz,
                    lz = in[6] * wx + in[7] * wy + in[8] * wz;
                double cx = -(wy * lz - wz * ly), cy = -(wz * lx - wx * lz), cz = -(wx * ly - wy * lx);
                d[0] = inv[0] * cx + inv[1] * cy + inv[2] * cz;
                d[1] = inv[3] * cx + inv[4] * cy + inv[5] * cz;
                d[2] = inv[6] * cx + inv[7] * cy + inv[8] * cz;
                double qw = y[3], qx = y[4], qy = y[5], qz = y[6];
                d[3] = 0.5 * (-qx * wx - qy * wy - qz * wz);
                d[4] = 0.5 * (qw * wx + qy * wz - qz * wy);
                d[5] = 0.5 * (qw * wy - qx * wz + qz * wx);
                d[6] = 0.5 * (qw * wz + qx * wy - qy * wx);
                return true;
            }
        };
        double[] y = {w0Body[0], w0Body[1], w0Body[2], q0[0], q0[1], q0[2], q0[3]};
        if (!new DormandPrince54(7, 1e-14, 1e-13).step(euler, 0, y, t)) {
            throw new IllegalStateException("the reference integration of Euler's equations failed at t = " + t + " s");
        }
        double[] q = {y[3], y[4], y[5], y[6]};
        Quaternion.normalize(q, 0);
        return q;
    }
}
