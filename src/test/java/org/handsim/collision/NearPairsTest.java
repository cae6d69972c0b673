package org.handsim.collision;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
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
 * {@link NearPairs}, the coherent queries of {@link TreeQuery} and {@link CoherentQuery}: the
 * pairs gathered at one pose give exactly the full query's result — pairs, their order,
 * segments bit for bit — at every pose displaced by less than their clearance, on random shapes
 * and poses; a body moving in small steps gets the full query's result at every step with few
 * walks; the motion bound holds; the separation of two k-DOPs against hand-worked distances.
 */
class NearPairsTest {
    private static final long SEED = 345;

    /** Two unit cubes [0,1]³ and B = [0,1]³ moved by (dx, dy, dz); the k-DOPs of their corners. */
    private static double separation(int k, double dx, double dy, double dz) {
        Kdop kd = Kdop.of(k);
        double[] a = new double[k], b = new double[k];
        kd.setEmpty(a, 0);
        kd.setEmpty(b, 0);
        for (int c = 0; c < 8; c++) {
            double x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
            kd.addPoint(a, 0, x, y, z);
            kd.addPoint(b, 0, x + dx, y + dy, z + dz);
        }
        return kd.separation(a, 0, b, 0);
    }

    @Test
    void separationOfTwoCubesIsTheWidestSlabGapOverTheDirectionsLength() {
        double tol = 1e-14;
        // face to face, 1 apart: the x slabs [0,1] and [2,3]; x+y spans [0,2] and [2,4], gap 0
        for (int k : Kdop.SUPPORTED_K) assertEquals(1, separation(k, 2, 0, 0), tol, "k=" + k);
        // edge to edge along (1,1,0): distance √2; axes see 1, x+y sees (4-2)/√2 = √2
        assertEquals(1, separation(6, 2, 2, 0), tol);
        assertEquals(1, separation(14, 2, 2, 0), tol);       // x+y+z: [4,6] vs [0,3] gives 1/√3
        assertEquals(Math.sqrt(2), separation(18, 2, 2, 0), tol);
        assertEquals(Math.sqrt(2), separation(26, 2, 2, 0), tol);
        // corner to corner along (1,1,1): distance √3; x+y+z sees (6-3)/√3 = √3, x+y sees (4-2)/√2
        assertEquals(1, separation(6, 2, 2, 2), tol);
        assertEquals(Math.sqrt(3), separation(14, 2, 2, 2), tol);
        assertEquals(Math.sqrt(2), separation(18, 2, 2, 2), tol);
        assertEquals(Math.sqrt(3), separation(26, 2, 2, 2), tol);
        // overlapping cubes: not positive
        for (int k : Kdop.SUPPORTED_K) assertTrue(separation(k, 0.5, 0.5, 0) <= 0, "k=" + k);
    }

    /** The largest displacement of B's vertices in A's frame between poses p0 and p1 (exact over the hull). */
    private static double displacement(TriangleMesh b, double[] p0, double[] p1) {
        double[] v = b.vertices();
        double worst = 0;
        for (int i = 0; i < v.length; i += 3) {
            double s = 0;
            for (int r = 0; r < 3; r++) {
                double d = (p1[4 * r] - p0[4 * r]) * v[i] + (p1[4 * r + 1] - p0[4 * r + 1]) * v[i + 1]
                    + (p1[4 * r + 2] - p0[4 * r + 2]) * v[i + 2] + (p1[4 * r + 3] - p0[4 * r + 3]);
                s += d * d;
            }
            worst = Math.max(worst, Math.sqrt(s));
        }
        return worst * (1 + 1e-12);
    }

    private static void assertSameResult(CollisionResult want, CollisionResult got, String what) {
        assertEquals(want.pairCount(), got.pairCount(), "pairs, " + what);
        assertEquals(want.segmentCount(), got.segmentCount(), "segments, " + what);
        for (int p = 0; p < want.pairCount(); p++) {
            assertEquals(want.triangleA(p), got.triangleA(p), "pair " + p + " A, " + what);
            assertEquals(want.triangleB(p), got.triangleB(p), "pair " + p + " B, " + what);
            assertEquals(want.isCoplanar(p), got.isCoplanar(p), "pair " + p + " coplanar, " + what);
            assertEquals(want.coplanarArea(p), got.coplanarArea(p), "pair " + p + " area, " + what);
            assertEquals(want.segmentStart(p + 1), got.segmentStart(p + 1), "pair " + p + " segments, " + what);
        }
        assertArrayEquals(Arrays.copyOf(want.segments(), 6 * want.segmentCount()), Arrays.copyOf(got.segments(), 6 * got.segmentCount()),
            "segment end points, " + what);
    }

