package org.handsim.spark;

import java.io.IOException;
import java.io.InputStream;
import java.io.Serializable;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.apache.spark.SimpleFutureAction;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.api.java.JavaSparkContext;
import org.handsim.plan.IndexedJob;
import org.handsim.plan.TrialEngine;
import org.handsim.scenario.Home;
import scala.Function0;
import scala.Function1;
import scala.Function2;
import scala.collection.Iterator;
import scala.jdk.javaapi.CollectionConverters;
import scala.runtime.BoxedUnit;

/**
 * Runs an {@link IndexedJob} as one Apache Spark job. The N task indices are cut into
 * partitions of consecutive indices (at least {@link #TASKS_PER_CORE} per core, at most
 * {@link #MAX_CHUNK} indices each); each Spark task runs its chunk and returns its results as a
 * whole. The driver takes the chunks as they complete ({@code SparkContext.submitJob} with a
 * result handler), keeps those that arrive ahead of their turn, and hands the results to the
 * sink in index order on the calling thread — so the table is written as the job goes and
 * memory holds only the chunks that finished early.
 *
 * <p><b>Retries.</b> A task that throws, or whose executor is lost, is run again by Spark
 * (up to {@code spark.task.maxFailures} attempts; in {@code local[N,F]} mode F). A chunk's
 * result counts only once: chunks are keyed by partition (and so by trial index) and a
 * second copy of one already received is dropped ({@link #duplicatesDropped()}); the sink
 * checks the indices run 0, 1, 2, … without gap or repeat.
 *
 * <p><b>Cluster.</b> With a {@code spark://} master the executors get HandSim's jars
 * ({@code spark.jars}: the files {@code handsim-jars.txt} lists, from the folder of this jar),
 * headless Java3D, and {@code handsim.home} of
 * the driver: executors read the hand's meshes and the object file at the driver's paths (one
 * machine, or the same install path and a shared file system).
 */
public final class SparkEngine implements TrialEngine {
    /** Partitions per core, for balance. */
    public static final int TASKS_PER_CORE = 4;
    /** Most task indices in one partition. */
    public static final int MAX_CHUNK = 25;

    private volatile int duplicates;

    @Override
    public String name() { return "spark"; }

    /** Copies of a chunk dropped in the last run (a retried task whose first result had arrived). */
    public int duplicatesDropped() { return duplicates; }

    @Override
    public <R extends Serializable> void run(IndexedJob<R> job, int n, Settings settings, Consumer<? super R> sink) throws Exception {
        try (JavaSparkContext sc = new JavaSparkContext(conf(settings))) {
            duplicates = runOn(sc, job, n, sink);
        }
    }

    /** The configuration for a master URL: quiet, no web UI, loopback for one machine; jars and JVM options for a cluster. */
    public static SparkConf conf(Settings s) throws IOException {
        String master = s.master() == null ? "local[*]" : s.master();
        SparkConf c = new SparkConf().setAppName(s.appName()).setMaster(master);
        c.set("spark.ui.enabled", "false");
        c.set("spark.ui.showConsoleProgress", "false");
        if (master.startsWith("local") || isLoopback(master)) {
            c.set("spark.driver.host", "127.0.0.1");
            c.set("spark.driver.bindAddress", "127.0.0.1");
        }
        if (!master.startsWith("local")) {
            c.setJars(handsimJars().toArray(new String[0]));
            // (Spark 3.5 adds the Java 17 --add-opens to executors itself)
            c.set("spark.executor.extraJavaOptions", "-Xss16m -Djava.awt.headless=true -Dj3d.rend=noop -Dhandsim.home="
                + Home.dir().toAbsolutePath());
        }
        return c;
    }

    private static boolean isLoopback(String master) {
        return master.startsWith("spark://127.") || master.startsWith("spark://localhost:") || master.equals("spark://localhost");
    }

