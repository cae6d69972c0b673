package org.handsim.grasp;

import java.util.Arrays;

/**
 * Convex hull of points in d dimensions (2 ≤ d ≤ 8; the grasp wrench space uses d = 6), by
 * Quickhull: C. B. Barber, D. P. Dobkin, H. Huhdanpaa, "The Quickhull algorithm for convex
 * hulls", ACM TOMS 22(4), 1996. Our own code (no n-dimensional hull exists on Maven Central;
 * docs/DESIGN.md decision 5); the facets are simplices (d vertices each), stored on primitive
 * arrays and reused from call to call, so a warm instance allocates nothing.
 *
 * <h2>The algorithm</h2>
 * <ol>
 *   <li><b>Affine rank and the initial simplex</b> (a pivoted Gram–Schmidt on the points): the
 *       point farthest from the centroid, then repeatedly the point farthest from the affine
 *       span of those chosen. If that distance is at most {@link #RANK_TOLERANCE} × S (S the
 *       largest absolute coordinate) before d + 1 points are chosen, the points are
 *       lower-dimensional: no hull is built ({@link #isFullDimensional()} false, volume 0).
 *       Duplicate, coincident and collinear points fall here.</li>
 *   <li>Every other point goes into the <em>outside set</em> of the first facet it lies above
 *       by more than the tolerance τ = {@link #DISTANCE_TOLERANCE} × S; points above no facet are
 *       inside (or within τ of the boundary) and are dropped.</li>
 *   <li><b>Adding a point</b> p (the furthest point of a facet's outside set): the facets p sees
 *       (signed distance &gt; τ) are found by a breadth-first walk from that facet; each ridge
 *       between a visible and a hidden facet (the horizon) gets a new facet, the ridge plus p.
 *       The new facets are linked to each other across their ridges through p by a hash of the
 *       ridges' vertex sets. Where rounding pinches the visible region (a ridge through p would
 *       get four new facets, and the facet graph would stop being a manifold), the step is undone
 *       and retried with the visibility threshold moved off τ ({@link #THRESHOLDS}), so the
 *       facet graph always stays a closed manifold, never a dangling pointer. The points of the
 *       visible facets' outside sets are partitioned among the new facets (a point above no new
 *       facet is inside the new hull: Barber et al., Lemma 3.3 and §3).</li>
 *   <li>Repeat while an outside set is non-empty; an explicit work list, no recursion.</li>
 * </ol>
 * A facet's hyperplane n·x = b (unit n, pointing out) comes from its parents' (a rotation of the
 * horizon ridge, kept when every vertex lies within {@link #REFIT_TOLERANCE} × S of it) or
 * else from its d vertices by Gaussian elimination with full pivoting; b is the mean of n·v
 * over the vertices. The interior point
 * (the initial simplex's centroid) orients it.
 *
 * <h2>What it reports</h2>
 * The volume (the sum of the simplices from the interior point to each facet), the smallest
 * facet offset b (the signed distance from the origin to the nearest facet hyperplane: the
 * Ferrari–Canny ε when positive), the number of simplicial facets, and the number of facets of
 * the polytope (simplicial facets whose hyperplanes agree within {@link #MERGE_TOLERANCE} × S,
 * merged across ridges), the count qhull gives when it merges coplanar facets.
 *
 * <p>{@link #epsilon} computes only the smallest offset, best first (see its Javadoc for the
 * proof). Not thread-safe: one instance per thread.
 */
public final class ConvexHull {
    /**
     * Lower-dimensional when no point is farther than this × S from the span of the chosen ones.
     * Thinner point sets are degenerate ones blurred by rounding: their hulls are slivers whose
     * simplicial facets have ill-determined hyperplanes (a 1e-9 S sliver gave facets that points
     * lay 0.4 % of S above; at 1e-6 S the worst is 10 τ, at 1e-5 S below τ — measured on 200
     * perturbed coincident and collinear grasps each), and a wrench space that thin holds
     * nothing physically meaningful.
     */
    public static final double RANK_TOLERANCE = 1e-6;
    /** τ / S: a point must be farther than τ above a facet to count as outside it. */
    public static final double DISTANCE_TOLERANCE = 1e-11;
    /** A hyperplane found by rotation is kept when all its vertices lie within this × S of it. */
    static final double REFIT_TOLERANCE = 1e-13;
    /** Neighbouring simplicial facets within this × S of each other's hyperplane are one facet. */
    public static final double MERGE_TOLERANCE = 1e-9;

    /**
     * Most simplicial facets a hull may hold at once: 2^20, about 175 MB of facet arrays (and
     * twice that while they grow). A 6-D hull's facets grow much faster than its points (random
     * grasps: 200 contacts of 8 edges give 930 000 facets in 30 s; 4 contacts of 256 edges, points
     * on four circles, pass 2^20), so this, not the number of points, bounds memory.
     */
    public static final int MAX_FACETS = 1 << 20;

    /** A hull that would need more than {@link #MAX_FACETS} facets: refused, never out of memory. */
    public static final class TooLargeException extends IllegalStateException {
        private static final long serialVersionUID = 1L;

        TooLargeException(String message) { super(message); }
    }

    static final boolean DEBUG = Boolean.getBoolean("handsim.hullDebug");
    private static final byte INSIDE = 0, PENDING = 1, VERTEX = 2;

    private final int d;

    // input
    private double[] pts;
    private int n;
    private double scale, tau;
    private boolean full;

    // points
    private int[] pointNext = new int[0];
    private byte[] pointState = new byte[0];

    // facets (index f: vertices and neighbours at f*d .. f*d+d-1; neighbour i is opposite vertex i)
    private int capacity;
    private int highWater;
    private int[] verts, nbr;
    /**
     * For facet f's neighbour g = nbr[f·d + i]: the slot of f among g's neighbours
     * (nbr[g·d + nbrSlot[f·d + i]] == f), kept beside nbr so that crossing a ridge needs no search.
     */
    private int[] nbrSlot;
    private double[] normal, offset, furthestDist;
    private int[] outHead, furthest, gen, mark;
    private boolean[] alive;
    /**
     * +1 or −1: the sign that makes facet f's ordered vertices an outward simplex. Set from the
     * geometry for the initial simplex, then inherited (a new facet is its visible parent with
     * one vertex replaced in place, which keeps the orientation), so the volume is a signed sum
     * over a consistently oriented surface: where rounding folds nearly coplanar facets over
     * each other, the folds cancel instead of counting twice.
     */
    private byte[] orientation;
    private int[] freeList;
    private int freeCount, aliveCount, created;
    private int epoch;

