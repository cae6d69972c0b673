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
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.model.SceneGeometry;
import org.handsim.scenario.UnitRule;
import org.handsim.files.CsvInput;
import org.handsim.files.InputFile;
import org.handsim.text.Json;
import org.handsim.text.JsonObject;
import org.handsim.text.JsonWriter;
import org.handsim.process.SteadyTiming;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code handsim quality CONTACTS [--friction MU] [--edges M] [--center x,y,z] [--radius R]
 * [--object FILE] [--timing [--repeat N]]}: the quality of a grasp given as point contacts: the
 * L1 grasp wrench space of their linearised friction cones ({@link GraspWrenches}), its force
 * closure, ε, volume and facets ({@link WrenchSpace#quality}), and on request the steady-state
 * time of that computation ({@link SteadyTiming}: seconds of warm-up, so only when asked).
 * CONTACTS may be what {@code handsim grasp} prints, whose torque origin, radius, friction and
 * cone edges are then the defaults: the same ε as grasp. Output contract: one JSON line with the
 * keys {@link #JSON_KEYS}.
 */
@Command(name = "quality", mixinStandardHelpOptions = true, sortOptions = false,
    description = {"Grasp quality of point contacts: force closure, epsilon and volume.",
        "Point contacts have Coulomb friction (the L1 grasp wrench",
        "space: the 6-D convex hull of w = (f, (p - c) x f / R) over the m edges f of",
        "each contact's friction cone).",
        "CONTACTS: a CSV file, header x,y,z,nx,ny,nz; one contact a row: the point",
        "(metres) and the normal = the direction of the force the finger applies,",
        "INTO the object (need not be unit); or what handsim grasp prints (or the",
        "summary.json of handsim run): its contacts, centre, radius, friction and cone",
        "edges, so that the same options give grasp's epsilon. Cone edge i: n + mu",
        "(cos(2 pi i/m) t1 + sin(2 pi i/m) t2), t1 = n x a/|n x a|, a = e_x if",
        "|n_x| < 0.9 else e_y, t2 = n x t1.",
        "The torque origin c and length R: --center and --radius; else those of",
        "--object FILE (an object file, or a scenario's placed object: its centroid",
        "and largest centroid-to-vertex distance, as handsim grasp); else the grasp",
        "file's; else c = 0 and R = 1 m (with a note on standard error).",
        "Prints {\"contacts\":n,\"wrenches\":n,\"force_closure\":bool,\"epsilon\":e,",
        "  \"volume\":v,\"facets\":n,\"center_m\":[x,y,z],\"radius_m\":R}",
        "force_closure: the origin strictly inside the hull (farther than 1e-11 x the",
        "largest |wrench coordinate| from every facet); epsilon: the radius of the",
        "largest origin-centred ball inside the hull (N), 0 without force closure;",
        "volume: 6-D volume (0 when the wrenches span fewer than 6 dimensions);",
        "facets: facets of the hull (coplanar ones merged); center_m, radius_m: the",
        "c and R used. --timing adds \"time_us_median\":t, the quality computation",
        "alone in microseconds: the median of --repeat timed batches after a warm-up",
        "of at least 0.5 s and 10 000 calls, then until the JIT has been idle for",
        "0.25 s (at most 5 s).",
        "Example: the face centres of a 60 mm cube, c its centre, R = 0.052,",
        "  x,y,z,nx,ny,nz",
        "  0.03,0,0,-1,0,0       -0.03,0,0,1,0,0     (one row each)",
        "  0,0.03,0,0,-1,0       0,-0.03,0,0,1,0",
        "  0,0,0.03,0,0,-1       0,0,-0.03,0,0,1",
        "  handsim quality cube.csv --radius 0.052 --edges 4",
        "  {\"contacts\":6,\"wrenches\":24,\"force_closure\":true,",
        "   \"epsilon\":0.16654334688162284,\"volume\":0.060007254210286784,",
        "   \"facets\":148,\"center_m\":[0,0,0],\"radius_m\":0.052}",
        "  (epsilon = mu a / (sqrt(3) R), a = 0.03: the support in the torque",
        "  direction (0,0,0,1,1,-1)/sqrt(3); WrenchSpaceTest derives it.)",
        "Limits: at most 100 000 contacts and 1 600 distinct wrenches (contacts x",
        "edges; repeated ones count once) for the whole hull, and 2^20 hull facets;",
        "beyond, exit 2 saying how many fit. Progress every 5 s when the hull is slow.",
        "Exit codes: 0 ok, 2 bad arguments or a bad row (its line named), 3 a file",
        "cannot be read."})
public final class QualityCommand implements Callable<Integer> {
    /** The input header. */
    static final String HEADER = "x,y,z,nx,ny,nz";
    /** The output keys, in order ({@code time_us_median} only with {@code --timing}). */
    static final List<String> JSON_KEYS = List.of("contacts", "wrenches", "force_closure", "epsilon", "volume", "facets", "center_m", "radius_m",
        "time_us_median");
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

    @Parameters(index = "0", paramLabel = "CONTACTS", description = "contacts: CSV with the header x,y,z,nx,ny,nz, or handsim grasp's JSON")
    Path file;

    @Option(names = "--friction", paramLabel = "MU", description = "Coulomb coefficient mu >= 0 (default: the grasp file's, else 0.5)")
    String frictionText;

    @Option(names = "--edges", paramLabel = "M", description = "friction cone edges, 1..1024 (default: the grasp file's, else 8)")
    String edgesText;

    @Option(names = "--center", paramLabel = "x,y,z", description = "torque origin c, metres (default: --object's centroid, the grasp file's, else 0,0,0)")
    String centerText;

    @Option(names = "--radius", paramLabel = "R", description = "characteristic length R > 0, metres: torques are divided by it (default: --object's, the grasp file's, else 1)")
    String radiusText;

    @Option(names = "--object", paramLabel = "FILE", description = {"the object the contacts are on: c and R as handsim grasp", "takes them (an object file at its own coordinates, or", "a scenario .json: its object as placed)"})
    Path object;

    @Option(names = "--units", paramLabel = "auto|mm|cm|m",
        description = {Args.UNITS_HELP_1, Args.UNITS_HELP_2, Args.UNITS_HELP_3, "(of --object's file)"})
    String units;

    @Option(names = "--timing", description = "also time the computation (time_us_median; seconds of warm-up)")
    boolean timing;

    @Option(names = "--repeat", paramLabel = "N", description = "timed batches of --timing, 1..1000 (default " + DEFAULT_REPEAT + ")")
    String repeatText;

    @Override
    public Integer call() throws IOException {
        Double mu = frictionText == null ? null : Args.numbers("--friction", frictionText, 1)[0];
        Integer m = edgesText == null ? null : integer("--edges", edgesText);
        Args.frictionAndEdges(mu, m);
        double[] c = centerText == null ? null : Args.numbers("--center", centerText, 3);
        Double r = radiusText == null ? null : Args.numbers("--radius", radiusText, 1)[0];
        if (r != null && !(r > 0)) throw CliError.usage("handsim: --radius must be > 0, got " + radiusText);
        if (repeatText != null && !timing) throw CliError.usage("handsim: --repeat needs --timing");
        int repeat = repeatText == null ? DEFAULT_REPEAT : integer("--repeat", repeatText);
        if (repeat < 1 || repeat > 1000) throw CliError.usage("handsim: --repeat must be in 1..1000, got " + repeatText);
        if (units != null && object == null) throw CliError.usage("handsim: --units needs --object");
        Scenario.Units chosen = units == null ? null : Args.units(units);
        Args.inputFile(file);
        Contacts contacts = read(file);
        if ((c == null || r == null) && object != null) {
            double[] cr = objectScaling(object, chosen, spec.commandLine().getErr());
            if (c == null) c = new double[] {cr[0], cr[1], cr[2]};
            if (r == null) r = cr[3];
        }
        if (c == null) c = contacts.center() != null ? contacts.center() : new double[3];
        boolean unscaled = r == null && contacts.radius() == null;
        if (r == null) r = contacts.radius() != null ? contacts.radius() : 1.0;
        double friction = mu != null ? mu : contacts.friction() != null ? contacts.friction() : FrictionCone.DEFAULT_MU;
        int edges = m != null ? m : contacts.edges() != null ? contacts.edges() : FrictionCone.DEFAULT_EDGES;
        Map<String, Object> json;
        try {
            json = quality(contacts, friction, edges, c, r, timing ? repeat : 0, spec.commandLine().getErr());
        } catch (ConvexHull.TooLargeException e) {
            String why = e.getMessage();
            throw CliError.usage("handsim: " + file + ": " + (why.startsWith("the convex hull")
                ? contacts.count() + " contacts x " + edges + " cone edges: " + why + "; use fewer contacts or --edges" : why));
        }
        if (unscaled) {
            spec.commandLine().getErr().println("handsim quality: torques divided by R = 1 m (no --radius, --object or grasp file:"
                + " handsim grasp divides by the object's radius)");
        }
        spec.commandLine().getOut().println(JsonWriter.write(json));
        return 0;
    }

    /**
     * The torque origin and length {cx, cy, cz, R} of {@code --object}: a scenario's object as
     * placed, or an object file at its own coordinates in its unit ({@code chosen}, else judged by
     * its size) — the centroid and the largest centroid-to-vertex distance that {@code handsim
     * grasp} divides by ({@link SceneGeometry#centroidAndRadius}).
     *
     * @throws CliError exit 3 if the file cannot be loaded, exit 2 for a scenario without an object
     */
    static double[] objectScaling(Path file, Scenario.Units chosen, java.io.PrintWriter err) {
        Args.inputFile(file);
        try {
            Scenario.ObjectPlacement placement;
            if (file.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".json")) {
                Scenario s = Scenario.load(file);
                if (s.object() == null) throw CliError.usage("handsim: --object " + file + ": the scenario has no object");
                placement = s.object();
                if (chosen != null) placement = placement.withScale(placement.scale(), chosen);
            } else {
                UnitRule.Choice u = UnitRule.resolve(file, Scenario.DEFAULT_DIVISIONS, chosen);
                if (u.bySize()) err.println(UnitRule.notice("handsim quality", file, u.units(), "--units"));
                placement = Scenario.ObjectPlacement.of(file, new double[3], new double[3], 1.0, Scenario.DEFAULT_DIVISIONS, u.units());
            }
            return new SceneGeometry(placement, SceneGeometry.DEFAULT_K).centroidAndRadius();
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, "handsim: " + e.getMessage(), e);
        }
    }

    /**
     * Points and normals, 3 values each per contact, and what a grasp file says of its scaling
     * and cones (null when not given: a CSV file).
     */
    record Contacts(int count, double[] points, double[] normals, double[] center, Double radius, Double friction, Integer edges) {
        Contacts(int count, double[] points, double[] normals) {
            this(count, points, normals, null, null, null, null);
        }
    }

    /**
     * Reads CONTACTS: what {@code handsim grasp} prints, or {@code handsim run}'s summary.json
     * (its {@code grasp}), when the file starts with '{'; else the CSV file.
     *
     * @throws CliError exit 2 naming FILE:LINE (CSV) or the field (JSON) for bad input, exit 3 if
     *                  the file cannot be read
     */
    static Contacts read(Path file) {
        String head;
        try {
            head = new String(InputFile.head(file, 64), java.nio.charset.StandardCharsets.UTF_8).replace("\uFEFF", "").stripLeading();
        } catch (InputFile.InputFileException e) {
            throw new CliError(CliError.LOAD, "handsim: " + e.getMessage(), e);
        }
        return head.startsWith("{") ? readGrasp(file) : readCsv(file);
    }

    /** The contacts and scaling of a grasp as {@code handsim grasp} prints it (or summary.json's {@code grasp}). */
    static Contacts readGrasp(Path file) {
        try {
            String text = InputFile.readText(file, MAX_GRASP_BYTES, "the limit of a grasp file");
            JsonObject root = JsonObject.parse(file.toString(), text);
            JsonObject g = root.has("contacts") || !root.has("grasp") ? root : root.object("grasp");
            int n = g.list("contacts").size();
            if (n > MAX_CONTACTS) throw g.error("contacts", "more than " + MAX_CONTACTS + " contacts");
            double[] p = new double[3 * n], nrm = new double[3 * n];
            for (int i = 0; i < n; i++) {
                JsonObject ct = g.objectAt("contacts", i);
                System.arraycopy(ct.numbers("point", 3), 0, p, 3 * i, 3);
                double[] d = ct.numbers("normal", 3);
                if (!(Math.max(Math.abs(d[0]), Math.max(Math.abs(d[1]), Math.abs(d[2]))) > 0)) throw ct.error("normal", "must be a non-zero vector");
                System.arraycopy(d, 0, nrm, 3 * i, 3);
            }
            double[] c = g.has("center_m") ? g.numbers("center_m", 3) : null;
            Double r = g.has("radius_m") ? g.positive("radius_m") : null;
            Double mu = g.has("friction") ? g.nonNegative("friction") : null;
            Integer m = g.has("cone_edges") ? g.integer("cone_edges") : null;
            if (mu != null && FrictionCone.muProblem(mu) != null) throw g.error("friction", FrictionCone.muProblem(mu));
            if (m != null && (m < 1 || m > 1024)) throw g.error("cone_edges", "must be between 1 and 1024, got " + m);
            return new Contacts(n, p, nrm, c, r, mu, m);
        } catch (Json.JsonException e) {
            throw CliError.usage("handsim: " + e.getMessage());
        } catch (InputFile.InputFileException e) {
            throw new CliError(CliError.LOAD, "handsim: " + e.getMessage(), e);
        }
    }

    /** Largest grasp JSON read: 100 000 contacts of about 200 bytes. */
    static final long MAX_GRASP_BYTES = 32L << 20;

    /**
     * Reads CONTACTS.csv.
     *
     * @throws CliError exit 2 naming FILE:LINE for a bad header or row (not six finite numbers,
     *                  a zero normal), exit 3 if the file cannot be read
     */
    static Contacts readCsv(Path file) {
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
     * @param repeat timed batches of {@link SteadyTiming#median}; 0: not timed (no {@code time_us_median})
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
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("contacts", n);
        out.put("wrenches", count);
        out.put("force_closure", q.forceClosure());
        out.put("epsilon", q.epsilon());
        out.put("volume", q.volume());
        out.put("facets", q.facets());
        out.put("center_m", c.clone());
        out.put("radius_m", r);
        if (repeat > 0) {
            SteadyTiming.Result t = first >= SteadyTiming.SLOW_SECONDS ? SteadyTiming.once(first) : SteadyTiming.median(() -> {
                GraspQuality x = WrenchSpace.quality(w, count, n);
                return x.volume() + x.epsilon();
            }, repeat);
            out.put("time_us_median", Math.round(t.medianMicros() * 100) / 100.0);   // µs to 0.01, as collide
        }
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
