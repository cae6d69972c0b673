package org.handsim.collision;

import java.util.Arrays;
import org.handsim.math.RigidTransform;

/**
 * Collision query between two {@link KdopTree}s, B placed in A's frame by a rigid transform:
 * every intersecting triangle pair with its segments (paper Section IV, first step).
 *
 * <p><b>The walk</b> (Klosowski et al. 1998; FCL {@code collisionRecurse}, here with an
 * explicit stack): push the two roots; pop a node pair and test their k-DOPs; if they are
 * disjoint, drop the pair; if both are leaves, test their triangle pairs
 * ({@link TriangleIntersector}); otherwise replace the pair by the two pairs made with the
 * children of the node with more triangles. The walk only calls {@link Kdop#overlap} with k
 * as a number of slots and the triangle test: it knows nothing of the direction set.
 *
 * <p><b>Placement of B</b> (DESIGN.md decision 4). Tree A is used as it is; B's tree is stored
 * in B's own frame and must be seen in A's frame. Two ways, both measured
 * (docs/BENCHMARKS.md, "collision"):
 * <ul>
 *   <li>{@link Placement#REFIT}: transform all of B's vertices into A's frame and refit every
 *       k-DOP of B bottom-up into this query's scratch (O(n) per query, exact-fit bounds);</li>
 *   <li>{@link Placement#TRANSFORM}, the default: walk in A's frame and map B's stored k-DOPs
 *       on demand, only for the nodes the walk visits, by a conservative linear map
 *       ({@link TransformedBounds}; leaves are fitted exactly to their placed vertices); transform
 *       only the B vertices the walk touches. Internal bounds are looser than refitted ones (a
 *       k-DOP of a rotated k-DOP), so the walk tests more node pairs, but it never pays for the
 *       parts of B far from A. Measured (docs/BENCHMARKS.md, rotated sphere overlap, k = 18):
 *       about equal at 320 triangles, 1.5× faster at 1 280, 3.7× at 5 120, 7× at 20 480;
 *       40–160× on the near misses (a refit is O(n) even when nothing is close); at hand scale
 *       (140-triangle finger links against the sphere and the mug) within ±30 % either way,
 *       and REFIT is a microsecond ahead only where B is the 12-triangle box.</li>
 * </ul>
 * Both give exactly the same pairs (the bounds are conservative, and B's vertices are
 * transformed by the same formula, {@link KdopTree#transformPoints}). Before either, B's root
 * box is placed as an oriented box and tested against A's root box: separated meshes cost a
 * few dozen flops. For an exactly identity transform no placement work is done at all.
 * <p><b>Allocation.</b> None per query once the scratch (stack, caches, result buffers) has
 * grown to the sizes the trees need.
 *
 * <p><b>Threads.</b> A query object holds scratch: one per thread. Trees are only read; many
 * queries may share them (but nobody may {@link KdopTree#refit} a tree during a query).
 */
public final class TreeQuery {
    /** How tree B is brought into A's frame. */
    public enum Placement {
        /** Transform all of B's vertices and refit all of B's k-DOPs (in this query's scratch). */
        REFIT,
        /** Map B's k-DOPs and vertices lazily, only where the walk goes. */
        TRANSFORM
    }

    /** The placement a new query uses (chosen by benchmark). */
    public static final Placement DEFAULT_PLACEMENT = Placement.TRANSFORM;

    private Placement placement = DEFAULT_PLACEMENT;
    private final TriangleIntersector tt = new TriangleIntersector();
    private final TransformedBounds tb = new TransformedBounds();
    private final double[] m = new double[12];
    private int[] stack = new int[256];
    private double[] placedBounds = new double[0];
    private int[] nodeStamp = new int[0];
    private double[] placedVerts = new double[0];
    private int[] vertStamp = new int[0];
    private int stamp;

    /** Sets the placement; returns this. */
    public TreeQuery placement(Placement p) {
        if (p == null) throw new IllegalArgumentException("placement must not be null");
        placement = p;
        return this;
    }

    /** @return the placement in use */
    public Placement placement() { return placement; }

    /**
     * All intersecting triangle pairs of A and B, B placed in A's frame by {@code poseB}
     * (B's tree frame → A's tree frame). Segments are in A's frame, metres.
     *
     * @param out cleared and filled (pass the same object every time to avoid allocation)
     * @return {@code out}
     * @throws IllegalArgumentException if the trees have different k
     */
    public CollisionResult collide(KdopTree a, KdopTree b, RigidTransform poseB, CollisionResult out) {
        poseB.copyTo(m, 0);
        run(a, b, out, false);
        return out;
    }

    /** As {@link #collide(KdopTree, KdopTree, RigidTransform, CollisionResult)} with the 12 row-major values at {@code pose[off..]}. */
    public CollisionResult collide(KdopTree a, KdopTree b, double[] pose, int off, CollisionResult out) {
        System.arraycopy(pose, off, m, 0, 12);
        run(a, b, out, false);
        return out;
    }

