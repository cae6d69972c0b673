package org.handsim.model;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.handsim.collision.CollisionResult;
import org.handsim.collision.KdopTree;
import org.handsim.collision.TreeQuery;
import org.handsim.hand.HandDescription;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;

/**
 * Whether the whole hand — palm and the nine links, the fingers FREE at given motor counts
 * and spread — touches the object when the palm is placed at a given pose: the question the
 * planner's approach asks ({@code plan.Autograsp}). The links are placed exactly as
 * {@link HandModel} places them (world ← palm ← {k0}, forward kinematics of the FREE joint
 * angles of eqs 1–4), and tested on the contact query's own trees (the scene's object and link
 * trees, the palm's {@code vrml/hand/palm.wrl} at the links' divisions and k) by the same
 * surface-intersection test ({@link TreeQuery#intersects}, stopped at the first intersecting
 * triangle pair), so a pose this class calls clear starts the simulation without contacts. A
 * part whose bounding sphere is apart from the object's costs that one test.
 *
 * <p>Not thread-safe (query scratch): one per thread.
 */
public final class HandClearance {
    private final SceneGeometry scene;
    private final HandDescription hand = HandDescription.barrettHand();
    private final Transmission tr = new Transmission(hand);
    private final FingerKinematics[] fk = new FingerKinematics[3];
    private final double[] frames = new double[FingerKinematics.FRAMES_LENGTH];
    private final double[] joints = new double[3], base = new double[12], palm = new double[12];
    private final double[][] baseInPalm = new double[3][12];   // palm ← {k0} of each finger
    private final TriangleMesh palmMesh;
    private final double[] centroid;
    private final double objectReach;
    /** The palm's tree for each k, with the mesh it was built from (a changed palm file gives a new mesh: built again). */
    private static final Map<Integer, PalmTree> PALM_TREES = new ConcurrentHashMap<>();
    private record PalmTree(TriangleMesh mesh, KdopTree tree) {}
    private final KdopTree[] trees = new KdopTree[4];     // palm, links 1..3
    private final double[][] spheres = new double[4][];   // their bounding spheres, own frames
    private final KdopTree objectTree;
    private final double[] worldFromObject, objectSphere = new double[4];
    private final TreeQuery query = new TreeQuery();
    private final CollisionResult result = new CollisionResult();
    private final double[] partFromObject = new double[12], partFromWorld = new double[12];

    /**
     * @param object the object and its placement (a scenario's)
     * @throws ScenarioException naming file, line and column if the object cannot be loaded
     */
    public HandClearance(Scenario.ObjectPlacement object) {
        scene = new SceneGeometry(object, SceneGeometry.DEFAULT_K);
        for (int k = 1; k <= 3; k++) {
            fk[k - 1] = new FingerKinematics(hand.finger(k));
            hand.finger(k).baseInPalm().copyTo(baseInPalm[k - 1], 0);
        }
        double[] cr = scene.centroidAndRadius();   // the torque origin c and R of the grasp evaluation
        centroid = new double[] {cr[0], cr[1], cr[2]};
        objectReach = cr[3];
        objectTree = scene.objectTree();
        worldFromObject = scene.worldFromObject();
        int k = objectTree.k();
        Path palmFile = SceneMeshes.palmFile();
        palmMesh = SceneMeshes.mesh(palmFile, SceneMeshes.LINK_DIVISIONS, 1.0);
        trees[0] = PALM_TREES.compute(k, (x, was) -> was != null && was.mesh() == palmMesh ? was : new PalmTree(palmMesh, KdopTree.build(palmMesh, x))).tree();
        spheres[0] = SceneGeometry.boundingSphere(palmMesh);
        for (int j = 1; j <= 3; j++) {
            trees[j] = scene.linkTree(j);
            spheres[j] = SceneGeometry.boundingSphere(scene.linkMesh(j));
        }
        double[] os = SceneGeometry.boundingSphere(scene.objectMesh());
        RigidTransform.of(worldFromObject).apply(new double[] {os[0], os[1], os[2]}, objectSphere);
        objectSphere[3] = os[3];
    }

    /** The object's centroid, world frame, metres (the grasp evaluation's torque origin, {@link SceneGeometry#centroidAndRadius}); a new array. */
    public double[] objectCentroid() { return centroid.clone(); }

    /** The largest distance from the centroid to a vertex of the object, metres. */
    public double objectReach() { return objectReach; }

    /** The object's thinnest width, metres (an estimate from above, {@link SceneGeometry#minThickness}). */
    public double objectMinThickness() { return scene.minThickness(); }

    /**
     * True if the palm placed by {@code worldFromPalm}, or a link of a finger at motor counts
     * {@code fingerCounts[k−1]} (FREE) with the spread at {@code spreadCounts}, intersects the
     * object. Parts are tested palm first, then fingers 1–3 from the outer link in.
     */
    public boolean touches(RigidTransform worldFromPalm, double spreadCounts, double[] fingerCounts) {
        worldFromPalm.copyTo(palm, 0);
        return touchesAt(palm, spreadCounts, fingerCounts);
    }

    /**
     * As {@link #touches(RigidTransform, double, double[])} with {@code world ← palm} as its 12
     * row-major values (allocation-free: the approach asks this some thirty times a trial).
     */
    public boolean touches(double[] worldFromPalm, double spreadCounts, double[] fingerCounts) {
        System.arraycopy(worldFromPalm, 0, palm, 0, 12);
        return touchesAt(palm, spreadCounts, fingerCounts);
    }

