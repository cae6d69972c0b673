package org.handsim.mesh;

import java.nio.Buffer;
import java.nio.DoubleBuffer;
import java.nio.FloatBuffer;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.math.RigidTransform;
import org.jogamp.java3d.Geometry;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.GeometryStripArray;
import org.jogamp.java3d.Group;
import org.jogamp.java3d.IndexedGeometryArray;
import org.jogamp.java3d.IndexedGeometryStripArray;
import org.jogamp.java3d.IndexedQuadArray;
import org.jogamp.java3d.IndexedTriangleArray;
import org.jogamp.java3d.IndexedTriangleFanArray;
import org.jogamp.java3d.IndexedTriangleStripArray;
import org.jogamp.java3d.J3DBuffer;
import org.jogamp.java3d.Link;
import org.jogamp.java3d.Node;
import org.jogamp.java3d.QuadArray;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.Switch;
import org.jogamp.java3d.Transform3D;
import org.jogamp.java3d.TransformGroup;
import org.jogamp.java3d.TriangleArray;
import org.jogamp.java3d.TriangleFanArray;
import org.jogamp.java3d.TriangleStripArray;
import org.jogamp.vecmath.Point3d;
import org.jogamp.vecmath.Point3f;

/**
 * The tessellation walk (paper Section III-B): takes a Java3D scene graph apart into triangle
 * meshes in one frame, with every TransformGroup on the way applied.
 *
 * <h2>The walk</h2>
 * <pre>
 * stack ← [(root, M = scale·I, part = default)]
 * while stack not empty:
 *     (node, M, part) ← pop
 *     TransformGroup:  M ← M · T(node); push children
 *     Switch:          push the selected child(ren) only (whichChild / child mask)
 *     Link:            push its SharedGroup (a shared subgraph is walked once per Link)
 *     other Group:     push children (BranchGroup, SharedGroup, OrderedGroup, Java3D
 *                      Primitive such as utils.geometry.Box/Sphere/Cylinder/Cone, ...)
 *     named Group:     part ← the part of that name (grouping {@link Grouping#NAMED_PARTS})
 *     Shape3D:         for each of its geometries: triangles (below), corners mapped by M
 * </pre>
 * The stack is explicit, so a scene nested 100 000 levels deep cannot overflow the Java stack.
 * Children are pushed in reverse so triangles come out in scene order.
 *
 * <h2>Triangles from every GeometryArray kind</h2>
 * TriangleArray (3 vertices per triangle), QuadArray (quad 0123 ⇒ 012, 023), TriangleStripArray
 * (strip v0 v1 v2 v3 ... ⇒ 012, 213, 234, ... keeping the winding), TriangleFanArray (⇒ 012, 023,
 * ...), their Indexed forms (indices in [initialIndexIndex, +validIndexCount)), with coordinates
 * by copy, by reference (float[], double[], Point3f[], Point3d[]), interleaved, or in NIO
 * buffers. Line and point arrays, Text3D and other geometry have no area: they are skipped and
 * counted ({@link Result#skippedGeometries}).
 *
 * <h2>Output</h2>
 * Per part a {@link TriangleMesh} on primitive arrays, in metres when {@link #scale} converts the
 * file's unit. Vertices are shared within one geometry instance (only vertices used by a kept
 * triangle are emitted); not welded across geometries (see {@link MeshWelder}). A triangle whose
 * area after transformation is zero is dropped and counted ({@link Result#degenerate}). A
 * transform with negative determinant (a mirror) reverses the winding, so normals still point
 * out. Hot loops run on primitive arrays with reused scratch; nothing is allocated per triangle.
 *
 * <p>A guard ({@link #maxTriangles}) stops scenes whose sharing multiplies geometry beyond
 * reason (a DEF/USE "billion laughs"): a counting pass over the graph, with each SharedGroup
 * counted once, refuses them before any triangle is produced. Not thread-safe; the walk only reads the scene graph
 * (which needs the read capabilities the VRML loader sets if the scene is live or compiled).
 */
