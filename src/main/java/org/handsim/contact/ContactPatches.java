package org.handsim.contact;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.handsim.collision.CollisionResult;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * Contact surface generation (paper Section IV, second step; DESIGN.md decision 3): the
 * intersection segments of a collision query are chained into patches, and each patch becomes
 * one point contact.
 *
 * <p><b>Chaining.</b> Two segments belong to the same patch when an end point of one lies
 * within the tolerance of an end point of the other (each coordinate within
 * {@link #tolerance()}, by default {@value #TOLERANCE_FACTOR} × the larger bounding-box
 * diagonal of the two meshes); a patch is a connected set of segments (union–find over a sweep
 * of the end points sorted along their widest axis). Adjacent triangle pairs compute a shared
 * end point from the same edge and plane, so their copies agree to a few ulps; the tolerance
 * only has to absorb that.
 *
 * <p><b>Point contact of a patch.</b>
 * <ul>
 *   <li>centre: the centre of the bounding box of the patch's segment end points (the paper's
 *       rule);</li>
 *   <li>normal: a weighted sum of the unit normals of one side's triangles in the patch,
 *       normalised — by default ({@link NormalSide#LEAST_SPREAD}) the side whose normals spread
 *       least: where one side is flat (its triangles coplanar) and the other an edge or a vertex,
 *       the flat side's (the paper's cube: its edge on the inner link's flat face gives the
 *       face's normal, the same for every angle of the cube about that edge; the cube's own two
 *       faces would give a normal 31.45° off it that turns with the cube), else, the sides
 *       spreading alike, the object's ({@link NormalSide#OBJECT} always takes the object's, the
 *       paper's rule). The object is mesh B by default ({@link #objectSide}); the normal always
 *       points <em>out of B, into A</em>, so with the object on side A the sum of A's normals is
 *       negated. Weights ({@link NormalRule}), the same for both sides and for their
 *       {@link #spread}: the paper's rule ({@link NormalRule#AREA}) weights
 *       each distinct object triangle of the patch by its area. Its triangles are the band the
 *       intersection curve runs through, and where the mesh's triangles are larger on one side
 *       of the curve than on the other (a UV sphere tilted against the contact, any mesh of
 *       varying density) the band is wider there and the normal leans that way, at every
 *       resolution: a 2 cm sphere 2 mm into a plane, random orientations, mean error 4–7° for
 *       UV spheres of 16, 32 and 64 segments alike (ContactPatchesTest; these errors are the
 *       sphere's own normals, {@link NormalSide#OBJECT}: against the flat plane
 *       {@link NormalSide#LEAST_SPREAD} takes the plane's normal, which is exact). The default
 *       {@link NormalRule#CURVE} weights each pair's object normal by the length of its piece
 *       of the intersection curve instead (a discrete ∮ n ds, independent of the band's width),
 *       or, in a face-to-face contact, by the coplanar overlap areas: mean error 1.3°, 0.40°,
 *       0.11° on the same cases, shrinking with the resolution (on icospheres of 320, 1 280,
 *       5 120 triangles: 0.88°, 0.15°, 0.08°, where the paper's rule gives 2.2°, 1.1°, 0.64°).
 *       Worked example: a finger link A pressed down onto a table B
 *       (B's top face normal +z) gives normal (0, 0, 1): the direction in which the table
 *       pushes the link. Swapping A and B and naming the same mesh as object flips the normal
 *       exactly;</li>
 *   <li>area: an estimate of the patch area, |a·n| with a = ½ Σ (s − c) × (e − c) the vector
 *       area of the intersection curve (segments are oriented along n_A × n_B by the
 *       intersector, so a closed curve circulates one way), or the overlap area of the coplanar
 *       pairs if larger; for a sphere dipping into a plane it converges to the disc πr²;</li>
 *   <li>the triangles of A and of B it touched, and the number of triangle pairs.</li>
 * </ul>
 * Never a NaN normal: when the chosen side's weighted normals cancel (|Σ aᵢnᵢ| ≤ 1e-6·Σ aᵢ;
 * with {@link NormalSide#OBJECT} e.g. a box sunk face-first into another, whose side faces
 * alone cross the other surface), the other mesh's triangles are used instead (with the sign
 * that keeps "out of B"), {@link NormalSource#OTHER_SIDE}; if they cancel too, the normal of the largest object triangle
 * in the patch, {@link NormalSource#LARGEST_TRIANGLE}; if every triangle has zero area, +z,
 * {@link NormalSource#AXIS}.
 *
 * <p><b>Frames.</b> Segments and results are in A's frame (the frame of the query); B's
 * triangle normals are rotated by the pose the query used.
 *
 * <p><b>Threads.</b> Holds scratch and the last result: one instance per thread. Allocation:
 * none per call once the buffers have grown, except {@link #contacts()} (value objects).
 */
public final class ContactPatches {
    /** Default tolerance for end points to coincide, per metre of bounding-box diagonal. */
    public static final double TOLERANCE_FACTOR = 1e-9;
    /** Relative size below which a weighted normal sum counts as cancelled. */
    public static final double CANCEL_RATIO = 1e-6;

    /** Which mesh's triangles the contact normal is taken from. */
    public enum ObjectSide { A, B }

    /**
     * Which side of a patch gives its normal. A contact is defined by the surface that is
     * smooth there: where the cube's edge lies on a link's flat face, the face's normal is the
     * contact's, whatever the angle of the cube's two faces (turning the cube about the edge
     * does not change the contact), while the object's normals there are an edge's — two faces
     * 90° apart whose weighted sum leans with the cube (31.45° off the link face's normal in the
     * paper's experiment).
     */
    public enum NormalSide {
        /** Always the object's triangles (the paper's rule); the other side's only when the object's cancel. */
        OBJECT,
        /**
         * The side whose weighted normals spread least ({@link #spread}): a flat side (coplanar
         * triangles, spread 0) against an edge or a vertex gives the flat side's normal, signed
         * out of the object as always; when both sides spread alike (within {@value #SPREAD_TIE},
         * e.g. two faces flat against each other) the object's.
         */
        LEAST_SPREAD
    }

    /**
     * How much one side's weighted unit normals spread: 1 − |Σ wᵢnᵢ| / Σ wᵢ, 0 when they are
     * all parallel (a flat face), about 0.29 for an edge between two faces at 90° weighted
     * equally, 1 when they cancel. The weights are the {@link NormalRule}'s.
     */
    public static double spread(double sumX, double sumY, double sumZ, double weight) {
        if (!(weight > 0)) return 1;
        return Math.max(0, 1 - Math.sqrt(sumX * sumX + sumY * sumY + sumZ * sumZ) / weight);
    }

    /** Spreads closer than this count as equal ({@link NormalSide#LEAST_SPREAD} then keeps the object's normal). */
    public static final double SPREAD_TIE = 1e-9;

    /** Where a contact normal came from. */
    public enum NormalSource {
        /** The object's triangles (the paper's rule). */
        OBJECT,
        /**
         * The other mesh's triangles, because their normals spread less than the object's
         * ({@link NormalSide#LEAST_SPREAD}: e.g. a link's flat face under the object's edge).
         */
        FLATTER_SIDE,
        /** The object's normals cancelled; the other mesh's triangles, sign adjusted. */
        OTHER_SIDE,
        /** Both sums cancelled; the largest object triangle in the patch. */
        LARGEST_TRIANGLE,
        /** Every triangle in the patch has zero area: +z. */
        AXIS
    }

    /**
     * How the object's triangle normals are weighted. The measurements behind the default are in
     * the class comment.
     */
    public enum NormalRule {
        /** The paper's rule: each distinct object triangle of the patch once, weighted by its area. */
        AREA,
        /**
         * Each triangle pair's object normal weighted by the length of its intersection segment
         * (a discrete ∮ n ds along the intersection curve); if the patch has coplanar overlaps of
         * positive area, by those areas only (the faces in contact).
         */
        CURVE
    }

    private ObjectSide objectSide = ObjectSide.B;
    private NormalRule rule = NormalRule.CURVE;
    private NormalSide normalSide = NormalSide.LEAST_SPREAD;
    private final double[] sumA = new double[12], sumB = new double[12];
    private double tolerance = Double.NaN;
    private TriangleMesh tolA, tolB;        // the meshes defaultTol was computed for
    private double defaultTol, tolUsed;

    // scratch
    private int[] parent = new int[64];
    private int[] idx = new int[128];
    private double[] key = new double[128];
    private int[] rootToPatch = new int[64];
    private int[] pairPatch = new int[64], pairOrder = new int[64], patchFirst = new int[17];
    private int[] markA = new int[0], markB = new int[0];
    private int markBase;
    private final double[] rot = new double[12];

    // results
    private int patches;
    private double[] center = new double[48], normal = new double[48], areas = new double[16];
    private int[] pairCount = new int[16];
    private NormalSource[] source = new NormalSource[16];
    private int[] triAStart = new int[17], triBStart = new int[17];
    private int[] triA = new int[64], triB = new int[64];

    /** Sets which mesh's triangles give the normal (default B); returns this. */
    public ContactPatches objectSide(ObjectSide side) {
        if (side == null) throw new IllegalArgumentException("objectSide must not be null");
        objectSide = side;
        return this;
    }

    /** @return the object side in use */
    public ObjectSide objectSide() { return objectSide; }

    /** Sets how the object's normals are weighted (default {@link NormalRule#CURVE}); returns this. */
    public ContactPatches normalRule(NormalRule r) {
        if (r == null) throw new IllegalArgumentException("normalRule must not be null");
        rule = r;
        return this;
    }

    /** @return the normal rule in use */
    public NormalRule normalRule() { return rule; }

    /** Sets which side gives the normal (default {@link NormalSide#LEAST_SPREAD}); returns this. */
    public ContactPatches normalSide(NormalSide side) {
        if (side == null) throw new IllegalArgumentException("normalSide must not be null");
        normalSide = side;
        return this;
    }

    /** @return which side gives the normal */
    public NormalSide normalSide() { return normalSide; }

    /**
     * Fixes the chaining tolerance (metres, &gt; 0); NaN restores the default
     * ({@value #TOLERANCE_FACTOR} × the larger bounding-box diagonal of the two meshes).
     */
    public ContactPatches tolerance(double metres) {
        if (!(metres > 0) && !Double.isNaN(metres)) throw new IllegalArgumentException("tolerance must be positive, got " + metres);
        tolerance = metres;
        return this;
    }

    /** @return the tolerance used by the last {@link #build} (metres) */
    public double tolerance() { return tolUsed; }

    /**
     * Builds the patches and point contacts of a query result.
     *
     * @param r     the query result (segments in A's frame)
     * @param a     mesh A (its normals and areas; its own frame is the query frame)
     * @param b     mesh B
     * @param poseB the transform the query placed B with (B's frame → A's frame)
     * @return the number of patches
     */
    public int build(CollisionResult r, TriangleMesh a, TriangleMesh b, RigidTransform poseB) {
        double tol = tolerance;
        if (Double.isNaN(tol)) {
            if (a != tolA || b != tolB) {
                tolA = a;
                tolB = b;
                defaultTol = TOLERANCE_FACTOR * Math.max(a.diagonal(), b.diagonal());
                if (!(defaultTol > 0)) defaultTol = Double.MIN_NORMAL;
            }
            tol = defaultTol;
        }
        poseB.copyTo(rot, 0);
        return build(r, a.normals(), a.areas(), b.normals(), b.areas(), rot, tol);
    }

    /**
     * The same from raw arrays: unit normals and areas per triangle of A (A's frame) and of B
     * (B's frame, rotated here by the rotation part of {@code poseB12}, 12 row-major values).
     */
    public int build(CollisionResult r, double[] normalsA, double[] areasA, double[] normalsB, double[] areasB,
                     double[] poseB12, double tol) {
        tolUsed = tol;
        int nseg = r.segmentCount(), npairs = r.pairCount();
        patches = 0;
        if (npairs == 0) return 0;
        double[] seg = r.segments();
        // ---- union-find over segments, joined by end points within tol
        ensureSegments(nseg);
        ensurePairs(npairs);
        for (int i = 0; i < nseg; i++) parent[i] = i;
        for (int p = 0; p < npairs; p++) {           // the segments of one pair are one piece
            for (int s = r.segmentStart(p) + 1; s < r.segmentStart(p + 1); s++) union(r.segmentStart(p), s);
        }
        int ne = 2 * nseg;
        double lo0 = Double.POSITIVE_INFINITY, lo1 = lo0, lo2 = lo0, hi0 = Double.NEGATIVE_INFINITY, hi1 = hi0, hi2 = hi0;
        for (int e = 0; e < ne; e++) {
            int o = 3 * e;
            lo0 = Math.min(lo0, seg[o]); hi0 = Math.max(hi0, seg[o]);
            lo1 = Math.min(lo1, seg[o + 1]); hi1 = Math.max(hi1, seg[o + 1]);
            lo2 = Math.min(lo2, seg[o + 2]); hi2 = Math.max(hi2, seg[o + 2]);
        }
        int axis = (hi0 - lo0) >= (hi1 - lo1) && (hi0 - lo0) >= (hi2 - lo2) ? 0 : ((hi1 - lo1) >= (hi2 - lo2) ? 1 : 2);
        for (int e = 0; e < ne; e++) {
            idx[e] = e;
            key[e] = seg[3 * e + axis];
        }
        heapSort(idx, key, ne);
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (int i = 0; i < ne; i++) {
            int ei = idx[i];
            double ki = key[ei];
            for (int j = i + 1; j < ne; j++) {
                int ej = idx[j];
                if (key[ej] - ki > tol) break;
                if (Math.abs(seg[3 * ei + a1] - seg[3 * ej + a1]) <= tol && Math.abs(seg[3 * ei + a2] - seg[3 * ej + a2]) <= tol) {
                    union(ei >> 1, ej >> 1);
                }
            }
        }
        // ---- number the patches; pairs by patch (counting sort)
        for (int s = 0; s < nseg; s++) rootToPatch[s] = -1;
        for (int p = 0; p < npairs; p++) {
            int root = find(r.segmentStart(p));
            if (rootToPatch[root] < 0) rootToPatch[root] = patches++;
            pairPatch[p] = rootToPatch[root];
        }
        ensurePatches(patches);
        Arrays.fill(patchFirst, 0, patches + 1, 0);
        for (int p = 0; p < npairs; p++) patchFirst[pairPatch[p] + 1]++;
        for (int q = 0; q < patches; q++) patchFirst[q + 1] += patchFirst[q];
        for (int p = 0; p < npairs; p++) pairOrder[patchFirst[pairPatch[p]]++] = p;
        for (int q = patches; q > 0; q--) patchFirst[q] = patchFirst[q - 1];
        patchFirst[0] = 0;
        // ---- per patch
        ensureMarks(normalsA.length / 3, normalsB.length / 3);
        int nA = 0, nB = 0;
        for (int q = 0; q < patches; q++) {
            int stampQ = markBase + q + 1;
            triAStart[q] = nA;
            triBStart[q] = nB;
            double bx0 = Double.POSITIVE_INFINITY, by0 = bx0, bz0 = bx0, bx1 = Double.NEGATIVE_INFINITY, by1 = bx1, bz1 = bx1;
            double copArea = 0;
            // weighted normal sums, index 0..3 = x, y, z, total weight; A's and B's (B's rotated into A's frame)
            double[] wa = sumA, wb = sumB;
            Arrays.fill(wa, 0);
            Arrays.fill(wb, 0);
            boolean anyCoplanar = false;
            int largestObj = -1;
            double largestArea = -1;
            for (int i = patchFirst[q]; i < patchFirst[q + 1]; i++) {
                int p = pairOrder[i];
                double len = 0;
                for (int s = r.segmentStart(p); s < r.segmentStart(p + 1); s++) {
                    int o0 = 6 * s;
                    double lx = seg[o0 + 3] - seg[o0], ly = seg[o0 + 4] - seg[o0 + 1], lz = seg[o0 + 5] - seg[o0 + 2];
                    len += Math.sqrt(lx * lx + ly * ly + lz * lz);
                    for (int e = 0; e < 2; e++) {
                        int o = o0 + 3 * e;
                        bx0 = Math.min(bx0, seg[o]); bx1 = Math.max(bx1, seg[o]);
                        by0 = Math.min(by0, seg[o + 1]); by1 = Math.max(by1, seg[o + 1]);
                        bz0 = Math.min(bz0, seg[o + 2]); bz1 = Math.max(bz1, seg[o + 2]);
                    }
                }
                boolean cop = r.isCoplanar(p) && r.coplanarArea(p) > 0;
                if (cop) {
                    copArea += r.coplanarArea(p);
                    anyCoplanar = true;
                }
                int ta = r.triangleA(p), tb = r.triangleB(p);
                double nax = normalsA[3 * ta], nay = normalsA[3 * ta + 1], naz = normalsA[3 * ta + 2];
                double x = normalsB[3 * tb], y = normalsB[3 * tb + 1], z = normalsB[3 * tb + 2];
                double nbx = poseB12[0] * x + poseB12[1] * y + poseB12[2] * z;
                double nby = poseB12[4] * x + poseB12[5] * y + poseB12[6] * z;
                double nbz = poseB12[8] * x + poseB12[9] * y + poseB12[10] * z;
                // CURVE rule: per pair, weight = coplanar overlap area (slots 4..7) or curve length (slots 8..11)
                int slot = cop ? 4 : 8;
                double w = cop ? r.coplanarArea(p) : len;
                wa[slot] += w * nax; wa[slot + 1] += w * nay; wa[slot + 2] += w * naz; wa[slot + 3] += w;
                wb[slot] += w * nbx; wb[slot + 1] += w * nby; wb[slot + 2] += w * nbz; wb[slot + 3] += w;
                // AREA rule (the paper's): each distinct triangle once, weight = its area (slots 0..3)
                if (markA[ta] != stampQ) {
                    markA[ta] = stampQ;
                    if (nA == triA.length) triA = Arrays.copyOf(triA, 2 * nA);
                    triA[nA++] = ta;
                    double aw = areasA[ta];
                    wa[0] += aw * nax; wa[1] += aw * nay; wa[2] += aw * naz; wa[3] += aw;
                    if (objectSide == ObjectSide.A && aw > largestArea) { largestArea = aw; largestObj = ta; }
                }
                if (markB[tb] != stampQ) {
                    markB[tb] = stampQ;
                    if (nB == triB.length) triB = Arrays.copyOf(triB, 2 * nB);
                    triB[nB++] = tb;
                    double bw = areasB[tb];
                    wb[0] += bw * nbx; wb[1] += bw * nby; wb[2] += bw * nbz; wb[3] += bw;
                    if (objectSide == ObjectSide.B && bw > largestArea) { largestArea = bw; largestObj = tb; }
                }
            }
            Arrays.sort(triA, triAStart[q], nA);
            Arrays.sort(triB, triBStart[q], nB);
            double cx = 0.5 * (bx0 + bx1), cy = 0.5 * (by0 + by1), cz = 0.5 * (bz0 + bz1);
            center[3 * q] = cx; center[3 * q + 1] = cy; center[3 * q + 2] = cz;
            // normal, out of B: the object's sum (negated for A) or, when it spreads more than the
            // other side's (an edge or a vertex on a flat face), the other side's; if the chosen
            // sum cancels, the other one
            int use = rule == NormalRule.AREA ? 0 : (anyCoplanar ? 4 : 8);
            double sgnObj = objectSide == ObjectSide.B ? 1 : -1;
            double[] obj = objectSide == ObjectSide.B ? wb : wa, oth = objectSide == ObjectSide.B ? wa : wb;
            double ox = sgnObj * obj[use], oy = sgnObj * obj[use + 1], oz = sgnObj * obj[use + 2], os = obj[use + 3];
            double tx = -sgnObj * oth[use], ty = -sgnObj * oth[use + 1], tz = -sgnObj * oth[use + 2], ts = oth[use + 3];
            NormalSource src = NormalSource.OBJECT, fallback = NormalSource.OTHER_SIDE;
            if (normalSide == NormalSide.LEAST_SPREAD
                && spread(tx, ty, tz, ts) < spread(ox, oy, oz, os) - SPREAD_TIE) {
                double x = ox, y = oy, z = oz, w = os;
                ox = tx; oy = ty; oz = tz; os = ts;
                tx = x; ty = y; tz = z; ts = w;
                src = NormalSource.FLATTER_SIDE;
                fallback = NormalSource.OBJECT;
            }
            double len = Math.sqrt(ox * ox + oy * oy + oz * oz);
            if (!(len > CANCEL_RATIO * os) || os == 0) {
                src = fallback;
                ox = tx; oy = ty; oz = tz;
                len = Math.sqrt(ox * ox + oy * oy + oz * oz);
                if (!(len > CANCEL_RATIO * ts) || ts == 0) {
                    src = NormalSource.LARGEST_TRIANGLE;
                    if (largestObj >= 0 && largestArea > 0) {
                        if (objectSide == ObjectSide.B) {
                            double x = normalsB[3 * largestObj], y = normalsB[3 * largestObj + 1], z = normalsB[3 * largestObj + 2];
                            ox = poseB12[0] * x + poseB12[1] * y + poseB12[2] * z;
                            oy = poseB12[4] * x + poseB12[5] * y + poseB12[6] * z;
                            oz = poseB12[8] * x + poseB12[9] * y + poseB12[10] * z;
                        } else {
                            ox = -normalsA[3 * largestObj]; oy = -normalsA[3 * largestObj + 1]; oz = -normalsA[3 * largestObj + 2];
                        }
                        len = Math.sqrt(ox * ox + oy * oy + oz * oz);
                    } else {
                        len = 0;
                    }
                    if (!(len > 0)) {
                        src = NormalSource.AXIS;
                        ox = 0; oy = 0; oz = 1; len = 1;
                    }
                }
            }
            double nx = ox / len, ny = oy / len, nz = oz / len;
            normal[3 * q] = nx; normal[3 * q + 1] = ny; normal[3 * q + 2] = nz;
            source[q] = src;
            // area: vector area of the (non-coplanar) curve about the centre, along n, plus coplanar overlaps
            double vx = 0, vy = 0, vz = 0;
            for (int i = patchFirst[q]; i < patchFirst[q + 1]; i++) {
                int p = pairOrder[i];
                if (r.isCoplanar(p)) continue;
                for (int s = r.segmentStart(p); s < r.segmentStart(p + 1); s++) {
                    int o = 6 * s;
                    double x0 = seg[o] - cx, y0 = seg[o + 1] - cy, z0 = seg[o + 2] - cz;
                    double x1 = seg[o + 3] - cx, y1 = seg[o + 4] - cy, z1 = seg[o + 5] - cz;
                    vx += y0 * z1 - z0 * y1;
                    vy += z0 * x1 - x0 * z1;
                    vz += x0 * y1 - y0 * x1;
                }
            }
            // a coplanar face contact is usually ringed by the transversal segments of the faces
            // next to it, which enclose the same region: take the larger, do not add
            areas[q] = Math.max(0.5 * Math.abs(vx * nx + vy * ny + vz * nz), copArea);
            pairCount[q] = patchFirst[q + 1] - patchFirst[q];
        }
        triAStart[patches] = nA;
        triBStart[patches] = nB;
        markBase += patches + 1;
        return patches;
    }

    // ------------------------------------------------------------------ results

    /** @return the number of patches (point contacts) of the last build */
    public int patchCount() { return patches; }

    /** Patch i's centre (A's frame, metres) into out[0..2]; returns out. */
    public double[] center(int i, double[] out) {
        System.arraycopy(center, 3 * i, out, 0, 3);
        return out;
    }

    /** Patch i's unit normal (out of B, A's frame) into out[0..2]; returns out. */
    public double[] normal(int i, double[] out) {
        System.arraycopy(normal, 3 * i, out, 0, 3);
        return out;
    }

    /** @return patch i's area estimate, m² */
    public double area(int i) { return areas[i]; }

    /** @return the number of triangle pairs in patch i */
    public int pairCount(int i) { return pairCount[i]; }

    /** @return where patch i's normal came from */
    public NormalSource normalSource(int i) { return source[i]; }

    /** @return the distinct triangles of A in patch i, ascending (new array) */
    public int[] trianglesA(int i) { return Arrays.copyOfRange(triA, triAStart[i], triAStart[i + 1]); }

    /** @return the distinct triangles of B in patch i, ascending (new array) */
    public int[] trianglesB(int i) { return Arrays.copyOfRange(triB, triBStart[i], triBStart[i + 1]); }

    /** @return the last build's point contacts as value objects */
    public List<PointContact> contacts() {
        List<PointContact> out = new ArrayList<>(patches);
        for (int i = 0; i < patches; i++) {
            out.add(new PointContact(center(i, new double[3]), normal(i, new double[3]), areas[i], pairCount[i],
                trianglesA(i), trianglesB(i), source[i]));
        }
        return out;
    }

    // ------------------------------------------------------------------ helpers

    private int find(int x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }

    private void union(int x, int y) {
        int rx = find(x), ry = find(y);
        if (rx != ry) parent[Math.max(rx, ry)] = Math.min(rx, ry);
    }

    /** Sorts idx[0..n) by key[idx[i]] ascending (heap sort: no recursion, no allocation). */
    static void heapSort(int[] idx, double[] key, int n) {
        for (int i = n / 2 - 1; i >= 0; i--) sift(idx, key, i, n);
        for (int end = n - 1; end > 0; end--) {
            int t = idx[0];
            idx[0] = idx[end];
            idx[end] = t;
            sift(idx, key, 0, end);
        }
    }

    private static void sift(int[] idx, double[] key, int i, int n) {
        int v = idx[i];
        double kv = key[v];
        while (true) {
            int c = 2 * i + 1;
            if (c >= n) break;
            if (c + 1 < n && key[idx[c + 1]] > key[idx[c]]) c++;
            if (key[idx[c]] <= kv) break;
            idx[i] = idx[c];
            i = c;
        }
        idx[i] = v;
    }

    private void ensureSegments(int nseg) {
        if (parent.length < nseg) {
            parent = new int[2 * nseg];
            rootToPatch = new int[2 * nseg];
        }
        if (idx.length < 2 * nseg) {
            idx = new int[4 * nseg];
            key = new double[4 * nseg];
        }
    }

    private void ensurePatches(int np) {
        if (areas.length < np) {
            int c = 2 * np;
            center = new double[3 * c];
            normal = new double[3 * c];
            areas = new double[c];
            pairCount = new int[c];
            source = new NormalSource[c];
            triAStart = new int[c + 1];
            triBStart = new int[c + 1];
        }
        if (patchFirst.length < np + 1) patchFirst = new int[2 * np + 1];
    }

    private void ensureMarks(int ta, int tb) {
        if (markA.length < ta) markA = new int[ta];
        if (markB.length < tb) markB = new int[tb];
        if (markBase > Integer.MAX_VALUE / 2) {
            Arrays.fill(markA, 0);
            Arrays.fill(markB, 0);
            markBase = 0;
        }
    }

    /** Grows the per-pair scratch. */
    private void ensurePairs(int np) {
        if (pairPatch.length < np) {
            pairPatch = new int[2 * np];
            pairOrder = new int[2 * np];
        }
    }
}
