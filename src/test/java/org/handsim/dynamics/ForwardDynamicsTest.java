package org.handsim.dynamics;

import static org.handsim.dynamics.DynamicsTesting.SEED;
import static org.handsim.dynamics.DynamicsTesting.randomState;
import static org.handsim.dynamics.DynamicsTesting.relative;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.hand.DhRow;
import org.handsim.hand.LinkInertia;
import org.junit.jupiter.api.Test;

class ForwardDynamicsTest {
    /** Forward dynamics inverts inverse dynamics: FD(q, q̇, ID(q, q̇, q̈)) = q̈. */
    @Test
    void invertsInverseDynamics() {
        for (int k = 1; k <= 3; k++) {
            LinkChain chain = LinkChain.finger(k);
            ChainDynamics d = new ClosedFormFinger(chain);
            ForwardDynamics fd = new ForwardDynamics(d);
            int n = chain.dof();
            double[] tau = new double[n], qdd = new double[n];
            Random r = new Random(SEED);
            double worst = 0;
            for (int s = 0; s < 2000; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                d.inverseDynamics(st.q, st.qd, st.qdd, st.g, tau);
                assertTrue(fd.accelerations(st.q, st.qd, tau, st.g, qdd));
                worst = Math.max(worst, relative(qdd, st.qdd));
            }
            // D's condition number (~1e2) times rounding
            assertTrue(worst < 1e-11, "finger " + k + ": " + worst);
        }
    }

    /** A chain without mass has D = 0: a failure outcome, the output untouched, no NaN. */
    @Test
    void aSingularMassMatrixIsAFailureNotANaN() {
        LinkInertia none = new LinkInertia(0, new double[3], new double[6]);
        LinkChain massless = LinkChain.of(new DhRow[] {new DhRow(0.1, 0, 0, 0), new DhRow(0.1, 0, 0, 0)},
            new LinkInertia[] {none, none});
        ForwardDynamics fd = new ForwardDynamics(new LagrangeEuler(massless));
        double[] out = {7, 7};
        assertFalse(fd.accelerations(new double[2], new double[2], new double[] {1, 1}, new double[3], out));
        assertArrayEquals(new double[] {7, 7}, out);

        // a point mass on the second link only: D is singular (rank 1) at q2 = 0 — the first joint
        // cannot be told from the second when both axes see the mass on one line
        LinkInertia point = new LinkInertia(1, new double[3], new double[6]);
        LinkChain degenerate = LinkChain.of(new DhRow[] {new DhRow(0, 0, 0, 0), new DhRow(0.1, 0, 0, 0)},
            new LinkInertia[] {none, point});
        fd = new ForwardDynamics(new NewtonEuler(degenerate));
        assertFalse(fd.accelerations(new double[2], new double[2], new double[] {1, 0}, new double[3], out));

        ForwardDynamics finger = new ForwardDynamics(new ClosedFormFinger(LinkChain.finger(1)));
        assertFalse(finger.accelerations(new double[] {Double.NaN, 0, 0}, new double[3], new double[3], new double[3], new double[3]));
    }

    @Test
    void outputMustNotAliasAnInput() {
        ForwardDynamics fd = new ForwardDynamics(new ClosedFormFinger(LinkChain.finger(1)));
        double[] q = new double[3], g = {0, 0, -9.81};
        assertThrows(IllegalArgumentException.class, () -> fd.accelerations(q, new double[3], new double[3], g, q));
        assertThrows(IllegalArgumentException.class, () -> fd.accelerations(q, new double[3], new double[2], g, new double[3]));
    }

    @Test
    void allocatesNothing() {
        ForwardDynamics fd = new ForwardDynamics(new ClosedFormFinger(LinkChain.finger(2)));
        double[] q = {0.1, 0.2, 0.3}, qd = {1, 2, 3}, tau = {0.01, 0.02, 0.03}, g = {0, 0, -9.81}, qdd = new double[3];
        FingerDynamicsOde ode = new FingerDynamicsOde(fd.dynamics(), g, FingerDynamicsOde.Torques.ZERO);
        Integrator[] all = {new ExplicitEuler(6), new SemiImplicitEuler(3), new RungeKutta4(6), new DormandPrince54(6, 1e-9, 1e-9)};
        double[] y = {0.1, 0.2, 0.3, 1, 2, 3};
        Runnable work = () -> {
            for (int i = 0; i < 5_000; i++) {
                q[0] += 1e-6;
                fd.accelerations(q, qd, tau, g, qdd);
                for (Integrator in : all) in.step(ode, 0, y, 1e-4);
            }
        };
        work.run();
        long bytes = DynamicsTesting.allocatedBytes(work);
        assertTrue(bytes < 1024, "allocated " + bytes + " bytes");
    }
}