    private final double[] interior;
    // scratch
    private int[] visible = new int[64], newFacets = new int[64], work = new int[64];
    /** For new facet k of the current step: the visible facet and the slot it was made from. */
    private int[] origin = new int[128];
    private int visibleCount, newCount, workCount;
    private final double[] ge, gx;
    private final int[] perm;
    private double[] resid = new double[0];
    private final double[] basis;
    private final int[] simplex, chosen;
    private final double[] refit;
    private int[] near = new int[0];
    private final FacetHeap heap = new FacetHeap();
    private int[] unionParent = new int[0];

    /** @param dimension d, 2 ≤ d ≤ 8 */
    public ConvexHull(int dimension) {
        if (dimension < 2 || dimension > 8) throw new IllegalArgumentException("dimension must be 2..8, got " + dimension);
        this.d = dimension;
        interior = new double[d];
        ge = new double[d * d];
        gx = new double[d];
        perm = new int[d];
        basis = new double[d];
        simplex = new int[d + 1];
        chosen = new int[d];
        refit = new double[d];
        ensureFacets(256);
    }

    // ------------------------------------------------------------------ public entry points

    /**
     * Builds the whole hull of {@code count} points ({@code points[i*d .. i*d+d-1]}).
     *
     * @return true if the points span d dimensions (else nothing is built: volume 0, no facets)
     * @throws IllegalArgumentException for a non-finite coordinate
     */
    public boolean build(double[] points, int count) {
        if (!buildOnce(points, count)) return false;
        if (!suspicious && !droppedPointOutside()) return true;
        if (supportsEveryPoint()) return true;
        // rounding spoiled the hull (nearly coplanar points): joggle, as qhull's QJ does
        if (joggled.length < count * d) joggled = new double[count * d];
        java.util.Random rnd = new java.util.Random(JOGGLE_SEED);
        for (double j = JOGGLE_FIRST; j <= JOGGLE_LAST; j *= 10) {
            double amount = j * scale;
            for (int i = 0; i < count * d; i++) joggled[i] = points[i] + amount * (2 * rnd.nextDouble() - 1);
            if (!buildOnce(joggled, count)) return false;
            if (!suspicious && !droppedPointOutside() || supportsEveryPoint()) return true;
        }
        return true;
    }

    /**
     * True if every point lies below every facet within {@link #CONVEXITY_SLACK} τ: the check
     * of a hull built after a step that needed a retry (O(facets × points)).
     */
    private boolean supportsEveryPoint() {
        double slack = CONVEXITY_SLACK * tau;
        for (int f = 0; f < highWater; f++) {
            if (!alive[f]) continue;
            for (int i = 0; i < n; i++) if (distance(i, f) > slack) return false;
        }
        return true;
    }

    /**
     * True if the built hull shows a flaw that Quickhull's steps, exact only in exact
     * arithmetic, can leave with nearly coplanar points: a ridge where the neighbour's far
     * vertex lies above the facet by more than {@link #CONVEXITY_SLACK} τ (a fold), or a point
     * off the surface (dropped as inside, or a vertex whose facets all went) above some facet.
     * O(facets × d) plus O(off-surface points × facets); in 6-D grasps nearly every wrench is a
     * vertex, so it costs little.
     */
    private boolean droppedPointOutside() {
        double slack = CONVEXITY_SLACK * tau;
        for (int i = 0; i < n; i++) onSurface[i] = false;
        for (int f = 0; f < highWater; f++) {
            if (!alive[f]) continue;
            int fo = f * d;
            for (int k = 0; k < d; k++) {
                onSurface[verts[fo + k]] = true;
                int g = nbr[fo + k];
                if (g > f && distance(verts[g * d + nbrSlot[fo + k]], f) > slack) return true;
            }
        }
        for (int i = 0; i < n; i++) {
            if (onSurface[i]) continue;
            for (int f = 0; f < highWater; f++) if (alive[f] && distance(i, f) > slack) return true;
        }
        return false;
    }

    private boolean[] onSurface = new boolean[0];

    /** First joggle, × S; then ×10 per retry up to {@link #JOGGLE_LAST}. */
    static final double JOGGLE_FIRST = 1e-10, JOGGLE_LAST = 1e-6;
    private static final long JOGGLE_SEED = 20261124L;
    private double[] joggled = new double[0];
    private boolean suspicious;

    private boolean buildOnce(double[] points, int count) {
        if (!start(points, count, true)) return false;
        workCount = 0;
        for (int f = 0; f < highWater; f++) if (alive[f] && outHead[f] >= 0) pushWork(f);
        while (workCount > 0) {
            int f = work[--workCount];
            if (!alive[f] || outHead[f] < 0) continue;
            int p = furthest[f];
            if (!addPoint(p, f)) {           // p dropped: the seed keeps its other points
                refreshFurthest(f);
                if (outHead[f] >= 0) pushWork(f);
                continue;
            }
            if (DEBUG) { String t = checkTopology(); if (t != null) throw new IllegalStateException("after adding " + p + ": " + t); }
            for (int k = 0; k < newCount; k++) if (outHead[newFacets[k]] >= 0) pushWork(newFacets[k]);
        }
        return true;
    }

