package org.handsim.collision;

import java.util.Arrays;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * A binary bounding-volume hierarchy of k-DOPs over a {@link TriangleMesh} (paper Section IV,
 * first step), on flat primitive arrays.
 *
 * <p><b>Build (top-down).</b> Start with all triangles in the root; a node with at most
 * {@code maxLeafSize} triangles is a leaf, any other is split in two by its triangles'
 * centroids, and the two halves are built the same way (an explicit work stack, no recursion).
 * Two split rules ({@link SplitRule}): {@link SplitRule#MEDIAN} puts half of the triangles on
 * each side of the median centroid along the widest extent of the centroids;
 * {@link SplitRule#SAH} bins the centroids along that extent into 16 bins and takes the bin
 * boundary of least surface-area-heuristic cost (area(left box)·n_left + area(right box)·n_right,
 * MacDonald–Booth 1990), the median when every centroid falls into one bin. Node bounds are then
 * fitted bottom-up: a leaf's k-DOP from its triangles' vertices, an internal node's as the merge
 * of its children's. The defaults ({@link #DEFAULT_SPLIT}, {@link #DEFAULT_LEAF_SIZE}) are the
 * fastest in the collision benchmark (docs/BENCHMARKS.md).
 *
 * <p><b>Layout (docs/STYLE.md, items 5, 6).</b> Nodes are numbered in depth-first pre-order, so the
 * left child of internal node i is i + 1. For node i:
 * <ul>
 *   <li>{@code bounds[i·k .. i·k + k − 1]}: its k-DOP, in the slot order of {@link Kdop};</li>
 *   <li>{@code child[i]}: the right child's index if ≥ 0; for a leaf the complement
 *       {@code ~first} (negative, FCL's signed-index idea) of its first entry in
 *       {@code order};</li>
 *   <li>{@code size[i]}: the number of triangles under the node (for a leaf, its count);</li>
 *   <li>{@code order}: triangle indices of the mesh, each leaf's triangles contiguous.</li>
 * </ul>
 * Zero-area triangles (exactly collinear vertices, tested with exact {@code orient2d} on the
 * three coordinate planes) stay in the tree, flagged in {@code degenerate}; the query skips and
 * counts them.
 *
 * <p><b>Refit.</b> {@link #refit(double[])} and {@link #refit(RigidTransform)} keep the
 * topology and recompute every k-DOP from new vertex positions (O(n)), for meshes that move or
 * deform. A rigidly moving link does not need it: {@link TreeQuery} places it per query, either
 * by refitting into its own scratch or by transforming bounds on demand, and leaves the tree
 * untouched.
 *
 * <p><b>Threads.</b> Immutable after build, except {@code refit}: any number of
 * {@link TreeQuery} instances (one per thread) may read one tree at the same time, as long as
 * nobody refits it meanwhile.
 *
 * <p>References: J. T. Klosowski et al., "Efficient collision detection using bounding volume
 * hierarchies of k-DOPs", IEEE TVCG 4(1), 1998 (k-DOP trees, median splitting); J. D.
 * MacDonald, K. S. Booth, "Heuristics for ray tracing using space subdivision", The Visual
 * Computer 6, 1990 (surface-area heuristic); FCL {@code BV_splitter.h}, {@code BV_node_base.h}.
 */
public final class KdopTree {
    /** How an internal node's triangles are divided between its two children. */
    public enum SplitRule {
        /** Half on each side of the median centroid along the widest centroid extent. */
        MEDIAN,
        /** Least surface-area-heuristic cost over 16 bins along the widest centroid extent. */
        SAH
    }

    /** The split rule {@link #build(TriangleMesh, int)} uses (chosen by benchmark). */
    public static final SplitRule DEFAULT_SPLIT = SplitRule.SAH;
    /** The leaf size {@link #build(TriangleMesh, int)} uses (chosen by benchmark). */
    public static final int DEFAULT_LEAF_SIZE = 2;
    private static final int SAH_BINS = 16;

    private final TriangleMesh mesh;
    private final Kdop kdop;
    private final int k;
    private final SplitRule splitRule;
    private final int maxLeafSize;
    final int[] tris;
    final int[] order;
    final int nodeCount;
    final int[] child;
    final int[] size;
    final double[] bounds;
    final boolean[] degenerate;
    private final int degenerateCount;
    private double[] vertices;
    /** Per triangle: normal (b−a)×(c−a) and its permanent terms ({@link Predicates#normal}) from {@link #vertices}. */
    final double[] triN, triNAbs;
    /** Bounding sphere {cx, cy, cz, r} of {@link #vertices}: the root box's centre, the farthest vertex. */
    final double[] sphere = new double[4];

    private KdopTree(TriangleMesh mesh, Kdop kdop, SplitRule rule, int maxLeafSize) {
        this.mesh = mesh;
        this.kdop = kdop;
        this.k = kdop.k();
        this.splitRule = rule;
        this.maxLeafSize = maxLeafSize;
        this.tris = mesh.triangles();
        this.vertices = mesh.vertices();
        int n = mesh.triangleCount();
        this.order = new int[n];
        for (int i = 0; i < n; i++) order[i] = i;
        this.degenerate = new boolean[n];
        Predicates pred = new Predicates();
        int dc = 0;
        for (int t = 0; t < n; t++) {
            if (collinear(pred, vertices, tris, t)) {
                degenerate[t] = true;
                dc++;
            }
        }
        this.degenerateCount = dc;
        int cap = Math.max(1, 2 * n);
        int[] ch = new int[cap];
        int[] sz = new int[cap];
        int count = n == 0 ? 0 : buildTopology(ch, sz);
        this.nodeCount = count;
        this.child = Arrays.copyOf(ch, count);
        this.size = Arrays.copyOf(sz, count);
        this.bounds = new double[count * k];
        this.triN = new double[3 * n];
        this.triNAbs = new double[3 * n];
        fitBounds(vertices, bounds);
        normals(vertices, tris, triN, triNAbs);
        fitSphere();
    }

    /** The sphere about the root box's centre reaching the farthest vertex (radius rounded up a little). */
    private void fitSphere() {
        if (nodeCount == 0) return;
        double cx = 0.5 * (bounds[0] + bounds[1]), cy = 0.5 * (bounds[2] + bounds[3]), cz = 0.5 * (bounds[4] + bounds[5]);
        double r2 = 0;
        for (int i = 0; i < vertices.length; i += 3) {
            double dx = vertices[i] - cx, dy = vertices[i + 1] - cy, dz = vertices[i + 2] - cz;
            r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
        }
        sphere[0] = cx;
        sphere[1] = cy;
        sphere[2] = cz;
        sphere[3] = Math.sqrt(r2) * (1 + 1e-12);
    }

    /** The floating-point normals and permanents of every triangle, as {@link Predicates#normal}. */
    static void normals(double[] v, int[] tris, double[] n, double[] nAbs) {
        for (int t = 0; t < tris.length; t += 3) {
            int a = 3 * tris[t], b = 3 * tris[t + 1], c = 3 * tris[t + 2];
            Predicates.normal(v[a], v[a + 1], v[a + 2], v[b], v[b + 1], v[b + 2], v[c], v[c + 1], v[c + 2], n, nAbs, t);
        }
    }

    /** Builds with the default split rule and leaf size. */
    public static KdopTree build(TriangleMesh mesh, int k) {
        return build(mesh, k, DEFAULT_SPLIT, DEFAULT_LEAF_SIZE);
    }

    /**
     * Builds the tree of {@code mesh} in the mesh's own frame.
     *
     * @param k           6, 14, 18 or 26
     * @param rule        split rule
     * @param maxLeafSize most triangles in a leaf, 1..64
     * @throws IllegalArgumentException naming k or maxLeafSize when out of range
     */
    public static KdopTree build(TriangleMesh mesh, int k, SplitRule rule, int maxLeafSize) {
        if (maxLeafSize < 1 || maxLeafSize > 64) {
            throw new IllegalArgumentException("maxLeafSize must be in 1..64, got " + maxLeafSize);
        }
        if (rule == null) throw new IllegalArgumentException("rule must not be null");
        return new KdopTree(mesh, Kdop.of(k), rule, maxLeafSize);
    }

    /** True if triangle t's vertices are exactly collinear (exact orient2d zero on all three coordinate planes). */
    static boolean collinear(Predicates pred, double[] v, int[] tri, int t) {
        int a = 3 * tri[3 * t], b = 3 * tri[3 * t + 1], c = 3 * tri[3 * t + 2];
        return pred.orient2d(v[a], v[a + 1], v[b], v[b + 1], v[c], v[c + 1]) == 0
            && pred.orient2d(v[a + 1], v[a + 2], v[b + 1], v[b + 2], v[c + 1], v[c + 2]) == 0
            && pred.orient2d(v[a + 2], v[a], v[b + 2], v[b], v[c + 2], v[c]) == 0;
    }

    // ------------------------------------------------------------------ build

    private int buildTopology(int[] ch, int[] sz) {
        int n = order.length;
        double[] cen = new double[3 * n];
        double[] box = new double[6 * n];   // per-triangle AABB for SAH
        double[] v = vertices;
        for (int t = 0; t < n; t++) {
            int a = 3 * tris[3 * t], b = 3 * tris[3 * t + 1], c = 3 * tris[3 * t + 2];
            for (int d = 0; d < 3; d++) {
                cen[3 * t + d] = (v[a + d] + v[b + d] + v[c + d]) / 3;
                box[6 * t + d] = Math.min(v[a + d], Math.min(v[b + d], v[c + d]));
                box[6 * t + 3 + d] = Math.max(v[a + d], Math.max(v[b + d], v[c + d]));
            }
        }
        // work stack: start, end, parent, (1 if right child)
        int[] stack = new int[4 * 64];
        int sp = 0;
        stack[sp++] = 0; stack[sp++] = n; stack[sp++] = -1; stack[sp++] = 0;
        int next = 0;
        double[] binBox = new double[6 * SAH_BINS];
        int[] binCount = new int[SAH_BINS];
        double[] rightArea = new double[SAH_BINS];
        int[] rightCount = new int[SAH_BINS];
        while (sp > 0) {
            int isRight = stack[--sp], parent = stack[--sp], e = stack[--sp], s = stack[--sp];
            int node = next++;
            if (isRight == 1) ch[parent] = node;
            sz[node] = e - s;
            if (e - s <= maxLeafSize) {
                ch[node] = ~s;
                continue;
            }
            // widest extent of the centroids
            double lox = Double.POSITIVE_INFINITY, loy = lox, loz = lox, hix = Double.NEGATIVE_INFINITY, hiy = hix, hiz = hix;
            for (int i = s; i < e; i++) {
                int t = order[i];
                double x = cen[3 * t], y = cen[3 * t + 1], z = cen[3 * t + 2];
                if (x < lox) lox = x;
                if (x > hix) hix = x;
                if (y < loy) loy = y;
                if (y > hiy) hiy = y;
                if (z < loz) loz = z;
                if (z > hiz) hiz = z;
            }
            double ex = hix - lox, ey = hiy - loy, ez = hiz - loz;
            int axis = ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
            double lo = axis == 0 ? lox : axis == 1 ? loy : loz;
            double extent = axis == 0 ? ex : axis == 1 ? ey : ez;
            int mid = -1;
            if (splitRule == SplitRule.SAH && extent > 0) {
                mid = sahSplit(s, e, axis, lo, extent, cen, box, binBox, binCount, rightArea, rightCount);
            }
            if (mid <= s || mid >= e) {
                mid = (s + e) >>> 1;
                select(order, cen, axis, s, e, mid);
            }
            if (sp + 8 > stack.length) stack = Arrays.copyOf(stack, 2 * stack.length);
            // right pushed first so that the left subtree is numbered right after its parent
            stack[sp++] = mid; stack[sp++] = e; stack[sp++] = node; stack[sp++] = 1;
            stack[sp++] = s; stack[sp++] = mid; stack[sp++] = node; stack[sp++] = 0;
        }
        return next;
    }

    /** Binned SAH split of order[s, e) along axis; returns the split index (partitioned). */
    private int sahSplit(int s, int e, int axis, double lo, double extent, double[] cen, double[] box,
                         double[] binBox, int[] binCount, double[] rightArea, int[] rightCount) {
        int nb = SAH_BINS;
        double scale = nb / extent;
        Arrays.fill(binCount, 0);
        for (int b = 0; b < nb; b++) {
            for (int d = 0; d < 3; d++) {
                binBox[6 * b + d] = Double.POSITIVE_INFINITY;
                binBox[6 * b + 3 + d] = Double.NEGATIVE_INFINITY;
            }
        }
        for (int i = s; i < e; i++) {
            int t = order[i];
            int b = Math.min(nb - 1, (int) ((cen[3 * t + axis] - lo) * scale));
            binCount[b]++;
            for (int d = 0; d < 3; d++) {
                binBox[6 * b + d] = Math.min(binBox[6 * b + d], box[6 * t + d]);
                binBox[6 * b + 3 + d] = Math.max(binBox[6 * b + 3 + d], box[6 * t + 3 + d]);
            }
        }
        // sweep from the right: area and count of bins b..nb-1
        double rx0 = Double.POSITIVE_INFINITY, ry0 = rx0, rz0 = rx0, rx1 = Double.NEGATIVE_INFINITY, ry1 = rx1, rz1 = rx1;
        int rc = 0;
        for (int b = nb - 1; b > 0; b--) {
            if (binCount[b] > 0) {
                rx0 = Math.min(rx0, binBox[6 * b]); ry0 = Math.min(ry0, binBox[6 * b + 1]); rz0 = Math.min(rz0, binBox[6 * b + 2]);
                rx1 = Math.max(rx1, binBox[6 * b + 3]); ry1 = Math.max(ry1, binBox[6 * b + 4]); rz1 = Math.max(rz1, binBox[6 * b + 5]);
            }
            rc += binCount[b];
            rightCount[b] = rc;
            rightArea[b] = rc == 0 ? 0 : area(rx1 - rx0, ry1 - ry0, rz1 - rz0);
        }
        double lx0 = Double.POSITIVE_INFINITY, ly0 = lx0, lz0 = lx0, lx1 = Double.NEGATIVE_INFINITY, ly1 = lx1, lz1 = lx1;
        int lc = 0, bestBin = -1;
        double bestCost = Double.POSITIVE_INFINITY;
        for (int b = 0; b < nb - 1; b++) {
            if (binCount[b] > 0) {
                lx0 = Math.min(lx0, binBox[6 * b]); ly0 = Math.min(ly0, binBox[6 * b + 1]); lz0 = Math.min(lz0, binBox[6 * b + 2]);
                lx1 = Math.max(lx1, binBox[6 * b + 3]); ly1 = Math.max(ly1, binBox[6 * b + 4]); lz1 = Math.max(lz1, binBox[6 * b + 5]);
            }
            lc += binCount[b];
            int rcount = rightCount[b + 1];
            if (lc == 0 || rcount == 0) continue;
            double cost = area(lx1 - lx0, ly1 - ly0, lz1 - lz0) * lc + rightArea[b + 1] * rcount;
            if (cost < bestCost) {
                bestCost = cost;
                bestBin = b;
            }
        }
        if (bestBin < 0) return -1;
        // partition: bins 0..bestBin left
        int i = s, j = e - 1;
        while (i <= j) {
            int t = order[i];
            int b = Math.min(nb - 1, (int) ((cen[3 * t + axis] - lo) * scale));
            if (b <= bestBin) {
                i++;
            } else {
                order[i] = order[j];
                order[j] = t;
                j--;
            }
        }
        return i;
    }

    private static double area(double x, double y, double z) {
        return x * y + y * z + z * x;
    }

    /** Quickselect: order[s, e) partitioned so that order[mid] has the mid-th centroid along axis. */
    private static void select(int[] order, double[] cen, int axis, int s, int e, int mid) {
        int lo = s, hi = e - 1;
        while (hi > lo) {
            double pivot = cen[3 * order[(lo + hi) >>> 1] + axis];
            int i = lo, j = hi;
            while (i <= j) {
                while (cen[3 * order[i] + axis] < pivot) i++;
                while (cen[3 * order[j] + axis] > pivot) j--;
                if (i <= j) {
                    int t = order[i];
                    order[i] = order[j];
                    order[j] = t;
                    i++;
                    j--;
                }
            }
            if (mid <= j) hi = j;
            else if (mid >= i) lo = i;
            else return;
        }
    }

    // ------------------------------------------------------------------ bounds

    /**
     * Fits every node's k-DOP into {@code out} (nodeCount·k doubles) from vertex positions
     * {@code v} (same layout as the mesh's): leaves from their triangles' vertices, internal
     * nodes bottom-up by merging (children have larger indices than their parent).
     */
    void fitBounds(double[] v, double[] out) {
        for (int i = nodeCount - 1; i >= 0; i--) {
            int o = i * k;
            int c = child[i];
            if (c < 0) {
                int first = ~c, end = first + size[i];
                kdop.setEmpty(out, o);
                for (int j = first; j < end; j++) {
                    int t = 3 * order[j];
                    for (int q = 0; q < 3; q++) {
                        int p = 3 * tris[t + q];
                        kdop.addPoint(out, o, v[p], v[p + 1], v[p + 2]);
                    }
                }
            } else {
                Kdop.merge(out, (i + 1) * k, out, c * k, out, o, k);
            }
        }
    }

    /**
     * Refits every k-DOP to new vertex positions (same count and order as the mesh's, metres);
     * the tree keeps its own copy. Not thread-safe with concurrent queries on this tree.
     *
     * @throws IllegalArgumentException if the array length differs from the mesh's
     */
    public void refit(double[] newVertices) {
        if (newVertices.length != mesh.vertices().length) {
            throw new IllegalArgumentException("refit needs " + mesh.vertices().length + " coordinates, got " + newVertices.length);
        }
        if (vertices == mesh.vertices()) vertices = new double[newVertices.length];
        System.arraycopy(newVertices, 0, vertices, 0, newVertices.length);
        fitBounds(vertices, bounds);
        normals(vertices, tris, triN, triNAbs);
        fitSphere();
    }

    /** Refits to the mesh's vertices moved by {@code pose} (mesh frame → new frame). */
    public void refit(RigidTransform pose) {
        if (vertices == mesh.vertices()) vertices = new double[mesh.vertices().length];
        double[] m = new double[12];
        pose.copyTo(m, 0);
        transformPoints(m, mesh.vertices(), vertices, mesh.vertexCount());
        fitBounds(vertices, bounds);
        normals(vertices, tris, triN, triNAbs);
        fitSphere();
    }

    /**
     * dst = m12 applied to the n points in src (the one formula every placement of a mesh
     * uses, so that the tree and the brute-force reference see bit-identical coordinates).
     * {@code dst} may be {@code src}.
     */
    public static void transformPoints(double[] m12, double[] src, double[] dst, int n) {
        for (int i = 0; i < 3 * n; i += 3) transformPoint(m12, src, i, dst, i);
    }

    /** dst[d..d+2] = m12 · src[s..s+2] (see {@link #transformPoints}). */
    static void transformPoint(double[] m, double[] src, int s, double[] dst, int d) {
        double x = src[s], y = src[s + 1], z = src[s + 2];
        dst[d] = m[0] * x + m[1] * y + m[2] * z + m[3];
        dst[d + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
        dst[d + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    }

    // ------------------------------------------------------------------ accessors

    /** @return the mesh the tree was built over */
    public TriangleMesh mesh() { return mesh; }

    /** @return k (6, 14, 18 or 26) */
    public int k() { return k; }

    /** @return the direction set */
    public Kdop kdop() { return kdop; }

    /** @return the split rule it was built with */
    public SplitRule splitRule() { return splitRule; }

    /** @return the largest leaf size it was built with */
    public int maxLeafSize() { return maxLeafSize; }

    /** @return the number of nodes (0 for an empty mesh) */
    public int nodeCount() { return nodeCount; }

    /** @return the number of zero-area triangles (kept, skipped by queries) */
    public int degenerateCount() { return degenerateCount; }

    /** @return true if node i is a leaf */
    public boolean isLeaf(int node) { return child[node] < 0; }

    /** @return the current vertex positions (the mesh's until a refit); do not modify */
    public double[] vertices() { return vertices; }

    /** @return {cx, cy, cz, r}: a sphere (metres, the tree's frame) that holds every vertex (a new array) */
    public double[] boundingSphere() { return sphere.clone(); }

    /** @return a copy of node i's k-DOP bounds (slot order of {@link Kdop}) */
    public double[] nodeBounds(int node) {
        return Arrays.copyOfRange(bounds, node * k, node * k + k);
    }

    /** @return the depth of the tree (1 for a single leaf, 0 when empty) */
    public int depth() {
        if (nodeCount == 0) return 0;
        int[] d = new int[nodeCount];
        int max = 0;
        d[0] = 1;
        for (int i = 0; i < nodeCount; i++) {
            max = Math.max(max, d[i]);
            if (child[i] >= 0) {
                d[i + 1] = d[i] + 1;
                d[child[i]] = d[i] + 1;
            }
        }
        return max;
    }

    /** @return the triangles of leaf {@code node} (a new array) */
    public int[] leafTriangles(int node) {
        if (child[node] >= 0) throw new IllegalArgumentException("node " + node + " is not a leaf");
        int first = ~child[node];
        return Arrays.copyOfRange(order, first, first + size[node]);
    }

    @Override
    public String toString() {
        return "KdopTree[" + mesh.name() + ", k=" + k + ", " + splitRule + ", leaf<=" + maxLeafSize + ", "
            + nodeCount + " nodes, depth " + depth() + "]";
    }
}
