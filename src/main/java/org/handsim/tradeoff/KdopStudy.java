package org.handsim.tradeoff;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import java.util.stream.Stream;
import org.handsim.chart.StudyTable;
import org.handsim.collision.BruteForce;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.Kdop;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.contact.ContactPatches;
import org.handsim.hand.HandDescription;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.HandModel;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.model.SceneGeometry;
import org.handsim.model.Simulation;
import org.handsim.scenario.SceneMeshes;

/**
 * Chart 3: k of the k-DOPs (6, 14, 18, 26) and the all-pairs loop ({@link BruteForce}) on the
 * hand grasping each model of {@code vrml/objects/}. The grasp: the object (scenario default
 * divisions, scale 1) stands centred on the palm's axis, its lowest point {@value #CLEARANCE_M}
 * m above the finger bases' plane, and the simulator closes all three fingers together (no
 * spread, no gravity, trapezoids to 17 500 counts) until each stalls on it (inner links held
 * by the clutch, outer links wrapped on after the breakaway), exactly as {@code handsim run}
 * would (k = {@value SceneGeometry#DEFAULT_K}); the final pose is kept. On that pose the nine
 * link–object queries (link in its DH frame as mesh A, object mapped into it, as
 * {@link SceneGeometry#collide} does) run at every k and with the all-pairs loop: x is the
 * wall time of all nine (the tree queries only: k changes nothing after them; the quietest of
 * {@value #ROUNDS} medians taken round-robin over the settings, as the machine is shared), y the
 * number of triangle–triangle tests. Every k and the loop return the same intersecting pairs
 * and segments (k changes only the speed); the table keeps pairs, segments and contacts to show
 * it.
 */
public final class KdopStudy implements Study {
    /** Gap between the object's lowest point and the plane of the finger bases, m. */
    static final double CLEARANCE_M = 0.005;
    /** Timing rounds (round-robin over the settings; the quietest median of each is kept). */
    static final int ROUNDS = 5;
    /** The all-pairs setting's k in the table. */
    static final int BRUTE = 0;

    static final List<String> COLUMNS = List.of("k", "query_s", "triangle_tests", "node_tests", "pairs", "segments", "contacts",
        "links_touching", "object_triangles");

    @Override
    public String id() {
        return "3-kdop";
    }

    /** The models of vrml/objects, sorted by name. */
    static List<Path> objects() {
        try (Stream<Path> s = Files.list(Home.dir().resolve("vrml").resolve("objects"))) {
            List<Path> out = new ArrayList<>();
            s.filter(p -> p.getFileName().toString().endsWith(".wrl")).sorted().forEach(out::add);
            return out;
        } catch (IOException e) {
            throw new IllegalStateException("cannot list vrml/objects: " + e, e);
        }
    }

    /** The hand closed on an object: its meshes and the nine link ← object poses (finger-major, link 1..3). */
    record Grasp(String name, TriangleMesh object, TriangleMesh[] links, RigidTransform[] linkFromObject, Scenario scenario) {}

    /** The grasp scenario of an object (see the class comment). */
    static Scenario graspScenario(Path object) {
        TriangleMesh m = SceneMeshes.mesh(object, Scenario.DEFAULT_DIVISIONS, 1.0);
        double[][] b = m.bounds();
        double cx = 0.5 * (b[0][0] + b[1][0]), cy = 0.5 * (b[0][1] + b[1][1]);
        // the finger bases stand Dw above the palm frame
        double z = HandDescription.barrettHand().palmDw() + CLEARANCE_M - b[0][2];
        String name = object.getFileName().toString().replace(".wrl", "");
        String close = "[{\"type\": \"trapezoid\", \"to\": 17500, \"v_max\": 8000, \"a_max\": 40000}]";
        String json = String.format(Locale.ROOT, "{\"name\": \"grasp-%s\", \"description\": \"all fingers close on %s (chart 3-kdop)\","
                + " \"gravity_m_s2\": [0, 0, 0], \"object\": {\"file\": \"%s\", \"position_m\": [%.9f, %.9f, %.9f]},"
                + " \"motors\": {\"M1\": %s, \"M2\": %s, \"M3\": %s}, \"dt_s\": 0.001,"
                + " \"outputs\": {\"trace\": false, \"charts\": false, \"torques\": true}}",
            name, object.getFileName(), object.toAbsolutePath().toString().replace("\\", "/"), -cx, -cy, z, close, close, close);
        return Scenario.parse(Home.scenarios().resolve("grasp-" + name + ".json"), json);
    }

    /** Runs the grasp scenario of an object and returns the final pose. */
    static Grasp grasp(Path object) {
        Scenario s = graspScenario(object);
        HandModel model = Simulation.model(s, false);
        model.run(null);
        TriangleMesh om = SceneMeshes.mesh(s.object().file(), s.object().divisions(), s.object().meshScale());
        TriangleMesh[] links = new TriangleMesh[9];
        RigidTransform[] poses = new RigidTransform[9];
        RigidTransform worldFromObject = s.object().worldFromObject();
        for (int k = 1; k <= 3; k++) {
            double[] frames = model.framesWorld(k);
            for (int j = 1; j <= 3; j++) {
                RigidTransform worldFromLink = RigidTransform.of(java.util.Arrays.copyOfRange(frames, 12 * j, 12 * j + 12));
                links[3 * (k - 1) + j - 1] = SceneMeshes.mesh(SceneMeshes.linkFile(j), SceneMeshes.LINK_DIVISIONS, 1.0);
                poses[3 * (k - 1) + j - 1] = worldFromLink.inverse().compose(worldFromObject);
            }
        }
        return new Grasp(s.name().replace("grasp-", ""), om, links, poses, s);
    }

