package org.handsim.trajectory;

/** Stays at one position for a given time (zero velocity and acceleration). */
public final class Hold implements Trajectory {
    private final double q, total;

    /**
     * @param at       position, counts
     * @param duration seconds (≥ 0)
     */
    public Hold(double at, double duration) {
        if (!(duration >= 0) || !Double.isFinite(duration)) throw new IllegalArgumentException("duration must be >= 0, got " + duration);
        this.q = at;
        this.total = duration;
    }

    @Override public double duration() { return total; }
    @Override public double start() { return q; }
    @Override public double end() { return q; }

    @Override
    public java.util.Map<String, Object> segment() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("type", "hold");
        m.put("duration_s", total);
        return m;
    }

    @Override
    public void sample(double t, double[] out) {
        out[0] = q;
        out[1] = 0;
        out[2] = 0;
    }
}
