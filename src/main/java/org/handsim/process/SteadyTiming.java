package org.handsim.process;

import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.function.DoubleSupplier;

/**
 * Steady-state timing of one operation for the commands that print a time, so the times they
 * print are honest. The operation is first run until the JIT has compiled it — at least
 * {@link #WARMUP_SECONDS} of wall time <em>and</em> at least {@link #WARMUP_CALLS} calls,
 * whichever comes later, capped at {@link #WARMUP_CAP_SECONDS} for very slow operations — and
 * then timed in {@code samples} batches; each batch runs enough calls to last about
 * {@link #BATCH_SECONDS} (so nanosecond-scale operations are not swamped by the clock), and the
 * median of the per-call times of the batches is reported. This is the scheme of the
 * {@code gradle bench} harness, so a command's figure and the benchmark's agree within noise.
 * Bounded for slow operations: one whose first run takes {@link #SLOW_SECONDS} or more is timed
 * by that run alone, and the timed batches stop after {@link #TIMED_CAP_SECONDS} (fewer samples
 * then, at least one), so timing never takes more than about 10 s beyond the first run.
 *
 * <p>The operation returns a number that depends on its work; it is accumulated into a
 * volatile sink so the JIT cannot drop the work.
 */
public final class SteadyTiming {
    /** Minimum warm-up wall time, seconds. */
    public static final double WARMUP_SECONDS = 0.5;
    /** Minimum warm-up calls. */
    public static final long WARMUP_CALLS = 10_000;
    /**
     * After the minimum warm-up, it goes on until the JIT's total compilation time
     * ({@link CompilationMXBean}) has not grown for this long, seconds.
     */
    public static final double JIT_QUIET_SECONDS = 0.25;
    /** Warm-up never runs longer than this, seconds (an operation of 1 ms needs 10 s for 10 000 calls). */
    public static final double WARMUP_CAP_SECONDS = 5.0;
    /**
     * Target duration of one timed batch, seconds: long enough that the clock (tens of ns) is
     * noise, short enough that most batches run between two of the scheduler's time slices when
     * other processes share the cores, so the median skips the batches a slice interrupts
     * (measured: with 5 ms batches a 30 µs query read 45–60 µs at load 10 on 2 cores, with 1 ms
     * batches 30–33 µs, the quiet figure; docs/BENCHMARKS.md).
     */
    public static final double BATCH_SECONDS = 0.001;
    /**
     * The timed batches stop once they have taken this long, seconds (at least one batch is
     * timed): an operation of 0.3 s would otherwise take 30 s for 101 batches.
     */
    public static final double TIMED_CAP_SECONDS = 5.0;
    /**
     * An operation whose first run takes this long, seconds, or longer is timed by that run alone
     * ({@link #once}): the JIT's share of a second is small, and repeating a 30 s hull computation
     * to take a median would take minutes.
     */
    public static final double SLOW_SECONDS = 1.0;

    /** Keeps results alive. */
    public static volatile double sink;

    /** The outcome: median seconds per call, the number of timed batches and calls, the warm-up. */
    public record Result(double medianSeconds, int samples, long timedCalls, long warmupCalls, double warmupSeconds) {
        /** @return the median in microseconds */
        public double medianMicros() { return medianSeconds * 1e6; }
    }

    private SteadyTiming() {}

    /**
     * Warms up by time, then times {@code samples} batches and returns the median per call.
     *
     * @param samples number of timed batches (≥ 1)
     */
    public static Result median(DoubleSupplier op, int samples) {
        return median(op, samples, warmupCap());
    }

    /**
     * {@link #WARMUP_CAP_SECONDS}, unless the system property {@code handsim.timing.warmupCapSeconds}
     * sets another cap: the test suite's JVM sets 0.05 s, since tests check what the commands
     * print, never how fast (a command's steady timing would otherwise cost each test seconds).
     */
    static double warmupCap() {
        String p = System.getProperty("handsim.timing.warmupCapSeconds");
        if (p == null) return WARMUP_CAP_SECONDS;
        try {
            double v = Double.parseDouble(p);
            return v >= 0 && v <= WARMUP_CAP_SECONDS ? v : WARMUP_CAP_SECONDS;
        } catch (NumberFormatException e) {
            return WARMUP_CAP_SECONDS;
        }
    }

    /** The result of timing one run of {@code seconds} (an operation slower than {@link #SLOW_SECONDS}). */
    public static Result once(double seconds) {
        return new Result(seconds, 1, 1, 0, 0);
    }

    /** {@link #median(DoubleSupplier, int)} with the warm-up capped at {@code capSeconds} (tests). */
    static Result median(DoubleSupplier op, int samples, double capSeconds) {
        if (samples < 1) throw new IllegalArgumentException("samples must be >= 1, got " + samples);
        double acc = 0;
        long calls = 0;
        long start = System.nanoTime();
        acc += op.getAsDouble();   // the first run: a slow operation is timed by it alone
        calls++;
        double first = (System.nanoTime() - start) / 1e9;
        if (first >= SLOW_SECONDS) {
            sink += acc;
            return once(first);
        }
        long minEnd = start + (long) (WARMUP_SECONDS * 1e9), cap = start + (long) (capSeconds * 1e9);
        long now;
        do {
            acc += op.getAsDouble();
            calls++;
            now = System.nanoTime();
        } while ((now < minEnd || calls < WARMUP_CALLS) && now < cap);
        CompilationMXBean jit = ManagementFactory.getCompilationMXBean();
        if (jit != null && jit.isCompilationTimeMonitoringSupported()) {
            long quiet = (long) (JIT_QUIET_SECONDS * 1e9);
            long compiled = jit.getTotalCompilationTime(), since = now;
            while (now - since < quiet && now < cap) {
                acc += op.getAsDouble();
                calls++;
                now = System.nanoTime();
                long c = jit.getTotalCompilationTime();
                if (c != compiled) {
                    compiled = c;
                    since = now;
                }
            }
        }
        double warmSeconds = (now - start) / 1e9;
        double perCall = warmSeconds / calls;
        long batch = Math.max(1, (long) (BATCH_SECONDS / Math.max(perCall, 1e-9)));
        double[] per = new double[samples];
        long timed = 0;
        long timedStart = System.nanoTime(), timedCap = timedStart + (long) (TIMED_CAP_SECONDS * 1e9);
        int taken = 0;
        for (int s = 0; s < samples; s++) {
            long t0 = System.nanoTime();
            for (long i = 0; i < batch; i++) acc += op.getAsDouble();
            long t1 = System.nanoTime();
            per[s] = (t1 - t0) / 1e9 / batch;
            timed += batch;
            taken++;
            if (t1 > timedCap) break;
        }
        sink += acc;
        if (taken < samples) {
            per = Arrays.copyOf(per, taken);
            samples = taken;
        }
        Arrays.sort(per);
        double med = samples % 2 == 1 ? per[samples / 2] : 0.5 * (per[samples / 2 - 1] + per[samples / 2]);
        return new Result(med, samples, timed, calls, warmSeconds);
    }
}