    /** The nine queries of a grasp at one k ({@link #BRUTE} = the all-pairs loop), counters summed. */
    static final class HandQuery {
        final Grasp g;
        final int k;
        private final KdopTree objectTree;
        private final KdopTree[] linkTrees = new KdopTree[9];
        private final TreeQuery query = new TreeQuery();
        private final BruteForce brute = new BruteForce();
        final CollisionResult[] results = new CollisionResult[9];

        HandQuery(Grasp g, int k) {
            this.g = g;
            this.k = k;
            objectTree = k == BRUTE ? null : KdopTree.build(g.object(), k);
            KdopTree[] perLink = new KdopTree[3];
            for (int i = 0; i < 9; i++) {
                results[i] = new CollisionResult();
                if (k != BRUTE) {
                    int j = i % 3;
                    if (perLink[j] == null) perLink[j] = KdopTree.build(g.links()[i], k);
                    linkTrees[i] = perLink[j];
                }
            }
        }

        /** Runs the nine queries; returns the number of intersecting pairs. */
        int run() {
            int pairs = 0;
            for (int i = 0; i < 9; i++) {
                if (k == BRUTE) brute.collide(g.links()[i], g.object(), g.linkFromObject()[i], results[i]);
                else query.collide(linkTrees[i], objectTree, g.linkFromObject()[i], results[i]);
                pairs += results[i].pairCount();
            }
            return pairs;
        }

        long triangleTests() {
            long n = 0;
            for (CollisionResult r : results) n += r.triangleTests;
            return n;
        }

        long nodeTests() {
            long n = 0;
            for (CollisionResult r : results) n += r.nodeTests;
            return n;
        }

        int pairs() {
            int n = 0;
            for (CollisionResult r : results) n += r.pairCount();
            return n;
        }

        int segments() {
            int n = 0;
            for (CollisionResult r : results) n += r.segmentCount();
            return n;
        }

        int linksTouching() {
            int n = 0;
            for (CollisionResult r : results) if (r.intersecting()) n++;
            return n;
        }

        /** Point contacts of the nine results (patches, as {@link SceneGeometry} builds them). */
        int contacts() {
            ContactPatches cp = new ContactPatches();
            int n = 0;
            for (int i = 0; i < 9; i++) {
                if (results[i].intersecting()) n += cp.build(results[i], g.links()[i], g.object(), g.linkFromObject()[i]);
            }
            return n;
        }
    }

    static int[] settings() {
        int[] s = java.util.Arrays.copyOf(Kdop.SUPPORTED_K, Kdop.SUPPORTED_K.length + 1);
        s[s.length - 1] = BRUTE;
        return s;
    }

    @Override
    public StudyTable run(boolean quick, DoubleConsumer progress) {
        StudyTable t = new StudyTable(id(), "k-DOP k and brute force: the hand grasping each vrml/objects model", COLUMNS,
            "query_s", "triangle_tests", "wall time of the nine link-object queries (s, log)", "triangle-triangle tests (log)")
            .labelEveryPoint(false);
        List<Path> files = objects();
        if (quick) files = files.subList(0, Math.min(3, files.size()));
        int[] settings = settings();
        List<String> touching = new ArrayList<>();
        long linkTriangles = 0;
        // warm the JIT on the tree query and the all-pairs loop before anything is timed
        Grasp first = grasp(files.get(0));
        long warm = System.nanoTime();
        while ((System.nanoTime() - warm) / 1e9 < (quick ? 0.05 : 0.5)) {
            for (int s : settings) new HandQuery(first, s).run();
        }
        for (int o = 0; o < files.size(); o++) {
            Grasp g = grasp(files.get(o));
            linkTriangles = 0;
            for (TriangleMesh l : g.links()) linkTriangles += l.triangleCount();
            HandQuery[] qs = new HandQuery[settings.length];
            double[] best = new double[settings.length];
            java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
            for (int i = 0; i < settings.length; i++) {
                qs[i] = new HandQuery(g, settings[i]);
                qs[i].run();
            }
            // round-robin: a burst of load from other processes hits every setting alike; the quietest median is kept
            for (int round = 0; round < (quick ? 1 : ROUNDS); round++) {
                for (int i = 0; i < settings.length; i++) {
                    boolean brute = settings[i] == BRUTE;
                    double m = Timing.median(qs[i]::run, brute ? 1 : quick ? 1 : 5, brute ? 1 : quick ? 5 : 2001,
                        brute ? 0 : quick ? 0.02 : 0.05).medianSeconds();
                    best[i] = Math.min(best[i], m);
                }
            }
            for (int i = 0; i < settings.length; i++) {
                int s = settings[i];
                HandQuery q = qs[i];
                t.add(g.name(), s == BRUTE ? "brute force" : "k=" + s, s == SceneGeometry.DEFAULT_K,
                    s, best[i], q.triangleTests(), q.nodeTests(), q.pairs(), q.segments(), q.contacts(), q.linksTouching(),
                    g.object().triangleCount());
                if (s == SceneGeometry.DEFAULT_K) touching.add(g.name() + " " + q.linksTouching() + " (" + q.contacts() + " contacts)");
            }
            if (progress != null) progress.accept((o + 1.0) / files.size());
        }
        t.note("grasp", "grasp: object centred on the palm axis, all three fingers closed until they stall (simulated, k = 18); link meshes "
            + linkTriangles / 9 + " triangles on average, object triangles in the CSV");
        t.note("touching", "links touching the object (of 9): " + String.join(", ", touching));
        t.note("same", "every k and brute force find the same intersecting pairs and segments: k changes only the speed; default k = 18");
        t.note("labels", "labelled: the points on each object's Pareto front and the default; upper right, one per object: brute force; every point is in 3-kdop.csv");
        return t;
    }
}