    /**
     * The smallest facet offset of the hull — the signed distance from the origin to the nearest
     * facet hyperplane, positive when the origin is inside — without building the whole hull;
     * {@link Double#NaN} when the points are lower-dimensional.
     *
     * <p><b>Best-first Quickhull</b> (the idea of EPA, van den Bergen 2001, applied to the
     * origin's nearest facet). The partial hull H_k after k added points is a convex polytope
     * with H_k ⊆ H. Facets sit in a min-heap by offset; take the smallest-offset facet F:
     * <ul>
     *   <li>if some point lies above F by more than τ (a scan of the points not yet on the hull:
     *       this path keeps no outside sets), add the one farthest above it — the support point
     *       in the direction of F's normal, as EPA does — by a Quickhull step (F is visible from
     *       it, so F is replaced) and repeat;</li>
     *   <li>otherwise F's hyperplane supports the whole hull H (no point lies above it), so
     *       ε(H) ≤ b_F. If b_F &gt; 0, every facet of H_k has offset ≥ b_F &gt; 0, so the ball of
     *       radius b_F about the origin lies in H_k ⊆ H and ε(H) ≥ b_F: hence ε(H) = b_F. If
     *       b_F ≤ 0, a supporting hyperplane of H has the origin on or beyond it: the origin is
     *       not strictly inside H, no force closure.</li>
     * </ul>
     * It ends because every step adds a point. Facets whose offsets are within τ of the best
     * final one are settled too, and every final candidate's offset is refined
     * ({@link #minOffset()}), so this path and {@link #build} report the same ε to rounding.
     * Tested against {@link #build} on hundreds of
     * seeded sets (GraspQualityReferenceTest, WrenchSpaceTest).
     */
    public double epsilon(double[] points, int count) {
        if (!start(points, count, false)) return Double.NaN;
        heap.clear();
        for (int f = 0; f < highWater; f++) if (alive[f]) heap.push(offset[f], f, gen[f]);
        double best = Double.POSITIVE_INFINITY;
        while (!heap.isEmpty() && heap.topKey() <= best + tau) {
            int f = heap.topFacet(), g = heap.topGen();
            heap.pop();
            if (!alive[f] || gen[f] != g) continue;
            int p = farthestPendingAbove(f);
            if (p >= 0) {
                if (!addPoint(p, f)) {                  // p dropped (pathological): take f again
                    heap.push(offset[f], f, gen[f]);
                    continue;
                }
                for (int k = 0; k < newCount; k++) {
                    int nf = newFacets[k];
                    heap.push(offset[nf], nf, gen[nf]);
                }
                continue;
            }
            best = Math.min(best, facetSupport(f));
            if (best <= tau) return best;          // the origin is not strictly inside: settled
        }
        if (best == Double.POSITIVE_INFINITY) throw new IllegalStateException("best-first hull ran out of facets (a bug)");
        if (suspicious) {                           // a step needed a retry: the whole, checked hull decides
            double[] original = points;
            build(original, count);
            return minOffset();
        }
        return best;
    }

    /** True if the last build or epsilon call found the points to span d dimensions. */
    public boolean isFullDimensional() { return full; }

    /** τ of the last call: a point counts as above a facet only when farther than this. */
    public double tolerance() { return tau; }

    /**
     * Simplicial facets alive now: for a progress report from another thread while a build
     * runs (read without synchronisation: a recent value, not an exact one).
     */
    public int facetsSoFar() { return aliveCount; }

    /** Simplicial facets of the last {@link #build} (0 when lower-dimensional). */
    public int simplicialFacetCount() { return full ? aliveCount : 0; }

    /**
     * The smallest facet offset of the last build (see {@link #epsilon}); NaN if
     * lower-dimensional. Precisely: the smallest {@link #facetSupport} over the facets whose
     * offsets could give it (the smallest, and every one below the best value found + τ), so a
     * thin simplicial facet's rounding does not decide ε and a spoiled hyperplane cannot make it
     * smaller.
     */
    public double minOffset() {
        if (!full) return Double.NaN;
        double m = Double.POSITIVE_INFINITY;
        int fm = -1;
        for (int f = 0; f < highWater; f++) if (alive[f] && offset[f] < m) { m = offset[f]; fm = f; }
        double best = facetSupport(fm);
        for (int f = 0; f < highWater; f++) {
            if (alive[f] && f != fm && offset[f] < best + tau) best = Math.min(best, facetSupport(f));
        }
        return best;
    }

    /**
     * The support of the points in the direction of facet f's normal, h(n) = max_i n·p_i, from a
     * hyperplane refitted to the input points within τ of f's own: d of them spread as widely as
     * pivoted Gram–Schmidt finds, their null vector by elimination (f's stored normal when its d
     * vertices are all there is). When every point lies within τ of that hyperplane or below, the
     * value is its offset averaged over those points (the facet's distance from the origin, free
     * of one thin simplex's rounding); otherwise — a facet whose hyperplane rounding has spoiled,
     * possible on nearly degenerate input — it is the support h(n). Either way the value is at
     * least the distance from the origin to the hull's boundary, since the ball of radius ε
     * inside the hull has support ε in every direction; so a spoiled facet can never make ε
     * smaller, and one with a value ≤ τ proves there is no force closure.
     */
    private double facetSupport(int f) {
        int fo = f * d, k = 0;
        for (int i = 0; i < n; i++) {
            if (Math.abs(distance(i, f)) <= tau) near[k++] = i;
        }
        if (k <= d || !refitNormal(k, f)) System.arraycopy(normal, fo, refit, 0, d);
        double b = 0, h = Double.NEGATIVE_INFINITY;
        for (int j = 0; j < k; j++) {
            int q = near[j] * d;
            double sdot = 0;
            for (int c = 0; c < d; c++) sdot += refit[c] * pts[q + c];
            b += sdot;
        }
        b = k > 0 ? b / k : offset[f];
        for (int i = 0; i < n; i++) {
            int q = i * d;
            double sdot = 0;
            for (int c = 0; c < d; c++) sdot += refit[c] * pts[q + c];
            if (sdot > h) h = sdot;
        }
        return h <= b + tau ? b : h;
    }

