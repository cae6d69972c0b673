package org.handsim.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.handsim.collision.BruteForce;
import org.handsim.collision.CoherentQuery;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.Kdop;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.vrml.VrmlLoader;

/**
 * Suite "collision": k-DOP tree build and query times against triangle count, for every k and
 * both placements of the moving mesh, and the all-pairs loop, on the meshes and poses of
 * {@code bench-meshes/scenarios.csv} of the shared data folder ({@code handsim.shared}); the rotated overlap compared with FCL's 24-DOP
 * search, FCL measured in the same run by {@code build/fcl/fclbench} ({@code tools/fcl/build}; trees
 * prebuilt in one frame, search only; {@link #FCL_ROT_US} only when it is not built, and the
 * table says so; 56 / 122 / 238 / 486 pairs there and 20 / 32 / 56 / 116 in
 * sphere_box_shallow; how it was measured: docs/BENCHMARKS.md, collision), and B moving along a
 * path of small steps through that overlap (full and coherent query per step). Our query times
 * always include placing B (on-demand transform or full refit), FCL's do not. Trees are built with the defaults (SAH split, leaves of two triangles)
 * unless the row says otherwise; every tree result is checked against the all-pairs loop
 * before it is timed. Then the split rule and leaf size on the rotated overlap. The rows
 * compared with FCL and the tuning table are the quietest of three measurements.
 */
final class CollisionBench implements BenchMain.Suite {
    static final int[] FCL_ROT_PAIRS = {56, 122, 238, 486};
    static final int[] FCL_BOX_PAIRS = {20, 32, 56, 116};
    /**
     * FCL's 24-DOP search on sphere_overlap_rot, µs, for 320 / 1 280 / 5 120 / 20 480 triangles,
     * as measured on the project machine on 2026-11-24 (FCL master e5efcc41, Release build;
     * docs/BENCHMARKS.md): the tables' fallback when {@code build/fcl/fclbench} is not built, named
     * as such in them — a ratio against FCL is otherwise always measured in the same run.
     */
    static final double[] FCL_ROT_US = {28.0, 64.1, 129.8, 274.1};
    /** FCL's times of this run (or {@link #FCL_ROT_US}), and where they come from. */
    private double[] fclUs = FCL_ROT_US.clone();
    private String fclSource = "FCL not measured in this run (build it: tools/fcl/build, FCL_SRC=... for a Release build of FCL master):"
        + " the stored figures of 2026-11-24, FCL master Release on the project machine";
    private static final long WARMUP_MS = 300, SAMPLE_MS = 30;
    private static final int SAMPLES = 11;

    private final Map<String, TriangleMesh> meshes = new LinkedHashMap<>();
    private final boolean fclOnly;

    /** @param fclOnly only the comparison with FCL (suite "collision-fcl", about a minute) */
    CollisionBench(boolean fclOnly) {
        this.fclOnly = fclOnly;
    }

