package org.handsim.plan;

import java.io.Serializable;
import java.util.ArrayDeque;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;

/**
 * The thread-pool engine: tasks are handed out in chunks of consecutive indices, at most
 * {@link #WINDOW_PER_THREAD} chunks per thread in flight; the calling thread takes the chunks'
 * results in order, so results are delivered in index order and no more than the window is
 * held in memory whatever N is. A chunk is at most 16 tasks and an eighth of a thread's share of
 * what remains ({@link #chunkSize}): the chunks shrink toward the end, so the threads finish
 * within about one task of each other instead of one chunk (16 mug trials, some 50–80 ms: on 16
 * threads a few per cent of an 8 000-trial plan).
 */
public final class LocalEngine implements TrialEngine {
    /** Chunks in flight per thread. */
    static final int WINDOW_PER_THREAD = 4;

    @Override
    public String name() { return "local"; }

    @Override
    public <R extends Serializable> void run(IndexedJob<R> job, int n, Settings settings, Consumer<? super R> sink) throws Exception {
        int threads = settings.threads();
        ExecutorService pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "plan-worker");
            t.setDaemon(true);
            return t;
        });
        try {
            ArrayDeque<Future<Object[]>> inFlight = new ArrayDeque<>();
            int next = 0;
            int window = WINDOW_PER_THREAD * threads;
            while (next < n || !inFlight.isEmpty()) {
                while (next < n && inFlight.size() < window) {
                    int from = next, to = Math.min(n, next + chunkSize(n - next, threads));
                    inFlight.add(pool.submit(() -> {
                        Object[] out = new Object[to - from];
                        for (int i = from; i < to; i++) out[i - from] = job.run(i);
                        return out;
                    }));
                    next = to;
                }
                Object[] rs;
                try {
                    rs = inFlight.poll().get();
                } catch (ExecutionException e) {
                    Throwable c = e.getCause();
                    if (c instanceof Exception) throw (Exception) c;
                    if (c instanceof Error) throw (Error) c;
                    throw e;
                }
                for (Object r : rs) {
                    @SuppressWarnings("unchecked")
                    R v = (R) r;
                    sink.accept(v);
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }

    /**
     * Consecutive tasks in the next chunk when {@code remaining} tasks are left: small enough to
     * balance, large enough to be cheap to hand out.
     */
    static int chunkSize(int remaining, int threads) {
        return Math.max(1, Math.min(16, remaining / (threads * 8)));
    }
}