    @Test
    void nearPairsGiveTheFullQueryAtEveryCoveredPose() {
        SplittableRandom r = new SplittableRandom(SEED);
        TreeQuery full = new TreeQuery(), coherent = new TreeQuery();
        CollisionResult want = new CollisionResult(), got = new CollisionResult(), first = new CollisionResult();
        NearPairs near = new NearPairs();
        double[] p0 = new double[12], p1 = new double[12];
        int covered = 0, notCovered = 0, withPairs = 0, emptySets = 0;
        double[] steps = {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 3e-3};
        for (int c = 0; c < 120; c++) {
            TriangleMesh a = KdopTreeTest.shape(r.nextInt(8), r), b = KdopTreeTest.shape(r.nextInt(8), r);
            int k = Kdop.SUPPORTED_K[c % 4];
            KdopTree ta = KdopTree.build(a, k), tb = KdopTree.build(b, k);
            RigidTransform pose0 = c % 15 == 14 ? RigidTransform.IDENTITY : KdopTreeTest.randomPose(r, 0.05);
            pose0.copyTo(p0, 0);
            double reach = c % 3 == 0 ? 0 : r.nextDouble() * 0.004;
            coherent.near(ta, tb, p0, 0, reach, near);
            assertTrue(near.clearance() >= reach * (1 - 1e-6) - 1e-9, "clearance " + near.clearance() + " below reach " + reach);
            if (near.size() == 0) emptySets++;
            for (int s = 0; s < 10; s++) {
                double step = steps[r.nextInt(steps.length)];
                // a small motion of B in its own frame: translation up to the step, rotation up to 20·step rad
                RigidTransform move = RigidTransform.fromPose((2 * r.nextDouble() - 1) * step, (2 * r.nextDouble() - 1) * step,
                    (2 * r.nextDouble() - 1) * step, (2 * r.nextDouble() - 1) * step * 20, (2 * r.nextDouble() - 1) * step * 20,
                    (2 * r.nextDouble() - 1) * step * 20);
                RigidTransform.of(p0).compose(move).copyTo(p1, 0);
                double d = displacement(b, p0, p1);
                String what = String.format(Locale.ROOT, "case %d (%s vs %s, k=%d), step %d: displacement %.3g, clearance %.3g",
                    c, a.name(), b.name(), k, s, d, near.clearance());
                if (!near.covers(d)) {
                    notCovered++;
                    double dd = d;
                    assertThrows(IllegalArgumentException.class, () -> coherent.collide(ta, tb, p1, 0, near, dd, got), what);
                    continue;
                }
                covered++;
                full.collide(ta, tb, p1, 0, want);
                coherent.collide(ta, tb, p1, 0, near, d, got);
                assertSameResult(want, got, what);
                if (want.pairCount() > 0) withPairs++;
                assertEquals(want.intersecting(), coherent.intersects(ta, tb, p1, 0, near, d, first), what);
                if (want.intersecting()) {
                    assertEquals(want.triangleA(0), first.triangleA(0), "first pair, " + what);
                    assertEquals(want.triangleB(0), first.triangleB(0), "first pair, " + what);
                }
            }
        }
        System.out.printf(Locale.ROOT, "near pairs: %d covered poses (%d with pairs), %d not covered, %d empty sets%n",
            covered, withPairs, notCovered, emptySets);
        assertTrue(covered > 600 && withPairs > 150 && notCovered > 50 && emptySets > 10,
            covered + " covered, " + withPairs + " with pairs, " + notCovered + " not covered, " + emptySets + " empty");
    }

    @Test
    void theMotionBoundHolds() {
        SplittableRandom r = new SplittableRandom(SEED);
        double[] w0 = new double[12], w1 = new double[12], id = new double[12];
        RigidTransform.IDENTITY.copyTo(id, 0);
        for (int c = 0; c < 200; c++) {
            TriangleMesh m = KdopTreeTest.shape(r.nextInt(8), r);
            KdopTree t = KdopTree.build(m, 18);
            KdopTreeTest.randomPose(r, 0.05).copyTo(w0, 0);
            double step = Math.pow(10, -1 - 5 * r.nextDouble());
            RigidTransform.of(w0).compose(KdopTreeTest.randomPose(r, step)).copyTo(w1, 0);
            if (c % 2 == 0) RigidTransform.of(w1).compose(RigidTransform.fromPose(0, 0, 0, step, -step, step)).copyTo(w1, 0);
            double bound = CoherentQuery.motion(t.boundingSphere(), w0, w1);
            double exact = displacement(m, w0, w1);
            assertTrue(bound >= exact * (1 - 1e-9), "case " + c + ": bound " + bound + " below " + exact);
            // not looser than the sphere about the box centre allows
            assertTrue(bound <= 3 * exact + 1e-15, "case " + c + ": bound " + bound + " for " + exact);
            assertEquals(0.0, CoherentQuery.motion(t.boundingSphere(), w0, w0), "no motion, case " + c);
        }
    }

