package org.handsim.chart;

import java.awt.AWTError;
import java.awt.HeadlessException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import org.jfree.chart.JFreeChart;

/**
 * The charts of one command: drawn on worker threads while the command goes on, written
 * together at the end — or, when this JVM cannot draw (no fonts, a font library that does not
 * load, no display, a broken AWT), none of them, with the reason, so the command still writes
 * every table and summary and says once what is missing.
 *
 * <p><b>Why threads.</b> In a fresh JVM a chart's first drawing is slow: font and Java2D set-up,
 * JFreeChart's classes, interpreted rendering. {@link #start} begins that work at once on a
 * worker — by drawing a small warm-up chart that is thrown away — while the command loads and
 * runs on its own thread; the real charts then draw on up to {@value #MAX_THREADS} workers in
 * parallel while the command computes the rest of its summary. The workers are daemons that end
 * after a second idle, so a command that fails before {@link #finish()} leaves nothing behind.
 *
 * <p><b>Files.</b> Each chart is drawn to bytes first (PNG by {@link PngEncoder}, SVG by
 * JFreeSVG); {@link #finish()} writes them only when every chart was drawn, each file
 * atomically, so a failure leaves no chart files rather than some.
 *
 * <p><b>Failure.</b> The first failure on any worker is kept (the warm-up's, typically: later ones
 * only repeat it, as "Could not initialize class ..."; such a second-hand report gives way to
 * the original when another worker met it), later charts are skipped, and
 * {@link #finish()} returns {@link #reason(Throwable)}. {@link VirtualMachineError}s (out of
 * memory ...) are not a missing display: {@code finish} rethrows them.
 */
public final class ChartSet {
    /** Most charts drawn at once. */
    static final int MAX_THREADS = 4;

    private final ThreadPoolExecutor pool;
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private final List<Job> jobs = new ArrayList<>();

    /** A chart's two files, each drawn by its own task from its own chart object (a chart is not drawn by two threads at once). */
    private record Job(Path base, Future<byte[]> png, Future<byte[]> svg) {}

    private ChartSet(int threads) {
        pool = new ThreadPoolExecutor(threads, threads, 1, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), r -> {
            Thread t = new Thread(r, "charts");
            t.setDaemon(true);
            return t;
        });
        pool.allowCoreThreadTimeOut(true);
    }

    /**
     * Starts the workers and warms them up by drawing {@code warmUp} (PNG and SVG, thrown away):
     * a chart built like the command's, on a few points; null for no warm-up (charts that follow
     * at once).
     */
    public static ChartSet start(Supplier<JFreeChart> warmUp) {
        ChartSet s = new ChartSet(Math.max(1, Math.min(MAX_THREADS, Runtime.getRuntime().availableProcessors())));
        // a JVM that has drawn charts before (the resident server) is set up already: the warm-up would only take a core from the real charts
        if (warmUp != null && !drawnBefore) s.pool.execute(() -> s.attempt(() -> ChartExport.draw(warmUp.get(), 320, 240)));
        return s;
    }

    /** Whether this JVM has drawn a set of charts already (its fonts, Java2D and JFreeChart are set up). */
    private static volatile boolean drawnBefore;

    /**
     * Queues a chart: drawn now on the workers, its PNG and its SVG as two tasks (the supplier
     * runs for each, so two workers can draw the largest chart's two files at once), written by
     * {@link #finish()} as {@code base}.png and .svg.
     */
    public void add(Path base, int width, int height, Supplier<JFreeChart> chart) {
        jobs.add(new Job(base,
            pool.submit(() -> failure.get() != null ? null : attempt(() -> ChartExport.png(chart.get(), width, height))),
            pool.submit(() -> failure.get() != null ? null : attempt(() -> ChartExport.svg(chart.get(), width, height)))));
    }

    /** Runs {@code draw}, keeping its failure (the first of the set) instead of throwing; null then. */
    private <T> T attempt(Supplier<T> draw) {
        try {
            return draw.get();
        } catch (Throwable t) {   // a missing font library is an Error (UnsatisfiedLinkError, NoClassDefFoundError)
            keep(t);
            return null;
        }
    }

    /**
     * Keeps the most telling failure: the first, unless it only says that a class failed to
     * initialise on another thread (then that thread's own error, when it comes, replaces it).
     */
    private void keep(Throwable t) {
        while (true) {
            Throwable f = failure.get();
            if (f != null && !(secondHand(f) && !secondHand(t))) return;
            if (failure.compareAndSet(f, t)) return;
        }
    }

    /** A class-initialisation failure reported without its cause (what other threads see: "Could not initialize class"). */
    private static boolean secondHand(Throwable t) {
        Throwable r = root(t);
        return r instanceof NoClassDefFoundError || r instanceof ExceptionInInitializerError;
    }

    /**
     * Waits for every chart; then writes them all and returns null, or, if any could not be
     * drawn, writes none and returns the reason ({@link #reason(Throwable)}; the cause is
     * {@link #failure()}).
     *
     * @throws IOException if a file cannot be written
     */
    public String finish() throws IOException {
        List<ChartExport.Drawn> drawn = new ArrayList<>();
        for (Job j : jobs) {
            try {
                drawn.add(new ChartExport.Drawn(j.png().get(), j.svg().get()));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while drawing the charts", e);
            } catch (ExecutionException e) {   // attempt() catches everything: not expected
                keep(e.getCause());
            }
        }
        pool.shutdown();
        Throwable f = failure.get();
        if (f instanceof VirtualMachineError) throw (VirtualMachineError) f;
        if (f != null) return reason(f);
        for (int i = 0; i < jobs.size(); i++) ChartExport.write(drawn.get(i), jobs.get(i).base());
        if (!jobs.isEmpty()) drawnBefore = true;
        return null;
    }

    /** What made the charts fail (null if nothing did). */
    public Throwable failure() { return failure.get(); }

    /**
     * The cause of a drawing failure in one line: the innermost exception's class and message,
     * e.g. {@code UnsatisfiedLinkError: .../libfontmanager.so: libharfbuzz.so.0: cannot open
     * shared object file}.
     */
    public static String reason(Throwable t) {
        Throwable root = root(t);
        String m = root.getMessage();
        return root.getClass().getSimpleName() + (m == null || m.isBlank() ? "" : ": " + m.strip());
    }

    /** What to do about a drawing failure, for the warning: which package to install, or that it is a bug. */
    public static String remedy(Throwable t) {
        Throwable root = root(t);
        String text = String.valueOf(root.getMessage()).toLowerCase(Locale.ROOT);
        boolean fontCode = false;
        for (StackTraceElement e : root.getStackTrace()) {
            if (e.getClassName().startsWith("sun.font.")) fontCode = true;
        }
        if (root instanceof UnsatisfiedLinkError) {
            return "a native library of Java's font system does not load: install it and fonts"
                + " (Debian/Ubuntu: apt-get install libfreetype6 libharfbuzz0b libfontconfig1 fonts-dejavu-core)";
        }
        if (fontCode || text.contains("font")) return "install fonts (Debian/Ubuntu: apt-get install fonts-dejavu-core fontconfig)";
        if (root instanceof HeadlessException || root instanceof AWTError || text.contains("x11") || text.contains("display")) {
            return "no usable display: charts need none, so unset DISPLAY or set HANDSIM_JAVA_OPTS=-Djava.awt.headless=true";
        }
        return "this is a bug in drawing the charts: please report it with the stack trace";
    }

    private static Throwable root(Throwable t) {
        Throwable r = t;
        while (r.getCause() != null && r.getCause() != r) r = r.getCause();
        return r;
    }
}
