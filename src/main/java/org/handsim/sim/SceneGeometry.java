package org.handsim.sim;

import java.io.Reader;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.contact.ContactPatches;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.vrml.VrmlLoader;
import org.handsim.vrml.VrmlScene;

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
 * <p>Meshes and trees are immutable and shared between instances (and threads) through a
 * cache keyed by file, divisions, scale and k; each instance has its own query scratch, so one
 * instance per model (per thread).
 */
public final class SceneGeometry implements LinkContacts {
    /** Default k of the k-DOPs (issue 5's default; see docs/BENCHMARKS.md for the others). */
    public static final int DEFAULT_K = 18;
    /** Divisions the hand's meshes (links and, in the window, the palm) are loaded at. */
    public static final int LINK_DIVISIONS = 32;

    private static final Map<String, TriangleMesh> MESHES = new ConcurrentHashMap<>();
    private static final Map<String, KdopTree> TREES = new ConcurrentHashMap<>();

    private final TriangleMesh objectMesh;
    private final KdopTree objectTree;
    private final TriangleMesh[] linkMeshes = new TriangleMesh[3];
    private final KdopTree[] linkTrees = new KdopTree[3];
    private final double[] worldFromObject = new double[12];
    private final TreeQuery query = new TreeQuery();
    private final double[][] linkSpheres = new double[3][];
    private final double[] objectCentreWorld;
    private final double objectRadius;
    private final CollisionResult result = new CollisionResult();
    private final ContactPatches patches = new ContactPatches();
    private final double tolerance;
    private final double[] linkFromWorld = new double[12], pose = new double[12], c = new double[3], n = new double[3];

    /**
     * @param object the object and its placement (from a scenario)
     * @param k      6, 14, 18 or 26
     * @throws ScenarioException naming the file, line and column if a model cannot be loaded
     */
    public SceneGeometry(Scenario.ObjectPlacement object, int k) {
        objectMesh = mesh(object.file(), object.divisions(), object.meshScale());
        objectTree = tree(object.file(), object.divisions(), object.meshScale(), k, objectMesh);
        for (int j = 1; j <= 3; j++) {
            Path f = linkFile(j);
            linkMeshes[j - 1] = mesh(f, LINK_DIVISIONS, 1.0);
            linkTrees[j - 1] = tree(f, LINK_DIVISIONS, 1.0, k, linkMeshes[j - 1]);
        }
        object.worldFromObject().copyTo(worldFromObject, 0);
        double[] os = boundingSphere(objectMesh);
        objectCentreWorld = object.worldFromObject().apply(new double[] {os[0], os[1], os[2]});
        objectRadius = os[3];
        for (int j = 0; j < 3; j++) linkSpheres[j] = boundingSphere(linkMeshes[j]);
        double diag = 0;
        for (TriangleMesh m : new TriangleMesh[] {objectMesh, linkMeshes[0], linkMeshes[1], linkMeshes[2]}) {
            diag = Math.max(diag, m.diagonal());
        }
        tolerance = ContactPatches.TOLERANCE_FACTOR * diag;
        double[] centroid = objectMesh.centroid();
        double r = 0;
        double[] ov = objectMesh.vertices();
        for (int i = 0; i < ov.length; i += 3) {
            r = Math.max(r, sq(ov[i] - centroid[0]) + sq(ov[i + 1] - centroid[1]) + sq(ov[i + 2] - centroid[2]));
        }
        double[] cw = object.worldFromObject().apply(centroid);
        centroidAndRadius = new double[] {cw[0], cw[1], cw[2], Math.sqrt(r)};
        thickness = THICKNESS.computeIfAbsent(object.file().toAbsolutePath().normalize() + "|" + object.divisions() + "|" + object.meshScale(),
            x -> minWidth(objectMesh));
    }

    private static final Map<String, Double> THICKNESS = new ConcurrentHashMap<>();
    private final double thickness;
    private final double[] centroidAndRadius;

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

