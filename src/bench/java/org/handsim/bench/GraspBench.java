package org.handsim.bench;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.handsim.grasp.FrictionCone;
import org.handsim.grasp.GraspQuality;
import org.handsim.grasp.GraspWrenches;
import org.handsim.grasp.WrenchSpace;

/**
 * Suite "grasp": the grasp wrench space's quality for 3, 6 and 12 contacts × 8 cone edges
 * (μ = 0.5), the whole hull ({@link WrenchSpace#quality}: hull, ε, volume, facets) and ε with
 * force closure alone ({@link WrenchSpace#epsilon}), side by side with qhull through SciPy on
 * the SAME wrenches in the same run. Contacts: fingertip-like contacts on a mug-sized cylinder
 * (radius 40 mm, height 100 mm; c its centre, R its centre-to-rim distance), spread round it
 * at roughly even azimuths with random heights and normals tilted by ~0.2 rad, 8 seeded sets
 * per size in force closure, cycled. The wrenches go to {@code build/bench/grasp-NxM.csv}; then
 * {@code tools/grasp/qhull_bench.py} times qhull on them (options QJ, the anchor and
 * GraspIt!'s, and Qt Qx, the reference tests') if a python3 with scipy is found
 * ({@code HANDSIM_PYTHON}, {@code ~/.cache/handsim-py/bin/python}, or {@code python3}); else the
 * command is printed. Anchor: qhull 1.6 / 8 / 31 ms; goals: whole quality ≤ qhull,
 * ε and force closure ≤ qhull / 20. Noise on shared cores: {@link #ROUNDS} rounds alternate our
 * measurements and qhull's; each figure is its best round's median, and the load average is printed.
 * Set 0 of each size is also written as contacts ({@code build/bench/grasp-NxM-set0.csv}, the
 * input of {@code handsim quality}) and timed alone, so {@code tools/quality-vs-bench} can set the
 * command's {@code time_us_median} beside the bench's figure (honest timings).
 */
final class GraspBench implements BenchMain.Suite {
    static final int[] CONTACTS = {3, 6, 12};
    static final int EDGES = FrictionCone.DEFAULT_EDGES, SETS = 8;
    static final double MU = FrictionCone.DEFAULT_MU, RADIUS = 0.04, HALF_HEIGHT = 0.05;

    /** Rounds of (ours, then qhull's) measurements; each figure is the best round's median. */
    static final int ROUNDS = 3;

