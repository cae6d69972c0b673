package org.handsim.collision;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Locale;
import java.util.SplittableRandom;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/**
 * {@link KdopTree} and {@link TreeQuery}: structure, conservative bounds, and (docs/STYLE.md,
 * item 10) the same intersecting pairs as the all-pairs loop {@link BruteForce} for every k,
 * both split rules, two leaf sizes and both placements, on 200 random mesh pairs and poses.
 */
class KdopTreeTest {
    static final long SEED = 345;

    /** Random rigid transform: rotation of up to π about a random axis, translation in [−s, s]³. */
    static RigidTransform randomPose(SplittableRandom r, double s) {
        double ax = r.nextGaussian(), ay = r.nextGaussian(), az = r.nextGaussian();
        double l = Math.sqrt(ax * ax + ay * ay + az * az);
        double ang = Math.PI * r.nextDouble();
        return RigidTransform.fromPose((2 * r.nextDouble() - 1) * s, (2 * r.nextDouble() - 1) * s, (2 * r.nextDouble() - 1) * s,
            ax / l * ang, ay / l * ang, az / l * ang);
    }

    /** HandSim's own models (vrml/objects, vrml/hand), in metres. */
    static final String[] MODELS = {"objects/cube.wrl", "objects/sphere.wrl", "objects/cylinder.wrl", "objects/cone.wrl",
        "objects/lblock.wrl", "objects/ring.wrl", "objects/mug.wrl", "hand/finger_link1.wrl", "hand/finger_link2.wrl",
        "hand/finger_link3.wrl", "hand/palm.wrl"};
    /** Real-world files of the shared VRML corpus ({@link org.handsim.TestPaths#shared}; scaled to 6 cm; some have zero-area triangles). */
    static final String[] CORPUS = {"rl-examples_puma560/unimation-puma560.wrl", "freewrl_40.wrl", "java3d-vrml97_test.wrl",
        "openhrp3_pa10_3.wrl", "rl-examples_alpha1/alpha1.wrl", "choreonoid_hand_base.wrl", "freewrl_14.wrl"};
    private static final java.util.Map<String, TriangleMesh> LOADED = new java.util.HashMap<>();

    static synchronized TriangleMesh loaded(java.nio.file.Path file, boolean fit) {
        return LOADED.computeIfAbsent(file.toString(), f -> fit ? TestMeshes.fit(TestMeshes.vrml(file), 0.06) : TestMeshes.vrml(file));
    }

    /** One of the test shapes, a few centimetres across, chosen by {@code kind}. */
    static TriangleMesh shape(int kind, SplittableRandom r) {
        switch (kind) {
            case 6: return loaded(org.handsim.TestPaths.root().resolve("vrml").resolve(MODELS[r.nextInt(MODELS.length)]), false);
            case 7:
                if (!org.handsim.TestPaths.hasShared()) return TestMeshes.box(0.02, 0.02, 0.02, 2);
                return loaded(org.handsim.TestPaths.shared().resolve("vrml-corpus").resolve(CORPUS[r.nextInt(CORPUS.length)]), true);
            case 0: return TestMeshes.icosphere(2, 0.02);
            case 1: return TestMeshes.bumpy(2, 0.02, 0.15, r);
            case 2: return TestMeshes.box(0.02, 0.015, 0.01, 1 + r.nextInt(4));
            case 3: return TestMeshes.uvSphere(12 + 2 * r.nextInt(6), 0.025);
            case 4: return TestMeshes.soup(100 + r.nextInt(200), 0.02, r);
            default: return TestMeshes.grid(0.03, 4 + r.nextInt(8));
        }
    }

