package org.handsim.trajectory;

import java.util.List;

/**
 * Trajectories played one after the other (e.g. close, hold, open). Each segment must start
 * where the previous one ended; segments are located by binary search on their start times.
 */
public final class Sequence implements Trajectory {
    private final Trajectory[] parts;
    private final double[] starts;
    private final double total;

    /**
     * @throws IllegalArgumentException if the list is empty or a segment does not start where
     *                                  the previous one ended (naming the segment)
     */
    public Sequence(List<Trajectory> segments) {
        if (segments.isEmpty()) throw new IllegalArgumentException("a sequence needs at least one segment");
        parts = segments.toArray(new Trajectory[0]);
        starts = new double[parts.length];
        double t = 0;
        for (int i = 0; i < parts.length; i++) {
            if (i > 0 && Math.abs(parts[i].start() - parts[i - 1].end()) > 1e-9) {
                throw new IllegalArgumentException("segment " + i + " starts at " + parts[i].start()
                    + " counts but segment " + (i - 1) + " ends at " + parts[i - 1].end());
            }
            starts[i] = t;
            t += parts[i].duration();
        }
        total = t;
    }

    @Override public double duration() { return total; }
    @Override public double start() { return parts[0].start(); }
    @Override public double end() { return parts[parts.length - 1].end(); }

    /** @return the segments, in order */
    public List<Trajectory> segments() { return List.of(parts); }

    /** Not one segment: write {@link #segments()} one by one. */
    @Override
    public java.util.Map<String, Object> segment() {
        throw new UnsupportedOperationException("a sequence is a list of segments: write segments() one by one");
    }

    @Override
    public void sample(double t, double[] out) {
        int lo = 0, hi = parts.length - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (starts[mid] <= t) lo = mid; else hi = mid - 1;
        }
        parts[lo].sample(t - starts[lo], out);
    }
}
