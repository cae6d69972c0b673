package org.handsim.cli;

import org.handsim.scenario.NotFound;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.grasp.ConvexHull;
import org.handsim.grasp.FrictionCone;
import org.handsim.grasp.GraspQuality;
import org.handsim.grasp.GraspWrenches;
import org.handsim.grasp.WrenchSpace;
import org.handsim.files.CsvInput;
import org.handsim.text.JsonWriter;
import org.handsim.process.SteadyTiming;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code handsim quality CONTACTS.csv [--friction MU] [--edges M] [--center x,y,z] [--radius R]
 * [--repeat N]}: the quality of a grasp given as point contacts: the L1 grasp wrench
 * space of their linearised friction cones ({@link GraspWrenches}), its force closure, ε, volume
 * and facets ({@link WrenchSpace#quality}), and the steady-state time of that computation
 * ({@link SteadyTiming}). Output contract: one JSON line with the keys {@link #JSON_KEYS}.
 */
@Command(name = "quality", mixinStandardHelpOptions = true, sortOptions = false,
    description = {"Grasp quality of point contacts: force closure, epsilon and volume.",
        "Point contacts have Coulomb friction (the L1 grasp wrench",
        "space: the 6-D convex hull of w = (f, (p - c) x f / R) over the m edges f of",
        "each contact's friction cone).",
        "CONTACTS.csv: header x,y,z,nx,ny,nz; one contact a row: the point (metres)",
        "and the normal = the direction of the force the finger applies, INTO the",
        "object (need not be unit). Cone edge i: n + mu (cos(2 pi i/m) t1 +",
        "sin(2 pi i/m) t2), t1 = n x a/|n x a|, a = e_x if |n_x| < 0.9 else e_y,",
        "t2 = n x t1.",
        "Prints {\"contacts\":n,\"wrenches\":n,\"force_closure\":bool,\"epsilon\":e,",
        "  \"volume\":v,\"facets\":n,\"time_us_median\":t}",
        "force_closure: the origin strictly inside the hull (farther than 1e-11 x the",
        "largest |wrench coordinate| from every facet); epsilon: the radius of the",
        "largest origin-centred ball inside the hull (N), 0 without force closure;",
        "volume: 6-D volume (0 when the wrenches span fewer than 6 dimensions);",
        "facets: facets of the hull (coplanar ones merged); time_us_median: the",
        "quality computation alone, microseconds, median of N timed batches after a",
        "warm-up of at least 0.5 s and 10 000 calls, then until the JIT has been",
        "idle for 0.25 s (at most 5 s).",
        "Example: the face centres of a 60 mm cube, c its centre, R = 0.052,",
        "  x,y,z,nx,ny,nz",
        "  0.03,0,0,-1,0,0       -0.03,0,0,1,0,0     (one row each)",
        "  0,0.03,0,0,-1,0       0,-0.03,0,0,1,0",
        "  0,0,0.03,0,0,-1       0,0,-0.03,0,0,1",
        "  handsim quality cube.csv --radius 0.052 --edges 4",
        "  {\"contacts\":6,\"wrenches\":24,\"force_closure\":true,",
        "   \"epsilon\":0.16654334688162284,\"volume\":0.060007254210286784,",
        "   \"facets\":148,\"time_us_median\":...}",
        "  (epsilon = mu a / (sqrt(3) R), a = 0.03: the support in the torque",
        "  direction (0,0,0,1,1,-1)/sqrt(3); WrenchSpaceTest derives it.)",
        "Limits: at most 100 000 contacts and 1 600 distinct wrenches (contacts x",
        "edges; repeated ones count once) for the whole hull, and 2^20 hull facets;",
        "beyond, exit 2 saying how many fit. Progress every 5 s when the hull is slow.",
        "Exit codes: 0 ok, 2 bad arguments or a bad row (its line named), 3 the",
        "file cannot be read."})
public final class QualityCommand implements Callable<Integer> {
    /** The input header. */
    static final String HEADER = "x,y,z,nx,ny,nz";
    /** The output keys, in order. */
    static final List<String> JSON_KEYS = List.of("contacts", "wrenches", "force_closure", "epsilon", "volume", "facets", "time_us_median");
    /** Largest wrench coordinate accepted: the volume is a sixth power of it. */
    static final double MAX_WRENCH = 1e30;
    /**
     * A hull computation running longer than this, seconds, prints its progress on standard error
     * ... (system property {@code handsim.quality.progressAfterS}: a test sees the line on a
     * machine fast enough to finish first).
     */
    static final double PROGRESS_AFTER_S = Double.parseDouble(System.getProperty("handsim.quality.progressAfterS", "2"));
    /** ... every this many seconds. */
    static final double PROGRESS_EVERY_S = 5;
    /** Most rows of a contacts file: reading stays small (5 MB of numbers) whatever the file's length. */
    static final int MAX_CONTACTS = 100_000;
    /** Default number of timed batches. */
    static final int DEFAULT_REPEAT = 11;

    @Spec CommandSpec spec;

    @Parameters(index = "0", paramLabel = "CONTACTS.csv", description = "contacts: header x,y,z,nx,ny,nz")
    Path file;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb coefficient mu >= 0 (default 0.5)")
    String frictionText = String.valueOf(FrictionCone.DEFAULT_MU);

    @Option(names = "--edges", paramLabel = "M", description = "friction cone edges, 1..1024 (default 8)")
    String edgesText = String.valueOf(FrictionCone.DEFAULT_EDGES);

    @Option(names = "--center", paramLabel = "x,y,z", description = "torque origin c, metres (default 0,0,0)")
    String centerText = "0,0,0";

    @Option(names = "--radius", paramLabel = "R", description = "characteristic length R > 0, metres: torques are divided by it (default 1)")
    String radiusText = "1";

    @Option(names = "--repeat", paramLabel = "N", description = "timed batches for time_us_median, 1..1000 (default " + DEFAULT_REPEAT + ")")
    String repeatText = String.valueOf(DEFAULT_REPEAT);

    @Override
    public Integer call() throws IOException {
        double mu = Args.numbers("--friction", frictionText, 1)[0];
        int m = integer("--edges", edgesText);
        Args.frictionAndEdges(mu, m);
        double[] c = Args.numbers("--center", centerText, 3);
        double r = Args.numbers("--radius", radiusText, 1)[0];
        if (!(r > 0)) throw CliError.usage("handsim: --radius must be > 0, got " + radiusText);
        int repeat = integer("--repeat", repeatText);
        if (repeat < 1 || repeat > 1000) throw CliError.usage("handsim: --repeat must be in 1..1000, got " + repeatText);
        Args.inputFile(file);
        Contacts contacts = read(file);
        Map<String, Object> json;
        try {
            json = quality(contacts, mu, m, c, r, repeat, spec.commandLine().getErr());
        } catch (ConvexHull.TooLargeException e) {
            String why = e.getMessage();
            throw CliError.usage("handsim: " + file + ": " + (why.startsWith("the convex hull")
                ? contacts.count() + " contacts x " + m + " cone edges: " + why + "; use fewer contacts or --edges" : why));
        }
        spec.commandLine().getOut().println(JsonWriter.write(json));
        return 0;
    }

    /** Points and normals read from CONTACTS.csv, 3 values each per contact. */
    record Contacts(int count, double[] points, double[] normals) {}

    /**
     * Reads CONTACTS.csv.
     *
     * @throws CliError exit 2 naming FILE:LINE for a bad header or row (not six finite numbers,
     *                  a zero normal), exit 3 if the file cannot be read
     */
    static Contacts read(Path file) {
        double[] p = new double[48], nrm = new double[48];
        int n = 0;
        try (CsvInput in = new CsvInput(file, HEADER)) {
            while (in.next()) {
                if (n == MAX_CONTACTS) {
                    throw in.error("more than " + MAX_CONTACTS + " contacts (the limit of a contacts file; the whole wrench space takes at most "
                        + WrenchSpace.MAX_WRENCHES + " distinct wrenches)");
                }
                if (3 * n + 3 > p.length) {
                    p = java.util.Arrays.copyOf(p, 2 * p.length);
                    nrm = java.util.Arrays.copyOf(nrm, 2 * nrm.length);
                }
                for (int k = 0; k < 3; k++) {
                    p[3 * n + k] = in.number(k);
                    nrm[3 * n + k] = in.number(3 + k);
                }
                // the largest component, not the length: (1e-300, 0, 0) is a direction, its square underflows
                double len = Math.max(Math.abs(nrm[3 * n]), Math.max(Math.abs(nrm[3 * n + 1]), Math.abs(nrm[3 * n + 2])));
                if (!(len > 0)) throw in.error("the normal (" + in.text(3) + ", " + in.text(4) + ", " + in.text(5) + ") must be a finite non-zero vector");
                n++;
            }
        } catch (CsvInput.CsvException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        } catch (IOException e) {
            throw new CliError(CliError.LOAD, "handsim: " + file + ": " + e.getMessage(), e);
        }
        return new Contacts(n, java.util.Arrays.copyOf(p, 3 * n), java.util.Arrays.copyOf(nrm, 3 * n));
    }

    /**
     * The command's JSON object (the part that reads no file).
     *
     * @param repeat timed batches of {@link SteadyTiming#median}
     * @param err    where a computation slower than {@link #PROGRESS_AFTER_S} reports its progress
     * @throws CliError exit 2 if a wrench coordinate exceeds {@link #MAX_WRENCH} (the hull's
     *                  volume, a sixth power, would overflow)
     * @throws ConvexHull.TooLargeException beyond {@link WrenchSpace#MAX_WRENCHES} distinct
     *                  wrenches (at once) or {@link ConvexHull#MAX_FACETS} facets
     */
    static Map<String, Object> quality(Contacts contacts, double mu, int m, double[] c, double r, int repeat, java.io.PrintWriter err) {
        int n = contacts.count();
        if ((long) n * m > WrenchSpace.MAX_INPUT_WRENCHES) {
            throw CliError.usage("handsim: " + n + " contacts x " + m + " cone edges are " + (long) n * m + " wrenches, more than "
                + WrenchSpace.MAX_INPUT_WRENCHES + " (at most " + WrenchSpace.MAX_WRENCHES + " distinct ones make the whole wrench space)");
        }
        int count = n * m;
        double[] w = GraspWrenches.of(n, contacts.points(), contacts.normals(), mu, m, c, r);
        for (int i = 0; i < w.length; i++) {
            if (!(Math.abs(w[i]) <= MAX_WRENCH)) {
                throw CliError.usage("handsim: contact " + (i / (6 * m) + 1) + " gives a wrench coordinate beyond 1e30 ("
                    + w[i] + "): coordinates or --center too large, or --radius too small");
            }
        }
        ConvexHull hull = WrenchSpace.threadHull();
        long start = System.nanoTime();
        GraspQuality q;
        // a hull of many wrenches takes seconds: say so, with the facets built so far, every few seconds
        java.util.concurrent.ScheduledExecutorService ticker = java.util.concurrent.Executors.newSingleThreadScheduledExecutor(job -> {
            Thread th = new Thread(job, "quality-progress");
            th.setDaemon(true);
            return th;
        });
        ticker.scheduleAtFixedRate(() -> {
            err.println(String.format(java.util.Locale.ROOT, "handsim quality: %d contacts, %d wrenches: %d hull facets so far (%.0f s)",
                n, count, hull.facetsSoFar(), (System.nanoTime() - start) / 1e9));
            err.flush();
        }, (long) (PROGRESS_AFTER_S * 1000), (long) (PROGRESS_EVERY_S * 1000), java.util.concurrent.TimeUnit.MILLISECONDS);
        try {
            q = WrenchSpace.quality(w, count, n);
        } finally {
            ticker.shutdownNow();
        }
        double first = (System.nanoTime() - start) / 1e9;
        SteadyTiming.Result t = first >= SteadyTiming.SLOW_SECONDS ? SteadyTiming.once(first) : SteadyTiming.median(() -> {
            GraspQuality x = WrenchSpace.quality(w, count, n);
            return x.volume() + x.epsilon();
        }, repeat);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("contacts", n);
        out.put("wrenches", count);
        out.put("force_closure", q.forceClosure());
        out.put("epsilon", q.epsilon());
        out.put("volume", q.volume());
        out.put("facets", q.facets());
        out.put("time_us_median", Math.round(t.medianMicros() * 100) / 100.0);   // µs to 0.01, as collide
        return out;
    }

    private static int integer(String option, String text) {
        try {
            return Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw CliError.usage("handsim: " + option + ": '" + text + "' is not an integer");
        }
    }
}