public final class TessellationWalk {
    /** How triangles are grouped into meshes. */
    public enum Grouping {
        /** One mesh for the whole scene (one object per file). */
        WHOLE,
        /**
         * One mesh per named part: each Shape3D goes to its nearest ancestor Group that has a
         * name (VRML DEF names become Java3D names); shapes below no named group go to the
         * part named after the walk ({@link #name}).
         */
        NAMED_PARTS,
        /** One mesh per Shape3D instance. */
        SHAPES
    }

    private double scale = 1;
    private Grouping grouping = Grouping.WHOLE;
    private long maxTriangles = MeshLimits.MAX_TRIANGLES;
    private String name = "scene";

    /** Multiplies every coordinate (e.g. 0.001 for a file in millimetres); must be positive and finite. */
    public TessellationWalk scale(double s) {
        if (!(s > 0) || !Double.isFinite(s)) throw new IllegalArgumentException("scale must be a positive finite number, got " + s);
        this.scale = s;
        return this;
    }

    public TessellationWalk grouping(Grouping g) {
        this.grouping = g;
        return this;
    }

    /** Most triangles the walk may produce before it stops with an error (default 20 million). */
    public TessellationWalk maxTriangles(long n) {
        if (n < 1) throw new IllegalArgumentException("maxTriangles must be positive, got " + n);
        this.maxTriangles = n;
        return this;
    }

    /** Name of the mesh (WHOLE) or of the part for shapes under no named group (e.g. the file name). */
    public TessellationWalk name(String n) {
        this.name = n;
        return this;
    }

    /** The whole scene as one mesh, transforms applied, degenerate triangles dropped. */
    public static TriangleMesh mesh(Node root) {
        return new TessellationWalk().run(root).merged();
    }

    /** What a walk produced. */
    public static final class Result {
        private final List<TriangleMesh> meshes;
        private final String name;
        /** Shape3D instances (counting each use of a shared one) that had triangle geometry. */
        public final int shapes;
        /** Zero-area triangles dropped. */
        public final long degenerate;
        /** Geometries with no area (lines, points, text, unknown kinds) skipped. */
        public final int skippedGeometries;

        Result(List<TriangleMesh> meshes, String name, int shapes, long degenerate, int skipped) {
            this.meshes = meshes;
            this.name = name;
            this.shapes = shapes;
            this.degenerate = degenerate;
            this.skippedGeometries = skipped;
        }

        /** The meshes, one per part, in the order parts were first met (none empty). */
        public List<TriangleMesh> meshes() { return meshes; }

        /** All parts in one mesh (not welded); an empty mesh if there were no triangles. */
        public TriangleMesh merged() {
            if (meshes.size() == 1) return meshes.get(0);
            return TriangleMesh.concat(name, meshes);
        }

        /** Total number of (kept) triangles. */
        public long triangleCount() {
            long n = 0;
            for (TriangleMesh m : meshes) n += m.triangleCount();
            return n;
        }
    }

    // ------------------------------------------------------------------ walk state

    private static final class Part {
        final String name;
        double[] v = new double[3 * 64];
        int nv;
        int[] t = new int[3 * 64];
        int nt;

        Part(String name) {
            this.name = name;
        }

        int addVertex(double x, double y, double z) {
            if (3 * nv + 3 > v.length) v = Arrays.copyOf(v, Math.max(v.length * 2, 3 * nv + 3));
            v[3 * nv] = x; v[3 * nv + 1] = y; v[3 * nv + 2] = z;
            return nv++;
        }

        void addTriangle(int a, int b, int c) {
            if (3 * nt + 3 > t.length) t = Arrays.copyOf(t, Math.max(t.length * 2, 3 * nt + 3));
            t[3 * nt] = a; t[3 * nt + 1] = b; t[3 * nt + 2] = c;
            nt++;
        }
    }

    private static final class Frame {
        final Node node;
        final double[] m;
        final Part part;

        Frame(Node node, double[] m, Part part) {
            this.node = node;
            this.m = m;
            this.part = part;
        }
    }

