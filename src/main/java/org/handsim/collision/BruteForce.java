package org.handsim.collision;

import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * The all-pairs reference: every triangle of A against every triangle of B placed by a rigid
 * transform, with the same triangle test, the same vertex transform
 * ({@link KdopTree#transformPoints}) and the same zero-area rule as {@link TreeQuery}, so a
 * correct tree walk must return exactly its pairs. O(n·m): for tests and benchmarks.
 *
 * <p>Not thread-safe (scratch); one per thread.
 */
public final class BruteForce {
    private final TriangleIntersector tt = new TriangleIntersector();
    private final Predicates pred = new Predicates();
    private final double[] m = new double[12];
    private double[] placed = new double[0];

    /**
     * @param poseB B's frame → A's frame
     * @param out   cleared and filled; counters: triangle tests and degenerate pairs skipped
     * @return {@code out}
     */
    public CollisionResult collide(TriangleMesh a, TriangleMesh b, RigidTransform poseB, CollisionResult out) {
        out.clear();
        poseB.copyTo(m, 0);
        double[] vb = b.vertices();
        if (placed.length < vb.length) placed = new double[vb.length];
        KdopTree.transformPoints(m, vb, placed, b.vertexCount());
        double[] va = a.vertices();
        int[] ta = a.triangles(), tb = b.triangles();
        int na = a.triangleCount(), nb = b.triangleCount();
        boolean[] degA = degenerate(a), degB = degenerate(b);
        long exact0 = tt.predicates().exactCalls();
        for (int i = 0; i < na; i++) {
            for (int j = 0; j < nb; j++) {
                if (degA[i] || degB[j]) {
                    out.degenerateSkipped++;
                    continue;
                }
                out.triangleTests++;
                int r = tt.intersect(va, 3 * ta[3 * i], 3 * ta[3 * i + 1], 3 * ta[3 * i + 2],
                    placed, 3 * tb[3 * j], 3 * tb[3 * j + 1], 3 * tb[3 * j + 2]);
                if (r != TriangleIntersector.DISJOINT) out.add(i, j, tt, r);
            }
        }
        out.exactPredicates = tt.predicates().exactCalls() - exact0;
        return out;
    }

    /** Exactly collinear triangles of the mesh (in its own frame), by {@link KdopTree}'s own rule. */
    boolean[] degenerate(TriangleMesh mesh) {
        double[] v = mesh.vertices();
        int[] t = mesh.triangles();
        boolean[] d = new boolean[mesh.triangleCount()];
        for (int i = 0; i < d.length; i++) d[i] = KdopTree.collinear(pred, v, t, i);
        return d;
    }
}