    private boolean touchesAt(double[] worldFromPalm, double spreadCounts, double[] fingerCounts) {
        if (touches(0, worldFromPalm, 0)) return true;
        for (int k = 1; k <= 3; k++) {
            placeFinger(worldFromPalm, k, spreadCounts, fingerCounts[k - 1]);
            for (int j = 3; j >= 1; j--) {
                if (touches(j, frames, 12 * j)) return true;
            }
        }
        return false;
    }

    /**
     * True if a link of one finger intersects a link of another, each finger placed by its frames
     * {k0}..{k3} in the world ({@link HandModel#framesWorld}, 48 values: link j at offset 12·j).
     * The simulator stops a finger at the object, never at another finger, so fingers that close
     * past the object (an object smaller than the gap between their tips) pass through each other:
     * such a pose is not one the hand can reach, and its contacts are no grasp.
     */
    public boolean fingersCross(double[][] framesWorld) {
        for (int k = 0; k < 3; k++) {
            for (int m = k + 1; m < 3; m++) {
                for (int j = 1; j <= 3; j++) {
                    for (int i = 1; i <= 3; i++) {
                        if (linksTouch(framesWorld[k], j, framesWorld[m], i)) return true;
                    }
                }
            }
        }
        return false;
    }

    private final double[] linkFromLink = new double[12];

    /** Link j placed by {@code a[12j..]} against link i placed by {@code b[12i..]}: bounding spheres, then the trees. */
    private boolean linksTouch(double[] a, int j, double[] b, int i) {
        double[] sa = spheres[j], sb = spheres[i];
        int oa = 12 * j, ob = 12 * i;
        double dx = (a[oa] * sa[0] + a[oa + 1] * sa[1] + a[oa + 2] * sa[2] + a[oa + 3]) - (b[ob] * sb[0] + b[ob + 1] * sb[1] + b[ob + 2] * sb[2] + b[ob + 3]);
        double dy = (a[oa + 4] * sa[0] + a[oa + 5] * sa[1] + a[oa + 6] * sa[2] + a[oa + 7]) - (b[ob + 4] * sb[0] + b[ob + 5] * sb[1] + b[ob + 6] * sb[2] + b[ob + 7]);
        double dz = (a[oa + 8] * sa[0] + a[oa + 9] * sa[1] + a[oa + 10] * sa[2] + a[oa + 11]) - (b[ob + 8] * sb[0] + b[ob + 9] * sb[1] + b[ob + 10] * sb[2] + b[ob + 11]);
        double r = sa[3] + sb[3];
        if (dx * dx + dy * dy + dz * dz > r * r) return false;
        RigidTransform.inverseTimes(a, oa, b, ob, partFromWorld, linkFromLink, 0);
        return query.intersects(trees[j], trees[i], linkFromLink, 0, result);
    }

    /**
     * The largest distance from the palm origin to a vertex of the palm or of a link, metres,
     * for the given spread and finger counts (FREE): no point of the hand is farther, so a palm
     * origin more than {@code handReach + objectReach} from the centroid is clear of the object.
     */
    public double handReach(double spreadCounts, double[] fingerCounts) {
        RigidTransform.IDENTITY.copyTo(palm, 0);
        double r = reach(palmMesh, palm, 0);
        for (int k = 1; k <= 3; k++) {
            placeFinger(palm, k, spreadCounts, fingerCounts[k - 1]);
            for (int j = 1; j <= 3; j++) r = Math.max(r, reach(scene.linkMesh(j), frames, 12 * j));
        }
        return r;
    }

    /** Part p (0 palm, 1..3 link) placed by {@code w[o..o+11]} (world ← part) against the object. */
    private boolean touches(int p, double[] w, int o) {
        double[] s = spheres[p];
        double x = w[o] * s[0] + w[o + 1] * s[1] + w[o + 2] * s[2] + w[o + 3] - objectSphere[0];
        double y = w[o + 4] * s[0] + w[o + 5] * s[1] + w[o + 6] * s[2] + w[o + 7] - objectSphere[1];
        double z = w[o + 8] * s[0] + w[o + 9] * s[1] + w[o + 10] * s[2] + w[o + 11] - objectSphere[2];
        double reach = s[3] + objectSphere[3];
        if (x * x + y * y + z * z > reach * reach) return false;
        // part ← object = (world ← part)⁻¹ · (world ← object), as SceneGeometry places the object in a link's frame
        RigidTransform.inverseTimes(w, o, worldFromObject, 0, partFromWorld, partFromObject, 0);
        return query.intersects(trees[p], objectTree, partFromObject, 0, result);
    }

    private static double reach(TriangleMesh m, double[] w, int o) {
        double[] v = m.vertices();
        double r = 0;
        for (int i = 0; i < v.length; i += 3) {
            double x = w[o] * v[i] + w[o + 1] * v[i + 1] + w[o + 2] * v[i + 2] + w[o + 3];
            double y = w[o + 4] * v[i] + w[o + 5] * v[i + 1] + w[o + 6] * v[i + 2] + w[o + 7];
            double z = w[o + 8] * v[i] + w[o + 9] * v[i + 1] + w[o + 10] * v[i + 2] + w[o + 11];
            r = Math.max(r, x * x + y * y + z * z);
        }
        return Math.sqrt(r);
    }

    /** Frames {k0}..{k3} of finger k in the world, as {@link HandModel} computes them. */
    private void placeFinger(double[] worldFromPalm, int k, double spreadCounts, double counts) {
        RigidTransform.multiply(worldFromPalm, 0, baseInPalm[k - 1], 0, base, 0);   // as RigidTransform.compose
        joints[0] = hand.finger(k).spreadRadPerCount() * spreadCounts;
        joints[1] = tr.innerAngle(counts);
        joints[2] = tr.outerAngle(counts);
        fk[k - 1].framesFrom(base, joints, frames);
    }
}
