package org.handsim.tradeoff;

import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.function.DoubleConsumer;
import org.handsim.chart.StudyTable;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.contact.ContactPatches;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.Scenario;
import org.handsim.model.SceneGeometry;
import org.handsim.scenario.SceneMeshes;
import org.handsim.vrml.VrmlLoader;

/**
 * Chart 2: the object's tessellation resolution. Three VRML97 objects, written as text and
 * loaded as every scenario object is ({@link VrmlLoader} with {@code divisions}, normals off,
 * then {@link TessellationWalk}, merged): a {@code Sphere} (radius 0.04 m, as
 * vrml/objects/sphere.wrl), a {@code Cylinder} (radius 0.03 m, height 0.12 m, as
 * vrml/objects/cylinder.wrl) at divisions 6 … 128, and a cube of edge 0.06 m (the paper's)
 * written as an {@code IndexedFaceSet} of n × n squares per face (the loader's {@code Box}
 * ignores divisions) at n = 1 … 32.
 *
 * <p>Each is pressed into a large flat plate (the top face z = 0 of a 0.4 × 0.4 × 0.02 m box,
 * mesh A, as a link is in {@link SceneGeometry}) to a seeded-random depth of 5–15 % of its radius
 * (half the edge for the cube), in {@value #POSES} seeded-random poses, and the real contact pipeline runs:
 * k-DOP trees (k = {@value SceneGeometry#DEFAULT_K}), {@link TreeQuery}, {@link ContactPatches}
 * → one point contact. The analytic contact of the ideal shape with the plane z = 0 is known:
 * <ul>
 *   <li>sphere, centre c, any orientation: the circle of contact is centred at (cx, cy, 0);</li>
 *   <li>cylinder with its axis parallel to the plate (random direction in the plate, random roll
 *       about the axis): the contact loop is a rectangle (two lines along the axis joined by two
 *       chords on the caps) centred at the projection of the cylinder's centre;</li>
 *   <li>cube face-down (random turn about the plate normal): a square centred at the projection
 *       of the cube's centre;</li>
 * </ul>
 * and in every case the contact normal (out of the object) is −z. The patch centre is the centre
 * of the loop's bounding box (DESIGN.md decision 3), which for these symmetric loops is their
 * centre. Measured per shape and divisions: the worst and mean centre error (m, and relative to
 * the radius — half the edge for the cube), the worst and mean normal error (rad), and the
 * time of one query (tree query plus patches, as {@link SceneGeometry#collide} runs it: the
 * quietest of {@value #ROUNDS} medians).
 * A pose where the coarse polyhedron does not reach the plate (or gives other than one patch)
 * counts as missed; a setting with misses is not plotted.
 *
 * <p>Chart: series per shape × {centre, normal}; x the query time, y the worst error over the
 * poses — centre error divided by the radius, normal error in radians (both dimensionless).
 * The relative centre error is what {@link Resolution} reads (from this study's CSV, committed
 * as {@code tessellation-error.csv}) to turn a tolerance into divisions.
 */
public final class TessellationStudy implements Study {
    /** Seeded-random poses per shape (the same poses at every divisions). */
    static final int POSES = 32;
    /** Depth of the ideal shape in the plate, relative to its radius: seeded-random in [min, max]. */
    static final double DEPTH_MIN = 0.05, DEPTH_MAX = 0.15;
    /** Timing rounds, round-robin over every setting; the quietest median of each is kept (the machine is shared). */
    static final int ROUNDS = 5;
    /** Errors below this (relative) are round-off: the "error" column stores 0 (exact). */
    static final double ROUND_OFF = 1e-12;

    static final int[] ROUND = {6, 8, 12, 16, 24, 32, 48, 64, 96, 128};
    static final int[] QUICK_ROUND = {12, 16, 24, 48};
    static final int[] CUBE = {1, 2, 4, 8, 16, 32};
    static final int[] QUICK_CUBE = {1, 4};

    static final List<String> COLUMNS = List.of("divisions", "triangles", "query_s", "poses", "missed", "radius_m",
        "centre_error_m", "centre_error_rel", "centre_error_rel_mean", "normal_error_rad", "normal_error_rad_mean", "error");

    /** One test object: its name, size, VRML text at a resolution, default resolution and pose rule. */
    enum Shape {
        SPHERE("sphere", 0.04, Scenario.DEFAULT_DIVISIONS, 11),
        CYLINDER("cylinder", 0.03, Scenario.DEFAULT_DIVISIONS, 12),
        CUBE("cube", 0.03, 1, 13);

        final String label;
        /** Radius (half the edge for the cube), m. */
        final double radius;
        final int defaultDivisions;
        final long seed;

