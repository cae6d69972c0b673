package org.handsim.plan;

/**
 * The distribution of ε over the force-closure trials in bounded memory: {@link #BINS} equal
 * bins over [0, width·BINS); a value beyond the range doubles the width (merging bins in
 * pairs) until it fits, so the histogram of a million trials costs what the first one did.
 * Trials without force closure (ε = 0) are counted apart.
 */
public final class EpsilonHistogram {
    /** Number of bins. */
    public static final int BINS = 40;
    private final long[] counts = new long[BINS];
    private double width = Double.NaN;
    private long noClosure;
    private double max;

    /** Adds one trial's ε (0 or NaN: no force closure). */
    public void add(boolean forceClosure, double epsilon) {
        if (!forceClosure || !(epsilon > 0)) {
            noClosure++;
            return;
        }
        if (Double.isNaN(width)) width = niceWidth(epsilon);
        while (epsilon >= width * BINS) {
            for (int b = 0; b < BINS / 2; b++) counts[b] = counts[2 * b] + counts[2 * b + 1];
            for (int b = BINS / 2; b < BINS; b++) counts[b] = 0;
            width *= 2;
        }
        counts[(int) Math.min(BINS - 1, Math.floor(epsilon / width))]++;
        max = Math.max(max, epsilon);
    }

    /** The first width: a power of two over BINS that holds the first value in the upper half of the range. */
    private static double niceWidth(double e) {
        return Math.pow(2, Math.ceil(Math.log(e * 1.0000001 / BINS) / Math.log(2))) ;
    }

    /** Bin width (NaN before the first force-closure value). */
    public double width() { return width; }
    /** Counts per bin (a copy); bin b is [b·width, (b+1)·width). */
    public long[] counts() { return counts.clone(); }
    /** Trials without force closure. */
    public long noClosure() { return noClosure; }
    /** Largest ε added (0 if none). */
    public double max() { return max; }
    /** Bins up to the last non-empty one (at least 1). */
    public int usedBins() {
        int u = 1;
        for (int b = 0; b < BINS; b++) if (counts[b] > 0) u = b + 1;
        return u;
    }
}
