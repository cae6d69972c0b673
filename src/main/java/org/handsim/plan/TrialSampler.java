package org.handsim.plan;

import java.util.SplittableRandom;

/**
 * Seeded trial parameters, a pure function of (seed, N, index) and the object's shape, so the
 * same seed gives the same trials whatever the engine, the thread count or the partitioning.
 *
 * <p><b>Approach directions</b>: half the trials come from the Fibonacci sphere of N points
 * (González 2010, "Measurement of areas on a sphere using Fibonacci and latitude–longitude
 * lattices"): point i has z = 1 − (2i + 1)/N and azimuth i·π(3 − √5), nearly uniform for every
 * N, the whole lattice turned by one random rotation drawn from the seed (Shoemake's uniform
 * quaternion, Graphics Gems III); point i is where the hand comes from, seen from the object's
 * centroid, and the approach is its opposite. The other half come along one of the object's
 * principal axes ({@link ObjectFrame}), either way, each component jittered by up to ±
 * {@link #AXIS_JITTER}: GraspIt!'s primitive-based planner (Miller et al., "Automatic grasp
 * planning using shape primitives", ICRA 2003) approaches boxes and cylinders along their axes
 * and faces, where the fingers meet flat or round sides square on. Without a shape (null) every
 * trial takes the lattice.
 *
 * <p><b>Roll</b>: for half the trials the palm's x axis is turned onto the projection of the
 * longest principal axis (the middle one when the approach runs along the longest) on the palm
 * plane, plus a quarter turn 0 to 3 times and up to ±{@link #ROLL_JITTER} rad, so the fingers
 * close across or along the object; the others uniform in [0, 2π).
 *
 * <p><b>Spread</b>: uniform integer in [0, {@link #SPREAD_COUNTS_USED}] (0 to 90°): from fingers 1
 * and 2 side by side opposite finger 3 (0) through the three at 120° (60°, 1 050 counts) to a
 * right angle. Beyond 90° fingers 1 and 2 swing round to finger 3's side and oppose nothing:
 * measured over 300 trials on each shape of docs/BENCHMARKS.md's set, spreads of 120–180° gave
 * force closure in 0–3 % of their trials, against 10–40 % below 90°.
 *
 * <p><b>Standoff</b>: which rule ({@link StandoffRule}: wrap or fingertips) and a uniform draw in
 * [0, 1) of where in its range; the standoff itself follows from the approach's first touch.
 *
 * <p>Per trial a {@link SplittableRandom} seeded by a mix of (seed, index) (Stafford's variant 13
 * of the MurmurHash3 finaliser, the one SplittableRandom itself uses) draws, in this order:
 * whether the approach follows an axis, which axis, which way, three jitters; whether the roll is
 * aligned, the quarter turns and the jitter, or the uniform roll; the spread; the standoff rule
 * and its draw. {@link StrictMath} throughout, so the numbers do not depend on the JVM's
 * intrinsics.
 */
public final class TrialSampler {
    /** Largest spread count of the hand (BH8-262: 3150 counts = 180°). */
    public static final int SPREAD_COUNTS_MAX = 3150;
    /** Largest spread count sampled: 90° (see the class comment). */
    public static final int SPREAD_COUNTS_USED = 1575;
    /** Share of the trials that approach along a principal axis. */
    public static final double AXIS_SHARE = 0.5;
    /** Jitter of an axis approach, per component of the direction before it is normalised. */
    public static final double AXIS_JITTER = 0.075;
    /** Share of the trials whose roll is aligned with the object's axes. */
    public static final double ALIGNED_ROLL_SHARE = 0.5;
    /** Jitter of an aligned roll, radians (±). */
    public static final double ROLL_JITTER = 0.1;
    private static final double GOLDEN_ANGLE = StrictMath.PI * (3 - StrictMath.sqrt(5));

    private final int n;
    private final long seed;
    private final ObjectFrame shape;
    private final double[] rot = new double[9];   // row-major rotation of the lattice

    /**
     * @param shape the object's principal axes, or null: the lattice alone and uniform rolls
     */
    public TrialSampler(int trials, long seed, ObjectFrame shape) {
        if (trials < 1) throw new IllegalArgumentException("trials must be >= 1, got " + trials);
        this.n = trials;
        this.seed = seed;
        this.shape = shape;
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

    /** The parameters of trial {@code index} (0..N−1). */
    public TrialParameters sample(int index) {
        if (index < 0 || index >= n) throw new IllegalArgumentException("trial index must be in [0, " + n + "), got " + index);
        SplittableRandom rnd = new SplittableRandom(mix(seed, index));
        double[] a = new double[3];
        if (shape != null && rnd.nextDouble() < AXIS_SHARE) {
            double[] e = shape.axis(rnd.nextInt(3));
            double sign = rnd.nextBoolean() ? 1 : -1;
            for (int r = 0; r < 3; r++) a[r] = sign * e[r] + AXIS_JITTER * (2 * rnd.nextDouble() - 1);
        } else {
            double[] u = fibonacci(index, n);
            for (int r = 0; r < 3; r++) a[r] = -(rot[3 * r] * u[0] + rot[3 * r + 1] * u[1] + rot[3 * r + 2] * u[2]);
        }
        double len = StrictMath.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (int r = 0; r < 3; r++) a[r] /= len;
        double roll;
        if (shape != null && rnd.nextDouble() < ALIGNED_ROLL_SHARE) {
            roll = alignedRoll(a) + StrictMath.PI / 2 * rnd.nextInt(4) + ROLL_JITTER * (2 * rnd.nextDouble() - 1);
            roll = roll - 2 * StrictMath.PI * StrictMath.floor(roll / (2 * StrictMath.PI));
        } else {
            roll = 2 * StrictMath.PI * rnd.nextDouble();
        }
        int spread = rnd.nextInt(SPREAD_COUNTS_USED + 1);
        boolean wrap = rnd.nextDouble() < StandoffRule.wrapShare(shape);
        double depth = rnd.nextDouble();
        return new TrialParameters(index, a, roll, spread, wrap, depth);
    }

    /**
     * The roll that turns the palm's x axis onto the projection of the longest principal axis on
     * the palm plane (the middle axis when the approach runs within about 37° of the longest):
     * its angle from the roll-0 x axis of {@link Autograsp#palmRotation}.
     */
    double alignedRoll(double[] a) {
        double[] e = shape.axis(0);
        if (StrictMath.abs(e[0] * a[0] + e[1] * a[1] + e[2] * a[2]) > 0.8) e = shape.axis(1);
        double[] x0 = Autograsp.rollZeroX(a);
        double[] y0 = {a[1] * x0[2] - a[2] * x0[1], a[2] * x0[0] - a[0] * x0[2], a[0] * x0[1] - a[1] * x0[0]};
        return StrictMath.atan2(e[0] * y0[0] + e[1] * y0[1] + e[2] * y0[2], e[0] * x0[0] + e[1] * x0[1] + e[2] * x0[2]);
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
