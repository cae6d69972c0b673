package org.handsim.plan;

import java.util.SplittableRandom;

/**
 * Seeded trial parameters, a pure function of (seed, N, index), so the same seed gives the
 * same trials whatever the engine, the thread count or the partitioning.
 *
 * <p><b>Approach directions</b>: the Fibonacci sphere of N points (González 2010, "Measurement
 * of areas on a sphere using Fibonacci and latitude–longitude lattices"): point i has
 * z = 1 − (2i + 1)/N and azimuth i·π(3 − √5), nearly uniform for every N; the whole lattice is
 * turned by one random rotation drawn from the seed (Shoemake's uniform quaternion, Graphics
 * Gems III), so different seeds give different directions. Point i is where the hand comes
 * from, seen from the object's centroid; the approach is its opposite.
 *
 * <p><b>Per trial</b>: a {@link SplittableRandom} seeded by a mix of (seed, index) (Stafford's
 * variant 13 of the MurmurHash3 finaliser, the one SplittableRandom itself uses) draws, in this
 * order, the roll (uniform in [0, 2π)), the spread q_M4 (uniform integer in [0, 3150]) and the
 * standoff (uniform in [0, standoffMax)). {@link StrictMath} throughout, so the numbers do not
 * depend on the JVM's intrinsics.
 */
public final class TrialSampler {
    /** Largest spread count (BH8-262: 3150 counts = 180°). */
    public static final int SPREAD_COUNTS_MAX = 3150;
    private static final double GOLDEN_ANGLE = StrictMath.PI * (3 - StrictMath.sqrt(5));

    private final int n;
    private final long seed;
    private final double standoffMax;
    private final double[] rot = new double[9];   // row-major rotation of the lattice

    public TrialSampler(int trials, long seed, double standoffMax) {
        if (trials < 1) throw new IllegalArgumentException("trials must be >= 1, got " + trials);
        this.n = trials;
        this.seed = seed;
        this.standoffMax = standoffMax;
        SplittableRandom r = new SplittableRandom(mix(seed, -1));
        // Shoemake: a uniform unit quaternion from three uniforms
        double u1 = r.nextDouble(), u2 = r.nextDouble(), u3 = r.nextDouble();
        double a = StrictMath.sqrt(1 - u1), b = StrictMath.sqrt(u1);
        double w = a * StrictMath.sin(2 * StrictMath.PI * u2), x = a * StrictMath.cos(2 * StrictMath.PI * u2);
        double y = b * StrictMath.sin(2 * StrictMath.PI * u3), z = b * StrictMath.cos(2 * StrictMath.PI * u3);
        rot[0] = 1 - 2 * (y * y + z * z); rot[1] = 2 * (x * y - w * z);     rot[2] = 2 * (x * z + w * y);
        rot[3] = 2 * (x * y + w * z);     rot[4] = 1 - 2 * (x * x + z * z); rot[5] = 2 * (y * z - w * x);
        rot[6] = 2 * (x * z - w * y);     rot[7] = 2 * (y * z + w * x);     rot[8] = 1 - 2 * (x * x + y * y);
    }

    public TrialSampler(PlanSpec spec) {
        this(spec.trials(), spec.seed(), spec.standoffMax());
    }

    /** The parameters of trial {@code index} (0..N−1). */
    public TrialParameters sample(int index) {
        if (index < 0 || index >= n) throw new IllegalArgumentException("trial index must be in [0, " + n + "), got " + index);
        double[] u = fibonacci(index, n);
        double[] a = new double[3];
        for (int r = 0; r < 3; r++) a[r] = -(rot[3 * r] * u[0] + rot[3 * r + 1] * u[1] + rot[3 * r + 2] * u[2]);
        double len = StrictMath.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (int r = 0; r < 3; r++) a[r] /= len;
        SplittableRandom rnd = new SplittableRandom(mix(seed, index));
        double roll = 2 * StrictMath.PI * rnd.nextDouble();
        int spread = rnd.nextInt(SPREAD_COUNTS_MAX + 1);
        double standoff = standoffMax * rnd.nextDouble();
        return new TrialParameters(index, a, roll, spread, standoff);
    }

    /** Point i of the N-point Fibonacci sphere (unit vector). */
    static double[] fibonacci(int i, int n) {
        double z = 1 - (2.0 * i + 1) / n;
        double r = StrictMath.sqrt(Math.max(0, 1 - z * z));
        double phi = GOLDEN_ANGLE * i;
        return new double[] {r * StrictMath.cos(phi), r * StrictMath.sin(phi), z};
    }

    /** A 64-bit seed for (plan seed, index): Stafford's mix13 of seed·φ + index. */
    static long mix(long seed, long index) {
        long z = seed * 0x9E3779B97F4A7C15L + index;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