    @Override
    public void run() throws Exception {
        Path dir = Path.of(System.getProperty("handsim.shared", "../shared")).resolve("bench-meshes");
        if (!Files.isDirectory(dir)) {
            System.out.println("bench-meshes folder " + dir + " absent: collision suite skipped");
            return;
        }
        List<String[]> rows = scenarios(dir.resolve("scenarios.csv"));
        // hand scale: HandSim's own object and finger-link models (DESIGN.md decision 4's case)
        rows.add(new String[] {"hand_sphere_link2", "objects/sphere.wrl", "hand/finger_link2.wrl", "0.06,0,0.03,0,0.3,0"});
        rows.add(new String[] {"hand_mug_link3", "objects/mug.wrl", "hand/finger_link3.wrl", "0.05,0.02,0.03,0.1,0.5,0.2"});
        Path models = Path.of(System.getProperty("handsim.root", ".")).resolve("vrml");
        for (String[] row : rows) {
            for (int c = 1; c <= 2; c++) {
                if (!meshes.containsKey(row[c])) {
                    Path f = row[c].contains("/") ? models.resolve(row[c]) : dir.resolve(row[c]);
                    meshes.put(row[c], TessellationWalk.mesh(new VrmlLoader().load(f).getSceneGroup()));
                }
            }
        }
        String fcl = fclTable();
        String steps = stepsTable();
        if (fclOnly) {
            System.out.println("\n### sphere_overlap_rot against FCL's 24-DOP search (our time includes placing B)\n\n" + fcl);
            System.out.println("### B moving in small steps through sphere_overlap_rot (k = 18; per step)\n\n" + steps);
            return;
        }
        StringBuilder buildTable = new StringBuilder("| mesh | triangles |");
        for (int k : Kdop.SUPPORTED_K) buildTable.append(" k=").append(k).append(" |");
        buildTable.append("\n|---|---:|").append("---:|".repeat(Kdop.SUPPORTED_K.length)).append('\n');
        for (Map.Entry<String, TriangleMesh> e : meshes.entrySet()) {
            TriangleMesh m = e.getValue();
            buildTable.append("| ").append(e.getKey()).append(" | ").append(m.triangleCount()).append(" |");
            for (int k : Kdop.SUPPORTED_K) {
                Bench.Result r = Bench.measure("build " + e.getKey() + " k=" + k, () -> KdopTree.build(m, k).nodeCount(),
                    WARMUP_MS, SAMPLES, SAMPLE_MS);
                buildTable.append(' ').append(Bench.human(r.medianNs)).append(" |");
            }
            buildTable.append('\n');
        }

        StringBuilder queryTable = new StringBuilder("| scenario | triangles A × B | pairs |");
        for (int k : Kdop.SUPPORTED_K) queryTable.append(" k=").append(k).append(" |");
        for (int k : Kdop.SUPPORTED_K) queryTable.append(" k=").append(k).append(" refit |");
        queryTable.append(" all pairs |\n|---|---|---:|").append("---:|".repeat(2 * Kdop.SUPPORTED_K.length + 1)).append('\n');
        StringBuilder pairsNote = new StringBuilder();
        for (String[] row : rows) {
            String name = row[0];
            TriangleMesh a = meshes.get(row[1]), b = meshes.get(row[2]);
            double[] p = parsePose(row[3]);
            RigidTransform pose = RigidTransform.fromPose(p[0], p[1], p[2], p[3], p[4], p[5]);
            String label = name + " " + a.triangleCount() + "x" + b.triangleCount();
            int level = levelOf(a.triangleCount());
            CollisionResult brute = new CollisionResult();
            BruteForce bf = new BruteForce();
            bf.collide(a, b, pose, brute);
            long[] want = brute.sortedPairKeys();
            queryTable.append("| ").append(name).append(" | ").append(a.triangleCount()).append(" × ").append(b.triangleCount())
                .append(" | ").append(want.length).append(" |");
            StringBuilder refitCells = new StringBuilder();
            for (int ki = 0; ki < Kdop.SUPPORTED_K.length; ki++) {
                int k = Kdop.SUPPORTED_K[ki];
                KdopTree ta = KdopTree.build(a, k), tb = KdopTree.build(b, k);
                for (TreeQuery.Placement pl : TreeQuery.Placement.values()) {
                    TreeQuery q = new TreeQuery().placement(pl);
                    CollisionResult r = new CollisionResult();
                    q.collide(ta, tb, pose, r);
                    if (!java.util.Arrays.equals(want, r.sortedPairKeys())) {
                        throw new IllegalStateException(label + " k=" + k + " " + pl + ": tree pairs differ from the all-pairs loop");
                    }
                    Bench.Result res = Bench.measure("query " + label + " k=" + k + " " + pl,
                        () -> q.collide(ta, tb, pose, r).pairCount() + r.nodeTests, WARMUP_MS, SAMPLES, SAMPLE_MS);
                    if (pl == TreeQuery.Placement.TRANSFORM) {
                        queryTable.append(' ').append(Bench.human(res.medianNs)).append(" |");
                    } else {
                        refitCells.append(' ').append(Bench.human(res.medianNs)).append(" |");
                    }
                }
            }
            queryTable.append(refitCells);
            long bruteTests = (long) a.triangleCount() * b.triangleCount();
            if (bruteTests <= 30_000_000L) {
                Bench.Result res = Bench.measure("all pairs " + label, () -> bf.collide(a, b, pose, brute).pairCount(), 0, 3, 1);
                queryTable.append(' ').append(Bench.human(res.medianNs)).append(" |\n");
            } else {
                queryTable.append(" not run (").append(bruteTests / 1_000_000).append(" M tests) |\n");
            }
            if (name.equals("sphere_box_shallow") && level >= 0) {
                pairsNote.append(String.format(Locale.ROOT, "sphere_box_shallow %d triangles: %d pairs (FCL %d)%n",
                    a.triangleCount(), want.length, FCL_BOX_PAIRS[level]));
            }
        }
        tuning();
        System.out.println("\n### Build (one tree, median)\n\n" + buildTable);
        System.out.println("### Query (B placed on demand; 'refit' columns: B refitted each query; all-pairs loop)\n\n" + queryTable);
        System.out.println("### sphere_overlap_rot against FCL's 24-DOP search (our time includes placing B)\n\n" + fcl);
        System.out.println("### B moving in small steps through sphere_overlap_rot (k = 18; per step)\n\n" + steps);
        System.out.println(pairsNote);
        System.out.println("### Split rule and leaf size (sphere_overlap_rot, k = 18, on-demand placement, quietest of 3)\n\n" + tuningTable);
    }