    /** True if A and B placed by {@code poseB} intersect; stops at the first pair (counters in {@code out}). */
    public boolean intersects(KdopTree a, KdopTree b, RigidTransform poseB, CollisionResult out) {
        poseB.copyTo(m, 0);
        run(a, b, out, true);
        return out.intersecting();
    }

    /** As {@link #intersects(KdopTree, KdopTree, RigidTransform, CollisionResult)} with the 12 row-major values at {@code pose[off..]}. */
    public boolean intersects(KdopTree a, KdopTree b, double[] pose, int off, CollisionResult out) {
        System.arraycopy(pose, off, m, 0, 12);
        run(a, b, out, true);
        return out.intersecting();
    }

    private static boolean isIdentity(double[] m) {
        return m[0] == 1 && m[1] == 0 && m[2] == 0 && m[3] == 0 && m[4] == 0 && m[5] == 1 && m[6] == 0 && m[7] == 0
            && m[8] == 0 && m[9] == 0 && m[10] == 1 && m[11] == 0;
    }

    private void run(KdopTree a, KdopTree b, CollisionResult out, boolean stopAtFirst) {
        if (a.k() != b.k()) throw new IllegalArgumentException("trees have different k: " + a.k() + " and " + b.k());
        out.clear();
        if (a.nodeCount == 0 || b.nodeCount == 0) return;
        long exact0 = tt.predicates().exactCalls();
        double[] bv = b.vertices();
        int nbv = bv.length / 3, nbt = b.tris.length / 3;
        boolean identity = isIdentity(m);
        if (!identity && !rootBoxesMayOverlap(a, b)) {
            out.nodeTests = 1;
            return;
        }
        boolean refit = !identity && placement == Placement.REFIT;
        lazy = !identity && placement == Placement.TRANSFORM;
        if (++stamp == Integer.MAX_VALUE) {
            Arrays.fill(nodeStamp, 0);
            Arrays.fill(vertStamp, 0);
            Arrays.fill(triStamp, 0);
            stamp = 1;
        }
        if (identity) {
            bb = b.bounds;
            vb = bv;
            nB = b.triN;
            nAbsB = b.triNAbs;
        } else {
            if (placedVerts.length < bv.length) placedVerts = new double[bv.length];
            if (placedBounds.length < b.bounds.length) placedBounds = new double[b.bounds.length];
            if (vertStamp.length < nbv) vertStamp = new int[nbv];
            if (nodeStamp.length < b.nodeCount) nodeStamp = new int[b.nodeCount];
            if (triStamp.length < nbt) {
                triStamp = new int[nbt];
                placedN = new double[3 * nbt];
                placedNAbs = new double[3 * nbt];
            }
            bb = placedBounds;
            vb = placedVerts;
            nB = placedN;
            nAbsB = placedNAbs;
            if (refit) {
                KdopTree.transformPoints(m, bv, placedVerts, nbv);
                b.fitBounds(placedVerts, placedBounds);
            } else {
                tb.prepare(b.kdop(), m);
            }
        }
        normalsPlaced = identity;
        walk(a, b, out, stopAtFirst);
        out.exactPredicates = tt.predicates().exactCalls() - exact0;
    }

    /**
     * The cheap first test: B's root box (k-DOP slots 0..5), placed by m as an oriented box and
     * bounded by an axis-aligned one (Arvo's |R| rule), against A's root box, widened by 1e-12
     * of the magnitudes for rounding. False only if the roots cannot overlap: then no placement
     * work at all (the separated case costs a few dozen flops).
     */
    private boolean rootBoxesMayOverlap(KdopTree a, KdopTree b) {
        double[] ra = a.bounds, rb = b.bounds;
        double cx = 0.5 * (rb[0] + rb[1]), cy = 0.5 * (rb[2] + rb[3]), cz = 0.5 * (rb[4] + rb[5]);
        double ex = 0.5 * (rb[1] - rb[0]), ey = 0.5 * (rb[3] - rb[2]), ez = 0.5 * (rb[5] - rb[4]);
        for (int i = 0; i < 3; i++) {
            double r0 = m[4 * i], r1 = m[4 * i + 1], r2 = m[4 * i + 2], t = m[4 * i + 3];
            double c = r0 * cx + r1 * cy + r2 * cz + t;
            double e = Math.abs(r0) * ex + Math.abs(r1) * ey + Math.abs(r2) * ez;
            double mg = 1e-12 * (Math.abs(r0 * cx) + Math.abs(r1 * cy) + Math.abs(r2 * cz) + Math.abs(t) + e);
            if (c - e - mg > ra[2 * i + 1] || c + e + mg < ra[2 * i]) return false;
        }
        return true;
    }

    // per-query state of the walk
    private boolean lazy, normalsPlaced;
    private double[] bb, vb, nB, nAbsB;
    private int[] triStamp = new int[0];
    private double[] placedN = new double[0], placedNAbs = new double[0];

