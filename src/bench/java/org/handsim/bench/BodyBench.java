package org.handsim.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import org.handsim.body.BodyScene;
import org.handsim.body.ContactProblem;
import org.handsim.body.ContactSolver;
import org.handsim.body.MassProperties;
import org.handsim.body.PolyhedralContactSolver;
import org.handsim.collision.DistanceQuery;
import org.handsim.collision.KdopTree;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.vrml.VrmlLoader;

/**
 * Suites of the free object ({@code org.handsim.body}).
 * <ul>
 *   <li>"body-solver": the step's convex problem solved by {@link ContactSolver} (Newton on the
 *       exact circular cones) and by {@link PolyhedralContactSolver} (ojAlgo's QP on 24-facet
 *       pyramids), on the problems of a box resting on a table, a box sliding down a tilted one
 *       and seeded 16-contact problems; and the whole body step of the box on the table.</li>
 *   <li>"body-proximity": {@link DistanceQuery} against FCL's distance query on every pair of
 *       {@code ../shared/bench-meshes/scenarios.csv}, FCL measured in the same run by
 *       {@code build/fcl/fcldistance} ({@code tools/fcl/build}), alternately with ours, each the
 *       quietest of five rounds' medians.</li>
 * </ul>
 */
final class BodyBench implements BenchMain.Suite {
    private final boolean proximity;

    BodyBench(boolean proximity) {
        this.proximity = proximity;
    }

    @Override
    public void run() throws Exception {
        if (proximity) proximity(); else solver();
    }

    // ------------------------------------------------------------------ solver

    private void solver() {
        Map<String, ContactProblem> problems = new LinkedHashMap<>();
        problems.put("box resting on a table (4 contacts)", sceneProblem(0));
        problems.put("box sliding down a 35° table (4 contacts)", sceneProblem(Math.toRadians(35)));
        SplittableRandom rnd = new SplittableRandom(5);
        for (int i = 0; i < 3; i++) problems.put("seeded, 16 contacts, #" + (i + 1), seeded(rnd, 16));
        StringBuilder t = new StringBuilder("| problem | Newton, exact cone | iterations | ojAlgo QP, 24-facet pyramid | ratio |\n|---|---:|---:|---:|---:|\n");
        for (Map.Entry<String, ContactProblem> e : problems.entrySet()) {
            ContactProblem p = e.getValue();
            ContactSolver s = new ContactSolver();
            PolyhedralContactSolver q = new PolyhedralContactSolver(PolyhedralContactSolver.DEFAULT_FACETS);
            s.solve(p);
            int its = s.iterations();
            double ours = cpuMedianUs(() -> { s.solve(p); return s.velocity(0); }, 300, 11, 30);
            double oj = cpuMedianUs(() -> { q.solve(p); return q.velocity(0); }, 300, 11, 30);
            System.out.printf(Locale.ROOT, "%s: newton %.2f us, ojalgo %.2f us%n", e.getKey(), ours, oj);
            t.append(String.format(Locale.ROOT, "| %s | %s | %d | %s | %.0f× |%n", e.getKey(), Bench.human(1e3 * ours), its,
                Bench.human(1e3 * oj), oj / ours));
        }
        BodyScene scene = table(0);
        for (int i = 0; i < 100; i++) scene.step(0.001);
        double step = cpuMedianUs(() -> { scene.step(0.001); return scene.contacts().size(); }, 500, 11, 50);
        System.out.println("\n### The step's contact problem (median per solve, thread CPU time)\n\n" + t);
        System.out.println("One whole step of the box resting on the table (proximity query, problem, exact Coulomb solve, integration): "
            + Bench.human(1e3 * step) + " (thread CPU time)\n");
    }

    private static final TriangleMesh BOX = box(0.03, 0.02, 0.01), TABLE = box(0.4, 0.3, 0.01);

    /** The box on the table tilted by a (as BodySceneTest), after 100 steps; its last step's problem. */
    private static ContactProblem sceneProblem(double a) {
        BodyScene s = table(a);
        for (int i = 0; i < 100; i++) s.step(0.001);
        return s.stepper().problem();
    }

