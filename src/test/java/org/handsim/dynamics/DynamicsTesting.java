package org.handsim.dynamics;

import java.lang.management.ManagementFactory;
import java.util.Random;
import org.handsim.hand.HandDescription;

/** Named tolerances, seeded random states and measures shared by the dynamics tests (docs/STYLE.md, item 12). */
final class DynamicsTesting {
    private DynamicsTesting() {}

    /** Two independent algorithms on the same state: rounding differences only. */
    static final double CROSS_CHECK = 1e-12;
    /** A formula derived by hand against the code: rounding only. */
    static final double EXACT = 1e-14;
    /** A central finite difference against an analytic derivative. */
    static final double FINITE_DIFFERENCE = 1e-8;
    /** The seed of every random sample. */
    static final long SEED = 345;
    /** States per finger in the cross-checks. */
    static final int STATES = 10_000;
    static final double G0 = 9.81;

    /** A random state of finger k's active joints over its joint range (and beyond, by 0.2 rad). */
    static final class State {
        final double[] q, qd, qdd, g;

        State(int n) {
            q = new double[n];
            qd = new double[n];
            qdd = new double[n];
            g = new double[3];
        }
    }

    /**
     * q over the hand's joint limits widened by 0.2 rad (spread θk1 ∈ [−π, π] covers both
     * fingers' signs), q̇ uniform in ±5 rad/s, q̈ uniform in ±50 rad/s², g of magnitude 9.81 in a
     * uniformly random direction.
     */
    static State randomState(LinkChain chain, Random r) {
        HandDescription h = HandDescription.barrettHand();
        double[][] lim = {{-Math.PI, Math.PI}, h.theta2Limits(), h.theta3Limits()};
        int n = chain.dof();
        State s = new State(n);
        for (int p = 0; p < n; p++) {
            double[] l = lim[chain.linkOfDof(p)];
            s.q[p] = l[0] - 0.2 + r.nextDouble() * (l[1] - l[0] + 0.4);
            s.qd[p] = -5 + 10 * r.nextDouble();
            s.qdd[p] = -50 + 100 * r.nextDouble();
        }
        double x = r.nextGaussian(), y = r.nextGaussian(), z = r.nextGaussian();
        double norm = Math.sqrt(x * x + y * y + z * z);
        s.g[0] = G0 * x / norm;
        s.g[1] = G0 * y / norm;
        s.g[2] = G0 * z / norm;
        return s;
    }

    /** ‖a − b‖∞ / ‖b‖∞, the norm-wise relative difference. */
    static double relative(double[] a, double[] b) {
        return relative(a, b, 0);
    }

    /**
     * ‖a − b‖∞ / max(‖b‖∞, scale): relative to the vector, or to a natural scale of its terms
     * when the vector is small because its terms cancel.
     */
    static double relative(double[] a, double[] b, double scale) {
        double num = 0, den = scale;
        for (int i = 0; i < b.length; i++) {
            num = Math.max(num, Math.abs(a[i] - b[i]));
            den = Math.max(den, Math.abs(b[i]));
        }
        return den == 0 ? num : num / den;
    }

    static double maxAbs(double[] a) {
        double m = 0;
        for (double v : a) m = Math.max(m, Math.abs(v));
        return m;
    }

    static double dot(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) s += a[i] * b[i];
        return s;
    }

    /** Bytes this thread allocates while running {@code r} (HotSpot's per-thread counter). */
    static long allocatedBytes(Runnable r) {
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long before = bean.getThreadAllocatedBytes(id);
        r.run();
        return bean.getThreadAllocatedBytes(id) - before;
    }
}
