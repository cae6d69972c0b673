package org.handsim.spark;

import java.util.HashMap;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Puts chunks that arrive in any order (Spark's completion order) back into index order: a chunk
 * is held until every earlier one has been handed on, then its results go to the sink, in order.
 * A second copy of a chunk already received (a retried or speculative task) is dropped and
 * counted, so every task index reaches the sink exactly once.
 */
final class ChunkOrder<R> {
    private final int parts, size;
    private final Consumer<? super R> sink;
    private final Map<Integer, SparkEngine.Chunk<R>> early = new HashMap<>();
    private int next, dropped;

    ChunkOrder(int parts, int size, Consumer<? super R> sink) {
        this.parts = parts;
        this.size = size;
        this.sink = sink;
    }

    /** Takes a chunk; hands on every chunk that is now next in line. */
    void offer(SparkEngine.Chunk<R> c) {
        if (c.part() < 0 || c.part() >= parts) throw new IllegalStateException("no partition " + c.part() + " in a job of " + parts);
        if (c.part() < next || early.containsKey(c.part())) {
            dropped++;
            return;
        }
        early.put(c.part(), c);
        for (SparkEngine.Chunk<R> d; (d = early.remove(next)) != null; next++) {
            if (d.from() != next * size) throw new IllegalStateException("partition " + next + " starts at " + d.from() + ", not " + next * size);
            for (R r : d.results()) sink.accept(r);
        }
    }

    boolean complete() { return next == parts; }
    int next() { return next; }
    /** Duplicate chunks dropped. */
    int dropped() { return dropped; }
    /** Chunks held, waiting for an earlier one. */
    int held() { return early.size(); }
}