    @Test
    void sameIntersectingPairsAsBruteForceOn200RandomCases() {
        SplittableRandom r = new SplittableRandom(SEED);
        BruteForce brute = new BruteForce();
        CollisionResult expected = new CollisionResult(), got = new CollisionResult();
        TreeQuery[] queries = {new TreeQuery().placement(TreeQuery.Placement.TRANSFORM), new TreeQuery().placement(TreeQuery.Placement.REFIT)};
        int intersecting = 0, totalPairs = 0, configurations = 0;
        long degenerate = 0;
        int cases = TestEffort.cases(200);   // all 200 in ./test --all
        for (int c = 0; c < cases; c++) {
            TriangleMesh a = shape(r.nextInt(8), r), b = shape(r.nextInt(8), r);
            RigidTransform pose = c % 10 == 9 ? RigidTransform.IDENTITY : randomPose(r, 0.04);
            brute.collide(a, b, pose, expected);
            long[] want = expected.sortedPairKeys();
            if (want.length > 0) intersecting++;
            degenerate += expected.degenerateSkipped;
            totalPairs += want.length;
            for (int k : Kdop.SUPPORTED_K) {
                for (KdopTree.SplitRule rule : KdopTree.SplitRule.values()) {
                    int leaf = (c + k) % 2 == 0 ? 1 : 4;
                    KdopTree ta = KdopTree.build(a, k, rule, leaf), tb = KdopTree.build(b, k, rule, leaf);
                    for (TreeQuery q : queries) {
                        q.collide(ta, tb, pose, got);
                        configurations++;
                        assertArrayEquals(want, got.sortedPairKeys(), String.format(Locale.ROOT,
                            "case %d (%s vs %s), k=%d, %s, leaf %d, %s", c, a.name(), b.name(), k, rule, leaf, q.placement()));
                        assertEquals(expected.segmentCount(), got.segmentCount(), "segments, case " + c);
                        assertTrue(got.triangleTests <= expected.triangleTests);
                    }
                }
            }
        }
        System.out.printf(Locale.ROOT, "tree vs brute force: %d cases (%d intersecting, %d pairs, %d degenerate pairs skipped), %d tree configurations%n",
            cases, intersecting, totalPairs, degenerate, configurations);
        assertTrue(intersecting > cases / 2, "too few intersecting cases: " + intersecting + " of " + cases);
    }

    /** Exactly touching meshes (shared vertices, coplanar faces) are found: the bounds are conservative. */
    @Test
    void exactContactsAreNotCulled() {
        BruteForce brute = new BruteForce();
        CollisionResult expected = new CollisionResult(), got = new CollisionResult();
        TriangleMesh box = TestMeshes.box(0.01, 0.01, 0.01, 3);
        TriangleMesh sphere = TestMeshes.icosphere(2, 0.0123);
        RigidTransform[] poses = {
            RigidTransform.translation(0.02, 0, 0),                         // faces touch exactly
            RigidTransform.translation(0.02, 0.02, 0.02),                   // corners touch
            RigidTransform.translation(0.02, 0.01, 0),                      // face/edge offsets
            RigidTransform.fromPose(0.02, 0, 0, 0, 0, Math.PI / 2),         // rotated, faces touch
        };
        for (TriangleMesh m : new TriangleMesh[] {box, sphere}) {
            for (RigidTransform pose : poses) {
                brute.collide(m, m, pose, expected);
                for (int k : Kdop.SUPPORTED_K) {
                    KdopTree t = KdopTree.build(m, k);
                    for (TreeQuery.Placement pl : TreeQuery.Placement.values()) {
                        new TreeQuery().placement(pl).collide(t, t, pose, got);
                        assertArrayEquals(expected.sortedPairKeys(), got.sortedPairKeys(), m.name() + " k=" + k + " " + pl + " " + pose);
                    }
                }
            }
        }
        brute.collide(box, box, RigidTransform.translation(0.02, 0, 0), expected);
        assertTrue(expected.pairCount() > 0, "touching boxes intersect (closed triangles)");
    }

    @Test
    void everyTriangleInExactlyOneLeafAndBoundsContainTheirTriangles() {
        SplittableRandom r = new SplittableRandom(SEED);
        TriangleMesh m = TestMeshes.bumpy(3, 0.03, 0.2, r);
        for (int k : Kdop.SUPPORTED_K) {
            for (KdopTree.SplitRule rule : KdopTree.SplitRule.values()) {
                for (int leaf : new int[] {1, 3, 8}) {
                    KdopTree t = KdopTree.build(m, k, rule, leaf);
                    int[] seen = new int[m.triangleCount()];
                    checkNode(t, 0, seen, leaf);
                    for (int s : seen) assertEquals(1, s);
                    assertTrue(t.depth() < 40, "depth " + t.depth());
                }
            }
        }
    }

    /** Returns the triangles under node; checks that node's bounds contain all their vertices. */
    private static int[] checkNode(KdopTree t, int node, int[] seen, int leaf) {
        int[] tris;
        if (t.isLeaf(node)) {
            tris = t.leafTriangles(node);
            assertTrue(tris.length >= 1 && tris.length <= leaf);
            for (int x : tris) seen[x]++;
        } else {
            int[] l = checkNode(t, node + 1, seen, leaf), rr = checkNode(t, t.child[node], seen, leaf);
            tris = Arrays.copyOf(l, l.length + rr.length);
            System.arraycopy(rr, 0, tris, l.length, rr.length);
        }
        double[] b = t.nodeBounds(node);
        double[] v = t.vertices();
        int[] tv = t.mesh().triangles();
        for (int x : tris) {
            for (int q = 0; q < 3; q++) {
                int p = 3 * tv[3 * x + q];
                assertTrue(t.kdop().contains(b, 0, v[p], v[p + 1], v[p + 2]), "node " + node);
            }
        }
        return tris;
    }