    /** The unit normal through the k points of {@code near} (a well-spread d-subset), oriented as f's, into refit; false if degenerate. */
    private boolean refitNormal(int k, int f) {
        int p0 = near[0];
        for (int j = 0; j < k; j++) {
            int q = near[j];
            for (int c = 0; c < d; c++) resid[j * d + c] = pts[q * d + c] - pts[p0 * d + c];
        }
        chosen[0] = p0;
        for (int r = 1; r < d; r++) {
            int bestJ = -1;
            double bestSq = -1;
            for (int j = 0; j < k; j++) {
                double sq = 0;
                for (int c = 0; c < d; c++) sq += resid[j * d + c] * resid[j * d + c];
                if (sq > bestSq) { bestSq = sq; bestJ = j; }
            }
            if (!(bestSq > 0)) return false;
            chosen[r] = near[bestJ];
            double len = Math.sqrt(bestSq);
            for (int c = 0; c < d; c++) basis[c] = resid[bestJ * d + c] / len;
            for (int pass = 0; pass < 2; pass++) {
                for (int j = 0; j < k; j++) {
                    double dot = 0;
                    for (int c = 0; c < d; c++) dot += resid[j * d + c] * basis[c];
                    for (int c = 0; c < d; c++) resid[j * d + c] -= dot * basis[c];
                }
            }
        }
        if (!nullVector(chosen, 0, refit, 0)) return false;
        double dir = 0;
        for (int c = 0; c < d; c++) dir += refit[c] * normal[f * d + c];
        if (dir < 0) for (int c = 0; c < d; c++) refit[c] = -refit[c];
        return true;
    }

    /**
     * d-dimensional volume of the last build's hull (0 when lower-dimensional): the signed sum of
     * the simplices from the interior point to each facet, oriented consistently (see
     * {@code orientation}).
     */
    public double volume() {
        if (!full) return 0;
        double sum = 0;
        double fact = 1;
        for (int i = 2; i <= d; i++) fact *= i;
        for (int f = 0; f < highWater; f++) {
            if (!alive[f]) continue;
            for (int r = 0; r < d; r++) {
                int v = verts[f * d + r];
                for (int c = 0; c < d; c++) ge[r * d + c] = pts[v * d + c] - interior[c];
            }
            sum += orientation[f] * determinant(ge, d);
        }
        return sum / fact;
    }

    /**
     * Facets of the polytope: simplicial facets merged across ridges where the neighbour's far
     * vertex lies within {@link #MERGE_TOLERANCE} × S of the facet's hyperplane (coplanar
     * neighbours, e.g. a facet spanned by a whole friction cone and three more wrenches).
     */
    public int facetCount() {
        if (!full) return 0;
        if (unionParent.length < highWater) unionParent = new int[capacity];
        for (int f = 0; f < highWater; f++) unionParent[f] = f;
        double mt = MERGE_TOLERANCE * scale;
        int groups = aliveCount;
        for (int f = 0; f < highWater; f++) {
            if (!alive[f]) continue;
            for (int i = 0; i < d; i++) {
                int g = nbr[f * d + i];
                if (g < f) continue;
                int x = verts[g * d + nbrSlot[f * d + i]];
                if (Math.abs(distance(x, f)) > mt) continue;
                int a = find(f), b = find(g);
                if (a != b) { unionParent[a] = b; groups--; }
            }
        }
        return groups;
    }

    /** The facets of the last build as rows {n_1, .., n_d, b} (n·x ≤ b inside); for tests. */
    double[][] facetPlanes() {
        double[][] out = new double[full ? aliveCount : 0][];
        int k = 0;
        for (int f = 0; f < highWater && full; f++) {
            if (!alive[f]) continue;
            out[k] = Arrays.copyOf(Arrays.copyOfRange(normal, f * d, f * d + d), d + 1);
            out[k++][d] = offset[f];
        }
        return out;
    }

    /** Checks the facet graph (tests and debugging): every neighbour alive, mutual, sharing all vertices but one; null if sound. */
    String checkTopology() {
        for (int f = 0; f < highWater; f++) {
            if (!alive[f]) continue;
            for (int i = 0; i < d; i++) {
                int g = nbr[f * d + i];
                if (g < 0 || !alive[g]) return "facet " + f + " slot " + i + ": neighbour " + g + " dead";
                int back = -1;
                for (int j = 0; j < d; j++) if (nbr[g * d + j] == f) back = j;
                if (back < 0) return "facet " + f + " -> " + g + " not mutual";
                if (nbrSlot[f * d + i] != back) return "facet " + f + " slot " + i + ": kept slot " + nbrSlot[f * d + i] + " in " + g + ", not " + back;
                for (int k = 0; k < d; k++) {
                    if (k == i) continue;
                    int v = verts[f * d + k];
                    boolean in = false;
                    for (int j = 0; j < d; j++) if (j != back && verts[g * d + j] == v) in = true;
                    if (!in) return "facet " + f + " and " + g + " do not share the ridge";
                }
            }
        }
        return null;
    }

    /** Facets the last call created, the initial simplex's included (the work done). */
    public int createdFacetCount() { return created; }

    /** Number of points the last call added as hull vertices (the work done). */
    public int vertexCount() {
        int c = 0;
        for (int i = 0; i < n; i++) if (pointState[i] == VERTEX) c++;
        return c;
    }

    // ------------------------------------------------------------------ set-up