    /**
     * The jars executors need besides Spark's: the {@code handsim-jars.txt} names, found in the
     * folder that holds this class's jar (the install's {@code lib/}).
     */
    static List<String> handsimJars() throws IOException {
        Path here;
        try {
            here = Path.of(SparkEngine.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IOException("cannot locate the HandSim jars: " + e.getMessage(), e);
        }
        // the install's lib/ beside this jar; in the tests (classes from a folder) the installed lib/ the build names
        Path lib = !Files.isDirectory(here) ? here.getParent()
            : System.getProperty("handsim.sparkLib") != null ? Path.of(System.getProperty("handsim.sparkLib")) : null;
        List<String> jars = new ArrayList<>();
        try (InputStream in = SparkEngine.class.getResourceAsStream("handsim-jars.txt")) {
            if (in == null || lib == null) throw new IOException("a cluster run needs HandSim installed (gradle :spark:installDist): "
                + "handsim-jars.txt or the lib folder is missing");
            for (String name : new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")) {
                if (name.isBlank()) continue;
                Path jar = lib.resolve(name.trim());
                if (!Files.isRegularFile(jar)) throw new IOException("a cluster run ships " + jar + ", which is missing");
                jars.add(jar.toString());
            }
        }
        return jars;
    }

    /** One partition's results: task indices from..from+results.size()−1. */
    record Chunk<R>(int part, int from, ArrayList<R> results) implements Serializable {
        private static final long serialVersionUID = 1L;
    }

    /** Partitions for n tasks at a default parallelism p. */
    static int partitions(int n, int p) {
        int parts = Math.max(p * TASKS_PER_CORE, (n + MAX_CHUNK - 1) / MAX_CHUNK);
        return Math.max(1, Math.min(n, parts));
    }

    /**
     * Runs the job on an existing context and returns the number of duplicate chunks dropped.
     * The sink gets every result once, in index order, on the calling thread.
     */
    @SuppressWarnings("unchecked")
    public static <R extends Serializable> int runOn(JavaSparkContext sc, IndexedJob<R> job, int n, Consumer<? super R> sink) throws Exception {
        int parts0 = partitions(n, sc.defaultParallelism());
        int size = (n + parts0 - 1) / parts0;
        int parts = (n + size - 1) / size;
        List<Integer> ids = new ArrayList<>(parts);
        for (int p = 0; p < parts; p++) ids.add(p);
        JavaRDD<Integer> rdd = sc.parallelize(ids, parts);
        Function1<Iterator<Integer>, Chunk<R>> work = (Function1<Iterator<Integer>, Chunk<R>> & Serializable) it -> {
            int p = it.next();
            int from = p * size, to = Math.min(n, from + size);
            ArrayList<R> out = new ArrayList<>(to - from);
            for (int i = from; i < to; i++) out.add(job.run(i));
            return new Chunk<>(p, from, out);
        };
        BlockingQueue<Chunk<R>> done = new LinkedBlockingQueue<>();
        Function2<Object, Chunk<R>, BoxedUnit> handler = (Function2<Object, Chunk<R>, BoxedUnit> & Serializable) (i, c) -> {
            done.add(c);
            return BoxedUnit.UNIT;
        };
        Function0<Object> result = (Function0<Object> & Serializable) () -> BoxedUnit.UNIT;
        List<Object> partitionIds = new ArrayList<>(ids);
        SimpleFutureAction<Object> f = sc.sc().submitJob(rdd.rdd(), work, CollectionConverters.asScala(partitionIds).toSeq(), handler, result);
        ChunkOrder<R> order = new ChunkOrder<>(parts, size, sink);
        while (!order.complete()) {
            Chunk<R> c = done.poll(50, TimeUnit.MILLISECONDS);
            if (c == null) {
                if (f.isCompleted() && done.isEmpty()) {
                    f.get();   // throws the job's failure
                    throw new IllegalStateException("the Spark job ended with partition " + order.next() + " of " + parts + " missing");
                }
                continue;
            }
            order.offer(c);
        }
        f.get();
        return order.dropped();
    }
}