    private final Map<Node, Part> partsByNode = new IdentityHashMap<>();
    private final Map<String, Integer> nameUse = new HashMap<>();
    private final LinkedHashMap<Part, Boolean> parts = new LinkedHashMap<>();
    private int shapes, skipped, shapeSerial;
    private long degenerate, emitted;
    // per-geometry-instance vertex map, reset by bumping the generation
    private int[] map = new int[0], gen = new int[0];
    private int generation;
    private final Transform3D t3d = new Transform3D();
    private final double[] m16 = new double[16];

    /** Walks the scene under {@code root}. */
    public Result run(Node root) {
        partsByNode.clear();
        nameUse.clear();
        parts.clear();
        shapes = skipped = shapeSerial = 0;
        degenerate = emitted = 0;
        long expected = expandedTriangles(root);
        if (expected > maxTriangles) {
            throw new IllegalStateException("the scene expands to " + (expected >= HUGE ? "more than " + HUGE : String.valueOf(expected))
                + " triangles, more than the limit of " + maxTriangles
                + " (shared DEF/USE or Inline geometry multiplied?); raise TessellationWalk.maxTriangles to allow it");
        }
        Part base = new Part(name);
        double[] m0 = {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0};
        ArrayDeque<Frame> stack = new ArrayDeque<>();
        stack.push(new Frame(root, m0, base));
        while (!stack.isEmpty()) {
            Frame f = stack.pop();
            Node n = f.node;
            double[] m = f.m;
            Part part = f.part;
            if (n instanceof Shape3D) {
                Shape3D s = (Shape3D) n;
                if (grouping == Grouping.SHAPES) part = shapePart(s);
                boolean any = false;
                for (int i = 0, k = s.numGeometries(); i < k; i++) {
                    any |= geometry(s.getGeometry(i), m, part);
                }
                if (any) shapes++;
                continue;
            }
            if (n instanceof Group) {
                Group g = (Group) n;
                if (grouping == Grouping.NAMED_PARTS && g.getName() != null) part = namedPart(g);
                if (g instanceof TransformGroup) {
                    ((TransformGroup) g).getTransform(t3d);
                    t3d.get(m16);
                    m = compose(m, m16);
                }
            }
            Node[] kids = children(n);
            for (int i = kids.length - 1; i >= 0; i--) stack.push(new Frame(kids[i], m, part));
        }
        List<TriangleMesh> out = new ArrayList<>();
        List<Part> order = new ArrayList<>();
        if (base.nt > 0) order.add(base);
        for (Part p : parts.keySet()) if (p.nt > 0) order.add(p);
        for (Part p : order) {
            out.add(new TriangleMesh(p.name, Arrays.copyOf(p.v, 3 * p.nv), Arrays.copyOf(p.t, 3 * p.nt)));
        }
        if (out.isEmpty()) out.add(new TriangleMesh(name, new double[0], new int[0]));
        return new Result(out, name, shapes, degenerate, skipped);
    }

    private static final long HUGE = Long.MAX_VALUE / 4;

    /** One node of the counting pass. */
    private static final class Count {
        final Node node;
        Node[] kids;
        int next;
        long sum;

        Count(Node node) {
            this.node = node;
        }
    }

    /**
     * Triangles the walk would produce (before dropping degenerate ones), computed without
     * producing them: one iterative post-order pass in which each SharedGroup is counted once
     * and its count reused for every Link to it. So a scene whose sharing multiplies geometry
     * exponentially (a DEF/USE "billion laughs") is refused at once, in time proportional to
     * the scene graph, not to the triangles it would expand to. Saturates at {@link #HUGE}.
     *
     * @throws IllegalStateException if a SharedGroup links to itself (a cycle)
     */
    static long expandedTriangles(Node root) {
        IdentityHashMap<Node, Long> memo = new IdentityHashMap<>();
        IdentityHashMap<Node, Boolean> open = new IdentityHashMap<>();
        ArrayDeque<Count> stack = new ArrayDeque<>();
        stack.push(new Count(root));
        long total = 0;
        while (!stack.isEmpty()) {
            Count f = stack.peek();
            if (f.kids == null) {
                Node n = f.node;
                Long known = memo.get(n);
                if (known != null) {
                    stack.pop();
                    total = addTo(stack, total, known);
                    continue;
                }
                if (open.put(n, Boolean.TRUE) != null) {
                    throw new IllegalStateException("the scene graph has a cycle through " + n + " (a SharedGroup that links to itself)");
                }
                f.kids = kids(f);
            }
            if (f.next < f.kids.length) {
                stack.push(new Count(f.kids[f.next++]));
                continue;
            }
            stack.pop();
            open.remove(f.node);
            if (f.node instanceof org.jogamp.java3d.SharedGroup) memo.put(f.node, f.sum);
            total = addTo(stack, total, f.sum);
        }
        return total;
    }

