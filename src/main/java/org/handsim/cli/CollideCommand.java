package org.handsim.cli;

import org.handsim.scenario.NotFound;
import org.handsim.text.SafeText;
import org.handsim.text.Decimal;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.Kdop;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.contact.ContactPatches;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.text.JsonWriter;
import org.handsim.process.SteadyTiming;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import org.handsim.scenario.MeshFiles;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.scenario.UnitRule;
import java.io.PrintWriter;
import java.io.StringWriter;

/**
 * {@code handsim collide A B [--units auto|mm|cm|m] [--pose-b tx,ty,tz,rx,ry,rz] [--k 18] [--timing [--repeat N]]}:
 * the contact geometry of two objects (VRML97, OBJ or STL; paper Section IV, first two steps).
 */
@Command(name = "collide", mixinStandardHelpOptions = true,
    description = {"Intersects two objects (VRML97 .wrl, OBJ .obj or STL .stl) with k-DOP trees (B placed by --pose-b).",
        "Prints {\"intersecting\":bool,\"pairs\":n,\"segments\":n,",
        "  \"patches\":[{\"center\":[x,y,z],\"normal\":[x,y,z],\"area_m2\":a,\"pairs\":n}],",
        "  \"counters\":{\"node_tests\":n,\"tri_tests\":n}}",
        "pairs: intersecting triangle pairs; segments: their intersection segments;",
        "patches: connected sets of segments, one point contact each: centre of the",
        "bounding box, unit normal out of B (from B's triangles), area estimate;",
        "A's frame, metres (each file's coordinates times its unit, --units).",
        "--timing adds \"build_ms\":t (both trees) and \"query_us_median\":t: the tree",
        "query including B's placement, once the JIT has compiled it: warm-up of at",
        "least 0.5 s and 10 000 queries, then until the JIT has been idle for 0.25 s",
        "(at most 5 s), then the median of --repeat timed batches of about 1 ms each",
        "(process.SteadyTiming, the scheme of gradle bench).",
        "At most 100 000 intersecting triangle pairs (coincident meshes: exit 2).",
        "Exit codes: 0 ok, 2 bad arguments, 3 a file cannot be loaded."})
public final class CollideCommand implements Callable<Integer> {
    @Spec CommandSpec spec;

    @Parameters(index = "0", paramLabel = "A", description = "object A: .wrl, .obj or .stl (its frame is the output frame)")
    Path fileA;

    @Parameters(index = "1", paramLabel = "B", description = "object B: .wrl, .obj or .stl")
    Path fileB;

    @Option(names = "--units", paramLabel = "auto|mm|cm|m", defaultValue = "auto",
        description = {Args.UNITS_HELP_1, Args.UNITS_HELP_2, Args.UNITS_HELP_3, "(for both files; auto judges each by itself)"})
    String units;

    @Option(names = "--pose-b", paramLabel = "tx,ty,tz,rx,ry,rz",
        description = "B in A's frame: translation (m) and axis-angle vector (rad); default 0,0,0,0,0,0")
    String poseB = "0,0,0,0,0,0";

    @Option(names = "--k", paramLabel = "K", description = "k of the k-DOPs: 6, 14, 18 (default) or 26")
    String kText = "18";

    @Option(names = "--timing", description = "also time the tree building and the query (build_ms, query_us_median; seconds of warm-up)")
    boolean timing;

    @Option(names = "--repeat", paramLabel = "N", description = {"timed batches of --timing after the warm-up", "(1..10000, default " + DEFAULT_REPEAT + "); the median per query is reported"})
    String repeatText;

    /**
     * Most intersecting triangle pairs collide reports: 100 000. Touching objects meet in far
     * fewer (a finger on the mug: tens; two 358 800-triangle spheres crossing: a few thousand);
     * coincident meshes meet in every triangle's neighbours (5.4 million pairs for that sphere
     * on itself), and joining such pairs into patches takes minutes (measured: 145 200 pairs of
     * a coincident 29 000-triangle sphere, 16 s).
     */
    static final int MAX_PAIRS = 100_000;
    /** Above this many triangles in A and B together, each phase is announced on standard error. */
    static final long PROGRESS_TRIANGLES = 100_000;

    /** Timed batches by default: the median of 101 batches of about 1 ms (0.1 s after the warm-up). */
    static final int DEFAULT_REPEAT = 101;

    @Override
    public Integer call() {
        double[] p = Args.numbers("--pose-b", poseB, 6);
        String range = RigidTransform.poseProblem("translation", java.util.Arrays.copyOfRange(p, 0, 3), "rotation", java.util.Arrays.copyOfRange(p, 3, 6));
        if (range != null) throw CliError.usage("handsim: --pose-b: " + range);
        int k = integer("--k", kText);
        boolean ok = false;
        for (int s : Kdop.SUPPORTED_K) ok |= s == k;
        if (!ok) throw CliError.usage("handsim: --k must be 6, 14, 18 or 26, got " + kText);
        if (repeatText != null && !timing) throw CliError.usage("handsim: --repeat needs --timing");
        int repeat = repeatText == null ? DEFAULT_REPEAT : integer("--repeat", repeatText);
        if (repeat < 1 || repeat > 10_000) throw CliError.usage("handsim: --repeat must be in 1..10000, got " + repeatText);
        Scenario.Units chosen = Args.units(units);
        StringWriter notices = new StringWriter();   // said once both files have loaded: an error stays one line
        PrintWriter said = new PrintWriter(notices);
        TriangleMesh a = loadMesh(fileA, chosen, said), b = loadMesh(fileB, chosen, said);
        said.flush();
        spec.commandLine().getErr().print(notices);
        RigidTransform pose = RigidTransform.fromPose(p[0], p[1], p[2], p[3], p[4], p[5]);
        java.io.PrintWriter err = spec.commandLine().getErr();
        Map<String, Object> json;
        try {
            json = collide(a, b, pose, k, timing ? repeat : 0, a.triangleCount() + (long) b.triangleCount() > PROGRESS_TRIANGLES ? err : null);
        } catch (CollisionResult.TooManyPairsException e) {
            throw CliError.usage("handsim collide: " + fileA + " and " + fileB + " at --pose-b " + poseB + " intersect in " + e.getMessage()
                + " (coincident or deeply interpenetrating meshes; the limit of collide, whose contact patches join every pair's"
                + " segments); move B with --pose-b");
        }
        spec.commandLine().getOut().println(JsonWriter.write(json));
        return 0;
    }