    /** Rounds of the interleaved FCL comparison: each time is the smallest of their medians. */
    static final int FCL_ROUNDS = 5;

    /**
     * sphere_overlap_rot on the four icospheres, every k on-demand and k = 18 refitted: the
     * 20 measurements are taken round-robin {@value #FCL_ROUNDS} times (so that a burst of load
     * from other sessions hits all of them alike) and each reports its quietest median.
     */
    private String fclTable() throws Exception {
        RigidTransform pose = RigidTransform.fromPose(1.5, 0.0, 0.0, 0.18708286933869706, 0.3741657386773941, 0.5612486080160912);
        String[] files = {"icosphere_s2.wrl", "icosphere_s3.wrl", "icosphere_s4.wrl", "icosphere_s5.wrl"};
        int nk = Kdop.SUPPORTED_K.length;
        List<Bench.Op> ops = new ArrayList<>();
        List<String> names = new ArrayList<>();
        int[] pairs = new int[files.length];
        for (int l = 0; l < files.length; l++) {
            TriangleMesh m = meshes.get(files[l]);
            for (int ki = 0; ki <= nk; ki++) {
                int k = ki < nk ? Kdop.SUPPORTED_K[ki] : 18;
                TreeQuery.Placement pl = ki < nk ? TreeQuery.Placement.TRANSFORM : TreeQuery.Placement.REFIT;
                KdopTree ta = KdopTree.build(m, k), tb = KdopTree.build(m, k);
                TreeQuery q = new TreeQuery().placement(pl);
                CollisionResult r = new CollisionResult();
                pairs[l] = q.collide(ta, tb, pose, r).pairCount();
                ops.add(() -> q.collide(ta, tb, pose, r).pairCount() + r.nodeTests);
                names.add("fcl-compare " + m.triangleCount() + " k=" + k + " " + pl);
            }
        }
        double[] best = new double[ops.size()];
        java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
        Path fcl = Path.of(System.getProperty("handsim.root", ".")).resolve("build/fcl/fclbench");
        List<String> fclFiles = Files.isExecutable(fcl) ? fclInputs(files, pose) : List.of();
        double[] fclBest = new double[files.length];
        java.util.Arrays.fill(fclBest, Double.POSITIVE_INFINITY);
        for (int round = 0; round < FCL_ROUNDS; round++) {
            for (int i = 0; i < ops.size(); i++) {
                best[i] = Math.min(best[i], Bench.measure(names.get(i) + " round " + (round + 1), ops.get(i), 150, 7, 20).medianUs());
            }
            if (!fclFiles.isEmpty()) runFcl(fcl, fclFiles, pairs, fclBest, round);
        }
        if (!fclFiles.isEmpty()) {
            fclUs = fclBest;
            fclSource = "FCL measured in this run, alternately with ours (build/fcl/fclbench: "
                + Files.readString(fcl.resolveSibling("fclbench.label")).strip() + ")";
        }
        StringBuilder t = new StringBuilder(fclSource + "\n\n| triangles | pairs (FCL) | FCL 24-DOP |");
        for (int k : Kdop.SUPPORTED_K) t.append(" k=").append(k).append(" |");
        t.append(" k=18 refit | best / FCL | k=18 / FCL | k=18 refit / FCL |\n|---:|---:|---:|")
            .append("---:|".repeat(nk + 4)).append('\n');
        for (int l = 0; l < files.length; l++) {
            double bestK = Double.POSITIVE_INFINITY;
            t.append(String.format(Locale.ROOT, "| %d | %d (%d) | %.1f µs |", meshes.get(files[l]).triangleCount(), pairs[l],
                FCL_ROT_PAIRS[l], fclUs[l]));
            for (int ki = 0; ki <= nk; ki++) {
                double u = best[l * (nk + 1) + ki];
                if (ki < nk) bestK = Math.min(bestK, u);
                t.append(String.format(Locale.ROOT, " %.1f µs |", u));
            }
            t.append(String.format(Locale.ROOT, " %.2f | %.2f | %.2f |%n", bestK / fclUs[l], best[l * (nk + 1) + 2] / fclUs[l],
                best[l * (nk + 1) + nk] / fclUs[l]));
        }
        return t.toString();
    }

