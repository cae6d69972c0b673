package org.handsim.cli;

import org.handsim.plan.Engines;
import org.handsim.plan.TrialEngine;

/**
 * The {@code --engine}, {@code --master} and {@code --threads} of {@code handsim plan} and
 * {@code handsim sweep}: the engine, the settings it runs with, how the command names it, and its
 * failure as a one-line error.
 *
 * @param name    {@code local} or {@code spark}
 * @param engine  the engine
 * @param threads worker threads (the local engine; Spark's {@code local[N]} when --threads is given)
 * @param url     the Spark master: --master, else {@code local[N]} with --threads N, else {@code local[*]}
 */
record EngineChoice(String name, TrialEngine engine, int threads, String url) {
    /**
     * Checks the options (exit 2 naming the bad one) and finds the engine.
     *
     * @param threadsOption   --threads, or null
     * @param defaultThreads  the threads when --threads is not given
     */
    static EngineChoice of(String name, String master, Integer threadsOption, int defaultThreads) {
        if (threadsOption != null && (threadsOption < 1 || threadsOption > org.handsim.sim.Sweep.MAX_THREADS)) {
            throw CliError.usage("handsim: --threads must be in [1, " + org.handsim.sim.Sweep.MAX_THREADS + "], got " + threadsOption);
        }
        TrialEngine engine;
        try {
            engine = Engines.find(name);
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        }
        if (master != null && !name.equals("spark")) throw CliError.usage("handsim: --master needs --engine spark");
        int n = threadsOption != null ? threadsOption : defaultThreads;
        return new EngineChoice(name, engine, n, master != null ? master : threadsOption != null ? "local[" + threadsOption + "]" : "local[*]");
    }

    /** The settings of a job named {@code appName}. */
    TrialEngine.Settings settings(String appName) {
        return new TrialEngine.Settings(threads, url, appName);
    }

    /** Where the job ran, for the command's closing line: {@code N threads} or the Spark master. */
    String where() {
        return name.equals("spark") ? url : threads + " thread" + (threads == 1 ? "" : "s");
    }

    /** Exit 1: {@code handsim: WHAT: the NAME engine failed: <the root cause's first line>}. */
    CliError failed(String what, Throwable e) {
        Throwable root = e;
        while (root.getCause() != null && root.getCause() != root) root = root.getCause();
        String m = root.getMessage() != null ? root.getMessage() : root.toString();
        int nl = m.indexOf('\n');
        return new CliError(1, "handsim: " + what + ": the " + name + " engine failed: " + (nl >= 0 ? m.substring(0, nl) : m));
    }
}