    private static BodyScene table(double a) {
        double[] n = {Math.sin(a), 0, Math.cos(a)};
        BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), RigidTransform.fromPose(0.01 * n[0], 0, 0.01 * n[2], 0, a, 0));
        s.addSupport(TABLE, RigidTransform.fromPose(-0.01 * n[0], 0, -0.01 * n[2], 0, a, 0));
        return s;
    }

    /** An axis-aligned box of half extents (hx, hy, hz): 8 vertices, 12 triangles, outward. */
    static TriangleMesh box(double hx, double hy, double hz) {
        double[] v = new double[24];
        for (int i = 0; i < 8; i++) {
            v[3 * i] = (i & 4) != 0 ? hx : -hx;
            v[3 * i + 1] = (i & 2) != 0 ? hy : -hy;
            v[3 * i + 2] = (i & 1) != 0 ? hz : -hz;
        }
        int[] t = {1, 3, 0, 4, 1, 0, 0, 3, 2, 2, 4, 0, 1, 7, 3, 5, 1, 4, 5, 7, 1, 3, 7, 2, 6, 4, 2, 2, 7, 6, 6, 5, 4, 7, 5, 6};
        return new TriangleMesh("box", v, t);
    }

    /** A feasible seeded problem: an object, n contacts around it, biases a random twist satisfies. */
    private static ContactProblem seeded(SplittableRandom rnd, int n) {
        ContactProblem p = new ContactProblem();
        p.begin(6);
        double[] iw = {2e-4, 0, 0, 0, 3e-4, 0, 0, 0, 4e-4};
        double[] free = new double[6];
        for (int i = 0; i < 6; i++) free[i] = (rnd.nextDouble() - 0.5) * (i < 3 ? 0.2 : 2);
        p.setObject(0.3, iw, free);
        double[] target = new double[6];
        for (int i = 0; i < 6; i++) target[i] = (rnd.nextDouble() - 0.5) * (i < 3 ? 0.05 : 0.5);
        for (int c = 0; c < n; c++) {
            int k = p.addConstraint(0.3 + 0.7 * rnd.nextDouble());
            double[] nrm = unit(rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5);
            double[] t1 = unit(nrm[1], -nrm[0], 0.0001), t2 = new double[3];
            t2[0] = nrm[1] * t1[2] - nrm[2] * t1[1]; t2[1] = nrm[2] * t1[0] - nrm[0] * t1[2]; t2[2] = nrm[0] * t1[1] - nrm[1] * t1[0];
            t1 = new double[] {t2[1] * nrm[2] - t2[2] * nrm[1], t2[2] * nrm[0] - t2[0] * nrm[2], t2[0] * nrm[1] - t2[1] * nrm[0]};
            double rx = -0.04 * nrm[0], ry = -0.04 * nrm[1], rz = -0.04 * nrm[2];
            double[][] d = {nrm, t1, t2};
            double[] jac = p.jacobian(), b = p.bias();
            double[] jv = new double[3];
            for (int r = 0; r < 3; r++) {
                double[] e = d[r];
                int o = (3 * k + r) * 6;
                jac[o] = e[0]; jac[o + 1] = e[1]; jac[o + 2] = e[2];
                jac[o + 3] = ry * e[2] - rz * e[1]; jac[o + 4] = rz * e[0] - rx * e[2]; jac[o + 5] = rx * e[1] - ry * e[0];
                for (int j = 0; j < 6; j++) jv[r] += jac[o + j] * target[j];
            }
            b[3 * k] = jv[0] - p.frictionCoefficient(k) * Math.hypot(jv[1], jv[2]) - 0.01 * rnd.nextDouble();
        }
        return p;
    }

    private static double[] unit(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }

    // ------------------------------------------------------------------ proximity

    private void proximity() throws Exception {
        Path dir = Path.of(System.getProperty("handsim.shared", "../shared")).resolve("bench-meshes");
        if (!Files.isDirectory(dir)) {
            System.out.println("bench-meshes folder " + dir + " absent: body-proximity suite skipped");
            return;
        }
        List<String[]> rows = CollisionBench.scenarios(dir.resolve("scenarios.csv"));
        Map<String, TriangleMesh> meshes = new LinkedHashMap<>();
        Path fcl = Path.of(System.getProperty("handsim.root", ".")).resolve("build/fcl/fcldistance");
        boolean withFcl = Files.isExecutable(fcl);
        Path out = Path.of(System.getProperty("handsim.root", ".")).resolve("build/bench");
        Files.createDirectories(out);
        List<Bench.Op> ops = new ArrayList<>();
        List<String> files = new ArrayList<>(), labels = new ArrayList<>();
        List<Double> ours = new ArrayList<>();
        for (String[] row : rows) {
            for (int c = 1; c <= 2; c++) {
                if (!meshes.containsKey(row[c])) meshes.put(row[c], TessellationWalk.mesh(new VrmlLoader().load(dir.resolve(row[c])).getSceneGroup()));
            }
            TriangleMesh a = meshes.get(row[1]), b = meshes.get(row[2]);
            double[] p = CollisionBench.parsePose(row[3]);
            double[] pose = RigidTransform.fromPose(p[0], p[1], p[2], p[3], p[4], p[5]).toArray();
            KdopTree ta = KdopTree.build(a, 18), tb = KdopTree.build(b, 18);
            DistanceQuery q = new DistanceQuery();
            ours.add(q.distance(ta, tb, pose, 0));
            ops.add(() -> q.distance(ta, tb, pose, 0));
            labels.add(row[0] + " " + a.triangleCount() + "x" + b.triangleCount());
            if (withFcl) {
                Path f = out.resolve("fcldist-" + files.size() + ".txt");
                StringBuilder sb = new StringBuilder().append(a.vertexCount()).append(' ').append(a.triangleCount()).append(' ')
                    .append(b.vertexCount()).append(' ').append(b.triangleCount()).append('\n');
                append(sb, a);
                append(sb, b);
                for (double x : pose) sb.append(x).append(' ');
                Files.writeString(f, sb.append('\n'));
                files.add(f.toString());
            }
        }
        int n = ops.size();
        double[] best = new double[n], fclBest = new double[n], fclDist = new double[n];
        java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(fclBest, Double.POSITIVE_INFINITY);
        for (int round = 0; round < 5; round++) {
            for (int i = 0; i < n; i++) best[i] = Math.min(best[i], cpuMedianUs(ops.get(i), 150, 7, 20));
            if (withFcl) {
                List<String> cmd = new ArrayList<>(List.of(fcl.toString(), "20", "7", "150"));
                cmd.addAll(files);
                Process pr = new ProcessBuilder(cmd).redirectErrorStream(true).start();
                String[] lines = new String(pr.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).split("\n");
                if (pr.waitFor() != 0 || lines.length < n) throw new IllegalStateException("fcldistance failed: " + String.join(" / ", lines));
                for (int i = 0; i < n; i++) {
                    String[] f = lines[i].split(" ");     // fcldist FILE DISTANCE median_us=T sink=..
                    fclDist[i] = Double.parseDouble(f[2]);
                    fclBest[i] = Math.min(fclBest[i], Double.parseDouble(f[3].substring("median_us=".length())));
                }
            }
        }
        String source = withFcl ? "Thread CPU time (the machine is shared: wall time counts other processes' turns); FCL measured in this run,"
            + " alternately with ours (build/fcl/fcldistance: "
            + Files.readString(fcl.resolveSibling("fclbench.label")).strip() + ")" : "FCL not built (tools/fcl/build): ours alone";
        StringBuilder t = new StringBuilder(source + "\n\n| pair | distance (ours) | distance (FCL) | ours, k = 18 | FCL, OBBRSS | ours / FCL |\n|---|---:|---:|---:|---:|---:|\n");
        for (int i = 0; i < n; i++) {
            t.append(String.format(Locale.ROOT, "| %s | %.12f | %s | %.2f µs | %s | %s |%n", labels.get(i), ours.get(i),
                withFcl ? String.format(Locale.ROOT, "%.12f", fclDist[i]) : "–", best[i],
                withFcl ? String.format(Locale.ROOT, "%.2f µs", fclBest[i]) : "–",
                withFcl ? String.format(Locale.ROOT, "%.2f", best[i] / fclBest[i]) : "–"));
        }
        System.out.println("\n### Mesh distance against FCL's distance query (quietest of 5 interleaved medians)\n\n" + t);
    }

    /**
     * The median over {@code samples} batches of this thread's CPU time per call (µs), after
     * {@code warmMs} of CPU time warming up; batches of about {@code sampleMs}: as fcldistance
     * measures FCL.
     */
    static double cpuMedianUs(Bench.Op op, long warmMs, int samples, long sampleMs) {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        long t0 = mx.getCurrentThreadCpuTime();
        long calls = 0;
        double acc = 0;
        while (mx.getCurrentThreadCpuTime() - t0 < warmMs * 1_000_000L || calls < 2) { acc += op.run(); calls++; }
        double per = (mx.getCurrentThreadCpuTime() - t0) / (double) calls;
        long batch = Math.max(1, (long) (sampleMs * 1e6 / Math.max(per, 1)));
        double[] us = new double[samples];
        for (int s = 0; s < samples; s++) {
            long a = mx.getCurrentThreadCpuTime();
            for (long i = 0; i < batch; i++) acc += op.run();
            us[s] = (mx.getCurrentThreadCpuTime() - a) / 1e3 / batch;
        }
        Bench.sink += acc;
        java.util.Arrays.sort(us);
        return us[samples / 2];
    }

    private static void append(StringBuilder sb, TriangleMesh m) {
        double[] v = m.vertices();
        for (int i = 0; i < v.length; i += 3) sb.append(v[i]).append(' ').append(v[i + 1]).append(' ').append(v[i + 2]).append('\n');
        int[] t = m.triangles();
        for (int i = 0; i < t.length; i += 3) sb.append(t[i]).append(' ').append(t[i + 1]).append(' ').append(t[i + 2]).append('\n');
    }
}
