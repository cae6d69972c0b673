package org.handsim.model;

import java.nio.file.Path;
import java.util.Map;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.CoherentQuery;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.contact.ContactPatches;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.process.BoundedCache;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.scenario.SceneMeshes;

/**
 * The geometry of a scene and its collision back end: the hand's link meshes
 * ({@code vrml/hand/finger_link{1,2,3}.wrl}, each in its own DH frame {kj}, one set for all
 * fingers) and the object's mesh, each with its k-DOP tree, built once; per step the link's
 * tree is queried against the object's with the relative transform, the intersection segments
 * become patches and each patch one point contact (paper Section IV; DESIGN.md decisions 3, 4).
 *
 * <p>The query runs in the link's frame: the link is mesh A, the object mesh B placed by
 * {@code link ← world ← object}; the query maps only the object nodes the walk reaches
 * ({@link TreeQuery.Placement#TRANSFORM}, the faster placement by benchmark), so a large object
 * costs nothing where the link is not. Contacts are returned in the world frame with the
 * object's outward normal.
 *
 * <p><b>Temporal coherence</b> ({@link #coherent(boolean)}, on by default). A link moves a
 * little between two queries (one step, or less inside an event's bisection), so each link of
 * each finger has its {@link CoherentQuery}: it keeps the triangle pairs near at an anchor pose
 * and answers from them while the link stays within their clearance (testing none while a
 * closing link is still farther from the object than it has moved since the anchor), and
 * re-anchors otherwise. Either way exactly the full query's contacts. {@link #counter} says how
 * often each ran.
 *
 * <p>Meshes and trees are immutable and shared between instances (and threads) through
 * bounded caches ({@link BoundedCache}, {@link SceneMeshes#CACHE_TRIANGLES}) keyed by file, divisions,
 * mesh scale (the placement's units × scale) and k, each made once however many threads ask;
 * an instance costs no geometry work. Each instance has its own query scratch, so one
 * instance per model (per thread).
 */
public final class SceneGeometry implements LinkContacts {
    /** Default k of the k-DOPs (docs/BENCHMARKS.md compares the others). */
    public static final int DEFAULT_K = 18;

    private final int k;
    private final Path objectFile;
    private final Shape objectShape;
    private final Shape[] linkShapes = new Shape[3];
    private final TriangleMesh objectMesh;
    private final KdopTree objectTree;
    private final TriangleMesh[] linkMeshes = new TriangleMesh[3];
    private final KdopTree[] linkTrees = new KdopTree[3];
    private final double[] worldFromObject = new double[12];
    private final TreeQuery query;
    private final double[][] linkSpheres = new double[3][];
    private final double[] objectCentreWorld;
    private final double objectRadius;
    private final CollisionResult result;
    private final ContactPatches patches;
    private final double tolerance;
    private final double[] linkFromWorld = new double[12], pose = new double[12], c = new double[3], n = new double[3];
    // temporal coherence: per finger and link (index 3·(finger−1) + link−1)
    private boolean coherent = true;
    private final CoherentQuery[] coherentQueries;
    /** Set when another instance took over this one's scratch: it answers no more queries. */
    private boolean retired;
    private final long[] counters = new long[Counter.values().length];

    /** What the collision back end did (see {@link #counter}; in {@code summary.json}'s counters). */
    public enum Counter {
        /** Queries answered by the bounding-sphere test alone. */
        SPHERE_APART,
        /** Walks of the two trees: the gathering of near pairs (coherent) or the full query. */
        TREE_WALKS,
        /** Queries answered from the near pairs of an earlier walk, without a walk. */
        COHERENT_QUERIES,
        /** Triangle–triangle tests, in walks and from near pairs. */
        TRIANGLE_TESTS
    }

    /**
     * @param object the object and its placement (from a scenario)
     * @param k      6, 14, 18 or 26
     * @throws ScenarioException naming the file, line and column if a model cannot be loaded
     */
    public SceneGeometry(Scenario.ObjectPlacement object, int k) {
        this(object, k, null);
    }