        Shape(String label, double radius, int defaultDivisions, long seed) {
            this.label = label;
            this.radius = radius;
            this.defaultDivisions = defaultDivisions;
            this.seed = seed;
        }

        /** The VRML97 text of the object (for the cube: the n × n grid of each face). */
        String vrml(int divisions) {
            switch (this) {
                case SPHERE: return "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.04 } }\n";
                case CYLINDER: return "#VRML V2.0 utf8\nShape { geometry Cylinder { radius 0.03 height 0.12 } }\n";
                default: return cubeVrml(2 * radius, divisions);
            }
        }

        /** The object's mesh at a resolution, through the scenario objects' loading path. */
        TriangleMesh mesh(int divisions) {
            // the cube's grid is in its text; the loader's divisions (curved primitives only) stay at the default
            return TessellationStudy.mesh(label + "-" + divisions, vrml(divisions), this == CUBE ? Scenario.DEFAULT_DIVISIONS : divisions);
        }

        /**
         * The seeded poses: object frame → plate frame, the ideal shape {@link #DEPTH_MIN} to
         * {@link #DEPTH_MAX} × radius deep in the plate, and the analytic contact centre in the plate frame (normal −z).
         */
        List<double[]> poses() {
            SplittableRandom r = new SplittableRandom(seed);
            List<double[]> out = new ArrayList<>();
            for (int i = 0; i < POSES; i++) {
                double h = radius * (DEPTH_MIN + (DEPTH_MAX - DEPTH_MIN) * r.nextDouble());
                double x0 = 0.01 * (r.nextDouble() - 0.5), y0 = 0.01 * (r.nextDouble() - 0.5);
                RigidTransform rot;
                switch (this) {
                    case SPHERE: {
                        double ax = r.nextGaussian(), ay = r.nextGaussian(), az = r.nextGaussian();
                        double l = Math.sqrt(ax * ax + ay * ay + az * az), a = Math.PI * r.nextDouble() / l;
                        rot = RigidTransform.fromPose(0, 0, 0, a * ax, a * ay, a * az);
                        break;
                    }
                    case CYLINDER: {
                        // roll psi about the axis (VRML y), axis → plate x, then turn phi about z
                        double phi = 2 * Math.PI * r.nextDouble(), psi = 2 * Math.PI * r.nextDouble();
                        rot = RigidTransform.rotZ(phi).compose(RigidTransform.rotZ(-Math.PI / 2))
                            .compose(RigidTransform.fromPose(0, 0, 0, 0, psi, 0));
                        break;
                    }
                    default:
                        rot = RigidTransform.rotZ(2 * Math.PI * r.nextDouble());
                }
                RigidTransform pose = RigidTransform.translation(x0, y0, radius - h).compose(rot);
                double[] p = new double[15];
                pose.copyTo(p, 0);
                p[12] = x0;
                p[13] = y0;
                p[14] = 0;
                out.add(p);
            }
            return out;
        }
    }

    /** Loads VRML text as {@link SceneMeshes#mesh} loads a scenario's object file. */
    static TriangleMesh mesh(String name, String vrml, int divisions) {
        return SceneMeshes.mesh(name, new StringReader(vrml), divisions, 1.0);
    }

