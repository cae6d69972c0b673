package org.handsim.plan;

import java.io.Serializable;

/**
 * A job of N independent tasks 0..N−1, each a pure function of its index (a plan's trials, a
 * sweep's runs). Serialisable, so a distributed engine can ship it to its workers; it must
 * not throw for an expected failure (a failed trial is a result), so an exception is a fault
 * the engine may retry.
 *
 * @param <R> the result of one task (serialisable)
 */
@FunctionalInterface
public interface IndexedJob<R extends Serializable> extends Serializable {
    /** Runs task {@code index}. Called from any thread; implementations keep per-thread state themselves. */
    R run(int index);
}
