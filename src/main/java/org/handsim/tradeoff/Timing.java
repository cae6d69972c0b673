package org.handsim.tradeoff;

import java.util.Arrays;
import java.util.function.Supplier;

/**
 * Wall time of a piece of work for the studies: one untimed warm-up call, then timed calls
 * until both {@code minRuns} and {@code minSeconds} are reached (at most {@code maxRuns}); the
 * median is reported. The result of each call is kept so the JIT cannot drop the work.
 */
public final class Timing {
    private Timing() {}

    /** The result of a timing: the median seconds per call, the number of timed calls, the last value computed. */
    public record Result<T>(double medianSeconds, int runs, T value) {}

    public static <T> Result<T> median(Supplier<T> work, int minRuns, int maxRuns, double minSeconds) {
        T value = work.get();
        double[] times = new double[Math.max(1, maxRuns)];
        int n = 0;
        double total = 0;
        while (n < times.length && (n < minRuns || total < minSeconds)) {
            long t0 = System.nanoTime();
            value = work.get();
            double s = (System.nanoTime() - t0) / 1e9;
            times[n++] = s;
            total += s;
        }
        double[] sorted = Arrays.copyOf(times, n);
        Arrays.sort(sorted);
        double med = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        return new Result<>(med, n, value);
    }
}