    private static long addTo(ArrayDeque<Count> stack, long total, long v) {
        Count parent = stack.peek();
        if (parent == null) return Math.min(HUGE, total + v);
        parent.sum = Math.min(HUGE, parent.sum + v);
        return total;
    }

    /** The children the walk would visit (a Shape3D has none: its triangles go to its sum). */
    private static Node[] kids(Count f) {
        Node n = f.node;
        if (n instanceof Shape3D) {
            Shape3D s = (Shape3D) n;
            for (int i = 0, k = s.numGeometries(); i < k; i++) f.sum = Math.min(HUGE, f.sum + triangles(s.getGeometry(i)));
            return new Node[0];
        }
        return children(n);
    }

    /**
     * The non-null children the walk visits below a node, in scene order: a Link's SharedGroup,
     * a Switch's selected child(ren), any other Group's children; none for other nodes (lights,
     * backgrounds, behaviours, ...). Shape3D is handled by the caller.
     */
    private static Node[] children(Node n) {
        if (n instanceof Link) {
            Node sg = ((Link) n).getSharedGroup();
            return sg == null ? new Node[0] : new Node[] {sg};
        }
        if (!(n instanceof Group)) return new Node[0];
        Group g = (Group) n;
        int nc = g.numChildren();
        if (g instanceof Switch) {
            Switch sw = (Switch) g;
            int w = sw.getWhichChild();
            if (w == Switch.CHILD_NONE) return new Node[0];
            if (w == Switch.CHILD_MASK) {
                java.util.BitSet mask = sw.getChildMask();
                List<Node> l = new ArrayList<>();
                for (int i = 0; i < nc; i++) if (mask.get(i) && sw.getChild(i) != null) l.add(sw.getChild(i));
                return l.toArray(new Node[0]);
            }
            if (w != Switch.CHILD_ALL) return w >= 0 && w < nc && sw.getChild(w) != null ? new Node[] {sw.getChild(w)} : new Node[0];
        }
        List<Node> l = new ArrayList<>(nc);
        for (int i = 0; i < nc; i++) if (g.getChild(i) != null) l.add(g.getChild(i));
        return l.toArray(new Node[0]);
    }

    /** Triangles of one geometry as the walk would cut it (0 for non-surface geometry). */
    private static long triangles(Geometry geom) {
        if (!(geom instanceof GeometryArray)) return 0;
        GeometryArray g = (GeometryArray) geom;
        if (g instanceof IndexedGeometryArray) {
            int c = ((IndexedGeometryArray) g).getValidIndexCount();
            if (g instanceof IndexedTriangleArray) return c / 3;
            if (g instanceof IndexedQuadArray) return 2L * (c / 4);
            if (g instanceof IndexedGeometryStripArray && (g instanceof IndexedTriangleStripArray || g instanceof IndexedTriangleFanArray)) {
                IndexedGeometryStripArray sa = (IndexedGeometryStripArray) g;
                int[] counts = new int[sa.getNumStrips()];
                sa.getStripIndexCounts(counts);
                long t = 0;
                for (int k : counts) t += Math.max(0, k - 2);
                return t;
            }
            return 0;
        }
        int c = g.getValidVertexCount();
        if (g instanceof TriangleArray) return c / 3;
        if (g instanceof QuadArray) return 2L * (c / 4);
        if (g instanceof TriangleStripArray || g instanceof TriangleFanArray) {
            GeometryStripArray sa = (GeometryStripArray) g;
            int[] counts = new int[sa.getNumStrips()];
            sa.getStripVertexCounts(counts);
            long t = 0;
            for (int k : counts) t += Math.max(0, k - 2);
            return t;
        }
        return 0;
    }

