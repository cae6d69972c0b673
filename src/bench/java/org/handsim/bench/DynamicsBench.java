package org.handsim.bench;

import java.util.Locale;
import java.util.Random;
import org.handsim.dynamics.ChainDynamics;
import org.handsim.dynamics.ClosedFormFinger;
import org.handsim.dynamics.FingerDynamicsOde;
import org.handsim.dynamics.ForwardDynamics;
import org.handsim.dynamics.HandDynamics;
import org.handsim.dynamics.LagrangeEuler;
import org.handsim.dynamics.LinkChain;
import org.handsim.dynamics.NewtonEuler;
import org.handsim.dynamics.RungeKutta4;

/**
 * Suite "dynamics": eq (8) for a 3-joint BarrettHand finger (finger 1) — τ by the closed form
 * (the simulator's fast path), the general Lagrange–Euler and Newton–Euler; D alone; D, H, C
 * together; forward dynamics (D, H, C + Cholesky); one RK4 step. States cycle through 1024
 * seeded random ones so nothing is constant-folded.
 *
 * <p>Anchors: Pinocchio (C++) on the same kind of chain and machine, RNEA ≈ 450 ns per
 * τ and CRBA ≈ 200 ns per mass matrix. Goals: the step's τ ≤ 225 ns (half of RNEA), the
 * general Lagrange–Euler ≤ 1350 ns (3× RNEA).
 */
final class DynamicsBench implements BenchMain.Suite {
    private static final double PINOCCHIO_RNEA_NS = 450;
    private static final double PINOCCHIO_CRBA_NS = 200;
    private static final int STATES = 1024;

    private final double[][] q = new double[STATES][3], qd = new double[STATES][3], qdd = new double[STATES][3];
    private final double[][] tauIn = new double[STATES][3];
    private final double[] g = {0, 0, -9.81};
    private int i;

    DynamicsBench() {
        Random r = new Random(345);
        for (int s = 0; s < STATES; s++) {
            q[s][0] = -Math.PI / 2 + Math.PI * r.nextDouble();
            q[s][1] = 2.4 * r.nextDouble();
            q[s][2] = 1.7 * r.nextDouble();
            for (int j = 0; j < 3; j++) {
                qd[s][j] = -5 + 10 * r.nextDouble();
                qdd[s][j] = -50 + 100 * r.nextDouble();
                tauIn[s][j] = -0.1 + 0.2 * r.nextDouble();
            }
        }
    }

    private int next() {
        i = (i + 1) & (STATES - 1);
        return i;
    }

    private Bench.Result tau(String name, ChainDynamics d) {
        double[] out = new double[3];
        return Bench.measure(name, () -> {
            int s = next();
            d.inverseDynamics(q[s], qd[s], qdd[s], g, out);
            return out[0] + out[1] + out[2];
        });
    }

    private Bench.Result mass(String name, ChainDynamics d) {
        double[] out = new double[9];
        return Bench.measure(name, () -> {
            d.massMatrix(q[next()], out);
            return out[0] + out[4] + out[8];
        });
    }

    private static void ratio(Bench.Result r, double anchor, String what) {
        System.out.println(String.format(Locale.ROOT, "    -> %.2f x Pinocchio %s (%.0f ns)", r.medianNs / anchor, what, anchor));
    }

    @Override
    public void run() {
        LinkChain f1 = LinkChain.finger(1);
        ClosedFormFinger cf = new ClosedFormFinger(f1);
        LagrangeEuler le = new LagrangeEuler(f1);
        NewtonEuler ne = new NewtonEuler(f1);

        ratio(tau("tau, closed form (fast path), 3-joint finger", cf), PINOCCHIO_RNEA_NS, "RNEA");
        ratio(tau("tau, general Lagrange-Euler", le), PINOCCHIO_RNEA_NS, "RNEA");
        ratio(tau("tau, recursive Newton-Euler", ne), PINOCCHIO_RNEA_NS, "RNEA");

        HandDynamics hand = HandDynamics.barrettHand();
        double[] t3 = new double[3], q3 = new double[3], qd3 = new double[3], qdd3 = new double[3];
        Bench.measure("tau, HandDynamics 3-joint layout, finger 3 (2 joints)", () -> {
            int s = next();
            q3[1] = q[s][1];
            q3[2] = q[s][2];
            qd3[1] = qd[s][1];
            qd3[2] = qd[s][2];
            qdd3[1] = qdd[s][1];
            qdd3[2] = qdd[s][2];
            hand.inverseDynamics(3, q3, qd3, qdd3, g, t3);
            return t3[1] + t3[2];
        });

        ratio(mass("D alone, closed form", cf), PINOCCHIO_CRBA_NS, "CRBA");
        ratio(mass("D alone, general Lagrange-Euler", le), PINOCCHIO_CRBA_NS, "CRBA");
        ratio(mass("D alone, Newton-Euler (n unit-acceleration passes)", ne), PINOCCHIO_CRBA_NS, "CRBA");

        double[] d9 = new double[9], h = new double[3], c = new double[3];
        Bench.measure("D, H, C together, closed form", () -> {
            int s = next();
            cf.terms(q[s], qd[s], g, d9, h, c);
            return d9[0] + h[0] + c[1];
        });

        for (ChainDynamics d : new ChainDynamics[] {cf, le, ne}) {
            ForwardDynamics fd = new ForwardDynamics(d);
            double[] out = new double[3];
            Bench.measure("forward dynamics (D, H, C + Cholesky), " + d.getClass().getSimpleName(), () -> {
                int s = next();
                fd.accelerations(q[s], qd[s], tauIn[s], g, out);
                return out[0] + out[1] + out[2];
            });
        }

        FingerDynamicsOde ode = new FingerDynamicsOde(cf, g, FingerDynamicsOde.Torques.ZERO);
        RungeKutta4 rk = new RungeKutta4(6);
        double[] y = new double[6];
        Bench.measure("RK4 step (4 forward dynamics), closed form", () -> {
            int s = next();
            System.arraycopy(q[s], 0, y, 0, 3);
            System.arraycopy(qd[s], 0, y, 3, 3);
            rk.step(ode, 0, y, 1e-4);
            return y[0] + y[5];
        });
    }
}