    /**
     * Writes fclbench's inputs, build/bench/fcl-NAME.txt: "nv nt", A's vertices, B's vertices
     * placed by {@code pose} with {@link KdopTree#transformPoints} (the formula of our own
     * placement, so both libraries see bit-identical coordinates), the triangles.
     */
    private List<String> fclInputs(String[] files, RigidTransform pose) throws java.io.IOException {
        Path dir = Path.of(System.getProperty("handsim.root", ".")).resolve("build/bench");
        Files.createDirectories(dir);
        double[] m12 = new double[12];
        pose.copyTo(m12, 0);
        List<String> out = new ArrayList<>();
        for (String f : files) {
            TriangleMesh m = meshes.get(f);
            double[] v = m.vertices(), placed = new double[v.length];
            KdopTree.transformPoints(m12, v, placed, m.vertexCount());
            StringBuilder sb = new StringBuilder().append(m.vertexCount()).append(' ').append(m.triangleCount()).append('\n');
            for (double[] src : new double[][] {v, placed}) {
                for (int i = 0; i < v.length; i += 3) sb.append(src[i]).append(' ').append(src[i + 1]).append(' ').append(src[i + 2]).append('\n');
            }
            int[] tri = m.triangles();
            for (int i = 0; i < tri.length; i += 3) sb.append(tri[i]).append(' ').append(tri[i + 1]).append(' ').append(tri[i + 2]).append('\n');
            Path p = dir.resolve("fcl-" + f.replace(".wrl", ".txt"));
            Files.writeString(p, sb);
            out.add(p.toString());
        }
        return out;
    }