    private Part namedPart(Group g) {
        Part p = partsByNode.get(g);
        if (p == null) {
            String n = g.getName();
            int use = nameUse.merge(n, 1, Integer::sum);
            p = new Part(use == 1 ? n : n + "#" + use);
            partsByNode.put(g, p);
            parts.put(p, Boolean.TRUE);
        }
        return p;
    }

    private Part shapePart(Shape3D s) {
        String n = s.getName() != null ? s.getName() : name + ".shape" + (++shapeSerial);
        int use = nameUse.merge(n, 1, Integer::sum);
        Part p = new Part(use == 1 ? n : n + "#" + use);
        parts.put(p, Boolean.TRUE);
        return p;
    }

    /** Row-major 3×4 affine a · (4×4 b, only its top three rows used), a new array. */
    private static double[] compose(double[] a, double[] b) {
        double[] r = new double[12];
        RigidTransform.multiply(a, 0, b, 0, r, 0);
        return r;
    }

    // ------------------------------------------------------------------ geometry

    /** Vertex source: either floats (with stride and offset) or doubles (stride 3). */
    private float[] fsrc;
    private double[] dsrc;
    private int stride, offset;

    /** @return true if the geometry is a surface (triangles came from it, possibly all degenerate) */
    private boolean geometry(Geometry geom, double[] m, Part part) {
        if (!(geom instanceof GeometryArray)) {
            if (geom != null) skipped++;
            return false;
        }
        GeometryArray g = (GeometryArray) geom;
        boolean surface = g instanceof TriangleArray || g instanceof QuadArray || g instanceof TriangleStripArray
            || g instanceof TriangleFanArray || g instanceof IndexedTriangleArray || g instanceof IndexedQuadArray
            || g instanceof IndexedTriangleStripArray || g instanceof IndexedTriangleFanArray;
        if (!surface || (g.getVertexFormat() & GeometryArray.COORDINATES) == 0) {
            skipped++;
            return false;
        }
        int nverts = vertexSource(g);
        if (nverts <= 0) return true;
        if (map.length < nverts) {
            map = new int[Math.max(nverts, 2 * map.length)];
            gen = new int[map.length];
            generation = 0;
        }
        if (++generation == Integer.MAX_VALUE) {
            Arrays.fill(gen, 0);
            generation = 1;
        }
        boolean flip = det(m) < 0;
        if (g instanceof IndexedGeometryArray) {
            IndexedGeometryArray ig = (IndexedGeometryArray) g;
            int[] idx = indices(ig);
            int first = ig.getInitialIndexIndex(), count = ig.getValidIndexCount();
            if (g instanceof IndexedTriangleArray) {
                for (int k = first; k + 2 < first + count; k += 3) tri(idx[k], idx[k + 1], idx[k + 2], m, part, flip, nverts);
            } else if (g instanceof IndexedQuadArray) {
                for (int k = first; k + 3 < first + count; k += 4) {
                    tri(idx[k], idx[k + 1], idx[k + 2], m, part, flip, nverts);
                    tri(idx[k], idx[k + 2], idx[k + 3], m, part, flip, nverts);
                }
            } else {
                IndexedGeometryStripArray sa = (IndexedGeometryStripArray) g;
                int[] counts = new int[sa.getNumStrips()];
                sa.getStripIndexCounts(counts);
                strips(idx, first, counts, g instanceof IndexedTriangleFanArray, m, part, flip, nverts);
            }
        } else {
            int first = (g.getVertexFormat() & GeometryArray.BY_REFERENCE) != 0 ? g.getInitialCoordIndex() : g.getInitialVertexIndex();
            int count = g.getValidVertexCount();
            if (g instanceof TriangleArray) {
                for (int k = first; k + 2 < first + count; k += 3) tri(k, k + 1, k + 2, m, part, flip, nverts);
            } else if (g instanceof QuadArray) {
                for (int k = first; k + 3 < first + count; k += 4) {
                    tri(k, k + 1, k + 2, m, part, flip, nverts);
                    tri(k, k + 2, k + 3, m, part, flip, nverts);
                }
            } else {
                GeometryStripArray sa = (GeometryStripArray) g;
                int[] counts = new int[sa.getNumStrips()];
                sa.getStripVertexCounts(counts);
                strips(null, first, counts, g instanceof TriangleFanArray, m, part, flip, nverts);
            }
        }
        return true;
    }