    /** The on-demand placed bounds contain the placed vertices and are exact for the identity. */
    @Test
    void transformedBoundsAreConservative() {
        SplittableRandom r = new SplittableRandom(SEED);
        TriangleMesh m = TestMeshes.bumpy(3, 0.03, 0.2, r);
        for (int k : Kdop.SUPPORTED_K) {
            KdopTree t = KdopTree.build(m, k);
            Kdop kd = t.kdop();
            TransformedBounds tb = new TransformedBounds();
            double[] out = new double[k], placed = new double[m.vertices().length], mm = new double[12];
            double worstRatio = 0;
            for (int trial = 0; trial < 50; trial++) {
                randomPose(r, 0.1).copyTo(mm, 0);
                tb.prepare(kd, mm);
                KdopTree.transformPoints(mm, m.vertices(), placed, m.vertexCount());
                for (int node = 0; node < t.nodeCount(); node += 7) {
                    tb.apply(t.bounds, node * k, out, 0);
                    for (int x : subtree(t, node)) {
                        for (int q = 0; q < 3; q++) {
                            int p = 3 * m.triangles()[3 * x + q];
                            assertTrue(kd.contains(out, 0, placed[p], placed[p + 1], placed[p + 2]), "k=" + k + " node " + node);
                        }
                    }
                }
                // tightness at the root: placed width / refitted width per direction
                double[] exact = new double[k];
                kd.fit(placed, m.vertexCount(), exact, 0);
                tb.apply(t.bounds, 0, out, 0);
                for (int j = 0; j < k; j += 2) worstRatio = Math.max(worstRatio, (out[j + 1] - out[j]) / (exact[j + 1] - exact[j]));
            }
            assertTrue(worstRatio < 2.0, "k=" + k + " loose by " + worstRatio);
            Arrays.fill(mm, 0);
            mm[0] = mm[5] = mm[10] = 1;
            tb.prepare(kd, mm);
            tb.apply(t.bounds, 0, out, 0);
            double[] root = t.nodeBounds(0);
            for (int j = 0; j < k; j++) assertEquals(root[j], out[j], 1e-13, "identity (up to the rounding margin), slot " + j);
        }
    }

    private static int[] subtree(KdopTree t, int node) {
        if (t.isLeaf(node)) return t.leafTriangles(node);
        int[] l = subtree(t, node + 1), rr = subtree(t, t.child[node]);
        int[] all = Arrays.copyOf(l, l.length + rr.length);
        System.arraycopy(rr, 0, all, l.length, rr.length);
        return all;
    }

    /**
     * No allocation per query once the buffers have grown (DESIGN.md: hot loops allocate
     * nothing), measured with the JVM's per-thread allocation counter, for both placements.
     */
    @Test
    void queriesAllocateNothingOnceWarm() {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        org.junit.jupiter.api.Assumptions.assumeTrue(mx instanceof com.sun.management.ThreadMXBean);
        com.sun.management.ThreadMXBean tmx = (com.sun.management.ThreadMXBean) mx;
        TriangleMesh m = TestMeshes.icosphere(3, 1);
        KdopTree ta = KdopTree.build(m, 18), tb = KdopTree.build(m, 18);
        double[] pose = new double[12];
        RigidTransform.fromPose(1.5, 0, 0, 0.187, 0.374, 0.561).copyTo(pose, 0);
        for (TreeQuery.Placement pl : TreeQuery.Placement.values()) {
            TreeQuery q = new TreeQuery().placement(pl);
            CollisionResult r = new CollisionResult();
            // a few queries grow the buffers: the code allocates nothing of itself, escape analysis or not
            for (int i = 0; i < 20; i++) q.collide(ta, tb, pose, 0, r);
            long id = Thread.currentThread().getId();
            long before = tmx.getThreadAllocatedBytes(id);
            for (int i = 0; i < 100; i++) q.collide(ta, tb, pose, 0, r);
            long bytes = tmx.getThreadAllocatedBytes(id) - before;
            assertTrue(r.pairCount() == 122, "pairs " + r.pairCount());
            assertTrue(bytes < 1000, pl + ": " + bytes + " bytes in 100 queries");
        }
    }