    /** Makes B node nb's bounds available in A's frame (lazy placement), at bb[nb·k]. */
    private void placeNode(KdopTree b, int nb) {
        if (nodeStamp[nb] == stamp) return;
        nodeStamp[nb] = stamp;
        int k = b.k(), o = nb * k;
        int c = b.child[nb];
        if (c < 0) {
            // a leaf: the exact k-DOP of its placed vertices (which the triangle tests need anyway)
            Kdop kd = b.kdop();
            kd.setEmpty(bb, o);
            double[] src = b.vertices();
            for (int j = ~c, e = j + b.size[nb]; j < e; j++) {
                int t = 3 * b.order[j];
                for (int q = 0; q < 3; q++) {
                    int p = 3 * b.tris[t + q];
                    placeVertex(src, p);
                    kd.addPoint(bb, o, vb[p], vb[p + 1], vb[p + 2]);
                }
            }
        } else {
            tb.apply(b.bounds, o, bb, o);
        }
    }

    private void placeVertex(double[] src, int off) {
        int v = off / 3;
        if (vertStamp[v] != stamp) {
            KdopTree.transformPoint(m, src, off, vb, off);
            vertStamp[v] = stamp;
        }
    }

    /** Makes B triangle t's normal (from its placed vertices) available at nB[3t]. */
    private void placeNormal(KdopTree b, int t) {
        if (triStamp[t] == stamp) return;
        triStamp[t] = stamp;
        int o = 3 * t;
        int p0 = 3 * b.tris[o], p1 = 3 * b.tris[o + 1], p2 = 3 * b.tris[o + 2];
        if (lazy) {
            double[] src = b.vertices();
            placeVertex(src, p0);
            placeVertex(src, p1);
            placeVertex(src, p2);
        }
        double[] v = vb;
        Predicates.normal(v[p0], v[p0 + 1], v[p0 + 2], v[p1], v[p1 + 1], v[p1 + 2], v[p2], v[p2 + 1], v[p2 + 2], nB, nAbsB, o);
    }

    private void walk(KdopTree a, KdopTree b, CollisionResult out, boolean stopAtFirst) {
        final int k = a.k();
        final double[] ba = a.bounds, va = a.vertices(), nA = a.triN, nAbsA = a.triNAbs;
        final double[] bbl = bb;
        final int[] childA = a.child, childB = b.child, sizeA = a.size, sizeB = b.size;
        final int[] orderA = a.order, orderB = b.order, trisA = a.tris, trisB = b.tris;
        final boolean[] degA = a.degenerate, degB = b.degenerate;
        final boolean lz = lazy, placeNormals = !normalsPlaced;
        int[] stk = stack;
        int sp = 0;
        long tests = 1, triTests = 0, degSkipped = 0;
        if (lz) placeNode(b, 0);
        if (Kdop.overlap(ba, 0, bbl, 0, k)) {
            stk[sp++] = 0;
            stk[sp++] = 0;
        }
        while (sp > 0) {
            int nb = stk[--sp], na = stk[--sp];
            int ca = childA[na], cb = childB[nb];
            if (ca < 0 && cb < 0) {
                int fa = ~ca, ea = fa + sizeA[na], fb = ~cb, eb = fb + sizeB[nb];
                for (int i = fa; i < ea; i++) {
                    int ta = orderA[i];
                    for (int j = fb; j < eb; j++) {
                        int tbi = orderB[j];
                        if (degA[ta] || degB[tbi]) {
                            degSkipped++;
                            continue;
                        }
                        if (placeNormals) placeNormal(b, tbi);
                        triTests++;
                        int r = tt.intersect(va, 3 * trisA[3 * ta], 3 * trisA[3 * ta + 1], 3 * trisA[3 * ta + 2], nA, nAbsA, 3 * ta,
                            vb, 3 * trisB[3 * tbi], 3 * trisB[3 * tbi + 1], 3 * trisB[3 * tbi + 2], nB, nAbsB, 3 * tbi);
                        if (r != TriangleIntersector.DISJOINT) {
                            out.add(ta, tbi, tt, r);
                            if (stopAtFirst) {
                                sp = 0;
                                i = ea;
                                break;
                            }
                        }
                    }
                }
                continue;
            }
            if (sp + 4 > stk.length) {
                stk = Arrays.copyOf(stk, 2 * stk.length);
                stack = stk;
            }
            tests += 2;
            if (cb < 0 || (ca >= 0 && sizeA[na] >= sizeB[nb])) {
                int ob = nb * k;
                if (Kdop.overlap(ba, ca * k, bbl, ob, k)) {
                    stk[sp++] = ca; stk[sp++] = nb;
                }
                if (Kdop.overlap(ba, (na + 1) * k, bbl, ob, k)) {
                    stk[sp++] = na + 1; stk[sp++] = nb;
                }
            } else {
                int oa = na * k;
                if (lz) {
                    placeNode(b, cb);
                    placeNode(b, nb + 1);
                }
                if (Kdop.overlap(ba, oa, bbl, cb * k, k)) {
                    stk[sp++] = na; stk[sp++] = cb;
                }
                if (Kdop.overlap(ba, oa, bbl, (nb + 1) * k, k)) {
                    stk[sp++] = na; stk[sp++] = nb + 1;
                }
            }
        }
        out.nodeTests = tests;
        out.triangleTests = triTests;
        out.degenerateSkipped = degSkipped;
    }
}
