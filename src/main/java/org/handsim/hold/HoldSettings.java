package org.handsim.hold;

/**
 * How the hold test pushes (DexGraspBench's protocol, with its defaults): a force F at the
 * object's centre of mass along each world axis in turn for T seconds, gravity off; a direction
 * passes while the object moves less than {@code maxDisplacementM} and turns less than
 * {@code maxRotationDeg} over the whole push. The ramp raises the force from 0 at
 * {@code rampRateNPerS} until the object has moved {@code rampDisplacementM} or turned
 * {@code rampRotationDeg}, up to {@code rampMaxN}.
 *
 * @param forceN            F, newtons; NaN: {@link #ACCELERATION} × the object's mass
 * @param durationS         T, seconds
 * @param dtS               the time step, seconds
 * @param gravity           keep the scenario's gravity during the pushes (off by default)
 * @param maxDisplacementM  the largest displacement of the centre of mass that passes, m
 * @param maxRotationDeg    the largest rotation that passes, degrees
 * @param rampDisplacementM the ramp stops once the centre of mass has moved this far, m
 * @param rampRotationDeg   or once the object has turned this far, degrees
 * @param rampRateNPerS     how fast the ramp raises the force, N/s
 * @param rampMaxN          the largest force the ramp reaches, N (a direction that holds it holds "at least" that)
 */
public record HoldSettings(double forceN, double durationS, double dtS, boolean gravity, double maxDisplacementM,
                           double maxRotationDeg, double rampDisplacementM, double rampRotationDeg, double rampRateNPerS,
                           double rampMaxN) implements java.io.Serializable {
    private static final long serialVersionUID = 1L;

    /**
     * DexGraspBench's push: 10 m/s² × the object's mass (JYChen18/DexGraspBench, its evaluation's
     * external force {@code 10 * obj_mass}); about one g, as the pipelines use.
     */
    public static final double ACCELERATION = 10;
    /** DexGraspBench's push duration, s. */
    public static final double DURATION_S = 2;
    /** DexGraspBench's thresholds: 5 cm and 15°. */
    public static final double MAX_DISPLACEMENT_M = 0.05, MAX_ROTATION_DEG = 15;
    /** The ramp's thresholds: 5 mm and 5°. */
    public static final double RAMP_DISPLACEMENT_M = 0.005, RAMP_ROTATION_DEG = 5;
    /** The ramp's rate, N/s: slow enough that the object's inertia adds little while it gives way. */
    public static final double RAMP_RATE_N_PER_S = 10;

    /** Checks every value; the messages name the command's options. */
    public HoldSettings {
        positive("--force", forceN, true);
        positive("--duration", durationS, false);
        positive("--dt", dtS, false);
        positive("--max-displacement", maxDisplacementM, false);
        positive("--max-rotation", maxRotationDeg, false);
        positive("--ramp-displacement", rampDisplacementM, false);
        positive("--ramp-rotation", rampRotationDeg, false);
        positive("--ramp-rate", rampRateNPerS, false);
        positive("--ramp-max", rampMaxN, false);
        if (dtS > durationS) throw new IllegalArgumentException("--dt (" + dtS + " s) must not exceed --duration (" + durationS + " s)");
    }

    /**
     * The time step of the pushes, s: 1 ms, the (a scenario's own step serves its closing,
     * whose events are located by bisection, and may be far coarser: the planner's is 50 ms).
     */
    public static final double DT_S = 0.001;

    /** The defaults: F from the mass, 2 s at 1 ms, gravity off, 5 cm, 15°; ramp 5 mm, 5°, 10 N/s up to {@code rampMaxN}. */
    public static HoldSettings defaults(double rampMaxN) {
        return new HoldSettings(Double.NaN, DURATION_S, DT_S, false, MAX_DISPLACEMENT_M, MAX_ROTATION_DEG, RAMP_DISPLACEMENT_M,
            RAMP_ROTATION_DEG, RAMP_RATE_N_PER_S, rampMaxN);
    }

    /** F for an object of the given mass, newtons. */
    public double force(double massKg) {
        return Double.isNaN(forceN) ? ACCELERATION * massKg : forceN;
    }

    /** These settings with F given. */
    public HoldSettings withForce(double f) {
        return new HoldSettings(f, durationS, dtS, gravity, maxDisplacementM, maxRotationDeg, rampDisplacementM, rampRotationDeg,
            rampRateNPerS, rampMaxN);
    }

    private static void positive(String option, double v, boolean nanAllowed) {
        if (nanAllowed && Double.isNaN(v)) return;
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(option + " must be a finite number > 0, got " + (Double.isFinite(v) ? org.handsim.text.Decimal.format(v) : String.valueOf(v)));
        }
    }
}