    private boolean start(double[] points, int count, boolean partition) {
        if (count < 0 || points.length < count * d) {
            throw new IllegalArgumentException("need " + d + "*count = " + d * count + " coordinates, got " + points.length);
        }
        pts = points;
        n = count;
        full = false;
        highWater = 0; freeCount = 0; aliveCount = 0; created = 0;
        suspicious = false;
        scale = 0;
        for (int i = 0; i < n * d; i++) {
            double a = Math.abs(points[i]);
            if (!(a < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("coordinate " + i % d + " of point " + i / d + " is not finite: " + points[i]);
            if (a > scale) scale = a;
        }
        tau = DISTANCE_TOLERANCE * scale;
        if (pointState.length < n) {
            pointState = new byte[n];
            pointNext = new int[n];
            resid = new double[n * d];
            near = new int[n];
            onSurface = new boolean[n];
            int old = hashA.length;
            hashA = Arrays.copyOf(hashA, n);
            hashB = Arrays.copyOf(hashB, n);
            for (int i = old; i < n; i++) {
                hashA[i] = splitMix((i + 1) * 0x9E3779B97F4A7C15L);
                hashB[i] = splitMix((i + 1) * 0xD1B54A32D192ED03L + 0x632BE59BD9B4E019L);
            }
        }
        Arrays.fill(pointState, 0, n, PENDING);
        if (n < d + 1 || scale == 0) return false;
        if (!initialSimplex()) return false;
        full = true;
        // the d+1 facets of the simplex: facet j leaves out simplex vertex j
        for (int c = 0; c < d; c++) {
            double s = 0;
            for (int j = 0; j <= d; j++) s += pts[simplex[j] * d + c];
            interior[c] = s / (d + 1);
        }
        for (int j = 0; j <= d; j++) {
            int f = newFacet();
            int slot = 0;
            for (int k = 0; k <= d; k++) {
                if (k == j) continue;
                verts[f * d + slot] = simplex[k];
                // the neighbour opposite simplex vertex k is the facet that leaves out k: facet index k
                nbr[f * d + slot] = k;
                nbrSlot[f * d + slot] = f < k ? f : f - 1;   // facet k holds simplex vertex f at that slot
                slot++;
            }
            hyperplane(f, -1);
            for (int r = 0; r < d; r++) {
                int v = verts[f * d + r];
                for (int c = 0; c < d; c++) ge[r * d + c] = pts[v * d + c] - interior[c];
            }
            orientation[f] = determinant(ge, d) > 0 ? (byte) 1 : (byte) -1;
        }
        for (int j = 0; j <= d; j++) pointState[simplex[j]] = VERTEX;
        // partition every other point among the simplex's facets (the best-first path keeps no
        // outside sets: it looks for the point farthest above the facet it takes)
        for (int i = 0; i < n && partition; i++) {
            if (pointState[i] != PENDING) continue;
            assign(i, d + 1);
        }
        return true;
    }

    /** Pivoted Gram–Schmidt on the points: picks the initial simplex; false if lower-dimensional. */
    private boolean initialSimplex() {
        double[] cen = gx;
        Arrays.fill(cen, 0);
        for (int i = 0; i < n; i++) for (int c = 0; c < d; c++) cen[c] += pts[i * d + c];
        for (int c = 0; c < d; c++) cen[c] /= n;
        int p0 = -1;
        double best = -1;
        for (int i = 0; i < n; i++) {
            double s = 0;
            for (int c = 0; c < d; c++) { double t = pts[i * d + c] - cen[c]; s += t * t; }
            if (s > best) { best = s; p0 = i; }
        }
        simplex[0] = p0;
        for (int i = 0; i < n; i++) for (int c = 0; c < d; c++) resid[i * d + c] = pts[i * d + c] - pts[p0 * d + c];
        double lim = RANK_TOLERANCE * scale;
        for (int k = 1; k <= d; k++) {
            int pk = -1;
            double bestSq = -1;
            for (int i = 0; i < n; i++) {
                double s = 0;
                for (int c = 0; c < d; c++) { double t = resid[i * d + c]; s += t * t; }
                if (s > bestSq) { bestSq = s; pk = i; }
            }
            double len = Math.sqrt(bestSq);
            if (!(len > lim)) return false;
            simplex[k] = pk;
            for (int c = 0; c < d; c++) basis[c] = resid[pk * d + c] / len;
            for (int i = 0; i < n; i++) {
                double dot = 0;
                for (int c = 0; c < d; c++) dot += resid[i * d + c] * basis[c];
                for (int c = 0; c < d; c++) resid[i * d + c] -= dot * basis[c];
            }
            // a second pass keeps the residuals orthogonal to the span in floating point
            // (classical Gram–Schmidt twice is enough: Giraud et al. 2005)
            for (int i = 0; i < n; i++) {
                double dot = 0;
                for (int c = 0; c < d; c++) dot += resid[i * d + c] * basis[c];
                for (int c = 0; c < d; c++) resid[i * d + c] -= dot * basis[c];
            }
        }
        return true;
    }

    // ------------------------------------------------------------------ the Quickhull step

    /**
     * Visibility thresholds, × τ, tried in turn when the horizon of a point is not a manifold:
     * rounding can leave a facet nearly coplanar with p counted hidden between visible ones
     * (or the reverse), which pinches the visible region at a (d−3)-face, so some ridge through
     * p would have four new facets. Counting such facets visible (negative thresholds) or
     * hidden (larger ones) removes the pinch; the error is at most the threshold.
     */
    private static final double[] THRESHOLDS = {1, 10, 100, 1e3, 1e4};

    /**
     * Adds point p, which lies above facet seed by more than τ; the new facets are in
     * newFacets. False, with the hull unchanged and p marked inside, in the pathological case
     * that no threshold gives a manifold horizon (an error below 1e4 τ = 1e-7 S).
     */
    private boolean addPoint(int p, int seed) {
        pointState[p] = VERTEX;
        double seedDist = distance(p, seed);
        for (double k : THRESHOLDS) {
            double t = k * tau;
            if (t >= seedDist) continue;
            if (k != THRESHOLDS[0]) suspicious = true;
            if (tryCone(p, seed, t)) {
                // partition the outside sets of the visible facets among the new facets; free them
                for (int q = 0; q < visibleCount; q++) {
                    int f = visible[q];
                    int pt = outHead[f];
                    while (pt >= 0) {
                        int nextPt = pointNext[pt];
                        if (pointState[pt] == PENDING) assignNew(pt);
                        pt = nextPt;
                    }
                    outHead[f] = -1;
                    freeFacet(f);
                }
                return true;
            }
        }
        pointState[p] = INSIDE;
        newCount = 0;
        suspicious = true;
        return false;
    }

    /**
     * One attempt at the cone from p: the facets p lies above by more than t, found breadth-first
     * from seed, replaced by a new facet on each horizon ridge, linked by {@link #linkByHash}.
     * False (everything undone) if the horizon is not a manifold.
     */
    private boolean tryCone(int p, int seed, double t) {
        epoch += 3;
        int visMark = epoch, hidMark = epoch + 1;
        newMark = epoch + 2;
        newVertex = p;
        // 1. visible facets: breadth-first from the seed
        visibleCount = 0;
        pushVisible(seed);
        mark[seed] = visMark;
        for (int q = 0; q < visibleCount; q++) {
            int f = visible[q];
            for (int i = 0; i < d; i++) {
                int g = nbr[f * d + i];
                int m = mark[g];
                if (m == visMark || m == hidMark) continue;
                if (distance(p, g) > t) { mark[g] = visMark; pushVisible(g); }
                else mark[g] = hidMark;
            }
        }
        // 2. a new facet on every horizon ridge: the visible facet with p in place of the vertex
        //    opposite the ridge (so the ridge keeps its slots)
        newCount = 0;
        for (int q = 0; q < visibleCount; q++) {
            int f = visible[q];
            for (int i = 0; i < d; i++) {
                int g = nbr[f * d + i];
                if (mark[g] == visMark) continue;
                int nf = newFacet();
                for (int k = 0; k < d; k++) { verts[nf * d + k] = verts[f * d + k]; nbr[nf * d + k] = -1; }
                verts[nf * d + i] = p;
                int back = nbrSlot[f * d + i];
                nbr[nf * d + i] = g;
                nbrSlot[nf * d + i] = back;
                nbr[g * d + back] = nf;
                nbrSlot[g * d + back] = i;
                mark[nf] = newMark;
                orientation[nf] = orientation[f];
                if (!rotatedHyperplane(nf, f, g, p)) hyperplane(nf, f);
                pushNew(nf);
                ensureOrigin(newCount);
                origin[2 * (newCount - 1)] = f;
                origin[2 * (newCount - 1) + 1] = i;
            }
        }
        if (coneQueue.length < newCount) coneQueue = new int[2 * newCount];
        // 3. link the new facets to each other across their ridges through p
        if (newCount > 0 && linkByHash(p) && coneIsSound(Math.max(Math.abs(t), tau))) return true;
        for (int q = 0; q < newCount; q++) {       // undo
            int nf = newFacets[q], i = origin[2 * q + 1], g = nbr[nf * d + i], back = nbrSlot[nf * d + i];
            nbr[g * d + back] = origin[2 * q];
            nbrSlot[g * d + back] = i;
            freeFacet(nf);
        }
        newCount = 0;
        return false;
    }

    /**
     * The new cone is sound: every new facet reached from the first across ridges through p
     * (the horizon is one piece), and locally convex — across each of its ridges the
     * neighbour's far vertex lies below it, within {@link #CONVEXITY_SLACK} × t. Rounding near
     * coplanar facets can make a visible region that is not a disc (an annulus, or p on the
     * wrong side of a nearly flat fold), whose cone folds over; this rejects it.
     */
    private boolean coneIsSound(double t) {
        double slack = CONVEXITY_SLACK * t;
        int stamp = ++coneEpoch;
        int reached = 1, head = 0;
        coneMark[newFacets[0]] = stamp;
        coneQueue[0] = newFacets[0];
        while (head < reached) {
            int nf = coneQueue[head++], no = nf * d;
            for (int k = 0; k < d; k++) {
                int g = nbr[no + k];
                if (distance(verts[g * d + nbrSlot[no + k]], nf) > slack) return false;
                if (verts[no + k] != newVertex && coneMark[g] != stamp && isNew(g)) {
                    coneMark[g] = stamp;
                    coneQueue[reached++] = g;
                }
            }
        }
        return reached == newCount;
    }

    private int newMark, newVertex, coneEpoch;
    private int[] coneMark = new int[0], coneQueue = new int[64];
    /** A new facet may have a neighbour's far vertex this many × the visibility threshold above it. */
    static final double CONVEXITY_SLACK = 100;

    private boolean isNew(int f) {
        return mark[f] == newMark;
    }

    /**
     * Links the new facets by matching their ridges through p in a hash table keyed by the
     * ridge's vertex set: two independent 64-bit sums of per-vertex hashes (Zobrist hashing;
     * a false match needs both sums to collide, odds about 2^-120 per pair). False if some
     * ridge is met more than twice (a pinched horizon) or left unmatched.
     */
    private boolean linkByHash(int p) {
        int need = Math.max(16, 2 * newCount * (d - 1));
        int size = Integer.highestOneBit(need - 1) << 1;
        if (tableKey.length < size) {
            tableKey = new long[size];
            tableKey2 = new long[size];
            tableFacet = new int[size];
            tableSlot = new int[size];
            tableStamp = new int[size];
        }
        int mask = size - 1;
        int stamp = ++tableEpoch;
        if (stamp == 0) { Arrays.fill(tableStamp, 0); stamp = ++tableEpoch; }
        for (int q = 0; q < newCount; q++) {
            int nf = newFacets[q], i0 = origin[2 * q + 1], no = nf * d;
            long total = 0, total2 = 0;
            for (int k = 0; k < d; k++) {
                int v = verts[no + k];
                total += hashA[v];
                total2 += hashB[v];
            }
            for (int k = 0; k < d; k++) {
                if (k == i0) continue;
                int v = verts[no + k];
                long key = total - hashA[v], key2 = total2 - hashB[v];
                int h = (int) (key ^ (key >>> 32)) & mask;
                while (true) {
                    if (tableStamp[h] != stamp) {
                        tableStamp[h] = stamp;
                        tableKey[h] = key;
                        tableKey2[h] = key2;
                        tableFacet[h] = nf;
                        tableSlot[h] = k;
                        break;
                    }
                    if (tableKey[h] == key && tableKey2[h] == key2) {
                        int of = tableFacet[h];
                        if (of < 0) return false;                       // a third facet on this ridge
                        int os = tableSlot[h];
                        nbr[no + k] = of;
                        nbrSlot[no + k] = os;
                        nbr[of * d + os] = nf;
                        nbrSlot[of * d + os] = k;
                        tableFacet[h] = -1;
                        break;
                    }
                    h = (h + 1) & mask;
                }
            }
        }
        for (int q = 0; q < newCount; q++) {
            int no = newFacets[q] * d;
            for (int k = 0; k < d; k++) if (nbr[no + k] < 0) return false;
        }
        return true;
    }

    private long[] tableKey = new long[0], tableKey2 = new long[0];
    private int[] tableFacet = new int[0], tableSlot = new int[0], tableStamp = new int[0];
    private int tableEpoch;
    /** Two independent 64-bit hashes of each point index (SplitMix64 outputs). */
    private long[] hashA = new long[0], hashB = new long[0];

    private static long splitMix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    private void ensureOrigin(int count) {
        if (origin.length < 2 * count) origin = Arrays.copyOf(origin, 4 * count);
    }

    /** Puts point i into the outside set of the first new facet it lies above, else marks it inside. */
    private void assignNew(int i) {
        for (int k = 0; k < newCount; k++) {
            int f = newFacets[k];
            double dist = distance(i, f);
            if (dist > tau) { addToOutside(f, i, dist); return; }
        }
        pointState[i] = INSIDE;
    }

    /** Initial partition: facets 0..count-1 are the simplex's. */
    private void assign(int i, int count) {
        for (int f = 0; f < count; f++) {
            double dist = distance(i, f);
            if (dist > tau) { addToOutside(f, i, dist); return; }
        }
        pointState[i] = INSIDE;
    }

    private void addToOutside(int f, int i, double dist) {
        pointNext[i] = outHead[f];
        outHead[f] = i;
        if (pointNext[i] < 0 || dist > furthestDist[f]) { furthest[f] = i; furthestDist[f] = dist; }
    }

    /** Drops non-pending points from f's outside set and finds its furthest point again. */
    private void refreshFurthest(int f) {
        int prev = -1, pt = outHead[f];
        while (pt >= 0) {
            int nx = pointNext[pt];
            if (pointState[pt] != PENDING) {
                if (prev < 0) outHead[f] = nx; else pointNext[prev] = nx;
            } else {
                double dist = distance(pt, f);
                if (prev < 0 || dist > furthestDist[f]) { furthest[f] = pt; furthestDist[f] = dist; }
                prev = pt;
            }
            pt = nx;
        }
    }

    /** The pending point farthest above facet f by more than τ, or −1 (then f supports the hull). */
    private int farthestPendingAbove(int f) {
        int bestPt = -1;
        double best = tau;
        for (int i = 0; i < n; i++) {
            if (pointState[i] != PENDING) continue;
            double dist = distance(i, f);
            if (dist > best) { best = dist; bestPt = i; }
        }
        return bestPt;
    }

    // ------------------------------------------------------------------ geometry

    private double distance(int point, int f) {
        int po = point * d, fo = f * d;
        double s = -offset[f];
        for (int c = 0; c < d; c++) s += normal[fo + c] * pts[po + c];
        return s;
    }

    /**
     * The hyperplane of facet f from its vertices: the null vector of the (d−1)×d matrix of edge
     * vectors by Gaussian elimination with full pivoting, normalised, oriented away from the
     * interior point. If the vertices are degenerate (a zero pivot), the hyperplane of facet
     * {@code fallback} is used (the visible facet it replaces).
     */
    private void hyperplane(int f, int fallback) {
        int fo = f * d;
        if (!nullVector(verts, fo, normal, fo)) {
            if (fallback < 0) throw new IllegalStateException("degenerate initial simplex (a bug)");
            System.arraycopy(normal, fallback * d, normal, fo, d);
        }
        double b = 0, bi = 0;
        for (int r = 0; r < d; r++) {
            int v = verts[fo + r] * d;
            double s = 0;
            for (int c = 0; c < d; c++) s += normal[fo + c] * pts[v + c];
            b += s;
        }
        b /= d;
        for (int c = 0; c < d; c++) bi += normal[fo + c] * interior[c];
        if (bi > b) {
            for (int c = 0; c < d; c++) normal[fo + c] = -normal[fo + c];
            b = -b;
        }
        offset[f] = b;
    }

    /**
     * The unit normal of the hyperplane through the d points {@code vertices[from..from+d-1]}:
     * the null vector of their (d−1)×d edge matrix by Gaussian elimination with full pivoting,
     * into {@code out[at..at+d-1]}; false if a pivot is exactly zero (degenerate points).
     */
    private boolean nullVector(int[] vertices, int from, double[] out, int at) {
        int v0 = vertices[from] * d;
        int rows = d - 1;
        for (int r = 0; r < rows; r++) {
            int v = vertices[from + r + 1] * d;
            for (int c = 0; c < d; c++) ge[r * d + c] = pts[v + c] - pts[v0 + c];
        }
        for (int c = 0; c < d; c++) perm[c] = c;
        for (int k = 0; k < rows; k++) {
            int pr = k, pc = k;
            double big = 0;
            for (int r = k; r < rows; r++) {
                for (int c = k; c < d; c++) {
                    double a = Math.abs(ge[r * d + c]);
                    if (a > big) { big = a; pr = r; pc = c; }
                }
            }
            if (big == 0) return false;
            if (pr != k) {
                for (int c = 0; c < d; c++) { double t = ge[k * d + c]; ge[k * d + c] = ge[pr * d + c]; ge[pr * d + c] = t; }
            }
            if (pc != k) {
                for (int r = 0; r < rows; r++) { double t = ge[r * d + k]; ge[r * d + k] = ge[r * d + pc]; ge[r * d + pc] = t; }
                int t = perm[k]; perm[k] = perm[pc]; perm[pc] = t;
            }
            double piv = ge[k * d + k];
            for (int r = k + 1; r < rows; r++) {
                double fac = ge[r * d + k] / piv;
                if (fac == 0) continue;
                for (int c = k + 1; c < d; c++) ge[r * d + c] -= fac * ge[k * d + c];
                ge[r * d + k] = 0;
            }
        }
        // the free column perm[d-1] = 1; back substitution
        gx[d - 1] = 1;
        for (int k = rows - 1; k >= 0; k--) {
            double s = ge[k * d + d - 1];
            for (int c = k + 1; c < rows; c++) s += ge[k * d + c] * gx[c];
            gx[k] = -s / ge[k * d + k];
        }
        double len = 0;
        for (int c = 0; c < d; c++) len += gx[c] * gx[c];
        len = Math.sqrt(len);
        for (int c = 0; c < d; c++) out[at + perm[c]] = gx[c] / len;
        return true;
    }

    /**
     * The hyperplane of new facet nf (horizon ridge of visible f and hidden g, plus p) without
     * elimination: the ridge's normal space is spanned by n_f and n_g, so the new normal is
     * n ∝ δ_g n_f − δ_f n_g with δ the signed distances of p (then n·(p − r) = 0 for a ridge
     * point r); O(d) instead of O(d³). Accepted only if every vertex lies within
     * {@link #REFIT_TOLERANCE} × S of the result — the accuracy Gaussian elimination gives —
     * else false (nearly parallel n_f and n_g), and the caller eliminates.
     */
    private boolean rotatedHyperplane(int nf, int f, int g, int p) {
        double df = distance(p, f), dg = distance(p, g);
        int fo = f * d, go = g * d, no = nf * d;
        double len = 0;
        for (int c = 0; c < d; c++) {
            double v = dg * normal[fo + c] - df * normal[go + c];
            normal[no + c] = v;
            len += v * v;
        }
        len = Math.sqrt(len);
        if (!(len > 0)) return false;
        double inv = 1 / len;
        for (int c = 0; c < d; c++) normal[no + c] *= inv;
        return fitOffset(nf);
    }

    /** Sets the offset of f from its normal (mean over the vertices, oriented out); false if a vertex is off by more than REFIT_TOLERANCE·S. */
    private boolean fitOffset(int f) {
        int fo = f * d;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY, b = 0;
        for (int r = 0; r < d; r++) {
            int v = verts[fo + r] * d;
            double s = 0;
            for (int c = 0; c < d; c++) s += normal[fo + c] * pts[v + c];
            b += s;
            if (s < lo) lo = s;
            if (s > hi) hi = s;
        }
        if (hi - lo > REFIT_TOLERANCE * scale) return false;
        b /= d;
        double bi = 0;
        for (int c = 0; c < d; c++) bi += normal[fo + c] * interior[c];
        if (bi > b) {
            for (int c = 0; c < d; c++) normal[fo + c] = -normal[fo + c];
            b = -b;
        }
        offset[f] = b;
        return true;
    }

    /** Determinant of the n×n matrix a (row-major, destroyed), Gaussian elimination with partial pivoting. */
    private static double determinant(double[] a, int n) {
        double det = 1;
        for (int k = 0; k < n; k++) {
            int pr = k;
            double big = Math.abs(a[k * n + k]);
            for (int r = k + 1; r < n; r++) {
                double v = Math.abs(a[r * n + k]);
                if (v > big) { big = v; pr = r; }
            }
            if (big == 0) return 0;
            if (pr != k) {
                for (int c = k; c < n; c++) { double t = a[k * n + c]; a[k * n + c] = a[pr * n + c]; a[pr * n + c] = t; }
                det = -det;
            }
            double piv = a[k * n + k];
            det *= piv;
            for (int r = k + 1; r < n; r++) {
                double fac = a[r * n + k] / piv;
                if (fac == 0) continue;
                for (int c = k + 1; c < n; c++) a[r * n + c] -= fac * a[k * n + c];
            }
        }
        return det;
    }

    // ------------------------------------------------------------------ facet storage

    private int newFacet() {
        int f;
        if (freeCount > 0) f = freeList[--freeCount];
        else {
            if (highWater == capacity) {
                if (capacity >= MAX_FACETS) {
                    throw new TooLargeException("the convex hull of " + n + " points needs more than " + MAX_FACETS + " facets (the limit of"
                        + " its memory, about 175 MB)");
                }
                ensureFacets(Math.min(2 * capacity, MAX_FACETS));
            }
            f = highWater++;
        }
        alive[f] = true;
        gen[f]++;
        created++;
        outHead[f] = -1;
        furthest[f] = -1;
        furthestDist[f] = 0;
        mark[f] = 0;
        aliveCount++;
        return f;
    }

    private void freeFacet(int f) {
        alive[f] = false;
        aliveCount--;
        freeList[freeCount++] = f;
    }

    private void ensureFacets(int cap) {
        if (cap <= capacity) return;
        verts = grow(verts, cap * d);
        nbr = grow(nbr, cap * d);
        nbrSlot = grow(nbrSlot, cap * d);
        normal = growD(normal, cap * d);
        offset = growD(offset, cap);
        furthestDist = growD(furthestDist, cap);
        outHead = grow(outHead, cap);
        furthest = grow(furthest, cap);
        gen = grow(gen, cap);
        mark = grow(mark, cap);
        freeList = grow(freeList, cap);
        coneMark = grow(coneMark, cap);
        orientation = orientation == null ? new byte[cap] : Arrays.copyOf(orientation, cap);
        alive = alive == null ? new boolean[cap] : Arrays.copyOf(alive, cap);
        capacity = cap;
    }

    private static int[] grow(int[] a, int len) { return a == null ? new int[len] : Arrays.copyOf(a, len); }

    private static double[] growD(double[] a, int len) { return a == null ? new double[len] : Arrays.copyOf(a, len); }

    private void pushVisible(int f) {
        if (visibleCount == visible.length) visible = Arrays.copyOf(visible, 2 * visibleCount);
        visible[visibleCount++] = f;
    }

    private void pushNew(int f) {
        if (newCount == newFacets.length) newFacets = Arrays.copyOf(newFacets, 2 * newCount);
        newFacets[newCount++] = f;
    }

    private void pushWork(int f) {
        if (workCount == work.length) work = Arrays.copyOf(work, 2 * workCount);
        work[workCount++] = f;
    }

    private int find(int f) {
        while (unionParent[f] != f) {
            unionParent[f] = unionParent[unionParent[f]];
            f = unionParent[f];
        }
        return f;
    }
}
