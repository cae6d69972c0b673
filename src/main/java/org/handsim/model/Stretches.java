package org.handsim.model;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Stretches of steps in which a watched value stays above its threshold, each turned into one
 * warning — so a long run in such a state warns once, not per step. Values are watched under
 * integer keys (a finger, a finger's link); a stretch of one key ends at the first step whose
 * value is at or below the threshold. The warnings name the key's subject, the stretch's start
 * and end time and its largest value with its time, in the words of a {@link Wording}. After
 * {@code maxWarnings} stretches of one key the rest are counted in one line.
 *
 * <p>Used by {@link HandModel} for the contact forces that carry no joint torques (the residual)
 * and for forces above Barrett's rating. Not thread-safe. Watching allocates nothing once the
 * ended stretches' arrays have grown (they keep their capacity across {@link #clear()}): the words
 * are made only when {@link #warnings()} is asked for.
 */
final class Stretches {
    /** The words of the warnings. */
    interface Wording {
        /** One stretch of {@code key}: from {@code start} to {@code end} (s), largest value {@code max} at {@code maxAt}. */
        String stretch(int key, double start, double end, double max, double maxAt);

        /** {@code more} stretches of {@code key} beyond the warned ones, the largest value among them {@code max}. */
        String more(int key, int more, double max);
    }

    private final double threshold;
    private final int maxWarnings;
    private final Wording wording;
    private final double[] start, end, max, maxAt, moreMax;
    private final int[] count;
    // the stretches warned about one by one, in the order they ended: key, start, end, max, time of max
    private int endedCount;
    private int[] endedKey = new int[8];
    private double[] ended = new double[4 * 8];

    /**
     * @param keys        how many keys (0 .. keys−1)
     * @param threshold   a value above this starts or continues a stretch
     * @param maxWarnings stretches of one key warned one by one
     */
    Stretches(int keys, double threshold, int maxWarnings, Wording wording) {
        this.threshold = threshold;
        this.maxWarnings = maxWarnings;
        this.wording = wording;
        start = new double[keys];
        end = new double[keys];
        max = new double[keys];
        maxAt = new double[keys];
        moreMax = new double[keys];
        count = new int[keys];
        clear();
    }

    /** Forgets every stretch. */
    void clear() {
        Arrays.fill(start, Double.NaN);
        Arrays.fill(count, 0);
        Arrays.fill(moreMax, 0);
        endedCount = 0;
    }

    /** The value of {@code key} at time t (s): starts, continues or ends its stretch. */
    void watch(int key, double value, double t) {
        if (value > threshold) {
            if (Double.isNaN(start[key])) {
                start[key] = t;
                max[key] = value;
                maxAt[key] = t;
            } else if (value > max[key]) {
                max[key] = value;
                maxAt[key] = t;
            }
            end[key] = t;
        } else if (!Double.isNaN(start[key])) {
            if (++count[key] <= maxWarnings) keep(key);
            else moreMax[key] = Math.max(moreMax[key], max[key]);
            start[key] = Double.NaN;
        }
    }

    private void keep(int key) {
        if (endedCount == endedKey.length) {
            endedKey = Arrays.copyOf(endedKey, 2 * endedCount);
            ended = Arrays.copyOf(ended, 8 * endedCount);
        }
        endedKey[endedCount] = key;
        int o = 4 * endedCount++;
        ended[o] = start[key];
        ended[o + 1] = end[key];
        ended[o + 2] = max[key];
        ended[o + 3] = maxAt[key];
    }

    /** The warnings so far: the stretches in the order they ended, then the counted ones and those still going on, by key. */
    List<String> warnings() {
        List<String> w = new ArrayList<>();
        for (int s = 0; s < endedCount; s++) {
            int o = 4 * s;
            w.add(wording.stretch(endedKey[s], ended[o], ended[o + 1], ended[o + 2], ended[o + 3]));
        }
        for (int key = 0; key < start.length; key++) {
            if (count[key] > maxWarnings) w.add(wording.more(key, count[key] - maxWarnings, moreMax[key]));
            if (!Double.isNaN(start[key])) w.add(wording.stretch(key, start[key], end[key], max[key], maxAt[key]));
        }
        return w;
    }
}
