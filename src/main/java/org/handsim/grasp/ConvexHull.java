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
 *       The new facets are linked to each other by rotating about each (d−3)-face of the horizon
 *       through the visible facets (the walk stops at the first hidden facet): this pairs the
 *       new facets consistently even where rounding makes the visible region pinched, so the
 *       facet graph stays a closed pseudomanifold, never a dangling pointer. The points of the
 *       visible facets' outside sets are partitioned among the new facets (a point above no new
 *       facet is inside the new hull: Barber et al., Lemma 3.3 and §3).</li>
 *   <li>Repeat while an outside set is non-empty; an explicit work list, no recursion.</li>
 * </ol>
 * A facet's hyperplane n·x = b (unit n, pointing out) comes from its d vertices by Gaussian
 * elimination with full pivoting; b is the mean of n·v over the vertices. The interior point
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
    /** Lower-dimensional when no point is farther than this × S from the span of the chosen ones. */
    public static final double RANK_TOLERANCE = 1e-9;
    /** τ / S: a point must be farther than τ above a facet to count as outside it. */
    public static final double DISTANCE_TOLERANCE = 1e-11;
    /** Neighbouring simplicial facets within this × S of each other's hyperplane are one facet. */
    public static final double MERGE_TOLERANCE = 1e-9;

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
    private int[] verts, nbr, hnew;
    private double[] normal, offset, furthestDist;
    private int[] outHead, furthest, gen, mark;
    private boolean[] alive;
    private int[] freeList;
    private int freeCount, aliveCount;
    private int epoch;

    private final double[] interior;
    // scratch
    private int[] visible = new int[64], newFacets = new int[64], work = new int[64];
    /** For new facet k of the current step: the visible facet and the slot it was made from. */
    private int[] origin = new int[128];
    private int visibleCount, newCount, workCount;
    private final double[] ge, gx, rowTmp;
    private final int[] perm;
    private double[] resid = new double[0];
    private final double[] basis;
    private final int[] simplex;
    private final FacetHeap heap = new FacetHeap();
    private int[] unionParent = new int[0];

    /** @param dimension d, 2 ≤ d ≤ 8 */
    public ConvexHull(int dimension) {
        if (dimension < 2 || dimension > 8) throw new IllegalArgumentException("dimension must be 2..8, got " + dimension);
        this.d = dimension;
        interior = new double[d];
        ge = new double[d * d];
        gx = new double[d];
        rowTmp = new double[d];
        perm = new int[d];
        basis = new double[d * d];
        simplex = new int[d + 1];
        ensureFacets(256);
    }

    /** The dimension d. */
    public int dimension() { return d; }

    // ------------------------------------------------------------------ public entry points

    /**
     * Builds the whole hull of {@code count} points ({@code points[i*d .. i*d+d-1]}).
     *
     * @return true if the points span d dimensions (else nothing is built: volume 0, no facets)
     * @throws IllegalArgumentException for a non-finite coordinate
     */
    public boolean build(double[] points, int count) {
        if (!start(points, count)) return false;
        workCount = 0;
        for (int f = 0; f < highWater; f++) if (alive[f] && outHead[f] >= 0) pushWork(f);
        while (workCount > 0) {
            int f = work[--workCount];
            if (!alive[f] || outHead[f] < 0) continue;
            addPoint(furthest[f], f);
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
     *   <li>if some point lies above F by more than τ (its outside set, then every pending point
     *       is checked), add the furthest such point (a Quickhull step; F is visible, so it is
     *       replaced) and repeat;</li>
     *   <li>otherwise F's hyperplane supports the whole hull H (no point lies above it), so
     *       ε(H) ≤ b_F. If b_F &gt; 0, every facet of H_k has offset ≥ b_F &gt; 0, so the ball of
     *       radius b_F about the origin lies in H_k ⊆ H and ε(H) ≥ b_F: hence ε(H) = b_F. If
     *       b_F ≤ 0, a supporting hyperplane of H has the origin on or beyond it: the origin is
     *       not strictly inside H, no force closure.</li>
     * </ul>
     * It ends because every step adds a point. Tested against {@link #build} on hundreds of
     * seeded sets (GraspQualityReferenceTest, WrenchSpaceTest).
     */
    public double epsilon(double[] points, int count) {
        if (!start(points, count)) return Double.NaN;
        heap.clear();
        for (int f = 0; f < highWater; f++) if (alive[f]) heap.push(offset[f], f, gen[f]);
        while (!heap.isEmpty()) {
            int f = heap.topFacet(), g = heap.topGen();
            heap.pop();
            if (!alive[f] || gen[f] != g) continue;
            int p = refreshOutside(f) ? furthest[f] : farthestPendingAbove(f);
            if (p < 0) return offset[f];
            addPoint(p, f);
            for (int k = 0; k < newCount; k++) {
                int nf = newFacets[k];
                heap.push(offset[nf], nf, gen[nf]);
            }
        }
        throw new IllegalStateException("best-first hull ran out of facets (a bug)");
    }

    /** True if the last build or epsilon call found the points to span d dimensions. */
    public boolean isFullDimensional() { return full; }

    /** τ of the last call: a point counts as above a facet only when farther than this. */
    public double tolerance() { return tau; }

    /** The largest absolute coordinate S of the last call's points. */
    public double scale() { return scale; }

    /** Simplicial facets of the last {@link #build} (0 when lower-dimensional). */
    public int simplicialFacetCount() { return full ? aliveCount : 0; }

    /** The smallest facet offset of the last build (see {@link #epsilon}); NaN if lower-dimensional. */
    public double minOffset() {
        if (!full) return Double.NaN;
        double m = Double.POSITIVE_INFINITY;
        for (int f = 0; f < highWater; f++) if (alive[f] && offset[f] < m) m = offset[f];
        return m;
    }

    /** d-dimensional volume of the last build's hull (0 when lower-dimensional). */
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
            sum += Math.abs(determinant(ge, d));
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
                int x = farVertex(g, f);
                if (Math.abs(distance(x, f)) > mt) continue;
                int a = find(f), b = find(g);
                if (a != b) { unionParent[a] = b; groups--; }
            }
        }
        return groups;
    }

    /** Number of points the last call added as hull vertices (the work done). */
    public int vertexCount() {
        int c = 0;
        for (int i = 0; i < n; i++) if (pointState[i] == VERTEX) c++;
        return c;
    }

    // ------------------------------------------------------------------ set-up

    private boolean start(double[] points, int count) {
        if (count < 0 || points.length < count * d) {
            throw new IllegalArgumentException("need " + d + "*count = " + d * count + " coordinates, got " + points.length);
        }
        pts = points;
        n = count;
        full = false;
        highWater = 0; freeCount = 0; aliveCount = 0;
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
                slot++;
            }
            hyperplane(f, -1);
        }
        for (int j = 0; j <= d; j++) pointState[simplex[j]] = VERTEX;
        // partition every other point among the simplex's facets
        for (int i = 0; i < n; i++) {
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

    /** Adds point p, which lies above facet seed by more than τ. The new facets are in newFacets. */
    private void addPoint(int p, int seed) {
        epoch += 2;
        int visMark = epoch, hidMark = epoch + 1;
        pointState[p] = VERTEX;
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
                if (distance(p, g) > tau) { mark[g] = visMark; pushVisible(g); }
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
                nbr[nf * d + i] = g;
                nbr[g * d + slotOfNeighbour(g, f)] = nf;
                hnew[f * d + i] = nf;
                mark[nf] = 0;
                hyperplane(nf, f);
                pushNew(nf);
                // remember where it came from: the visible facet f and slot i
                work2Ensure(newCount);
                origin[2 * (newCount - 1)] = f;
                origin[2 * (newCount - 1) + 1] = i;
            }
        }
        if (newCount == 0) throw new IllegalStateException("point " + p + " sees every facet (a bug)");
        // 3. link the new facets to each other: rotate about each (d-3)-face through the visible facets
        for (int q = 0; q < newCount; q++) {
            int nf = newFacets[q], f0 = origin[2 * q], i0 = origin[2 * q + 1];
            for (int k = 0; k < d; k++) {
                if (k == i0 || nbr[nf * d + k] >= 0) continue;
                int cur = f0, v = verts[f0 * d + k], w = verts[f0 * d + i0];
                int guard = 0;
                while (true) {
                    int sv = slotOfVertex(cur, v);
                    int next = nbr[cur * d + sv];
                    if (mark[next] != visMark) {
                        int partner = hnew[cur * d + sv];
                        nbr[nf * d + k] = partner;
                        nbr[partner * d + slotOfVertex(cur, w)] = nf;
                        break;
                    }
                    int x = verts[next * d + slotOfNeighbour(next, cur)];
                    v = w; w = x; cur = next;
                    if (++guard > visibleCount + 1) throw new IllegalStateException("hull topology broken at point " + p + " (a bug)");
                }
            }
        }
        // 4. partition the outside sets of the visible facets among the new facets; free them
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
    }

    private void work2Ensure(int count) {
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

    /** Drops points that became vertices from f's outside set; true if any remain (furthest updated). */
    private boolean refreshOutside(int f) {
        int prev = -1, pt = outHead[f];
        double best = -1;
        int bestPt = -1;
        while (pt >= 0) {
            int nx = pointNext[pt];
            if (pointState[pt] != PENDING) {
                if (prev < 0) outHead[f] = nx; else pointNext[prev] = nx;
            } else {
                double dist = distance(pt, f);
                if (dist > best) { best = dist; bestPt = pt; }
                prev = pt;
            }
            pt = nx;
        }
        if (bestPt < 0) { outHead[f] = -1; return false; }
        furthest[f] = bestPt;
        furthestDist[f] = best;
        return true;
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
        int v0 = verts[fo] * d;
        int rows = d - 1;
        for (int r = 0; r < rows; r++) {
            int v = verts[fo + r + 1] * d;
            for (int c = 0; c < d; c++) ge[r * d + c] = pts[v + c] - pts[v0 + c];
        }
        for (int c = 0; c < d; c++) perm[c] = c;
        boolean degenerate = false;
        for (int k = 0; k < rows; k++) {
            int pr = k, pc = k;
            double big = 0;
            for (int r = k; r < rows; r++) {
                for (int c = k; c < d; c++) {
                    double a = Math.abs(ge[r * d + c]);
                    if (a > big) { big = a; pr = r; pc = c; }
                }
            }
            if (big == 0) { degenerate = true; break; }
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
        if (degenerate) {
            if (fallback < 0) throw new IllegalStateException("degenerate initial simplex (a bug)");
            System.arraycopy(normal, fallback * d, normal, fo, d);
        } else {
            // free column: perm[d-1] = 1; back substitution
            gx[d - 1] = 1;
            for (int k = rows - 1; k >= 0; k--) {
                double s = ge[k * d + d - 1];
                for (int c = k + 1; c < rows; c++) s += ge[k * d + c] * gx[c];
                gx[k] = -s / ge[k * d + k];
            }
            double len = 0;
            for (int c = 0; c < d; c++) len += gx[c] * gx[c];
            len = Math.sqrt(len);
            for (int c = 0; c < d; c++) normal[fo + perm[c]] = gx[c] / len;
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
            if (highWater == capacity) ensureFacets(2 * capacity);
            f = highWater++;
        }
        alive[f] = true;
        gen[f]++;
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
        hnew = grow(hnew, cap * d);
        normal = growD(normal, cap * d);
        offset = growD(offset, cap);
        furthestDist = growD(furthestDist, cap);
        outHead = grow(outHead, cap);
        furthest = grow(furthest, cap);
        gen = grow(gen, cap);
        mark = grow(mark, cap);
        freeList = grow(freeList, cap);
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

    private int slotOfNeighbour(int f, int g) {
        int fo = f * d;
        for (int i = 0; i < d; i++) if (nbr[fo + i] == g) return i;
        throw new IllegalStateException("facets " + f + " and " + g + " are not neighbours (a bug)");
    }

    private int slotOfVertex(int f, int v) {
        int fo = f * d;
        for (int i = 0; i < d; i++) if (verts[fo + i] == v) return i;
        throw new IllegalStateException("vertex " + v + " not in facet " + f + " (a bug)");
    }

    /** The vertex of g that is not in its neighbour f. */
    private int farVertex(int g, int f) {
        return verts[g * d + slotOfNeighbour(g, f)];
    }

    private int find(int f) {
        while (unionParent[f] != f) {
            unionParent[f] = unionParent[unionParent[f]];
            f = unionParent[f];
        }
        return f;
    }
}