    /** A cube of edge {@code edge} centred at the origin, each face an n × n grid of squares, as an IndexedFaceSet. */
    static String cubeVrml(double edge, int n) {
        double h = edge / 2, a = edge;
        double[][][] faces = {  // origin, u, v with u × v outward
            {{h, -h, -h}, {0, a, 0}, {0, 0, a}}, {{-h, -h, -h}, {0, 0, a}, {0, a, 0}},
            {{-h, h, -h}, {0, 0, a}, {a, 0, 0}}, {{-h, -h, -h}, {a, 0, 0}, {0, 0, a}},
            {{-h, -h, h}, {a, 0, 0}, {0, a, 0}}, {{-h, -h, -h}, {0, a, 0}, {a, 0, 0}}};
        StringBuilder pts = new StringBuilder(), idx = new StringBuilder();
        int base = 0;
        for (double[][] f : faces) {
            for (int j = 0; j <= n; j++) {
                for (int i = 0; i <= n; i++) {
                    double s = (double) i / n, t = (double) j / n;
                    for (int c = 0; c < 3; c++) {
                        double x = f[0][c] + s * f[1][c] + t * f[2][c];
                        if (Math.abs(x) < 1e-15) x = 0;
                        pts.append(String.format(Locale.ROOT, "%.9g", x)).append(c < 2 ? " " : ",\n");
                    }
                }
            }
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    int p = base + j * (n + 1) + i;
                    idx.append(p).append(' ').append(p + 1).append(' ').append(p + n + 2).append(' ').append(p + n + 1).append(" -1,\n");
                }
            }
            base += (n + 1) * (n + 1);
        }
        return "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { solid TRUE ccw TRUE convex TRUE\n  coord Coordinate { point [\n"
            + pts + "] }\n  coordIndex [\n" + idx + "] } }\n";
    }

    /** The probe: a 0.4 × 0.4 × 0.02 m box whose top face is z = 0 (12 triangles). */
    static TriangleMesh plate() {
        double a = 0.2, b = -0.02;
        double[] v = {-a, -a, b, a, -a, b, a, a, b, -a, a, b, -a, -a, 0, a, -a, 0, a, a, 0, -a, a, 0};
        int[] t = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
        return new TriangleMesh("plate", v, t);
    }

    /** What one shape at one resolution gives over the poses. */
    record Measure(int triangles, int missed, double centreWorst, double centreMean, double normalWorst, double normalMean,
                   double querySeconds) {}

    private final TriangleMesh plate = plate();
    private final KdopTree plateTree = KdopTree.build(plate, SceneGeometry.DEFAULT_K);

    /** One shape at one resolution ready to query: its mesh, tree and the placed poses. */
    final class Probe {
        final TriangleMesh mesh;
        final KdopTree tree;
        final List<double[]> poses;
        final List<RigidTransform> placed = new ArrayList<>();
        private final TreeQuery q = new TreeQuery();
        private final CollisionResult res = new CollisionResult();
        // the object's own normals: against the flat plate the simulator's default
        // (LEAST_SPREAD) takes the plate's, which is exact and says nothing of the tessellation
        private final ContactPatches cp = new ContactPatches().normalSide(ContactPatches.NormalSide.OBJECT);

        Probe(Shape shape, int divisions) {
            mesh = shape.mesh(divisions);
            tree = KdopTree.build(mesh, SceneGeometry.DEFAULT_K);
            poses = shape.poses();
            for (double[] p : poses) placed.add(RigidTransform.of(java.util.Arrays.copyOf(p, 12)));
        }

        /** The errors over the poses (querySeconds NaN). */
        Measure errors() {
            double[] c = new double[3], n = new double[3];
            int missed = 0, found = 0;
            double cw = 0, cs = 0, nw = 0, ns = 0;
            for (int i = 0; i < poses.size(); i++) {
                q.collide(plateTree, tree, placed.get(i), res);
                int np = cp.build(res, plate, mesh, placed.get(i));
                if (np != 1) {
                    missed++;
                    continue;
                }
                cp.center(0, c);
                cp.normal(0, n);
                double[] want = poses.get(i);
                double dc = Math.sqrt(sq(c[0] - want[12]) + sq(c[1] - want[13]) + sq(c[2] - want[14]));
                double dn = Math.atan2(Math.sqrt(n[0] * n[0] + n[1] * n[1]), -n[2]);  // angle to (0, 0, -1)
                cw = Math.max(cw, dc);
                cs += dc;
                nw = Math.max(nw, dn);
                ns += dn;
                found++;
            }
            return new Measure(mesh.triangleCount(), missed, cw, found > 0 ? cs / found : Double.NaN, nw,
                found > 0 ? ns / found : Double.NaN, Double.NaN);
        }

        /** All poses once, as {@link SceneGeometry#collide} runs a query: tree query, then patches. */
        int runAll() {
            int pairs = 0;
            for (RigidTransform p : placed) {
                q.collide(plateTree, tree, p, res);
                pairs += cp.build(res, plate, mesh, p) + res.pairCount();
            }
            return pairs;
        }

        /** Median seconds of one query (over timed runs of all poses). */
        double seconds(boolean quick) {
            return Timing.median(this::runAll, quick ? 1 : 5, quick ? 3 : 41, quick ? 0.01 : 0.04).medianSeconds() / placed.size();
        }
    }

    /**
     * Runs the poses of one shape at one resolution.
     *
     * @param timed whether to time the queries (the quietest of {@value #ROUNDS} medians, one after the other)
     */
    Measure measure(Shape shape, int divisions, boolean timed, boolean quick) {
        Probe p = new Probe(shape, divisions);
        Measure m = p.errors();
        double secs = Double.POSITIVE_INFINITY;
        for (int round = 0; timed && round < (quick ? 1 : ROUNDS); round++) secs = Math.min(secs, p.seconds(quick));
        return timed ? withSeconds(m, secs) : m;
    }

    private static Measure withSeconds(Measure m, double secs) {
        return new Measure(m.triangles(), m.missed(), m.centreWorst(), m.centreMean(), m.normalWorst(), m.normalMean(), secs);
    }

    private static double sq(double x) { return x * x; }

    @Override
    public String id() {
        return "2-tessellation";
    }

    @Override
    public StudyTable run(boolean quick, DoubleConsumer progress) {
        StudyTable t = new StudyTable(id(), "Object tessellation: contact error against the analytic contact, versus query time", COLUMNS,
            "query_s", "error", "time of one contact query: k-DOP tree query + patches (s, log)",
            "worst error over " + POSES + " poses: centre / radius, normal in rad (log)");
        t.note("probe", String.format(Locale.ROOT,
            "sphere r = 40 mm, cylinder r = 30 mm x 120 mm (setting: divisions), cube 60 mm (setting: n x n squares per face), each %.0f-%.0f %% of its radius deep in a flat plate, %d seeded poses; default: divisions %d (scenario default), cube 1 (vrml/objects/cube.wrl)",
            100 * DEPTH_MIN, 100 * DEPTH_MAX, POSES, Shape.SPHERE.defaultDivisions));
        t.note("series", "series: <shape> centre = worst contact-centre error / radius, <shape> normal = worst normal error (rad), same poses at every setting");
        t.note("cube", "cube: face contacts are exact at every subdivision (errors are round-off, drawn at the axis floor): subdividing only costs time");
        int total = 0, done = 0;
        for (Shape s : Shape.values()) total += divisions(s, quick).length;
        List<String> missedNotes = new ArrayList<>();
        List<Shape> shapes = new ArrayList<>();
        List<Integer> divs = new ArrayList<>();
        List<Probe> probes = new ArrayList<>();
        List<Measure> measures = new ArrayList<>();
        for (Shape s : Shape.values()) {
            for (int d : divisions(s, quick)) {
                Probe p = new Probe(s, d);
                shapes.add(s);
                divs.add(d);
                probes.add(p);
                measures.add(p.errors());
                if (progress != null) progress.accept(0.2 * ++done / total);
            }
        }
        // warm the JIT on the query before anything is timed (the first setting would pay for it), then
        // time round-robin: a burst of load from other processes hits every setting alike; the quietest median is kept
        long warm = System.nanoTime();
        while ((System.nanoTime() - warm) / 1e9 < (quick ? 0.05 : 0.5)) probes.get(probes.size() / 3).runAll();
        double[] secs = new double[probes.size()];
        java.util.Arrays.fill(secs, Double.POSITIVE_INFINITY);
        int rounds = quick ? 1 : ROUNDS;
        for (int round = 0; round < rounds; round++) {
            for (int i = 0; i < probes.size(); i++) {
                secs[i] = Math.min(secs[i], probes.get(i).seconds(quick));
                if (progress != null) progress.accept(0.2 + 0.8 * (round * probes.size() + i + 1) / (rounds * probes.size()));
            }
        }
        for (int i = 0; i < probes.size(); i++) {
            Shape s = shapes.get(i);
            int d = divs.get(i);
            Measure m = withSeconds(measures.get(i), secs[i]);
            boolean def = d == s.defaultDivisions;
            double crel = m.centreWorst() / s.radius, crelMean = m.centreMean() / s.radius;
            double[] common = {d, m.triangles(), m.querySeconds(), POSES, m.missed(), s.radius, m.centreWorst(), crel, crelMean,
                m.normalWorst(), m.normalMean()};
            double yc = m.missed() > 0 ? Double.NaN : crel < ROUND_OFF ? 0 : crel;
            double yn = m.missed() > 0 ? Double.NaN : m.normalWorst() < ROUND_OFF ? 0 : m.normalWorst();
            t.add(s.label + " centre", String.valueOf(d), def, with(common, yc));
            t.add(s.label + " normal", String.valueOf(d), def, with(common, yn));
            if (m.missed() > 0) missedNotes.add(s.label + " " + d + ": " + m.missed() + "/" + POSES);
        }
        if (!missedNotes.isEmpty()) {
            t.note("missed", "not plotted (the coarse polyhedron missed the plate in some poses): " + String.join(", ", missedNotes));
        }
        return t;
    }

    static int[] divisions(Shape s, boolean quick) {
        if (s == Shape.CUBE) return quick ? QUICK_CUBE : CUBE;
        return quick ? QUICK_ROUND : ROUND;
    }

    private static double[] with(double[] common, double y) {
        double[] v = java.util.Arrays.copyOf(common, common.length + 1);
        v[common.length] = y;
        return v;
    }
}