    private static int integer(String option, String text) {
        try {
            return Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw CliError.usage("handsim: " + option + ": '" + SafeText.quote(text) + "' is not an integer");
        }
    }

    /** Segments round VRML Sphere, Cylinder and Cone nodes (the VRML loader's default). */
    static final int VRML_DIVISIONS = 32;

    /** {@link #collide(TriangleMesh, TriangleMesh, RigidTransform, int, int, java.io.PrintWriter)} without progress lines. */
    static Map<String, Object> collide(TriangleMesh a, TriangleMesh b, RigidTransform pose, int k, int repeat) {
        return collide(a, b, pose, k, repeat, null);
    }

    private static void say(java.io.PrintWriter progress, String line) {
        if (progress == null) return;
        progress.println("handsim collide: " + line);
        progress.flush();
    }

    /**
     * Loads an object file — VRML97, OBJ or STL ({@link MeshFiles}) — as one triangle mesh in
     * metres in the file's frame (every transform applied; vertices as in the file times its
     * unit, not welded). The unit is {@code chosen}, or (null) judged by the file's size with a
     * notice on {@code err} ({@link UnitRule}).
     *
     * @throws CliError exit 3 with FILE:LINE:COL: message (binary STL: FILE: byte N: message)
     */
    static TriangleMesh loadMesh(Path file, Scenario.Units chosen, PrintWriter err) {
        Args.inputFile(file);
        try {
            TriangleMesh m = MeshFiles.load(file, VRML_DIVISIONS, chosen != null ? chosen.metres() : 1.0).mesh();
            UnitRule.Choice u = UnitRule.resolve(m, chosen);
            if (!u.bySize()) return m;
            err.println(UnitRule.notice("handsim collide", file, u.units(), "--units"));
            return u.units() == Scenario.Units.M ? m : MeshFiles.load(file, VRML_DIVISIONS, u.units().metres()).mesh();
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage(), e);
        }
    }

    /**
     * The command's JSON object for two meshes (the part that does not read files).
     *
     * @param repeat timed batches after the warm-up ({@link SteadyTiming}); the median per query is
     *               reported; 0: not timed (no {@code build_ms}, {@code query_us_median})
     * @param progress where each phase is announced (large meshes), or null
     * @throws CollisionResult.TooManyPairsException beyond {@link #MAX_PAIRS} intersecting pairs
     */
    static Map<String, Object> collide(TriangleMesh a, TriangleMesh b, RigidTransform pose, int k, int repeat, java.io.PrintWriter progress) {
        long t0 = System.nanoTime();
        say(progress, "building the k-DOP trees of " + a.triangleCount() + " + " + b.triangleCount() + " triangles");
        KdopTree ta = KdopTree.build(a, k), tb = KdopTree.build(b, k);
        double buildMs = (System.nanoTime() - t0) / 1e6;
        TreeQuery q = new TreeQuery();
        CollisionResult r = new CollisionResult().limitPairs(MAX_PAIRS);
        say(progress, String.format(java.util.Locale.ROOT, "trees built in %.1f s; querying%s", buildMs / 1000, repeat > 0 ? " and timing the query" : ""));
        double median = repeat > 0 ? SteadyTiming.median(() -> q.collide(ta, tb, pose, r).pairCount() + r.nodeTests, repeat).medianMicros() : 0;
        q.collide(ta, tb, pose, r);
        say(progress, r.pairCount() + " intersecting pairs; joining their segments into patches");
        ContactPatches cp = new ContactPatches();
        int n = cp.build(r, a, b, pose);
        List<Object> patches = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Map<String, Object> pm = new LinkedHashMap<>();
            pm.put("center", Decimal.clean(cp.center(i, new double[3])));   // README: |x| < 1e-12 written as 0
            pm.put("normal", Decimal.clean(cp.normal(i, new double[3])));
            pm.put("area_m2", cp.area(i));
            pm.put("pairs", cp.pairCount(i));
            patches.add(pm);
        }
        Map<String, Object> counters = new LinkedHashMap<>();
        counters.put("node_tests", r.nodeTests);
        counters.put("tri_tests", r.triangleTests);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("intersecting", r.intersecting());
        out.put("pairs", r.pairCount());
        out.put("segments", r.segmentCount());
        out.put("patches", patches);
        out.put("counters", counters);
        if (repeat > 0) {
            out.put("build_ms", Math.round(buildMs * 1000) / 1000.0);
            out.put("query_us_median", Math.round(median * 100) / 100.0);
        }
        return out;
    }
}
