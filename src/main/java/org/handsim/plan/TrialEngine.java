package org.handsim.plan;

import java.io.Serializable;
import java.util.function.Consumer;

/**
 * Runs the N tasks of an {@link IndexedJob} and hands their results to a sink in index order,
 * on the calling thread, each exactly once — whatever the engine, the threads or the
 * partitioning, so a plan's table is the same. {@code local} ({@link LocalEngine}) uses a
 * thread pool; {@code spark} (the {@code spark/} subproject, found through
 * {@link java.util.ServiceLoader}) runs the tasks as an Apache Spark job.
 */
public interface TrialEngine {
    /** The name {@code --engine} selects. */
    String name();

    /**
     * Runs tasks 0..n−1; {@code sink} gets result i before result i+1, every result once.
     *
     * @throws Exception if the engine fails (a task that fails after the engine's retries, a lost cluster)
     */
    <R extends Serializable> void run(IndexedJob<R> job, int n, Settings settings, Consumer<? super R> sink) throws Exception;

    /**
     * @param threads worker threads (local) or the default parallelism hint; ≥ 1
     * @param master  Spark master URL ({@code local[*]}, {@code spark://HOST:7077}); ignored by local
     * @param appName the job's name in the engine's UI and logs
     */
    record Settings(int threads, String master, String appName) {
        public Settings {
            if (threads < 1) throw new IllegalArgumentException("--threads must be >= 1, got " + threads);
        }
    }
}
