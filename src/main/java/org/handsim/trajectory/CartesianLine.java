package org.handsim.trajectory;

import org.handsim.kinematics.CoupledReach;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;

/**
 * A finger motor trajectory whose fingertip follows a straight line through inverse
 * kinematics: from where the fingertip is at the start counts to a target point (in the
 * finger base frame {k0}, metres), with a quintic time scaling s(t) along the line.
 *
 * <p>One motor drives both joints of a free finger (eqs 3–4), so the fingertip can only follow
 * the line as closely as its coupled curve allows: at {@value #SAMPLES} points along the line
 * the counts whose fingertip comes closest are found exactly
 * ({@link CoupledReach}), and the counts are interpolated between them (piecewise cubic
 * Hermite, monotone where the samples are). {@link #maxDeviationM()} reports how far the
 * sampled fingertip strays from the line.
 */
public final class CartesianLine implements Trajectory {
    /** Number of points at which the line is solved. */
    public static final int SAMPLES = 101;

    private final double total;
    private final double[] q = new double[SAMPLES];
    private final double[] slope = new double[SAMPLES];
    private final double maxDeviation;
    private final double[] target;

    /**
     * @param finger      1, 2 or 3
     * @param fromCounts  start position of the finger motor, counts
     * @param spreadCounts the spread motor's (fixed) counts
     * @param target      end point of the fingertip in {k0}, metres
     * @param duration    seconds (&gt; 0)
     */
    public CartesianLine(int finger, double fromCounts, double spreadCounts, double[] target, double duration) {
        if (!(duration > 0)) throw new IllegalArgumentException("duration must be > 0, got " + duration);
        this.total = duration;
        this.target = target.clone();
        Transmission tr = Transmission.barrettHand();
        FingerKinematics fk = FingerKinematics.of(finger);
        double[] p0 = fk.fingertip(tr.joints(finger, fromCounts, spreadCounts, null));
        CoupledReach reach = CoupledReach.of(finger);
        double dev = 0;
        double[] p = new double[3];
        for (int i = 0; i < SAMPLES; i++) {
            double s = i / (double) (SAMPLES - 1);
            for (int c = 0; c < 3; c++) p[c] = p0[c] + s * (target[c] - p0[c]);
            if (i == 0) {
                q[i] = fromCounts;
            } else {
                CoupledReach.Result r = reach.closest(p);
                q[i] = r.qMk();
                dev = Math.max(dev, r.errorM());
            }
        }
        maxDeviation = dev;
        // Fritsch–Carlson monotone slopes (in counts per unit s)
        double h = 1.0 / (SAMPLES - 1);
        for (int i = 0; i < SAMPLES; i++) {
            double dl = i > 0 ? (q[i] - q[i - 1]) / h : Double.NaN;
            double dr = i < SAMPLES - 1 ? (q[i + 1] - q[i]) / h : Double.NaN;
            if (i == 0) slope[i] = dr;
            else if (i == SAMPLES - 1) slope[i] = dl;
            else slope[i] = (dl * dr <= 0) ? 0 : 2 / (1 / dl + 1 / dr);
        }
    }

    /** @return the largest distance from the line of the sampled fingertip, metres */
    public double maxDeviationM() { return maxDeviation; }

    @Override public double duration() { return total; }

    @Override
    public java.util.Map<String, Object> segment() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("type", "line");
        m.put("target_m", target.clone());
        m.put("duration_s", total);
        return m;
    }
    @Override public double start() { return q[0]; }
    @Override public double end() { return q[SAMPLES - 1]; }

    @Override
    public void sample(double t, double[] out) {
        if (t <= 0) { out[0] = q[0]; out[1] = 0; out[2] = 0; return; }
        if (t >= total) { out[0] = q[SAMPLES - 1]; out[1] = 0; out[2] = 0; return; }
        // quintic time scaling s(t) and its derivatives
        double u = t / total, u2 = u * u, u3 = u2 * u;
        double s = u3 * (10 - 15 * u + 6 * u2);
        double sd = 30 * u2 * (1 - 2 * u + u2) / total;
        double sdd = 60 * u * (1 - 3 * u + 2 * u2) / (total * total);
        double h = 1.0 / (SAMPLES - 1);
        int i = Math.min(SAMPLES - 2, (int) (s / h));
        double x = (s - i * h) / h, x2 = x * x, x3 = x2 * x;
        double h00 = 2 * x3 - 3 * x2 + 1, h10 = x3 - 2 * x2 + x, h01 = -2 * x3 + 3 * x2, h11 = x3 - x2;
        double qs = h00 * q[i] + h10 * h * slope[i] + h01 * q[i + 1] + h11 * h * slope[i + 1];
        double dq = ((6 * x2 - 6 * x) * q[i] + (3 * x2 - 4 * x + 1) * h * slope[i]
            + (-6 * x2 + 6 * x) * q[i + 1] + (3 * x2 - 2 * x) * h * slope[i + 1]) / h;
        double ddq = ((12 * x - 6) * q[i] + (6 * x - 4) * h * slope[i]
            + (-12 * x + 6) * q[i + 1] + (6 * x - 2) * h * slope[i + 1]) / (h * h);
        out[0] = qs;
        out[1] = dq * sd;
        out[2] = ddq * sd * sd + dq * sdd;
    }
}
