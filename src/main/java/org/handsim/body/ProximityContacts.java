package org.handsim.body;

import java.util.Arrays;
import org.handsim.collision.KdopTree;
import org.handsim.collision.NearPairs;
import org.handsim.collision.TreeQuery;
import org.handsim.collision.TriangleDistance;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * The contact points between the free object and one other body (a support, a finger link)
 * from proximity (DESIGN.md decision 7): every feature pair of nearby triangles closer than the
 * margin δ or penetrating less than the depth D becomes a candidate, and each patch of
 * candidates is reduced to at most {@value #MAX_POINTS_PER_PATCH} points that span it.
 *
 * <p><b>Nearby triangles</b>: the pairs whose k-DOP bounds and boxes are within δ, by the trees'
 * {@link TreeQuery#near} walk (the object placed in the other body's frame). The walk gathers
 * the pairs within δ + {@value #SLACK_FRACTION}·δ and is not repeated while no point of the object
 * has moved, relative to the other body, by as much as the pairs' clearance leaves above δ
 * ({@link NearPairs#clearance()}; the motion bounded by |ΔR·c + Δt| + ‖ΔR‖_F·ρ, c and ρ the
 * centre and radius of the object's vertices' bounding sphere): every pair now within δ was
 * then within the clearance, so it is in the list (temporal coherence: an object held in the
 * hand or resting on a table walks the trees once in many steps: walking them every step costs 40 % of a step).
 * The features below are tested at the current pose.
 *
 * <p><b>Features</b> (the closest features of two disjoint convex pieces are a vertex and a face,
 * or two edges; Ericson 2005, §5.1.9; Lin and Canny's Voronoi regions):
 * <ul>
 *   <li>a vertex of one mesh over a face of the other: its projection lies in the triangle, its
 *       signed distance g along the face's outward normal is in [−D, δ], and the vertex is the
 *       mesh's extreme point toward the face — no neighbour of it lies closer to the face's plane
 *       ({@link MeshTopology}). Without that last test, a table's vertex beside a box's side face
 *       would make a wall that stops the box sliding;</li>
 *   <li>two edges whose closest points lie inside both (a vertex end belongs to the vertex
 *       case): the direction m between them (or the edges' cross product when they cross) must
 *       leave both edges through their outside — the two faces at each edge lie behind it — which
 *       also tells apart two edges a distance d apart (g = d) from two that passed through each
 *       other (g = −d, m reversed). Only convex edges take part: a flat edge (between coplanar
 *       faces) is its face's inside, and would pass that test both ways — a box sliding over a
 *       table's inner edge met a wall there — and a concave edge has no outside.</li>
 * </ul>
 * Each candidate is a point midway between the two features, the unit normal along which the
 * other body pushes the object, and the gap.
 *
 * <p><b>The manifold</b>: candidates are grouped by normal (within {@value #PATCH_ANGLE_DEG}° of a
 * patch's first, deepest candidate); each patch keeps its deepest candidate and the candidates
 * farthest along eight directions 45° apart in the plane normal to its normal, so a face lying on
 * a face keeps the corners of their overlap and resists tipping and twisting, and the normal
 * force spreads over the contact area (the paper's future work); duplicates count once:
 * N = {@value #MAX_POINTS_PER_PATCH} at most.
 *
 * <p>One per (object, other body) pair and thread; allocation-free once its buffers have grown.
 */
public final class ProximityContacts {
    /** The default margin δ, m: contacts closer than this are kept, so resting contact does not chatter. */
    public static final double DEFAULT_MARGIN = 1e-3;
    /** Most points a patch keeps: its deepest and the extremes along 8 directions. */
    public static final int MAX_POINTS_PER_PATCH = 9;
    /** Candidates whose normals are within this angle of a patch's first form one patch. */
    public static final double PATCH_ANGLE_DEG = 20;
    private static final double PATCH_COS = Math.cos(Math.toRadians(PATCH_ANGLE_DEG));
    private static final double SUPPORT_TOLERANCE = 1e-6;
    /** The walk's reach above the margin, as a fraction of it: how far the object may move before the walk is repeated. */
    static final double SLACK_FRACTION = 0.5;
    // the manifold's eight directions, 45° apart: cos and sin of dir·π/4, once
    private static final double[] SPAN_COS = new double[8], SPAN_SIN = new double[8];
    static {
        for (int dir = 0; dir < 8; dir++) {
            double ang = dir * Math.PI / 4;
            SPAN_COS[dir] = Math.cos(ang);
            SPAN_SIN[dir] = Math.sin(ang);
        }
    }

    private final KdopTree other, object;
    private final MeshTopology otherTopo, objectTopo;
    private final TreeQuery query = new TreeQuery();
    private final NearPairs near = new NearPairs();
    private final TriangleDistance td = new TriangleDistance();
    private final double[] pose = new double[12], scratch = new double[12];
    private final double[] placed, placedNormals;
    private final int[] vertStamp, triStamp;
    // the face each vertex was last tested over in this query (a vertex is in several triangles of the near pairs)
    private final int[] objectVertFace, objectVertStamp, otherVertFace, otherVertStamp;
    private int stamp;
    // candidates, in the other body's frame
    private int nc;
    private double[] cand = new double[7 * 64];     // px, py, pz, nx, ny, nz, gap
    private int[] order = new int[64], patchOf = new int[64];
    private final double[] patchNormal = new double[3 * 64];
    private final int[] picked = new int[MAX_POINTS_PER_PATCH];
    private final double[] p = new double[3], nrm = new double[3], vel = new double[3], t1 = new double[3], t2 = new double[3];
    // the walk's pose and margin, and the object's vertices' bounding sphere (mesh frame)
    private final double[] nearPose = new double[12];
    private double nearMargin = Double.NaN;
    private final double cx, cy, cz, radius;
    // per triangle edge 3t + e: whether it is convex (a property of the mesh, whatever its pose)
    private final boolean[] otherConvex, objectConvex;
    private long walks;

    /**
     * @param otherTree  the other body's tree (its own frame)
     * @param objectTree the object's tree (mesh frame), of the same k
     */
    public ProximityContacts(KdopTree otherTree, MeshTopology otherTopology, KdopTree objectTree, MeshTopology objectTopology) {
        this.other = otherTree;
        this.object = objectTree;
        this.otherTopo = otherTopology;
        this.objectTopo = objectTopology;
        TriangleMesh om = objectTree.mesh();
        placed = new double[om.vertices().length];
        placedNormals = new double[om.normals().length];
        vertStamp = new int[om.vertexCount()];
        triStamp = new int[om.triangleCount()];
        objectVertFace = new int[om.vertexCount()];
        objectVertStamp = new int[om.vertexCount()];
        otherVertFace = new int[otherTree.mesh().vertexCount()];
        otherVertStamp = new int[otherTree.mesh().vertexCount()];
        double[] v = om.vertices();
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY}, hi = {-lo[0], -lo[0], -lo[0]};
        for (int i = 0; i < v.length; i++) {
            lo[i % 3] = Math.min(lo[i % 3], v[i]);
            hi[i % 3] = Math.max(hi[i % 3], v[i]);
        }
        cx = v.length == 0 ? 0 : 0.5 * (lo[0] + hi[0]);
        cy = v.length == 0 ? 0 : 0.5 * (lo[1] + hi[1]);
        cz = v.length == 0 ? 0 : 0.5 * (lo[2] + hi[2]);
        double r2 = 0;
        for (int i = 0; i < v.length; i += 3) r2 = Math.max(r2, (v[i] - cx) * (v[i] - cx) + (v[i + 1] - cy) * (v[i + 1] - cy) + (v[i + 2] - cz) * (v[i + 2] - cz));
        radius = Math.sqrt(r2);
        otherConvex = convexEdges(otherTree.mesh(), otherTopology);
        objectConvex = convexEdges(om, objectTopology);
    }

    /** {@link #convex} of every triangle edge of {@code mesh} in its own frame (convexity does not change with the pose). */
    private static boolean[] convexEdges(TriangleMesh mesh, MeshTopology topo) {
        int[] t = mesh.triangles();
        double[] v = mesh.vertices(), n = mesh.normals();
        boolean[] c = new boolean[t.length];
        for (int i = 0; i < t.length; i++) c[i] = convex(v, 3 * t[i], topo.across(i / 3, i % 3), n, 3 * (i / 3));
        return c;
    }

    /** @return how many times {@link #find} walked the trees (the others reused the last walk's pairs) */
    public long walks() { return walks; }

    /**
     * A bound on how far any point of the object moved, relative to the other body, between the
     * walk's pose and {@link #pose}: |ΔR·c + Δt| + ‖ΔR‖_F·ρ (m).
     */
    private double movedSinceWalk() {
        double[] a = pose, b = nearPose;
        double f = 0;
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                double d = a[4 * r + c] - b[4 * r + c];
                f += d * d;
            }
        }
        double dx = (a[0] - b[0]) * cx + (a[1] - b[1]) * cy + (a[2] - b[2]) * cz + a[3] - b[3];
        double dy = (a[4] - b[4]) * cx + (a[5] - b[5]) * cy + (a[6] - b[6]) * cz + a[7] - b[7];
        double dz = (a[8] - b[8]) * cx + (a[9] - b[9]) * cy + (a[10] - b[10]) * cz + a[11] - b[11];
        return Math.sqrt(dx * dx + dy * dy + dz * dz) + Math.sqrt(f) * radius;
    }

    /**
     * Finds the contacts and appends them to {@code out} (world frame).
     *
     * @param worldFromOther  the other body's pose (12 values)
     * @param worldFromObject the object mesh's pose (12 values)
     * @param margin          δ, m
     * @param depth           D, m: deeper penetrations are not contacts of this query
     * @param mu              Coulomb's μ of the pair
     * @param otherTwist      the other body's velocity (m/s, of the point at its frame's origin) and
     *                        angular velocity (rad/s), world, 6 values; null: at rest
     * @param bodyId          the other body's id in {@code out}
     * @return the number of contacts appended
     */
    public int find(double[] worldFromOther, double[] worldFromObject, double margin, double depth, double mu, double[] otherTwist,
                    int bodyId, BodyContacts out) {
        RigidTransform.inverseTimes(worldFromOther, worldFromObject, scratch, pose);
        // the last walk's pairs hold every pair within its clearance then: enough while the motion since keeps margin below it
        double moved = margin == nearMargin ? movedSinceWalk() : Double.NaN;
        if (!(margin + moved < near.clearance())) {
            query.near(other, object, pose, 0, margin * (1 + SLACK_FRACTION), near);
            System.arraycopy(pose, 0, nearPose, 0, 12);
            nearMargin = margin;
            moved = 0;
            walks++;
        }
        if (++stamp == Integer.MAX_VALUE) {
            Arrays.fill(vertStamp, 0);
            Arrays.fill(triStamp, 0);
            Arrays.fill(objectVertStamp, 0);
            Arrays.fill(otherVertStamp, 0);
            stamp = 1;
        }
        nc = 0;
        TriangleMesh am = other.mesh(), bm = object.mesh();
        double[] va = am.vertices(), na = am.normals(), aa = am.areas();
        int[] ta = am.triangles(), tb = bm.triangles();
        double[] ba = bm.areas();
        for (int i = 0, n = near.size(); i < n; i++) {
            int a = near.triangleA(i), b = near.triangleB(i);
            if (!(aa[a] > 0) || !(ba[b] > 0)) continue;
            // a pair whose separation then, less the motion since, is above the margin is as far from contact as the walk's reach allows
            if (near.separation(i) - moved > margin) continue;
            placeTriangle(bm, b);
            int a0 = 3 * ta[3 * a], a1 = 3 * ta[3 * a + 1], a2 = 3 * ta[3 * a + 2];
            int b0 = 3 * tb[3 * b], b1 = 3 * tb[3 * b + 1], b2 = 3 * tb[3 * b + 2];
            // the object's vertices over the other's face: pushed along the face's normal
            // (a vertex tested over this face already, from another of its triangles, would give the same candidate again)
            for (int k = 0; k < 3; k++) {
                int q = k == 0 ? b0 : k == 1 ? b1 : b2;
                if (objectVertStamp[q / 3] == stamp && objectVertFace[q / 3] == a) continue;
                objectVertStamp[q / 3] = stamp;
                objectVertFace[q / 3] = a;
                vertexFace(placed, q, va, a0, a1, a2, na, 3 * a, margin, depth, false, objectTopo, true);
            }
            // the other's vertices over the object's face: pushed against the face's normal
            for (int k = 0; k < 3; k++) {
                int q = k == 0 ? a0 : k == 1 ? a1 : a2;
                if (otherVertStamp[q / 3] == stamp && otherVertFace[q / 3] == b) continue;
                otherVertStamp[q / 3] = stamp;
                otherVertFace[q / 3] = b;
                vertexFace(va, q, placed, b0, b1, b2, placedNormals, 3 * b, margin, depth, true, otherTopo, false);
            }
            for (int ea = 0; ea < 3; ea++) {
                if (!otherConvex[3 * a + ea]) continue;
                for (int eb = 0; eb < 3; eb++) {
                    if (objectConvex[3 * b + eb]) edgeEdge(a, ea, b, eb, va, ta, tb, margin, depth);
                }
            }
        }
        int before = out.size();
        reduce(worldFromOther, mu, otherTwist, bodyId, out);
        return out.size() - before;
    }

    /** Places object triangle b's vertices and normal in the other body's frame (once per query). */
    private void placeTriangle(TriangleMesh bm, int b) {
        if (triStamp[b] == stamp) return;
        triStamp[b] = stamp;
        int[] tb = bm.triangles();
        double[] v = bm.vertices(), nb = bm.normals();
        for (int k = 0; k < 3; k++) placeVertex(v, tb[3 * b + k]);
        double x = nb[3 * b], y = nb[3 * b + 1], z = nb[3 * b + 2];
        placedNormals[3 * b] = pose[0] * x + pose[1] * y + pose[2] * z;
        placedNormals[3 * b + 1] = pose[4] * x + pose[5] * y + pose[6] * z;
        placedNormals[3 * b + 2] = pose[8] * x + pose[9] * y + pose[10] * z;
    }

    private void placeVertex(double[] v, int i) {
        if (vertStamp[i] == stamp) return;
        vertStamp[i] = stamp;
        double x = v[3 * i], y = v[3 * i + 1], z = v[3 * i + 2];
        placed[3 * i] = pose[0] * x + pose[1] * y + pose[2] * z + pose[3];
        placed[3 * i + 1] = pose[4] * x + pose[5] * y + pose[6] * z + pose[7];
        placed[3 * i + 2] = pose[8] * x + pose[9] * y + pose[10] * z + pose[11];
    }

    /**
     * Vertex {@code q} (offset, in {@code vq}) over face (f0, f1, f2) of {@code vf} with unit
     * normal {@code nf[no..]}; {@code faceIsObject}: the face is the object's (the push is then
     * against its normal). The vertex's neighbours come from {@code topo}, placed when
     * {@code vertexIsObject}.
     */
    private void vertexFace(double[] vq, int q, double[] vf, int f0, int f1, int f2, double[] nf, int no, double margin, double depth,
                            boolean faceIsObject, MeshTopology topo, boolean vertexIsObject) {
        double nx = nf[no], ny = nf[no + 1], nz = nf[no + 2];
        double px = vq[q], py = vq[q + 1], pz = vq[q + 2];
        double g = nx * (px - vf[f0]) + ny * (py - vf[f0 + 1]) + nz * (pz - vf[f0 + 2]);
        if (!(g <= margin && g >= -depth)) return;
        if (!inside(px, py, pz, vf, f0, f1, f2, nx, ny, nz)) return;
        // the vertex must be its mesh's extreme point toward the face: no neighbour nearer its plane
        int v = q / 3;
        int[] nb = topo.neighbours();
        double[] src = vq;
        for (int k = topo.neighbourStart(v), e = topo.neighbourEnd(v); k < e; k++) {
            int w = nb[k];
            if (vertexIsObject) placeVertex(object.mesh().vertices(), w);
            double dx = src[3 * w] - px, dy = src[3 * w + 1] - py, dz = src[3 * w + 2] - pz;
            double along = nx * dx + ny * dy + nz * dz;
            if (along < -SUPPORT_TOLERANCE * Math.sqrt(dx * dx + dy * dy + dz * dz)) return;
        }
        double s = faceIsObject ? -1 : 1;
        add(px - 0.5 * g * nx, py - 0.5 * g * ny, pz - 0.5 * g * nz, s * nx, s * ny, s * nz, g);
    }

    /** Whether p's projection along n lies in triangle (f0, f1, f2) (edges included, to rounding). */
    private static boolean inside(double px, double py, double pz, double[] v, int f0, int f1, int f2, double nx, double ny, double nz) {
        return edgeSide(px, py, pz, v, f0, f1, nx, ny, nz) && edgeSide(px, py, pz, v, f1, f2, nx, ny, nz)
            && edgeSide(px, py, pz, v, f2, f0, nx, ny, nz);
    }

    private static boolean edgeSide(double px, double py, double pz, double[] v, int s, int e, double nx, double ny, double nz) {
        double ex = v[e] - v[s], ey = v[e + 1] - v[s + 1], ez = v[e + 2] - v[s + 2];
        double qx = px - v[s], qy = py - v[s + 1], qz = pz - v[s + 2];
        double cx = ey * qz - ez * qy, cy = ez * qx - ex * qz, cz = ex * qy - ey * qx;
        double side = cx * nx + cy * ny + cz * nz;
        return side >= -1e-9 * (ex * ex + ey * ey + ez * ez);
    }

    /** Edge ea of the other's triangle a against edge eb of the object's triangle b. */
    private void edgeEdge(int a, int ea, int b, int eb, double[] va, int[] ta, int[] tb, double margin, double depth) {
        int p1 = 3 * ta[3 * a + ea], q1 = 3 * ta[3 * a + (ea + 1) % 3], r1 = 3 * ta[3 * a + (ea + 2) % 3];
        int p2 = 3 * tb[3 * b + eb], q2 = 3 * tb[3 * b + (eb + 1) % 3], r2 = 3 * tb[3 * b + (eb + 2) % 3];
        // (the caller passes convex edges only: a flat edge (a face's inside) is its face's, and
        // has no outside of its own; a concave edge has none either)
        double d2 = td.segments(va, p1, q1, placed, p2, q2);
        double lim = Math.max(margin, depth);
        if (d2 > lim * lim) return;
        if (!(td.s > 1e-9 && td.s < 1 - 1e-9 && td.t > 1e-9 && td.t < 1 - 1e-9)) return;
        double ax = td.pointA[0], ay = td.pointA[1], az = td.pointA[2];
        double bx = td.pointB[0], by = td.pointB[1], bz = td.pointB[2];
        double mx = bx - ax, my = by - ay, mz = bz - az;
        double d = Math.sqrt(d2);
        double e1x = va[q1] - va[p1], e1y = va[q1 + 1] - va[p1 + 1], e1z = va[q1 + 2] - va[p1 + 2];
        double e2x = placed[q2] - placed[p2], e2y = placed[q2 + 1] - placed[p2 + 1], e2z = placed[q2 + 2] - placed[p2 + 2];
        double len1 = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z), len2 = Math.sqrt(e2x * e2x + e2y * e2y + e2z * e2z);
        if (d > 1e-9 * (len1 + len2)) {
            mx /= d; my /= d; mz /= d;
        } else {
            mx = e1y * e2z - e1z * e2y; my = e1z * e2x - e1x * e2z; mz = e1x * e2y - e1y * e2x;
            double l = Math.sqrt(mx * mx + my * my + mz * mz);
            if (!(l > 1e-9 * len1 * len2)) return;                       // parallel edges: the vertex cases cover them
            mx /= l; my /= l; mz /= l;
            d = 0;
        }
        // the vertices across the edges, for the outside tests (placed only for the pairs that get here)
        int o1 = otherTopo.across(a, ea), o2 = objectTopo.across(b, eb);
        if (o2 >= 0) placeVertex(object.mesh().vertices(), o2);
        double sign;
        if (outside(mx, my, mz, va, p1, r1, o1) && outside(-mx, -my, -mz, placed, p2, r2, o2)) {
            sign = 1;
        } else if (outside(-mx, -my, -mz, va, p1, r1, o1) && outside(mx, my, mz, placed, p2, r2, o2)) {
            sign = -1;
        } else {
            return;
        }
        double g = sign * d;
        if (!(g <= margin && g >= -depth)) return;
        add(0.5 * (ax + bx), 0.5 * (ay + by), 0.5 * (az + bz), sign * mx, sign * my, sign * mz, g);
    }

    /**
     * Whether the edge at vertex offset {@code p} of a triangle with unit normal {@code n[no..]} is
     * convex: the vertex across it ({@code across}, a vertex index) lies below the triangle's plane
     * by more than rounding. A border edge (−1) counts as convex.
     */
    private static boolean convex(double[] v, int p, int across, double[] n, int no) {
        if (across < 0) return true;
        int o = 3 * across;
        double dx = v[o] - v[p], dy = v[o + 1] - v[p + 1], dz = v[o + 2] - v[p + 2];
        return n[no] * dx + n[no + 1] * dy + n[no + 2] * dz < -SUPPORT_TOLERANCE * Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Whether direction m leaves the edge at vertex offset {@code p} through its outside: the
     * triangle's third vertex (offset {@code r}) and the vertex across the edge ({@code across},
     * a vertex index, −1 at a border) lie behind it.
     */
    private static boolean outside(double mx, double my, double mz, double[] v, int p, int r, int across) {
        double dx = v[r] - v[p], dy = v[r + 1] - v[p + 1], dz = v[r + 2] - v[p + 2];
        if (mx * dx + my * dy + mz * dz > SUPPORT_TOLERANCE * Math.sqrt(dx * dx + dy * dy + dz * dz)) return false;
        if (across < 0) return true;
        int o = 3 * across;
        dx = v[o] - v[p]; dy = v[o + 1] - v[p + 1]; dz = v[o + 2] - v[p + 2];
        return !(mx * dx + my * dy + mz * dz > SUPPORT_TOLERANCE * Math.sqrt(dx * dx + dy * dy + dz * dz));
    }

    private void add(double px, double py, double pz, double nx, double ny, double nz, double g) {
        if (7 * (nc + 1) > cand.length) {
            cand = Arrays.copyOf(cand, 2 * cand.length);
            order = Arrays.copyOf(order, 2 * order.length);
            patchOf = Arrays.copyOf(patchOf, 2 * patchOf.length);
        }
        int o = 7 * nc++;
        cand[o] = px; cand[o + 1] = py; cand[o + 2] = pz;
        cand[o + 3] = nx; cand[o + 4] = ny; cand[o + 5] = nz;
        cand[o + 6] = g;
    }

    /** Groups the candidates into patches, keeps each patch's spanning points, and appends them in the world frame. */
    private void reduce(double[] w, double mu, double[] twist, int bodyId, BodyContacts out) {
        if (nc == 0) return;
        // deepest first (insertion sort on the gap: candidate lists are short)
        for (int i = 0; i < nc; i++) order[i] = i;
        for (int i = 1; i < nc; i++) {
            int c = order[i];
            double g = cand[7 * c + 6];
            int j = i - 1;
            while (j >= 0 && cand[7 * order[j] + 6] > g) {
                order[j + 1] = order[j];
                j--;
            }
            order[j + 1] = c;
        }
        int patches = 0;
        for (int i = 0; i < nc; i++) {
            int c = order[i];
            double nx = cand[7 * c + 3], ny = cand[7 * c + 4], nz = cand[7 * c + 5];
            int found = -1;
            for (int k = 0; k < patches && found < 0; k++) {
                if (nx * patchNormal[3 * k] + ny * patchNormal[3 * k + 1] + nz * patchNormal[3 * k + 2] >= PATCH_COS) found = k;
            }
            if (found < 0) {
                if (3 * patches + 3 > patchNormal.length) {
                    found = patches - 1;                                  // more than 64 directions: share the last
                } else {
                    found = patches++;
                    patchNormal[3 * found] = nx; patchNormal[3 * found + 1] = ny; patchNormal[3 * found + 2] = nz;
                }
            }
            patchOf[c] = found;
        }
        for (int k = 0; k < patches; k++) {
            BodyStepper.tangents(patchNormal[3 * k], patchNormal[3 * k + 1], patchNormal[3 * k + 2], t1, t2);
            int np = 0;
            // the deepest: the patch's first in depth order
            for (int i = 0; i < nc; i++) {
                if (patchOf[order[i]] == k) {
                    picked[np++] = order[i];
                    break;
                }
            }
            for (int dir = 0; dir < 8; dir++) {
                double c = SPAN_COS[dir], s = SPAN_SIN[dir];
                double dx = c * t1[0] + s * t2[0], dy = c * t1[1] + s * t2[1], dz = c * t1[2] + s * t2[2];
                int best = -1;
                double bestVal = Double.NEGATIVE_INFINITY;
                for (int i = 0; i < nc; i++) {
                    int cc = order[i];
                    if (patchOf[cc] != k) continue;
                    double val = dx * cand[7 * cc] + dy * cand[7 * cc + 1] + dz * cand[7 * cc + 2];
                    if (val > bestVal + 1e-12) {
                        bestVal = val;
                        best = cc;
                    }
                }
                boolean dup = false;
                for (int j = 0; j < np; j++) dup |= samePoint(picked[j], best);
                if (!dup) picked[np++] = best;
            }
            for (int j = 0; j < np; j++) emit(picked[j], w, mu, twist, bodyId, out);
        }
    }

    private boolean samePoint(int i, int j) {
        if (i == j) return true;
        double dx = cand[7 * i] - cand[7 * j], dy = cand[7 * i + 1] - cand[7 * j + 1], dz = cand[7 * i + 2] - cand[7 * j + 2];
        return dx * dx + dy * dy + dz * dz <= 1e-20
            && cand[7 * i + 3] * cand[7 * j + 3] + cand[7 * i + 4] * cand[7 * j + 4] + cand[7 * i + 5] * cand[7 * j + 5] > 1 - 1e-12;
    }

    private void emit(int c, double[] w, double mu, double[] twist, int bodyId, BodyContacts out) {
        int o = 7 * c;
        double x = cand[o], y = cand[o + 1], z = cand[o + 2];
        p[0] = w[0] * x + w[1] * y + w[2] * z + w[3];
        p[1] = w[4] * x + w[5] * y + w[6] * z + w[7];
        p[2] = w[8] * x + w[9] * y + w[10] * z + w[11];
        x = cand[o + 3]; y = cand[o + 4]; z = cand[o + 5];
        nrm[0] = w[0] * x + w[1] * y + w[2] * z;
        nrm[1] = w[4] * x + w[5] * y + w[6] * z;
        nrm[2] = w[8] * x + w[9] * y + w[10] * z;
        double[] ov = null;
        if (twist != null) {
            double rx = p[0] - w[3], ry = p[1] - w[7], rz = p[2] - w[11];
            vel[0] = twist[0] + twist[4] * rz - twist[5] * ry;
            vel[1] = twist[1] + twist[5] * rx - twist[3] * rz;
            vel[2] = twist[2] + twist[3] * ry - twist[4] * rx;
            ov = vel;
        }
        out.add(p, nrm, cand[o + 6], mu, ov, bodyId);
    }

    /** @return the candidates the last query found before the reduction */
    public int candidateCount() { return nc; }
}