    private static double sq(double x) { return x * x; }

    /** The mesh file of link j (1..3) of every finger. */
    public static Path linkFile(int j) {
        return Home.handModels().resolve("finger_link" + j + ".wrl");
    }

    /** The palm's mesh file (palm frame). */
    public static Path palmFile() {
        return Home.handModels().resolve("palm.wrl");
    }

    /**
     * Loads (once per file, divisions and scale) an object's file — VRML97, OBJ or STL, by its
     * type ({@link MeshFiles}) — as one triangle mesh in metres, degenerate triangles dropped.
     *
     * @throws ScenarioException with the loader's {@code FILE:LINE:COL: message} (or
     *         {@code FILE: byte N: message} for binary STL)
     */
    public static TriangleMesh mesh(Path file, int divisions, double scale) {
        String key = file.toAbsolutePath().normalize() + "|" + divisions + "|" + scale;
        TriangleMesh m = MESHES.get(key);
        if (m != null) return m;
        m = MeshFiles.load(file, divisions, scale).mesh();
        if (m.triangleCount() == 0) throw new ScenarioException(file + ":1:1: the file has no triangles to collide with");
        MESHES.putIfAbsent(key, m);
        return MESHES.get(key);
    }

    /**
     * Loads VRML text the way {@link #mesh(Path, int, double)} loads a file, not cached (the
     * tradeoff studies' generated objects).
     *
     * @throws VrmlParseException naming {@code name}, line and column
     */
    public static TriangleMesh mesh(String name, Reader vrml, int divisions, double scale) {
        return walk(new VrmlLoader().divisions(divisions).normals(false).load(name, vrml), name, scale);
    }

    private static TriangleMesh walk(VrmlScene scene, String name, double scale) {
        return new TessellationWalk().scale(scale).name(name).run(scene.getSceneGroup()).merged();
    }

    private static KdopTree tree(Path file, int divisions, double scale, int k, TriangleMesh m) {
        String key = file.toAbsolutePath().normalize() + "|" + divisions + "|" + scale + "|k" + k;
        return TREES.computeIfAbsent(key, x -> KdopTree.build(m, k));
    }

    public TriangleMesh objectMesh() { return objectMesh; }
    /** The object's tree (object frame) and link j's (frame {kj}), for other queries on the same trees ({@link HandClearance}). */
    KdopTree objectTree() { return objectTree; }
    KdopTree linkTree(int j) { return linkTrees[j - 1]; }
    /** Link j's mesh (1..3), in its own frame {kj}. */
    public TriangleMesh linkMesh(int j) { return linkMeshes[j - 1]; }
    /** {@code world ← object} (12 values, a copy). */
    public double[] worldFromObject() { return worldFromObject.clone(); }
    /** Counters of the last query. */
    public CollisionResult lastResult() { return result; }

    private void poseOfObjectInLink(double[] worldFromLink) {
        // linkFromWorld = inverse(worldFromLink)
        for (int r = 0; r < 3; r++) {
            for (int col = 0; col < 3; col++) linkFromWorld[4 * r + col] = worldFromLink[4 * col + r];
        }
        for (int r = 0; r < 3; r++) {
            linkFromWorld[4 * r + 3] = -(linkFromWorld[4 * r] * worldFromLink[3] + linkFromWorld[4 * r + 1] * worldFromLink[7]
                + linkFromWorld[4 * r + 2] * worldFromLink[11]);
        }
        RigidTransform.multiply(linkFromWorld, 0, worldFromObject, 0, pose, 0);
    }

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


    @Override
    public int collide(int finger, int link, double[] worldFromLink, ContactSet out) {
        if (apart(link, worldFromLink)) {
            result.clear();
            return 0;
        }
        poseOfObjectInLink(worldFromLink);
        query.collide(linkTrees[link - 1], objectTree, pose, 0, result);
        if (!result.intersecting()) return 0;
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
