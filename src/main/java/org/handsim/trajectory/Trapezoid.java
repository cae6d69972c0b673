package org.handsim.trajectory;

/**
 * Trapezoidal velocity profile (the paper's Section V input): constant acceleration a up to
 * the cruise velocity v, cruise, constant deceleration; triangular (no cruise, peak velocity
 * √(a·|Δq|)) when the move is too short to reach v.
 *
 * <p>Worked example: 0 → 17 500 counts with v = 5 000 counts/s and a = 25 000 counts/s²:
 * ramps of v/a = 0.2 s covering 500 counts each, cruise 16 500 counts in 3.3 s, total 3.7 s.
 */
public final class Trapezoid implements Trajectory {
    private final double q0, q1, dir, vPeak, accel, tRamp, tCruise, total;
    private final double vMax;

    /**
     * @param from   start position, counts
     * @param to     end position, counts
     * @param vMax   cruise velocity magnitude, counts/s (&gt; 0)
     * @param aMax   acceleration magnitude, counts/s² (&gt; 0)
     */
    public Trapezoid(double from, double to, double vMax, double aMax) {
        if (!(vMax > 0) || !Double.isFinite(vMax)) throw new IllegalArgumentException("v_max must be > 0, got " + vMax);
        if (!(aMax > 0) || !Double.isFinite(aMax)) throw new IllegalArgumentException("a_max must be > 0, got " + aMax);
        if (!Double.isFinite(from) || !Double.isFinite(to)) throw new IllegalArgumentException("positions must be finite");
        this.q0 = from;
        this.q1 = to;
        double dist = Math.abs(to - from);
        this.dir = Math.signum(to - from);
        this.accel = aMax;
        this.vMax = vMax;
        if (dist >= vMax * vMax / aMax) {
            vPeak = vMax;
            tRamp = vMax / aMax;
            tCruise = (dist - vMax * vMax / aMax) / vMax;
        } else {
            vPeak = Math.sqrt(dist * aMax);
            tRamp = vPeak / aMax;
            tCruise = 0;
        }
        this.total = 2 * tRamp + tCruise;
    }

    @Override public double duration() { return total; }
    @Override public double start() { return q0; }
    @Override public double end() { return q1; }

    @Override
    public java.util.Map<String, Object> segment() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("type", "trapezoid");
        m.put("to", q1);
        m.put("v_max", vMax);
        m.put("a_max", accel);
        return m;
    }

    /** @return true when the move never reaches v_max (triangular profile). */
    public boolean triangular() { return tCruise == 0; }

    /** @return the peak velocity magnitude, counts/s. */
    public double peakVelocity() { return vPeak; }

    @Override
    public void sample(double t, double[] out) {
        double s, v, a;
        if (t <= 0 || dir == 0) {
            s = 0; v = 0; a = 0;
            if (t > total) s = Math.abs(q1 - q0);
        } else if (t < tRamp) {
            a = accel; v = accel * t; s = 0.5 * accel * t * t;
        } else if (t < tRamp + tCruise) {
            a = 0; v = vPeak; s = 0.5 * vPeak * tRamp + vPeak * (t - tRamp);
        } else if (t < total) {
            double r = total - t;
            a = -accel; v = accel * r; s = Math.abs(q1 - q0) - 0.5 * accel * r * r;
        } else {
            s = Math.abs(q1 - q0); v = 0; a = 0;
        }
        out[0] = q0 + dir * s;
        out[1] = dir * v;
        out[2] = dir * a;
    }
}