    @Test
    void intersectsStopsAtTheFirstPair() {
        TriangleMesh m = TestMeshes.icosphere(3, 1);
        KdopTree t = KdopTree.build(m, 18);
        CollisionResult r = new CollisionResult();
        TreeQuery q = new TreeQuery();
        assertTrue(q.intersects(t, t, RigidTransform.translation(1.5, 0, 0), r));
        assertEquals(1, r.pairCount());
        assertFalse(q.intersects(t, t, RigidTransform.translation(2.5, 0, 0), r));
        assertEquals(1, r.nodeTests);
    }

    @Test
    void kdopOperationsByHand() {
        Kdop k18 = Kdop.of(18);
        double[] a = new double[18], b = new double[18];
        k18.fit(new double[] {0, 0, 0, 1, 1, 0}, 2, a, 0);
        assertEquals(0, a[0]);
        assertEquals(1, a[1]);
        assertEquals(2, a[7], 1e-15);          // max of x + y is 2
        assertEquals(0, a[12], 1e-15);         // min of x − y is 0 (slot 2·6)
        assertEquals(0, a[13], 1e-15);         // max of x − y is 0
        // the point (0.8, 0.2, 0) is inside the AABB of a but off the diagonal slab x − y = 0: separated
        k18.fit(new double[] {0.8, 0.2, 0}, 1, b, 0);
        double[] a6 = Arrays.copyOf(a, 6), b6 = Arrays.copyOf(b, 6);
        assertTrue(Kdop.overlap(a6, 0, b6, 0, 6), "AABBs overlap");
        assertFalse(Kdop.overlap(a, 0, b, 0, 18), "the 18-DOP separates them");
        double[] c = new double[18];
        Kdop.merge(a, 0, b, 0, c, 0, 18);
        assertTrue(Kdop.overlap(c, 0, b, 0, 18));
        assertTrue(k18.contains(c, 0, 0.8, 0.2, 0));
        assertThrows(IllegalArgumentException.class, () -> Kdop.of(24));
        assertEquals(3, Kdop.of(6).directionCount());
        assertEquals(13, Kdop.of(26).directionCount());
    }

    @Test
    void badArgumentsAreNamed() {
        TriangleMesh m = TestMeshes.icosphere(1, 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> KdopTree.build(m, 10));
        assertTrue(e.getMessage().contains("10"));
        e = assertThrows(IllegalArgumentException.class, () -> KdopTree.build(m, 6, KdopTree.SplitRule.SAH, 0));
        assertTrue(e.getMessage().contains("maxLeafSize"));
        KdopTree t6 = KdopTree.build(m, 6), t18 = KdopTree.build(m, 18);
        assertThrows(IllegalArgumentException.class, () -> new TreeQuery().collide(t6, t18, RigidTransform.IDENTITY, new CollisionResult()));
    }

    @Test
    void degenerateTrianglesAreSkippedAndCounted() {
        // two triangles, the second with collinear vertices, against a crossing triangle
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0.5, 0.5, 0, 1, 1, 0};
        TriangleMesh a = new TriangleMesh("a", v, new int[] {0, 1, 2, 3, 4, 5});
        TriangleMesh b = new TriangleMesh("b", new double[] {0.2, 0.2, -1, 0.2, 0.2, 1, 0.3, 0.3, 0}, new int[] {0, 1, 2});
        KdopTree ta = KdopTree.build(a, 18, KdopTree.SplitRule.MEDIAN, 2), tb = KdopTree.build(b, 18);
        assertEquals(1, ta.degenerateCount());
        CollisionResult r = new TreeQuery().collide(ta, tb, RigidTransform.IDENTITY, new CollisionResult());
        assertEquals(1, r.pairCount());
        assertEquals(0, r.triangleA(0));
        assertEquals(1, r.degenerateSkipped);
        CollisionResult bf = new BruteForce().collide(a, b, RigidTransform.IDENTITY, new CollisionResult());
        assertEquals(1, bf.degenerateSkipped);
    }

    @Test
    void refitFollowsMovedVertices() {
        TriangleMesh m = TestMeshes.icosphere(2, 0.02);
        RigidTransform pose = RigidTransform.fromPose(0.03, 0.01, 0, 0.3, 0.2, 0.1);
        KdopTree fixed = KdopTree.build(m, 18), moved = KdopTree.build(m, 18);
        moved.refit(pose);
        CollisionResult viaRefit = new TreeQuery().collide(fixed, moved, RigidTransform.IDENTITY, new CollisionResult());
        CollisionResult viaPose = new TreeQuery().collide(fixed, KdopTree.build(m, 18), pose, new CollisionResult());
        assertArrayEquals(viaPose.sortedPairKeys(), viaRefit.sortedPairKeys());
        assertTrue(viaRefit.pairCount() > 0);
    }
}