    /** One round of fclbench on the files (as our rounds: 150 ms warm-up, 7 batches of 20 ms); keeps each file's quietest median. */
    private static void runFcl(Path fcl, List<String> files, int[] pairs, double[] best, int round) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(fcl.toString(), "20", "7", "150"));
        cmd.addAll(files);
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String[] lines = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).split("\n");
        if (p.waitFor() != 0 || lines.length < files.size()) throw new IllegalStateException("fclbench failed: " + String.join(" / ", lines));
        for (int l = 0; l < files.size(); l++) {
            String[] f = lines[l].split(" ");   // fcl FILE TRIANGLES PAIRS median_us=T sink=..
            if (Integer.parseInt(f[3]) != pairs[l]) throw new IllegalStateException("FCL finds " + f[3] + " pairs, we " + pairs[l] + ": " + lines[l]);
            double us = Double.parseDouble(f[4].substring("median_us=".length()));
            System.out.printf(Locale.ROOT, "fcl-compare %s FCL 24-DOP round %d   median %.2f us%n", f[2], round + 1, us);
            best[l] = Math.min(best[l], us);
        }
    }

    /** Steps of the moving-B path. */
    static final int PATH_STEPS = 200;

    /**
     * Pose of B at step i of the moving path through sphere_overlap_rot: B's centre from x = 1.55
     * to 1.45 radii and its turn about (1, 2, 3) from 0.65 to 0.75 rad, in {@value #PATH_STEPS}
     * equal steps (5·10⁻⁴ radii and 5·10⁻⁴ rad a step: a finger link's step relative to its size
     * at dt = 1 ms is about 1.4·10⁻³).
     */
    static RigidTransform pathPose(int i) {
        double f = i / (double) (PATH_STEPS - 1);
        double x = 1.55 - 0.1 * f, angle = 0.65 + 0.1 * f, n = Math.sqrt(14);
        return RigidTransform.fromPose(x, 0, 0, angle / n, 2 * angle / n, 3 * angle / n);
    }

    /**
     * B moving along {@link #pathPose}: per step, the full query (k = 18, B placed on demand) and
     * the coherent query ({@link CoherentQuery}: near pairs, re-gathered when B has moved past
     * their clearance), checked equal at every step first; each time the quietest of
     * {@value #FCL_ROUNDS} round-robin medians of the whole path.
     */
    private String stepsTable() {
        String[] files = {"icosphere_s2.wrl", "icosphere_s3.wrl", "icosphere_s4.wrl", "icosphere_s5.wrl"};
        double[][] poses = new double[PATH_STEPS][12];
        for (int i = 0; i < PATH_STEPS; i++) pathPose(i).copyTo(poses[i], 0);
        double[] identity = new double[12];
        RigidTransform.IDENTITY.copyTo(identity, 0);
        List<Bench.Op> ops = new ArrayList<>();
        List<String> names = new ArrayList<>();
        int[] minPairs = new int[files.length], maxPairs = new int[files.length];
        long[] walks = new long[files.length];
        for (int l = 0; l < files.length; l++) {
            TriangleMesh m = meshes.get(files[l]);
            KdopTree ta = KdopTree.build(m, 18), tb = KdopTree.build(m, 18);
            TreeQuery q = new TreeQuery();
            CollisionResult r = new CollisionResult(), c = new CollisionResult();
            CoherentQuery cq = new CoherentQuery();
            minPairs[l] = Integer.MAX_VALUE;
            for (int i = 0; i < PATH_STEPS; i++) {
                q.collide(ta, tb, poses[i], 0, r);
                cq.collide(q, ta, identity, tb, poses[i], c);
                if (!java.util.Arrays.equals(r.sortedPairKeys(), c.sortedPairKeys()) || r.segmentCount() != c.segmentCount()) {
                    throw new IllegalStateException(m.triangleCount() + " triangles, step " + i + ": the coherent query differs from the full one");
                }
                minPairs[l] = Math.min(minPairs[l], r.pairCount());
                maxPairs[l] = Math.max(maxPairs[l], r.pairCount());
            }
            walks[l] = cq.walks();
            ops.add(() -> {
                double acc = 0;
                for (int i = 0; i < PATH_STEPS; i++) acc += q.collide(ta, tb, poses[i], 0, r).pairCount();
                return acc;
            });
            names.add("path " + m.triangleCount() + " full query");
            CoherentQuery timed = new CoherentQuery();
            ops.add(() -> {
                double acc = 0;
                timed.reset();
                for (int i = 0; i < PATH_STEPS; i++) acc += timed.collide(q, ta, identity, tb, poses[i], c).pairCount();
                return acc;
            });
            names.add("path " + m.triangleCount() + " coherent");
        }
        double[] best = new double[ops.size()];
        java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
        for (int round = 0; round < FCL_ROUNDS; round++) {
            for (int i = 0; i < ops.size(); i++) {
                best[i] = Math.min(best[i], Bench.measure(names.get(i) + " round " + (round + 1), ops.get(i), 150, 7, 30).medianUs() / PATH_STEPS);
            }
        }
        StringBuilder t = new StringBuilder("| triangles | pairs along the path | full query | coherent query | walks in "
            + PATH_STEPS + " steps | FCL 24-DOP (static search) | coherent / FCL |\n|---:|---:|---:|---:|---:|---:|---:|\n");
        for (int l = 0; l < files.length; l++) {
            t.append(String.format(Locale.ROOT, "| %d | %d–%d | %.1f µs | %.1f µs | %d | %.1f µs | %.2f |%n", meshes.get(files[l]).triangleCount(),
                minPairs[l], maxPairs[l], best[2 * l], best[2 * l + 1], walks[l], fclUs[l], best[2 * l + 1] / fclUs[l]));
        }
        return t.toString();
    }

    private final StringBuilder tuningTable = new StringBuilder();

    private void tuning() {
        RigidTransform pose = RigidTransform.fromPose(1.5, 0, 0, 0.18708286933869706, 0.3741657386773941, 0.5612486080160912);
        tuningTable.append("| triangles | median, leaf 1 | median, leaf 2 | median, leaf 4 | SAH, leaf 1 | SAH, leaf 2 | SAH, leaf 4 |\n")
            .append("|---:|---:|---:|---:|---:|---:|---:|\n");
        for (Map.Entry<String, TriangleMesh> e : meshes.entrySet()) {
            if (!e.getKey().startsWith("icosphere")) continue;
            TriangleMesh m = e.getValue();
            tuningTable.append("| ").append(m.triangleCount()).append(" |");
            for (KdopTree.SplitRule rule : KdopTree.SplitRule.values()) {
                for (int leaf : new int[] {1, 2, 4}) {
                    KdopTree ta = KdopTree.build(m, 18, rule, leaf), tb = KdopTree.build(m, 18, rule, leaf);
                    TreeQuery q = new TreeQuery();
                    CollisionResult r = new CollisionResult();
                    Bench.Result res = quietest(3, "tuning " + m.triangleCount() + " " + rule + " leaf " + leaf,
                        () -> q.collide(ta, tb, pose, r).pairCount() + r.nodeTests);
                    tuningTable.append(' ').append(Bench.human(res.medianNs)).append(" |");
                }
            }
            tuningTable.append('\n');
        }
    }

    /** The measurement with the smallest median of {@code rounds} (other sessions share the cores). */
    private static Bench.Result quietest(int rounds, String name, Bench.Op op) {
        Bench.Result best = null;
        for (int i = 0; i < rounds; i++) {
            Bench.Result r = Bench.measure(name, op, WARMUP_MS, SAMPLES, SAMPLE_MS);
            if (best == null || r.medianNs < best.medianNs) best = r;
        }
        return best;
    }

    private static int levelOf(int triangles) {
        switch (triangles) {
            case 320: return 0;
            case 1280: return 1;
            case 5120: return 2;
            case 20480: return 3;
            default: return -1;
        }
    }

    /** scenario, mesh_a, mesh_b, pose_b (quoted), comment. */
    static List<String[]> scenarios(Path csv) throws java.io.IOException {
        List<String[]> out = new ArrayList<>();
        List<String> lines = Files.readAllLines(csv);
        for (String line : lines.subList(1, lines.size())) {
            if (line.isBlank()) continue;
            List<String> cells = new ArrayList<>();
            StringBuilder cur = new StringBuilder();
            boolean quoted = false;
            for (char ch : line.toCharArray()) {
                if (ch == '"') quoted = !quoted;
                else if (ch == ',' && !quoted) { cells.add(cur.toString()); cur.setLength(0); }
                else cur.append(ch);
            }
            cells.add(cur.toString());
            out.add(cells.toArray(new String[0]));
        }
        return out;
    }

    static double[] parsePose(String s) {
        String[] p = s.split(",");
        double[] v = new double[6];
        for (int i = 0; i < 6; i++) v[i] = Double.parseDouble(p[i].trim());
        return v;
    }
}