    /** Strips (or fans) over indices idx (or over consecutive vertices when idx is null). */
    private void strips(int[] idx, int first, int[] counts, boolean fan, double[] m, Part part, boolean flip, int nverts) {
        int base = first;
        for (int c : counts) {
            for (int i = 0; i + 2 < c; i++) {
                int a, b, d;
                if (fan) {
                    a = base; b = base + i + 1; d = base + i + 2;
                } else if ((i & 1) == 0) {
                    a = base + i; b = base + i + 1; d = base + i + 2;
                } else {
                    a = base + i + 1; b = base + i; d = base + i + 2;
                }
                if (idx != null) tri(idx[a], idx[b], idx[d], m, part, flip, nverts);
                else tri(a, b, d, m, part, flip, nverts);
            }
            base += c;
        }
    }

    private static double det(double[] m) {
        return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
    }

    private static int[] indices(IndexedGeometryArray ig) {
        if ((ig.getVertexFormat() & GeometryArray.BY_REFERENCE_INDICES) != 0) {
            int[] r = ig.getCoordIndicesRef();
            if (r != null) return r;
        }
        int[] idx = new int[ig.getIndexCount()];
        ig.getCoordinateIndices(0, idx);
        return idx;
    }

    /** Points the vertex source at the geometry's coordinates; returns the number of vertices. */
    @SuppressWarnings("deprecation") // Point3f[]/Point3d[] references: still used by some geometry builders
    private int vertexSource(GeometryArray g) {
        int fmt = g.getVertexFormat();
        fsrc = null;
        dsrc = null;
        stride = 3;
        offset = 0;
        if ((fmt & GeometryArray.BY_REFERENCE) == 0) {
            int n = g.getVertexCount();
            dsrc = new double[3 * n];
            g.getCoordinates(0, dsrc);
            return n;
        }
        if ((fmt & GeometryArray.INTERLEAVED) != 0) {
            int s = 3;
            if ((fmt & GeometryArray.NORMALS) != 0) s += 3;
            if ((fmt & GeometryArray.COLOR_4) == GeometryArray.COLOR_4) s += 4;
            else if ((fmt & GeometryArray.COLOR_3) != 0) s += 3;
            int tdim = (fmt & GeometryArray.TEXTURE_COORDINATE_4) == GeometryArray.TEXTURE_COORDINATE_4 ? 4
                : (fmt & GeometryArray.TEXTURE_COORDINATE_3) != 0 ? 3 : (fmt & GeometryArray.TEXTURE_COORDINATE_2) != 0 ? 2 : 0;
            s += tdim * g.getTexCoordSetCount();
            stride = s;
            offset = s - 3;
            if ((fmt & GeometryArray.USE_NIO_BUFFER) != 0) {
                fsrc = floats(g.getInterleavedVertexBuffer());
            } else {
                fsrc = g.getInterleavedVertices();
            }
            return fsrc == null ? 0 : fsrc.length / stride;
        }
        if ((fmt & GeometryArray.USE_NIO_BUFFER) != 0) {
            J3DBuffer b = g.getCoordRefBuffer();
            Buffer nb = b == null ? null : b.getBuffer();
            if (nb instanceof DoubleBuffer) {
                DoubleBuffer db = ((DoubleBuffer) nb).duplicate();
                db.rewind();
                dsrc = new double[db.remaining()];
                db.get(dsrc);
                return dsrc.length / 3;
            }
            fsrc = floats(b);
            return fsrc == null ? 0 : fsrc.length / 3;
        }
        if (g.getCoordRefFloat() != null) {
            fsrc = g.getCoordRefFloat();
            return fsrc.length / 3;
        }
        if (g.getCoordRefDouble() != null) {
            dsrc = g.getCoordRefDouble();
            return dsrc.length / 3;
        }
        Point3f[] p3f = g.getCoordRef3f();
        if (p3f != null) {
            dsrc = new double[3 * p3f.length];
            for (int i = 0; i < p3f.length; i++) {
                dsrc[3 * i] = p3f[i].x; dsrc[3 * i + 1] = p3f[i].y; dsrc[3 * i + 2] = p3f[i].z;
            }
            return p3f.length;
        }
        Point3d[] p3d = g.getCoordRef3d();
        if (p3d != null) {
            dsrc = new double[3 * p3d.length];
            for (int i = 0; i < p3d.length; i++) {
                dsrc[3 * i] = p3d[i].x; dsrc[3 * i + 1] = p3d[i].y; dsrc[3 * i + 2] = p3d[i].z;
            }
            return p3d.length;
        }
        return 0;
    }

