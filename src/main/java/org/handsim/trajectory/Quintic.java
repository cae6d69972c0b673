package org.handsim.trajectory;

/**
 * Quintic polynomial from rest to rest: q(t) = q0 + Δq·(10τ³ − 15τ⁴ + 6τ⁵), τ = t/T, so
 * velocity and acceleration are zero at both ends (Craig, Introduction to Robotics, §7.3).
 * Peak velocity 1.875·Δq/T at τ = ½; peak acceleration 5.7735·Δq/T² at τ = ½ ∓ √3/6.
 */
public final class Quintic implements Trajectory {
    private final double q0, q1, total;

    /**
     * @param from     start position, counts
     * @param to       end position, counts
     * @param duration seconds (&gt; 0)
     */
    public Quintic(double from, double to, double duration) {
        if (!(duration > 0) || !Double.isFinite(duration)) throw new IllegalArgumentException("duration must be > 0, got " + duration);
        if (!Double.isFinite(from) || !Double.isFinite(to)) throw new IllegalArgumentException("positions must be finite");
        this.q0 = from;
        this.q1 = to;
        this.total = duration;
    }

    @Override public double duration() { return total; }
    @Override public double start() { return q0; }
    @Override public double end() { return q1; }

    @Override
    public java.util.Map<String, Object> segment() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("type", "quintic");
        m.put("to", q1);
        m.put("duration_s", total);
        return m;
    }

    @Override
    public void sample(double t, double[] out) {
        double d = q1 - q0;
        if (t <= 0) { out[0] = q0; out[1] = 0; out[2] = 0; return; }
        if (t >= total) { out[0] = q1; out[1] = 0; out[2] = 0; return; }
        double u = t / total, u2 = u * u, u3 = u2 * u;
        out[0] = q0 + d * u3 * (10 - 15 * u + 6 * u2);
        out[1] = d / total * 30 * u2 * (1 - 2 * u + u2);
        out[2] = d / (total * total) * 60 * u * (1 - 3 * u + 2 * u2);
    }
}
