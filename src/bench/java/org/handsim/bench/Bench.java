package org.handsim.bench;

import java.util.Arrays;
import java.util.Locale;

/**
 * A plain benchmark harness: warm-up, then timed samples, reporting the median (and the
 * 10th/90th percentiles) per operation. Each sample runs a batch of operations big enough to
 * last about {@code sampleMillis}, so nanosecond-scale calls are timed accurately. Results
 * are consumed through {@link #sink} so the JIT cannot remove the work.
 */
public final class Bench {
    /** Write results here (e.g. {@code Bench.sink += tau[0]}) to keep the work alive. */
    public static volatile double sink;

    /** One timed operation: returns a value that depends on the work done. */
    @FunctionalInterface
    public interface Op {
        double run();
    }

    /** Median and spread of one measurement, in nanoseconds per operation. */
    public static final class Result {
        public final String name;
        public final double medianNs, p10Ns, p90Ns;
        public final int samples;
        public final long opsPerSample;

        Result(String name, double medianNs, double p10Ns, double p90Ns, int samples, long opsPerSample) {
            this.name = name;
            this.medianNs = medianNs;
            this.p10Ns = p10Ns;
            this.p90Ns = p90Ns;
            this.samples = samples;
            this.opsPerSample = opsPerSample;
        }

        public double medianUs() { return medianNs / 1e3; }
        public double medianMs() { return medianNs / 1e6; }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%-55s median %s  (p10 %s, p90 %s; %d samples x %d ops)",
                name, human(medianNs), human(p10Ns), human(p90Ns), samples, opsPerSample);
        }
    }

    private Bench() {}

    /** Human-readable time for nanoseconds. */
    public static String human(double ns) {
        if (ns < 1e3) return String.format(Locale.ROOT, "%.1f ns", ns);
        if (ns < 1e6) return String.format(Locale.ROOT, "%.2f us", ns / 1e3);
        if (ns < 1e9) return String.format(Locale.ROOT, "%.2f ms", ns / 1e6);
        return String.format(Locale.ROOT, "%.2f s", ns / 1e9);
    }

    /** Measures with defaults: 1 s warm-up, 21 samples of ~50 ms. */
    public static Result measure(String name, Op op) {
        return measure(name, op, 1000, 21, 50);
    }

    /**
     * @param warmupMillis how long to run before timing
     * @param samples      how many timed samples (median over them)
     * @param sampleMillis target duration of one sample
     */
    public static Result measure(String name, Op op, long warmupMillis, int samples, long sampleMillis) {
        double acc = 0;
        long end = System.nanoTime() + warmupMillis * 1_000_000L;
        long calls = 0;
        long t0 = System.nanoTime();
        do {
            acc += op.run();
            calls++;
        } while (System.nanoTime() < end || calls < 2);
        double nsPerOp = (System.nanoTime() - t0) / (double) calls;
        long batch = Math.max(1, (long) (sampleMillis * 1e6 / Math.max(nsPerOp, 1)));
        double[] per = new double[samples];
        for (int s = 0; s < samples; s++) {
            long a = System.nanoTime();
            for (long i = 0; i < batch; i++) acc += op.run();
            per[s] = (System.nanoTime() - a) / (double) batch;
        }
        sink += acc;
        Arrays.sort(per);
        Result r = new Result(name, per[samples / 2], per[samples / 10], per[(samples * 9) / 10], samples, batch);
        System.out.println(r);
        return r;
    }
}