    private static float[] floats(J3DBuffer b) {
        Buffer nb = b == null ? null : b.getBuffer();
        if (!(nb instanceof FloatBuffer)) return null;
        FloatBuffer fb = ((FloatBuffer) nb).duplicate();
        fb.rewind();
        float[] out = new float[fb.remaining()];
        fb.get(out);
        return out;
    }

    // scratch for one triangle: transformed corners c, untransformed corners l
    private final double[] c = new double[9];
    private final double[] l = new double[9];

    /**
     * One triangle with geometry vertex indices a, b, d. It is degenerate if its area is zero in
     * the geometry's own coordinates (exactly collinear or repeated points, as written in the file)
     * or after the transforms (e.g. a zero scale).
     */
    private void tri(int a, int b, int d, double[] m, Part part, boolean flip, int nverts) {
        if (++emitted > maxTriangles) {
            throw new IllegalStateException("the scene expands to more than " + maxTriangles
                + " triangles (shared DEF/USE or Inline geometry multiplied?); raise TessellationWalk.maxTriangles to allow it");
        }
        if (a < 0 || b < 0 || d < 0 || a >= nverts || b >= nverts || d >= nverts) {
            throw new IllegalArgumentException("geometry index out of range: triangle (" + a + ", " + b + ", " + d
                + ") with " + nverts + " vertices");
        }
        corner(a, m, part, 0);
        corner(b, m, part, 3);
        corner(d, m, part, 6);
        if (zeroArea(l) || zeroArea(c)) {
            degenerate++;
            return;
        }
        int ia = vertex(a, part, 0), ib = vertex(b, part, 3), id = vertex(d, part, 6);
        if (flip) part.addTriangle(ia, id, ib); else part.addTriangle(ia, ib, id);
    }

    private static boolean zeroArea(double[] p) {
        double ux = p[3] - p[0], uy = p[4] - p[1], uz = p[5] - p[2];
        double wx = p[6] - p[0], wy = p[7] - p[1], wz = p[8] - p[2];
        double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
        return !(nx * nx + ny * ny + nz * nz > 0);
    }

    /** Position of geometry vertex v: as stored into l[o..o+2], transformed into c[o..o+2]. */
    private void corner(int v, double[] m, Part part, int o) {
        double x, y, z;
        if (fsrc != null) {
            int i = v * stride + offset;
            x = fsrc[i]; y = fsrc[i + 1]; z = fsrc[i + 2];
        } else {
            int i = 3 * v;
            x = dsrc[i]; y = dsrc[i + 1]; z = dsrc[i + 2];
        }
        l[o] = x; l[o + 1] = y; l[o + 2] = z;
        if (gen[v] == generation) {
            int i = 3 * map[v];
            c[o] = part.v[i]; c[o + 1] = part.v[i + 1]; c[o + 2] = part.v[i + 2];
            return;
        }
        c[o] = m[0] * x + m[1] * y + m[2] * z + m[3];
        c[o + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
        c[o + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    }

    /** The part's index of geometry vertex v, emitting it (from c[o..]) the first time. */
    private int vertex(int v, Part part, int o) {
        if (gen[v] == generation) return map[v];
        double x = c[o], y = c[o + 1], z = c[o + 2];
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            throw new IllegalArgumentException("vertex " + v + " is not finite after the transforms (" + x + ", " + y + ", " + z
                + "): a scale too large?");
        }
        gen[v] = generation;
        map[v] = part.addVertex(x, y, z);
        return map[v];
    }
}
