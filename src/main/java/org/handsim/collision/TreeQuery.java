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
 * as a number of slots and the triangle test: it knows nothing of the direction set. For a
 * leaf pair the first stage of the exact triangle test (each triangle's vertices against the
 * other's plane, filtered) runs in the walk, with the triangle's normal in locals, and is
 * passed on to {@link TriangleIntersector}: the disjoint pairs it settles (half of them on the
 * rotated sphere overlap) are never loaded into the intersector.
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
 *       parts of B far from A. When the walk places a node's two children it also tightens
 *       the node's placed bounds to the merge of theirs (a mapped k-DOP is looser the bigger
 *       the node): fewer node pairs, the same pairs found in the same order.
 *       Measured (docs/BENCHMARKS.md, rotated sphere overlap, k = 18):
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
    private double[] sepStack = new double[128];          // the gathering's node-pair separations, beside the stack
    private final double[] triBox = new double[6];        // the gathering's current A triangle's box
    private double[] placedBounds = new double[0];
    private int[] nodeStamp = new int[0];
    private double[] placedVerts = new double[0];
    private int[] vertStamp = new int[0];
    private int stamp;

    /**
     * Puts this query in the state of a new one — the default placement, no facet hints — keeping
     * its scratch arrays (their stamps stay valid: they only grow); returns this. For reuse by a
     * new owner (SceneGeometry's takeover of a retired instance's scratch).
     */
    public TreeQuery recycle() {
        placement = DEFAULT_PLACEMENT;
        tb.forgetHints();
        return this;
    }

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

    // ------------------------------------------------------------------ temporal coherence

    /**
     * Gathers into {@code out} the triangle pairs of A and B (B placed in A's frame by the 12
     * row-major values at {@code pose[off..]}) whose bounds are within {@code reach} metres of
     * each other, and the clearance up to which they stand for the full query ({@link NearPairs}
     * states the contract). The walk is the full query's, with each k-DOP overlap test replaced
     * by the separation of the two k-DOPs ({@link Kdop#separation}) compared with the reach, and
     * the triangle tests replaced by a test of the two triangles' axis-aligned boxes.
     *
     * @param reach metres, ≥ 0: pairs closer than this are kept; a larger reach keeps more pairs
     *              and gives a clearance at least as large
     * @return {@code out}
     * @throws IllegalArgumentException if the trees have different k or reach is negative or NaN
     */
    public NearPairs near(KdopTree a, KdopTree b, double[] pose, int off, double reach, NearPairs out) {
        if (a.k() != b.k()) throw new IllegalArgumentException("trees have different k: " + a.k() + " and " + b.k());
        if (!(reach >= 0)) throw new IllegalArgumentException("reach must be >= 0, got " + reach);
        System.arraycopy(pose, off, m, 0, 12);
        out.clear();
        out.reach = reach;
        if (a.nodeCount == 0 || b.nodeCount == 0) {
            out.clearance = Double.POSITIVE_INFINITY;
            return out;
        }
        double margin = roundingMargin(a, b);
        boolean identity = isIdentity(m);
        if (!identity) {
            double gap = rootBoxGap(a, b);
            if (gap > reach) {
                out.nodeTests = 1;
                out.clearance = gap - margin;
                return out;
            }
        }
        placeWithHints(b, identity, out.facetHints);
        out.margin = margin;
        out.clearance = gather(a, b, reach, margin, out) - margin;
        return out;
    }

    /**
     * The full query's result at a pose the near pairs cover, from the near pairs alone: each
     * pair whose separation is below {@code displacement} is tested as the full walk tests it,
     * in the walk's order; the others cannot intersect. The caller vouches for the cover: no
     * point of one mesh moved by {@code displacement} metres or more relative to the other since
     * the gathering pose, and {@code displacement} &lt; {@link NearPairs#clearance()}. The
     * node-test counter is 0.
     *
     * @param out cleared and filled
     * @return {@code out}
     * @throws IllegalArgumentException if the displacement is not below the clearance
     */
    public CollisionResult collide(KdopTree a, KdopTree b, double[] pose, int off, NearPairs near, double displacement,
                                   CollisionResult out) {
        System.arraycopy(pose, off, m, 0, 12);
        testNear(a, b, near, displacement, out, false);
        return out;
    }

    /** As {@link #collide(KdopTree, KdopTree, double[], int, NearPairs, double, CollisionResult)}, stopping at the first intersecting pair. */
    public boolean intersects(KdopTree a, KdopTree b, double[] pose, int off, NearPairs near, double displacement,
                              CollisionResult out) {
        System.arraycopy(pose, off, m, 0, 12);
        testNear(a, b, near, displacement, out, true);
        return out.intersecting();
    }

    private void testNear(KdopTree a, KdopTree b, NearPairs near, double displacement, CollisionResult out, boolean stopAtFirst) {
        if (a.k() != b.k()) throw new IllegalArgumentException("trees have different k: " + a.k() + " and " + b.k());
        if (!near.covers(displacement)) {
            throw new IllegalArgumentException("displacement " + displacement + " m is not below the near pairs' clearance " + near.clearance() + " m");
        }
        out.clear();
        int n = near.count;
        if (n == 0) return;
        long exact0 = tt.predicates().exactCalls();
        place(b, isIdentity(m), Placement.TRANSFORM, false);
        final double[] va = a.vertices(), nA = a.triN, nAbsA = a.triNAbs;
        final int[] trisA = a.tris, trisB = b.tris, nta = near.triA, ntb = near.triB;
        final double[] gap = near.gap;
        final boolean placeNormals = !normalsPlaced;
        int tested = 0;
        final boolean[] pending = near.pending;
        for (int i = 0; i < n; i++) {
            if (gap[i] > displacement) continue;
            int ta = nta[i], tbi = ntb[i];
            if (pending[i]) {
                // the pair's bound with the edge-edge axes, as the gathering would have made it
                // (B's vertices as placed then): the same number, so the same pairs are tested
                pending[i] = false;
                double[] ab = near.anchorB;
                int o = 9 * i;
                gap[i] = Math.max(near.boundWithoutEdges[i], edgeAxesGap(va, 3 * trisA[3 * ta], 3 * trisA[3 * ta + 1], 3 * trisA[3 * ta + 2],
                    ab, o, o + 3, o + 6)) - near.margin;
                if (gap[i] > displacement) continue;
            }
            if (placeNormals) placeNormal(b, tbi);
            tested++;
            int r = tt.intersect(va, 3 * trisA[3 * ta], 3 * trisA[3 * ta + 1], 3 * trisA[3 * ta + 2], nA, nAbsA, 3 * ta,
                vb, 3 * trisB[3 * tbi], 3 * trisB[3 * tbi + 1], 3 * trisB[3 * tbi + 2], nB, nAbsB, 3 * tbi);
            if (r != TriangleIntersector.DISJOINT) {
                out.add(ta, tbi, tt, r);
                if (stopAtFirst) break;
            }
        }
        out.triangleTests = tested;
        out.exactPredicates = tt.predicates().exactCalls() - exact0;
    }

    /**
     * How much the clearance is lowered for rounding (metres): 10⁻⁹ of the coordinates'
     * magnitude (A's root box, B's root box, the translation). The rounding it covers — of the
     * placed vertices, of the bounds, of the caller's displacement bound — is about 10⁻¹⁵ of it.
     */
    private double roundingMargin(KdopTree a, KdopTree b) {
        double s = 0;
        for (int j = 0; j < 6; j++) s = Math.max(s, Math.max(Math.abs(a.bounds[j]), Math.abs(b.bounds[j])));
        s += Math.max(Math.abs(m[3]), Math.max(Math.abs(m[7]), Math.abs(m[11])));
        return 1e-9 * s;
    }

    /**
     * The gap between A's root box and B's root box placed as an oriented box and bounded by an
     * axis-aligned one (as {@link #rootBoxesMayOverlap}): the widest gap along one axis, a lower
     * bound on the distance between the meshes; ≤ 0 when the boxes may overlap.
     */
    private double rootBoxGap(KdopTree a, KdopTree b) {
        double[] ra = a.bounds, rb = b.bounds;
        double cx = 0.5 * (rb[0] + rb[1]), cy = 0.5 * (rb[2] + rb[3]), cz = 0.5 * (rb[4] + rb[5]);
        double ex = 0.5 * (rb[1] - rb[0]), ey = 0.5 * (rb[3] - rb[2]), ez = 0.5 * (rb[5] - rb[4]);
        double gap = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < 3; i++) {
            double r0 = m[4 * i], r1 = m[4 * i + 1], r2 = m[4 * i + 2], t = m[4 * i + 3];
            double c = r0 * cx + r1 * cy + r2 * cz + t;
            double e = Math.abs(r0) * ex + Math.abs(r1) * ey + Math.abs(r2) * ez;
            double mg = 1e-12 * (Math.abs(r0 * cx) + Math.abs(r1 * cy) + Math.abs(r2 * cz) + Math.abs(t) + e);
            gap = Math.max(gap, Math.max(c - e - mg - ra[2 * i + 1], ra[2 * i] - (c + e + mg)));
        }
        return gap;
    }

    /**
     * The gap between triangles (p0, p1, p2) and (q0, q1, q2) along the axis n
     * ({@code n[o..o+2]}, not unit): the distance between their projections, ≤ 0 when these
     * overlap. A lower bound on the distance between the triangles for any axis; with a
     * triangle's normal it is how far the other lies off its plane. The normal is computed in
     * floating point (a sliver's may point anywhere): that is why all six vertices are
     * projected, not only the other triangle's.
     */
    private static double axisGap(double[] n, int o, double[] vp, int p0, int p1, int p2, double[] vq, int q0, int q1, int q2) {
        double nx = n[o], ny = n[o + 1], nz = n[o + 2];
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 0)) return Double.NEGATIVE_INFINITY;
        double a0 = nx * vp[p0] + ny * vp[p0 + 1] + nz * vp[p0 + 2];
        double a1 = nx * vp[p1] + ny * vp[p1 + 1] + nz * vp[p1 + 2];
        double a2 = nx * vp[p2] + ny * vp[p2 + 1] + nz * vp[p2 + 2];
        double b0 = nx * vq[q0] + ny * vq[q0 + 1] + nz * vq[q0 + 2];
        double b1 = nx * vq[q1] + ny * vq[q1 + 1] + nz * vq[q1 + 2];
        double b2 = nx * vq[q2] + ny * vq[q2 + 1] + nz * vq[q2 + 2];
        double aLo = Math.min(a0, Math.min(a1, a2)), aHi = Math.max(a0, Math.max(a1, a2));
        double bLo = Math.min(b0, Math.min(b1, b2)), bHi = Math.max(b0, Math.max(b1, b2));
        return Math.max(bLo - aHi, aLo - bHi) / len;
    }

    /**
     * The largest gap between the two triangles along the nine cross products of an edge of
     * one and an edge of the other (the edge–edge axes of the separating-axis test; parallel
     * edges give no axis): with the normals' gaps ({@link #axisGap}), the separating-axis lower
     * bound on their distance, exact when the closest points are inside two edges.
     */
    private final double[] axis = new double[3];
    private final int[] edgeA = new int[6], edgeB = new int[6];

    private double edgeAxesGap(double[] va, int a0, int a1, int a2, double[] vb, int b0, int b1, int b2) {
        int[] ea = edgeA, eb = edgeB;
        ea[0] = a0; ea[1] = a1; ea[2] = a1; ea[3] = a2; ea[4] = a2; ea[5] = a0;
        eb[0] = b0; eb[1] = b1; eb[2] = b1; eb[3] = b2; eb[4] = b2; eb[5] = b0;
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < 6; i += 2) {
            double ux = va[ea[i + 1]] - va[ea[i]], uy = va[ea[i + 1] + 1] - va[ea[i] + 1], uz = va[ea[i + 1] + 2] - va[ea[i] + 2];
            for (int j = 0; j < 6; j += 2) {
                double wx = vb[eb[j + 1]] - vb[eb[j]], wy = vb[eb[j + 1] + 1] - vb[eb[j] + 1], wz = vb[eb[j + 1] + 2] - vb[eb[j] + 2];
                axis[0] = uy * wz - uz * wy;
                axis[1] = uz * wx - ux * wz;
                axis[2] = ux * wy - uy * wx;
                best = Math.max(best, axisGap(axis, 0, va, a0, a1, a2, vb, b0, b1, b2));
            }
        }
        return best;
    }

    /**
     * The walk of {@link #walk} with separations instead of overlap tests (a pair is dropped as
     * soon as one direction separates it by more than the reach, that gap counting towards the
     * clearance, so the clearance is a little above the reach rather than the best bound): keeps the triangle
     * pairs within {@code reach}, each with its separation (the largest of its leaf pair's, its
     * triangles' boxes' and their gaps along the separating axes — each triangle's normal and,
     * when those leave them apart, the nine edge–edge cross products — less
     * {@code margin}), returns the smallest separation of what it dropped (+∞ if
     * nothing). Counts its node tests into {@code out}.
     */
    private double gather(KdopTree a, KdopTree b, double reach, double margin, NearPairs out) {
        final Kdop kd = a.kdop();
        final int k = a.k();
        final double[] ba = a.bounds, va = a.vertices();
        final double[] bbl = bb;
        final int[] childA = a.child, childB = b.child, sizeA = a.size, sizeB = b.size;
        final int[] orderA = a.order, orderB = b.order, trisA = a.tris, trisB = b.tris;
        final boolean[] degA = a.degenerate, degB = b.degenerate;
        final boolean lz = lazy, placeNormals = !normalsPlaced;
        final double[] src = b.vertices(), nA = a.triN;
        int[] stk = stack;
        double[] sep = sepStack;   // sep[sp / 2 − 1]: the separation of the node pair at stk[sp − 2..]
        int sp = 0;
        long tests = 1;
        double clear = Double.POSITIVE_INFINITY;
        if (lz) placeNode(b, 0);
        double s0 = kd.separationUpTo(ba, 0, bbl, 0, reach);
        if (s0 > reach) {
            clear = s0;
        } else {
            sep[0] = s0;
            stk[sp++] = 0;
            stk[sp++] = 0;
        }
        while (sp > 0) {
            int nb = stk[--sp], na = stk[--sp];
            int ca = childA[na], cb = childB[nb];
            if (ca < 0 && cb < 0) {
                int fa = ~ca, ea = fa + sizeA[na], fb = ~cb, eb = fb + sizeB[nb];
                // pushed within the reach, so its separationUpTo was the whole separation (and
                // B's node is placed once per walk: the same bounds now)
                double leafGap = sep[sp >> 1];
                for (int i = fa; i < ea; i++) {
                    int ta = orderA[i];
                    if (degA[ta]) continue;
                    int a0 = 3 * trisA[3 * ta], a1 = 3 * trisA[3 * ta + 1], a2 = 3 * trisA[3 * ta + 2];
                    double[] boxA = triBox;
                    for (int d = 0; d < 3; d++) {
                        boxA[2 * d] = Math.min(va[a0 + d], Math.min(va[a1 + d], va[a2 + d]));
                        boxA[2 * d + 1] = Math.max(va[a0 + d], Math.max(va[a1 + d], va[a2 + d]));
                    }
                    for (int j = fb; j < eb; j++) {
                        int tbi = orderB[j];
                        if (degB[tbi]) continue;
                        int b0 = 3 * trisB[3 * tbi], b1 = 3 * trisB[3 * tbi + 1], b2 = 3 * trisB[3 * tbi + 2];
                        if (lz) {
                            placeVertex(src, b0);
                            placeVertex(src, b1);
                            placeVertex(src, b2);
                        }
                        double gap = leafGap;
                        for (int d = 0; d < 3; d++) {
                            double amin = boxA[2 * d], amax = boxA[2 * d + 1];
                            double bmin = Math.min(vb[b0 + d], Math.min(vb[b1 + d], vb[b2 + d]));
                            double bmax = Math.max(vb[b0 + d], Math.max(vb[b1 + d], vb[b2 + d]));
                            gap = Math.max(gap, Math.max(amin - bmax, bmin - amax));
                        }
                        if (gap > reach) {
                            if (gap < clear) clear = gap;
                        } else {
                            // kept (so the clearance stays at least the boxes' gap); its own bound also uses the planes
                            if (placeNormals) placeNormal(b, tbi);
                            gap = Math.max(gap, Math.max(axisGap(nA, 3 * ta, va, a0, a1, a2, vb, b0, b1, b2),
                                axisGap(nB, 3 * tbi, va, a0, a1, a2, vb, b0, b1, b2)));
                            // apart: the edge-edge axes may show more, computed when first needed (testNear)
                            if (gap > 0) out.addPending(ta, tbi, gap, vb, b0, b1, b2);
                            else out.add(ta, tbi, gap - margin);
                        }
                    }
                }
                continue;
            }
            if (sp + 4 > stk.length) {
                stk = Arrays.copyOf(stk, 2 * stk.length);
                stack = stk;
            }
            if (sp + 4 > 2 * sep.length) {
                sep = Arrays.copyOf(sep, stk.length / 2);
                sepStack = sep;
            }
            tests += 2;
            if (cb < 0 || (ca >= 0 && sizeA[na] >= sizeB[nb])) {
                int ob = nb * k;
                double s1 = kd.separationUpTo(ba, ca * k, bbl, ob, reach), s2 = kd.separationUpTo(ba, (na + 1) * k, bbl, ob, reach);
                if (s1 > reach) {
                    if (s1 < clear) clear = s1;
                } else {
                    sep[sp >> 1] = s1;
                    stk[sp++] = ca; stk[sp++] = nb;
                }
                if (s2 > reach) {
                    if (s2 < clear) clear = s2;
                } else {
                    sep[sp >> 1] = s2;
                    stk[sp++] = na + 1; stk[sp++] = nb;
                }
            } else {
                int oa = na * k;
                if (lz) {
                    placeNode(b, cb);
                    placeNode(b, nb + 1);
                }
                double s1 = kd.separationUpTo(ba, oa, bbl, cb * k, reach), s2 = kd.separationUpTo(ba, oa, bbl, (nb + 1) * k, reach);
                if (s1 > reach) {
                    if (s1 < clear) clear = s1;
                } else {
                    sep[sp >> 1] = s1;
                    stk[sp++] = na; stk[sp++] = cb;
                }
                if (s2 > reach) {
                    if (s2 < clear) clear = s2;
                } else {
                    sep[sp >> 1] = s2;
                    stk[sp++] = na; stk[sp++] = nb + 1;
                }
            }
        }
        out.nodeTests = tests;
        return clear;
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
        boolean identity = isIdentity(m);
        if (!identity && !rootBoxesMayOverlap(a, b)) {
            out.nodeTests = 1;
            return;
        }
        place(b, identity, placement, true);
        walk(a, b, out, stopAtFirst);
        out.exactPredicates = tt.predicates().exactCalls() - exact0;
    }

    /** As {@code place(b, identity, TRANSFORM, true)}, the transformed bounds prepared from the given facet hints. */
    private void placeWithHints(KdopTree b, boolean identity, int[] hints) {
        place(b, identity, Placement.TRANSFORM, false);
        if (!identity) tb.prepare(b.kdop(), m, hints);
    }

    /**
     * Sets up this query's view of B in A's frame for transform {@link #m}: B's own arrays for
     * the identity; otherwise the scratch arrays, filled now (REFIT) or on demand (TRANSFORM).
     * Without {@code bounds} only vertices and normals are placed (on demand), no k-DOP.
     */
    private void place(KdopTree b, boolean identity, Placement pl, boolean bounds) {
        double[] bv = b.vertices();
        int nbv = bv.length / 3, nbt = b.tris.length / 3;
        boolean refit = !identity && bounds && pl == Placement.REFIT;
        lazy = !identity && !refit;
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
            } else if (bounds) {
                tb.prepare(b.kdop(), m);
            }
        }
        normalsPlaced = identity;
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
    private final int[] leafVerts = new int[12];    // a leaf's distinct vertex offsets (the first 12; more are added again)
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
            int[] seen = leafVerts;
            int n = 0;
            for (int j = ~c, e = j + b.size[nb]; j < e; j++) {
                int t = 3 * b.order[j];
                vertices:
                for (int q = 0; q < 3; q++) {
                    int p = 3 * b.tris[t + q];
                    // a vertex shared by the leaf's triangles is added once (adding it again changes nothing)
                    for (int s = 0; s < n; s++) if (seen[s] == p) continue vertices;
                    if (n < seen.length) seen[n++] = p;
                    placeVertex(src, p);
                    kd.addPoint(bb, o, vb[p], vb[p + 1], vb[p + 2]);
                }
            }
        } else {
            tb.apply(b.bounds, o, bb, o);
        }
    }

    /**
     * Places B node nb's children (left nb + 1, right cb) and, when they were not placed yet,
     * tightens nb's own placed bounds to the merge of theirs where that is tighter: a k-DOP
     * mapped by {@link TransformedBounds} is looser the bigger the node, so the merge of the
     * two mapped halves is usually inside the mapped whole. Both are bounds of nb's placed
     * vertices, so the walk still finds every pair, in the same order (it only drops node pairs
     * it would have descended in vain); it tests about a fifth fewer node pairs.
     */
    private void placeChildren(KdopTree b, int nb, int cb) {
        int l = nb + 1;
        if (nodeStamp[cb] == stamp && nodeStamp[l] == stamp) return;
        int k = b.k();
        if (b.child[l] >= 0 && b.child[cb] >= 0 && nodeStamp[l] != stamp && nodeStamp[cb] != stamp) {
            nodeStamp[l] = stamp;
            nodeStamp[cb] = stamp;
            tb.apply2(b.bounds, l * k, cb * k, bb, l * k, cb * k);
        } else {
            placeNode(b, l);
            placeNode(b, cb);
        }
        double[] x = bb;
        int o = nb * k, lo = l * k, r = cb * k;
        for (int j = 0; j < k; j += 2) {
            x[o + j] = Math.max(x[o + j], Math.min(x[lo + j], x[r + j]));
            x[o + j + 1] = Math.min(x[o + j + 1], Math.max(x[lo + j + 1], x[r + j + 1]));
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
                    if (degA[ta]) {
                        degSkipped += eb - fb;
                        continue;
                    }
                    int oa = 3 * ta, a0 = 3 * trisA[oa], a1 = 3 * trisA[oa + 1], a2 = 3 * trisA[oa + 2];
                    double ax = va[a0], ay = va[a0 + 1], az = va[a0 + 2];
                    double nx = nA[oa], ny = nA[oa + 1], nz = nA[oa + 2], mx = nAbsA[oa], my = nAbsA[oa + 1], mz = nAbsA[oa + 2];
                    for (int j = fb; j < eb; j++) {
                        int tbi = orderB[j];
                        if (degB[tbi]) {
                            degSkipped++;
                            continue;
                        }
                        triTests++;
                        // the first stage of the exact test, here so that most disjoint pairs are
                        // dropped without being loaded: B's vertices against A's plane (filtered:
                        // NaN where the sign is not certain, and then the intersector decides),
                        // then A's against B's
                        int ob = 3 * tbi, b0 = 3 * trisB[ob], b1 = 3 * trisB[ob + 1], b2 = 3 * trisB[ob + 2];
                        double bx = vb[b0], by = vb[b0 + 1], bz = vb[b0 + 2];
                        double e0 = Predicates.orient3dFiltered(nx, ny, nz, mx, my, mz, ax, ay, az, bx, by, bz);
                        double e1 = Predicates.orient3dFiltered(nx, ny, nz, mx, my, mz, ax, ay, az, vb[b1], vb[b1 + 1], vb[b1 + 2]);
                        double e2 = Predicates.orient3dFiltered(nx, ny, nz, mx, my, mz, ax, ay, az, vb[b2], vb[b2 + 1], vb[b2 + 2]);
                        if ((e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0)) continue;
                        if (placeNormals) placeNormal(b, tbi);
                        double qx = nB[ob], qy = nB[ob + 1], qz = nB[ob + 2], px = nAbsB[ob], py = nAbsB[ob + 1], pz = nAbsB[ob + 2];
                        double f0 = Predicates.orient3dFiltered(qx, qy, qz, px, py, pz, bx, by, bz, ax, ay, az);
                        double f1 = Predicates.orient3dFiltered(qx, qy, qz, px, py, pz, bx, by, bz, va[a1], va[a1 + 1], va[a1 + 2]);
                        double f2 = Predicates.orient3dFiltered(qx, qy, qz, px, py, pz, bx, by, bz, va[a2], va[a2 + 1], va[a2 + 2]);
                        if ((f0 > 0 && f1 > 0 && f2 > 0) || (f0 < 0 && f1 < 0 && f2 < 0)) continue;
                        int r = tt.intersect(va, a0, a1, a2, nA, nAbsA, oa, vb, b0, b1, b2, nB, nAbsB, ob, f0, f1, f2, e0, e1, e2);
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
                if (lz) placeChildren(b, nb, cb);
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