    /**
     * A body moving in small steps (translation and turn, now and then a jump) against another
     * (B moving and A still, or A moving and B still): {@link CoherentQuery} gives the full
     * query's result (at A⁻¹·B) at every step, bit for bit, both {@code collide} and
     * {@code intersects}, and walks the trees on a minority of the steps.
     */
    @Test
    void aCoherentQueryGivesTheFullQueryAtEveryStep() {
        SplittableRandom r = new SplittableRandom(SEED + 1);
        TreeQuery q = new TreeQuery(), full = new TreeQuery();
        CollisionResult want = new CollisionResult(), got = new CollisionResult(), first = new CollisionResult();
        double[] pose = new double[12], worldFromA = new double[12], worldFromB = new double[12];
        long steps = 0, withPairs = 0, walks = 0;
        for (int c = 0; c < TestEffort.cases(24); c++) {
            TriangleMesh a = KdopTreeTest.shape(r.nextInt(8), r), b = KdopTreeTest.shape(r.nextInt(8), r);
            KdopTree ta = KdopTree.build(a, 18), tb = KdopTree.build(b, 18);
            CoherentQuery cq = new CoherentQuery();
            // centres 5 cm apart along a random direction, B moving 50-150 µm a step towards A and turning slowly
            double ux = r.nextGaussian(), uy = r.nextGaussian(), uz = r.nextGaussian(), ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
            double speed = 5e-5 * (1 + 2 * r.nextDouble());
            double wx = r.nextGaussian() * 1e-3, wy = r.nextGaussian() * 1e-3, wz = r.nextGaussian() * 1e-3;
            for (int s = 0; s < 400; s++) {
                double d = 0.05 - speed * s;
                RigidTransform.fromPose(ux / ul * d, uy / ul * d, uz / ul * d, wx * s, wy * s, wz * s).copyTo(pose, 0);
                if (s % 97 == 96) pose[3] += 0.003;      // a jump now and then
                // in a common frame: A fixed at a pose, B at A·pose (half the cases A moves instead)
                RigidTransform base = c % 2 == 0 ? RigidTransform.fromPose(0.1, -0.2, 0.05, 0.3, 0.2, -0.1)
                    : RigidTransform.of(pose).inverse();
                base.copyTo(worldFromA, 0);
                base.compose(RigidTransform.of(pose)).copyTo(worldFromB, 0);
                double[] rel = new double[12], scratch = new double[12];
                RigidTransform.inverseTimes(worldFromA, worldFromB, scratch, rel);
                full.collide(ta, tb, rel, 0, want);
                if (s % 3 == 0) {
                    assertEquals(want.intersecting(), cq.intersects(q, ta, worldFromA, tb, worldFromB, first), "case " + c + " step " + s);
                } else {
                    cq.collide(q, ta, worldFromA, tb, worldFromB, got);
                    assertSameResult(want, got, "case " + c + " (" + a.name() + " vs " + b.name() + ") step " + s);
                }
                steps++;
                if (want.intersecting()) withPairs++;
            }
            walks += cq.walks();
            assertEquals(400, cq.walks() + cq.reused());
        }
        System.out.printf(Locale.ROOT, "coherent query: %d steps (%d with pairs), %d walks%n", steps, withPairs, walks);
        assertTrue(withPairs > steps / 10, withPairs + " of " + steps + " steps with pairs");
        assertTrue(walks * 3 < steps, walks + " walks in " + steps + " steps");
    }

    @Test
    void anEmptySetCertifiesTheMeshesApartUpToItsClearance() {
        TriangleMesh s = TestMeshes.icosphere(3, 0.02);
        KdopTree t = KdopTree.build(s, 18);
        TreeQuery q = new TreeQuery();
        NearPairs near = new NearPairs();
        CollisionResult want = new CollisionResult();
        double gap = 0.003;   // sphere surfaces 3 mm apart along x (the icosphere's vertices lie on the sphere)
        double[] p0 = new double[12];
        RigidTransform.translation(0.04 + gap, 0, 0).copyTo(p0, 0);
        q.near(t, t, p0, 0, 1e-4, near);
        assertEquals(0, near.size());
        // the clearance is a lower bound of the distance (at most the 3 mm between the spheres) and not far below it:
        // the polyhedra are a little farther apart than the spheres, and the k-DOP gaps see most of it
        assertTrue(near.clearance() > 0.5 * gap && near.clearance() <= gap + 1e-3, "clearance " + near.clearance());
        // moved straight towards A by just under the clearance: still apart
        double[] p1 = p0.clone();
        p1[3] -= near.clearance() * 0.999;
        q.collide(t, t, p1, 0, want);
        assertEquals(0, want.pairCount());
        // a clearance of −∞ covers nothing: an empty set that was never gathered
        NearPairs never = new NearPairs();
        assertTrue(!never.covers(0));
    }

    @Test
    void badArgumentsAreRefusedWithTheirValue() {
        KdopTree t = KdopTree.build(TestMeshes.icosphere(1, 0.02), 18), t6 = KdopTree.build(TestMeshes.icosphere(1, 0.02), 6);
        double[] id = new double[12];
        RigidTransform.IDENTITY.copyTo(id, 0);
        NearPairs near = new NearPairs();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new TreeQuery().near(t, t, id, 0, -1, near));
        assertTrue(e.getMessage().contains("-1"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new TreeQuery().near(t, t, id, 0, Double.NaN, near));
        assertThrows(IllegalArgumentException.class, () -> new TreeQuery().near(t, t6, id, 0, 0, near));
    }
}
