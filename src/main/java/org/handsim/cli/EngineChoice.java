package org.handsim.cli;

import org.handsim.plan.Engines;
import org.handsim.plan.TrialEngine;

/**
 * The {@code --engine}, {@code --master} and {@code --threads} of {@code handsim plan} and
 * {@code handsim sweep}: the engine, the settings it runs with, how the command names it, and its
 * failure as a one-line error.
 *
 * <p><b>Spark, before it starts.</b> A master HandSim cannot use is refused (exit 2) before Spark
 * is loaded: {@code local}, {@code local[N]}, {@code local[*]}, {@code local[N,F]} (N threads,
 * 1..{@value #MAX_LOCAL_THREADS}; F attempts per task) and {@code spark://HOST:PORT[,HOST:PORT..]}
 * (a standalone cluster) are accepted; {@code ''}, {@code local[0]}, {@code yarn}, {@code mesos://},
 * {@code k8s://} are not (HandSim ships no Hadoop or Kubernetes configuration). A
 * {@code spark://} master is probed first — a TCP connection to each address, at most
 * {@value #PROBE_MS} ms each — so an unreachable one is one line naming the URL and the reason
 * within seconds (Spark itself retries for a minute and prints a hundred lines of stack traces).
 * Spark's own logging goes to a file ({@link #sparkLog}; the engine's log4j2 configuration reads
 * {@code handsim.sparkLog}), never to the terminal: the command prints that Spark is starting,
 * the file's name, then its progress.
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
    /** Most threads of a {@code local[N]} master (as {@code --threads}, {@link org.handsim.scenario.Sweep#MAX_THREADS}). */
    static final int MAX_LOCAL_THREADS = org.handsim.scenario.Sweep.MAX_THREADS;
    /** Time allowed to open a TCP connection to each address of a {@code spark://} master, ms. */
    static final int PROBE_MS = 5000;

    private static final java.util.regex.Pattern LOCAL = java.util.regex.Pattern.compile("local(\\[(\\*|[0-9]+)(,([0-9]+))?\\])?");
    private static final java.util.regex.Pattern STANDALONE = java.util.regex.Pattern.compile("spark://([^,/\\s:]+|\\[[0-9a-fA-F:]+\\]):([0-9]{1,5})");

    /**
     * Why HandSim cannot use {@code master} as a Spark master (the accepted forms are in the class
     * comment), or null.
     */
    static String masterProblem(String master) {
        String forms = "local, local[N], local[*], local[N,F] (N threads 1.." + MAX_LOCAL_THREADS + ", F attempts per task)"
            + " or spark://HOST:PORT (a standalone cluster, e.g. tools/spark-cluster start)";
        if (master.isBlank()) return "is empty: use " + forms;
        java.util.regex.Matcher m = LOCAL.matcher(master);
        if (m.matches()) {
            if (m.group(2) != null && !m.group(2).equals("*")) {
                long n = m.group(2).length() > 9 ? Long.MAX_VALUE : Long.parseLong(m.group(2));
                if (n < 1 || n > MAX_LOCAL_THREADS) return "asks for " + m.group(2) + " threads: N must be 1.." + MAX_LOCAL_THREADS;
            }
            if (m.group(4) != null && (m.group(4).length() > 4 || Integer.parseInt(m.group(4)) < 1)) {
                return "asks for " + m.group(4) + " attempts per task: F must be 1..9999";
            }
            return null;
        }
        if (master.startsWith("spark://")) {
            for (String a : master.substring("spark://".length()).split(",", -1)) {
                java.util.regex.Matcher s = STANDALONE.matcher("spark://" + a);
                if (!s.matches() || Integer.parseInt(s.group(2)) < 1 || Integer.parseInt(s.group(2)) > 65535) {
                    return "is not spark://HOST:PORT (port 1..65535)";
                }
            }
            return null;
        }
        if (master.equals("yarn") || master.startsWith("mesos://") || master.startsWith("k8s://") || master.startsWith("local-cluster")) {
            return "is a cluster manager HandSim does not support (it ships no Hadoop, Mesos or Kubernetes configuration): use " + forms;
        }
        return "is not a Spark master: use " + forms;
    }

    /**
     * Null when some address of a {@code spark://} master accepts a TCP connection within
     * {@link #PROBE_MS} ms (or the master is local), else why none does.
     */
    static String unreachable(String master) {
        if (!master.startsWith("spark://")) return null;
        StringBuilder why = new StringBuilder();
        for (String a : master.substring("spark://".length()).split(",")) {
            int colon = a.lastIndexOf(':');
            String host = a.substring(0, colon).replace("[", "").replace("]", "");
            int port = Integer.parseInt(a.substring(colon + 1));
            try (java.net.Socket s = new java.net.Socket()) {
                s.connect(new java.net.InetSocketAddress(host, port), PROBE_MS);
                return null;
            } catch (java.net.UnknownHostException e) {
                why.append(why.length() == 0 ? "" : "; ").append(a).append(": unknown host");
            } catch (java.net.SocketTimeoutException e) {
                why.append(why.length() == 0 ? "" : "; ").append(a).append(": no answer within ").append(PROBE_MS / 1000).append(" s");
            } catch (java.io.IOException | IllegalArgumentException | SecurityException e) {
                why.append(why.length() == 0 ? "" : "; ").append(a).append(": ").append(e.getMessage() != null ? e.getMessage() : e.toString());
            }
        }
        return why.toString();
    }

    static EngineChoice of(String name, String master, Integer threadsOption, int defaultThreads) {
        if (threadsOption != null && (threadsOption < 1 || threadsOption > org.handsim.scenario.Sweep.MAX_THREADS)) {
            throw CliError.usage("handsim: --threads must be in [1, " + org.handsim.scenario.Sweep.MAX_THREADS + "], got " + threadsOption);
        }
        if (master != null && !name.equals("spark")) throw CliError.usage("handsim: --master needs --engine spark");
        if (master != null) {   // before Spark is looked for: a bad master is refused without loading it
            String why = masterProblem(master);
            if (why != null) throw CliError.usage("handsim: --master '" + org.handsim.text.SafeText.quote(master) + "' " + why);
            why = unreachable(master);
            if (why != null) {
                throw CliError.usage("handsim: --master " + org.handsim.text.SafeText.quote(master) + ": cannot connect (" + why
                    + "); is the cluster running? (tools/spark-cluster start prints its URL)");
            }
        }
        TrialEngine engine;
        try {
            engine = Engines.find(name);
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        }
        int n = threadsOption != null ? threadsOption : defaultThreads;
        return new EngineChoice(name, engine, n, master != null ? master : threadsOption != null ? "local[" + threadsOption + "]" : "local[*]");
    }

    /**
     * Before the engine runs: for Spark, a new log file for its own logging (the engine's log4j2
     * configuration reads the property {@code handsim.sparkLog}) and one line saying that Spark is
     * starting, where, and where it logs. Nothing for the local engine.
     */
    void announce(java.io.PrintWriter err, String command) {
        if (!name.equals("spark")) return;
        sparkLog = sparkLogFile();
        if (sparkLog != null) System.setProperty("handsim.sparkLog", sparkLog.toString());
        err.println("handsim " + command + ": starting Spark (master " + url + (sparkLog != null ? "; Spark's log: " + sparkLog : "")
            + "); progress follows once the first tasks finish");
        err.flush();
    }

    /** The file Spark logs into for this run (null until {@link #announce}, or if none could be made). */
    private static java.nio.file.Path sparkLog;

    private static java.nio.file.Path sparkLogFile() {
        try {
            java.nio.file.Path dir = java.nio.file.Path.of(System.getProperty("java.io.tmpdir"), "handsim-logs");
            java.nio.file.Files.createDirectories(dir);
            return java.nio.file.Files.createTempFile(dir, "spark-", ".log");
        } catch (java.io.IOException | RuntimeException e) {
            return null;
        }
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
        return new CliError(1, "handsim: " + what + ": the " + name + " engine failed: " + (nl >= 0 ? m.substring(0, nl) : m)
            + (name.equals("spark") && sparkLog != null ? " (Spark's log: " + sparkLog + ")" : ""));
    }
}