    @Override
    public void run() throws Exception {
        Path root = Path.of(System.getProperty("handsim.root", "."));
        Path dir = root.resolve("build/bench");
        Files.createDirectories(dir);
        List<String> files = new ArrayList<>();
        Map<Integer, double[][]> setsBySize = new LinkedHashMap<>();
        for (int n : CONTACTS) {
            double[][] contacts = new double[SETS][];
            double[][] sets = sets(n, new Random(1000 + n), contacts);
            setsBySize.put(n, sets);
            StringBuilder cs = new StringBuilder("x,y,z,nx,ny,nz\n");
            for (int i = 0; i < n; i++) {
                for (int c = 0; c < 6; c++) {
                    cs.append(c == 0 ? "" : ",").append(c < 3 ? contacts[0][3 * i + c] : contacts[0][3 * n + 3 * i + c - 3]);
                }
                cs.append('\n');
            }
            Files.writeString(dir.resolve("grasp-" + n + "x" + EDGES + "-set0.csv"), cs.toString());
            for (double[] w : sets) {
                GraspQuality q = WrenchSpace.quality(w, n * EDGES, n), e = WrenchSpace.epsilon(w, n * EDGES, n);
                if (q.forceClosure() != e.forceClosure() || Math.abs(q.epsilon() - e.epsilon()) > 1e-12 * Math.max(1, q.epsilon())) {
                    throw new IllegalStateException("epsilon paths disagree: " + q + " vs " + e);
                }
            }
            Path file = dir.resolve("grasp-" + n + "x" + EDGES + ".csv");
            StringBuilder sb = new StringBuilder("set,fx,fy,fz,tx,ty,tz\n");
            for (int s = 0; s < SETS; s++) {
                for (int j = 0; j < n * EDGES; j++) {
                    sb.append(s);
                    for (int c = 0; c < 6; c++) sb.append(',').append(sets[s][6 * j + c]);
                    sb.append('\n');
                }
            }
            Files.writeString(file, sb.toString());
            files.add(file.toString());
        }
        String python = python();
        List<String> cmd = new ArrayList<>(List.of(python == null ? "python3" : python, root.resolve("tools/grasp/qhull_bench.py").toString()));
        cmd.addAll(files);
        if (python == null) System.out.println("no python3 with scipy found: time qhull on the same wrenches with\n  " + String.join(" ", cmd));
        Map<Integer, Double> whole = new LinkedHashMap<>(), eps = new LinkedHashMap<>(), set0 = new LinkedHashMap<>();
        Map<String, Double> qj = new LinkedHashMap<>(), qx = new LinkedHashMap<>();
        int checked = 0;
        for (int round = 1; round <= ROUNDS; round++) {
            System.out.println("round " + round + " of " + ROUNDS + " (load average " + loadAverage() + ")");
            for (int n : CONTACTS) {
                double[][] sets = setsBySize.get(n);
                int[] k = {0};
                best(whole, n, Bench.measure(String.format(Locale.ROOT, "whole quality (hull, eps, volume, facets), %d x %d", n, EDGES), () -> {
                    double[] w = sets[k[0]++ % SETS];
                    GraspQuality q = WrenchSpace.quality(w, n * EDGES, n);
                    return q.volume() + q.facets();
                }, 1000, 11, 50).medianMs());
                best(set0, n, Bench.measure(String.format(Locale.ROOT, "whole quality, set 0 alone, %d x %d", n, EDGES), () -> {
                    GraspQuality q = WrenchSpace.quality(sets[0], n * EDGES, n);
                    return q.volume() + q.facets();
                }, 1000, 11, 50).medianMs());
                best(eps, n, Bench.measure(String.format(Locale.ROOT, "eps + force closure only, %d x %d", n, EDGES), () -> {
                    double[] w = sets[k[0]++ % SETS];
                    return WrenchSpace.epsilon(w, n * EDGES, n).epsilon();
                }, 1000, 11, 50).medianMs());
            }
            if (python == null) continue;
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) {
                    String[] f = line.split(" ");
                    if (f.length == 5 && f[0].equals("check")) {       // qhull's epsilon and volume of one set
                        int n = CONTACTS[files.indexOf(f[1])];
                        GraspQuality q = WrenchSpace.quality(setsBySize.get(n)[Integer.parseInt(f[2])], n * EDGES, n);
                        double e = Double.parseDouble(f[3]), v = Double.parseDouble(f[4]);
                        if (Math.abs(q.epsilon() - e) > 1e-9 * e || Math.abs(q.volume() - v) > 1e-9 * v) {
                            throw new IllegalStateException("differs from qhull: " + line + " vs " + q);
                        }
                        checked++;
                        continue;
                    }
                    System.out.println(line);
                    if (f.length < 4 || !f[0].equals("qhull")) continue;
                    double ms = Double.parseDouble(f[3].substring("median_ms=".length()));
                    Map<String, Double> into = f[2].equals("QJ") ? qj : qx;
                    into.merge(f[1], ms, Math::min);
                }
            }
            p.waitFor();
        }
        System.out.println("\nset 0 alone, best of " + ROUNDS + " rounds (tools/quality-vs-bench runs handsim quality on build/bench/grasp-NxM-set0.csv"
            + " with --radius " + Math.sqrt(RADIUS * RADIUS + HALF_HEIGHT * HALF_HEIGHT) + "):");
        for (int n : CONTACTS) System.out.printf(Locale.ROOT, "| %d x %d | set 0 alone | %.2f us |%n", n, EDGES, set0.get(n) * 1000);
        if (python == null) return;
        System.out.println(checked + " set evaluations: epsilon and volume equal qhull's (Qt Qx) to 1e-9");
        System.out.println("\nbest of " + ROUNDS + " rounds (load average now " + loadAverage() + "):");
        System.out.println("| wrenches | qhull QJ | qhull Qt Qx | whole quality | ratio to QJ | eps + closure | ratio to QJ |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|");
        for (int i = 0; i < CONTACTS.length; i++) {
            int n = CONTACTS[i];
            Double a = qj.get(files.get(i)), b = qx.get(files.get(i));
            if (a == null || b == null) continue;
            System.out.printf(Locale.ROOT, "| %d x %d | %.3f ms | %.3f ms | %.3f ms | 1/%.1f | %.4f ms | 1/%.0f |%n", n, EDGES, a, b,
                whole.get(n), a / whole.get(n), eps.get(n), a / eps.get(n));
        }
    }

    private static void best(Map<Integer, Double> into, int n, double ms) {
        into.merge(n, ms, Math::min);
    }

    private static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (java.io.IOException e) {
            return "unknown";
        }
    }

    /**
     * SETS seeded contact sets of n contacts round the cylinder, as wrenches; only sets in force
     * closure are kept (a grasp worth rating holds; without closure the ε path stops early).
     */
    static double[][] sets(int n, Random rnd, double[][] contacts) {
        double[][] out = new double[SETS][];
        double[] c = {0, 0, 0};
        double r = Math.sqrt(RADIUS * RADIUS + HALF_HEIGHT * HALF_HEIGHT);
        for (int s = 0; s < SETS; ) {
            double[] pts = new double[3 * n], nrm = new double[3 * n];
            double phase = rnd.nextDouble() * 2 * Math.PI;
            for (int i = 0; i < n; i++) {
                double az = phase + 2 * Math.PI * i / n + 0.3 * (rnd.nextDouble() - 0.5);
                double z = HALF_HEIGHT * (2 * rnd.nextDouble() - 1) * 0.8;
                pts[3 * i] = RADIUS * Math.cos(az);
                pts[3 * i + 1] = RADIUS * Math.sin(az);
                pts[3 * i + 2] = z;
                nrm[3 * i] = -Math.cos(az) + 0.2 * rnd.nextGaussian();
                nrm[3 * i + 1] = -Math.sin(az) + 0.2 * rnd.nextGaussian();
                nrm[3 * i + 2] = 0.2 * rnd.nextGaussian();
            }
            double[] w = GraspWrenches.of(n, pts, nrm, MU, EDGES, c, r);
            if (WrenchSpace.quality(w, n * EDGES, n).forceClosure()) {
                double[] pn = new double[6 * n];
                System.arraycopy(pts, 0, pn, 0, 3 * n);
                System.arraycopy(nrm, 0, pn, 3 * n, 3 * n);
                contacts[s] = pn;
                out[s++] = w;
            }
        }
        return out;
    }

    /** A python3 that imports scipy, or null. */
    static String python() {
        List<String> candidates = new ArrayList<>();
        String env = System.getenv("HANDSIM_PYTHON");
        if (env != null) candidates.add(env);
        candidates.add(System.getProperty("user.home") + "/.cache/handsim-py/bin/python");
        candidates.add("python3");
        for (String c : candidates) {
            try {
                Process p = new ProcessBuilder(c, "-c", "import scipy.spatial").redirectErrorStream(true).start();
                p.getInputStream().readAllBytes();
                if (p.waitFor() == 0) return c;
            } catch (java.io.IOException | InterruptedException e) {
                // not there: try the next
            }
        }
        return null;
    }
}