    /**
     * As {@link #SceneGeometry(Scenario.ObjectPlacement, int)}, taking over the query scratch of
     * {@code retired} (null: new scratch) — its tree query, coherent queries, contact patches
     * and result arrays, grown to the sizes its queries needed — put back in the state of new
     * scratch (no near pairs, no placement hints, counters 0), so the queries give what new
     * scratch gives, to the last bit; only the allocations are saved. For a caller that makes
     * model after model on one thread (the planner: one model per trial, where the growing of
     * that scratch allocated about 1 MB a mug trial). {@code retired} answers no more queries
     * (they throw {@link IllegalStateException}).
     *
     * @throws ScenarioException naming the file, line and column if a model cannot be loaded
     * @throws IllegalStateException if {@code retired} was already taken over
     */
    public SceneGeometry(Scenario.ObjectPlacement object, int k, SceneGeometry retired) {
        // the retired instance's shapes when they are the same (file, divisions, mesh scale, k):
        // a planning thread's next trial then takes no lock and builds no cache key
        boolean same = retired != null && retired.k == k && retired.objectFile.equals(object.file())
            && retired.objectShape.divisions == object.divisions() && retired.objectShape.scale == object.meshScale();
        Shape obj = same ? retired.objectShape : shape(object.file(), object.divisions(), object.meshScale(), k);
        this.k = k;
        objectFile = object.file();
        objectShape = obj;
        objectMesh = obj.mesh;
        objectTree = obj.tree;
        double diag = obj.diagonal;
        double linkWidth = Double.POSITIVE_INFINITY;
        for (int j = 1; j <= 3; j++) {
            Shape link = retired != null && retired.k == k ? retired.linkShapes[j - 1] : shape(SceneMeshes.linkFile(j), SceneMeshes.LINK_DIVISIONS, 1.0, k);
            linkShapes[j - 1] = link;
            if (retired == null || retired.k != k) linkWidth = Math.min(linkWidth, link.thickness());   // reused shapes: their width below
            linkMeshes[j - 1] = link.mesh;
            linkTrees[j - 1] = link.tree;
            linkSpheres[j - 1] = link.sphere;
            diag = Math.max(diag, link.diagonal);
        }
        object.worldFromObject().copyTo(worldFromObject, 0);
        double[] os = obj.sphere;
        objectCentreWorld = object.worldFromObject().apply(new double[] {os[0], os[1], os[2]});
        objectRadius = os[3];
        tolerance = ContactPatches.TOLERANCE_FACTOR * diag;
        objectCentroid = obj.centroid();
        double[] cw = object.worldFromObject().apply(objectCentroid);
        centroidAndRadius = new double[] {cw[0], cw[1], cw[2], obj.centroidReach()};
        thickness = same ? retired.thickness : obj.thickness();
        linkThickness = retired != null && retired.k == k ? retired.linkThickness : linkWidth;
        // the scratch last: a model that cannot be loaded leaves the retired instance as it was
        if (retired == null) {
            query = new TreeQuery();
            result = new CollisionResult();
            patches = new ContactPatches();
            coherentQueries = new CoherentQuery[9];
            for (int i = 0; i < coherentQueries.length; i++) coherentQueries[i] = new CoherentQuery();
        } else {
            if (retired.retired) throw new IllegalStateException("this scene geometry's scratch was already taken over");
            retired.retired = true;
            query = retired.query.recycle();
            result = retired.result;
            result.clear();
            patches = retired.patches;
            coherentQueries = retired.coherentQueries;
            for (CoherentQuery c : coherentQueries) c.recycle();
        }
    }



    /**
     * A mesh with what the queries need of it, made once per file, divisions, scale and k and
     * shared (immutable): its k-DOP tree, bounding sphere ({@link #boundingSphere}),
     * bounding-box diagonal, centroid and the largest distance from it to a vertex (the grasp
     * evaluation's torque origin and R) and, for an object, its thinnest width (made on first
     * use: links need none).
     */
    private static final class Shape {
        final String key;
        final int divisions;
        final double scale;
        final TriangleMesh mesh;
        final KdopTree tree;
        final double[] sphere;
        final double diagonal;
        private final double[] centroid;
        private final double centroidReach;
        private double thickness = Double.NaN;

        Shape(String key, int divisions, double scale, TriangleMesh mesh, int k) {
            this.key = key;
            this.divisions = divisions;
            this.scale = scale;
            this.mesh = mesh;
            this.tree = KdopTree.build(mesh, k);
            this.sphere = boundingSphere(mesh);
            this.diagonal = mesh.diagonal();
            this.centroid = mesh.centroid();
            double r = 0;
            double[] v = mesh.vertices();
            for (int i = 0; i < v.length; i += 3) r = Math.max(r, sq(v[i] - centroid[0]) + sq(v[i + 1] - centroid[1]) + sq(v[i + 2] - centroid[2]));
            this.centroidReach = Math.sqrt(r);
        }

        double[] centroid() { return centroid.clone(); }
        double centroidReach() { return centroidReach; }

        synchronized double thickness() {
            if (Double.isNaN(thickness)) thickness = minWidth(mesh);
            return thickness;
        }
    }

    private static final BoundedCache<String, Shape> SHAPES = new BoundedCache<>(SceneMeshes.CACHE_TRIANGLES, sh -> sh.mesh.triangleCount());

    private static Shape shape(Path file, int divisions, double scale, int k) {
        String key = file.toAbsolutePath().normalize() + "|" + divisions + "|" + scale + "|k" + k;
        TriangleMesh m = SceneMeshes.mesh(file, divisions, scale);   // the file's mesh now: a shape of an older one is made again
        return SHAPES.get(key, sh -> sh.mesh == m, x -> new Shape(x, divisions, scale, m, k));
    }

    private final double thickness, linkThickness;
    private final double[] centroidAndRadius, objectCentroid;

    @Override
    public double[] centroidAndRadius() {
        return centroidAndRadius.clone();
    }

    /**
     * An estimate from above of a mesh's thinnest width: the smallest extent along the 13
     * directions of the 26-DOP and the normals of (up to) its 500 largest triangles. Exact for a
     * box or a plate in any orientation (a face normal is the thin direction).
     */
    static double minWidth(TriangleMesh m) {
        double[] v = m.vertices();
        int nt = m.triangleCount();
        Integer[] order = new Integer[nt];
        for (int t = 0; t < nt; t++) order[t] = t;
        double[] areas = m.areas(), normals = m.normals();
        java.util.Arrays.sort(order, (a, b) -> Double.compare(areas[b], areas[a]));
        int use = Math.min(nt, 500);
        double[][] dirs = new double[13 + use][];
        int d = 0;
        for (int x = -1; x <= 1; x++) {
            for (int y = -1; y <= 1; y++) {
                for (int z = -1; z <= 1; z++) {
                    if (x > 0 || (x == 0 && y > 0) || (x == 0 && y == 0 && z > 0)) {
                        double l = Math.sqrt(x * x + y * y + z * z);
                        dirs[d++] = new double[] {x / l, y / l, z / l};
                    }
                }
            }
        }
        for (int u = 0; u < use; u++) {
            int t = order[u];
            dirs[d++] = new double[] {normals[3 * t], normals[3 * t + 1], normals[3 * t + 2]};
        }
        double best = Double.POSITIVE_INFINITY;
        for (int j = 0; j < d; j++) {
            double[] n = dirs[j];
            if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int p = 0; p < v.length; p += 3) {
                double s = n[0] * v[p] + n[1] * v[p + 1] + n[2] * v[p + 2];
                if (s < lo) lo = s;
                if (s > hi) hi = s;
            }
            best = Math.min(best, hi - lo);
        }
        return best;
    }

    @Override
    public double minThickness() {
        return thickness;
    }

    @Override
    public double minLinkThickness() {
        return linkThickness;
    }

    private static double sq(double x) { return x * x; }



    /**
     * Moves the object to {@code worldFromObject} (12 values): a free object (DESIGN.md decision
     * 7) after its step; the next queries see it there. Allocation-free.
     */
    void placeObject(double[] worldFromObject) {
        System.arraycopy(worldFromObject, 0, this.worldFromObject, 0, 12);
        double[] w = worldFromObject, os = objectShape.sphere, oc = objectCentroid;
        for (int i = 0; i < 3; i++) {
            objectCentreWorld[i] = w[4 * i] * os[0] + w[4 * i + 1] * os[1] + w[4 * i + 2] * os[2] + w[4 * i + 3];
            centroidAndRadius[i] = w[4 * i] * oc[0] + w[4 * i + 1] * oc[1] + w[4 * i + 2] * oc[2] + w[4 * i + 3];
        }
    }

    public TriangleMesh objectMesh() { return objectMesh; }
    /** The object's tree (object frame) and link j's (frame {kj}), for other queries on the same trees ({@link HandClearance}). */
    KdopTree objectTree() { return objectTree; }
    KdopTree linkTree(int j) { return linkTrees[j - 1]; }
    /** Link j's mesh (1..3), in its own frame {kj}. */
    public TriangleMesh linkMesh(int j) { return linkMeshes[j - 1]; }
    /** {@code world ← object} (12 values, a copy). */
    public double[] worldFromObject() { return worldFromObject.clone(); }
    /**
     * Counters of the last query: with coherence, the node tests are those of its gathering walk
     * (0 when it reused near pairs) and the triangle tests those of the near pairs it tested.
     */
    public CollisionResult lastResult() { return result; }

    /**
     * Bounding sphere {cx, cy, cz, r} of a mesh in its own frame, metres: centred at the centre
     * of its bounding box, the radius reaching the farthest vertex.
     */
    public static double[] boundingSphere(TriangleMesh m) {
        double[][] b = m.bounds();
        double cx = 0.5 * (b[0][0] + b[1][0]), cy = 0.5 * (b[0][1] + b[1][1]), cz = 0.5 * (b[0][2] + b[1][2]);
        double r = 0;
        double[] v = m.vertices();
        for (int i = 0; i < v.length; i += 3) r = Math.max(r, sq(v[i] - cx) + sq(v[i + 1] - cy) + sq(v[i + 2] - cz));
        return new double[] {cx, cy, cz, Math.sqrt(r)};
    }

    /**
     * The one test a far link costs: its bounding sphere against the object's (both placed in
     * the world). True when they are apart, so the tree query can be skipped.
     */
    private boolean apart(int link, double[] w) {
        double[] s = linkSpheres[link - 1];
        double x = w[0] * s[0] + w[1] * s[1] + w[2] * s[2] + w[3] - objectCentreWorld[0];
        double y = w[4] * s[0] + w[5] * s[1] + w[6] * s[2] + w[7] - objectCentreWorld[1];
        double z = w[8] * s[0] + w[9] * s[1] + w[10] * s[2] + w[11] - objectCentreWorld[2];
        double reach = s[3] + objectRadius;
        return x * x + y * y + z * z > reach * reach;
    }

    /**
     * Whether queries reuse the near pairs of earlier ones (default true); off, every query
     * that passes the sphere test walks the trees. Results are the same either way. Returns this.
     */
    public SceneGeometry coherent(boolean on) {
        coherent = on;
        for (CoherentQuery c : coherentQueries) c.reset();
        return this;
    }

    /** Whether queries reuse near pairs ({@link #coherent(boolean)}). */
    public boolean isCoherent() { return coherent; }

    /** How often each kind of work ran since construction ({@link Counter}). */
    public long counter(Counter c) { return counters[c.ordinal()]; }

    /** The counters by lower-case {@link Counter} name, in that order. */
    @Override
    public Map<String, Long> counters() {
        Map<String, Long> m = new java.util.LinkedHashMap<>();
        for (Counter c : Counter.values()) m.put(c.name().toLowerCase(java.util.Locale.ROOT), counters[c.ordinal()]);
        return m;
    }

    /** The tree query of link j at {@code w} into {@link #result}; false if it found nothing. */
    private boolean query(int finger, int link, double[] w, boolean firstOnly) {
        if (retired) throw new IllegalStateException("this scene geometry's scratch was taken over by another (SceneGeometry(object, k, retired))");
        if (apart(link, w)) {
            result.clear();
            counters[Counter.SPHERE_APART.ordinal()]++;
            return false;
        }
        KdopTree lt = linkTrees[link - 1];
        if (coherent) {
            CoherentQuery c = coherentQueries[3 * (finger - 1) + (link - 1)];
            long walks = c.walks();
            if (firstOnly) c.intersects(query, lt, w, objectTree, worldFromObject, result);
            else c.collide(query, lt, w, objectTree, worldFromObject, result);
            counters[(c.walks() > walks ? Counter.TREE_WALKS : Counter.COHERENT_QUERIES).ordinal()]++;
            if (result.intersecting()) System.arraycopy(c.relativePose(), 0, pose, 0, 12);
        } else {
            RigidTransform.inverseTimes(w, worldFromObject, linkFromWorld, pose);
            counters[Counter.TREE_WALKS.ordinal()]++;
            if (firstOnly) query.intersects(lt, objectTree, pose, 0, result);
            else query.collide(lt, objectTree, pose, 0, result);
        }
        counters[Counter.TRIANGLE_TESTS.ordinal()] += result.triangleTests;
        return result.intersecting();
    }

    @Override
    public boolean touches(int finger, int link, double[] worldFromLink) {
        return query(finger, link, worldFromLink, true);
    }

    @Override
    public int collide(int finger, int link, double[] worldFromLink, ContactSet out) {
        if (!query(finger, link, worldFromLink, false)) return 0;
        TriangleMesh lm = linkMeshes[link - 1];
        int np = patches.build(result, lm.normals(), lm.areas(), objectMesh.normals(), objectMesh.areas(), pose, tolerance);
        double[] w = worldFromLink;
        for (int i = 0; i < np; i++) {
            patches.center(i, c);
            patches.normal(i, n);
            double px = w[0] * c[0] + w[1] * c[1] + w[2] * c[2] + w[3];
            double py = w[4] * c[0] + w[5] * c[1] + w[6] * c[2] + w[7];
            double pz = w[8] * c[0] + w[9] * c[1] + w[10] * c[2] + w[11];
            double nx = w[0] * n[0] + w[1] * n[1] + w[2] * n[2];
            double ny = w[4] * n[0] + w[5] * n[1] + w[6] * n[2];
            double nz = w[8] * n[0] + w[9] * n[1] + w[10] * n[2];
            out.add(link, px, py, pz, nx, ny, nz, patches.area(i));
        }
        return np;
    }
}
