package org.handsim.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.List;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.Group;
import org.jogamp.java3d.IndexedQuadArray;
import org.jogamp.java3d.IndexedTriangleArray;
import org.jogamp.java3d.IndexedTriangleFanArray;
import org.jogamp.java3d.IndexedTriangleStripArray;
import org.jogamp.java3d.J3DBuffer;
import org.jogamp.java3d.LineArray;
import org.jogamp.java3d.Link;
import org.jogamp.java3d.QuadArray;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.SharedGroup;
import org.jogamp.java3d.Switch;
import org.jogamp.java3d.Transform3D;
import org.jogamp.java3d.TransformGroup;
import org.jogamp.java3d.TriangleArray;
import org.jogamp.java3d.TriangleFanArray;
import org.jogamp.java3d.TriangleStripArray;
import org.jogamp.vecmath.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The tessellation walk on hand-built Java3D scenes: the unit square x, y ∈ [0, 1] at z = 0
 * (area 1, normal +z, two triangles) written in every GeometryArray kind and storage mode must
 * come out the same; transforms, switches, shared groups, degenerate triangles and deep
 * nesting are checked against hand-worked values.
 */
class TessellationWalkTest {
    private static final double TOL = 1e-12;
    // the square's corners, counter-clockwise seen from +z
    private static final float[] P = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

    private static float[] corners(int... order) {
        float[] out = new float[3 * order.length];
        for (int i = 0; i < order.length; i++) System.arraycopy(P, 3 * order[i], out, 3 * i, 3);
        return out;
    }

    /** The square in every geometry kind and storage mode. */
    private static List<GeometryArray> squares() {
        List<GeometryArray> g = new ArrayList<>();
        TriangleArray ta = new TriangleArray(6, GeometryArray.COORDINATES);
        ta.setCoordinates(0, corners(0, 1, 2, 0, 2, 3));
        g.add(ta);
        QuadArray qa = new QuadArray(4, GeometryArray.COORDINATES);
        qa.setCoordinates(0, corners(0, 1, 2, 3));
        g.add(qa);
        TriangleStripArray ts = new TriangleStripArray(4, GeometryArray.COORDINATES, new int[] {4});
        ts.setCoordinates(0, corners(0, 1, 3, 2)); // strip 0 1 3 2 ⇒ (0 1 3), (3 1 2) keeps the winding
        g.add(ts);
        TriangleFanArray tf = new TriangleFanArray(4, GeometryArray.COORDINATES, new int[] {4});
        tf.setCoordinates(0, corners(0, 1, 2, 3));
        g.add(tf);
        IndexedTriangleArray ita = new IndexedTriangleArray(4, GeometryArray.COORDINATES, 6);
        ita.setCoordinates(0, P);
        ita.setCoordinateIndices(0, new int[] {0, 1, 2, 0, 2, 3});
        g.add(ita);
        IndexedQuadArray iqa = new IndexedQuadArray(4, GeometryArray.COORDINATES, 4);
        iqa.setCoordinates(0, P);
        iqa.setCoordinateIndices(0, new int[] {0, 1, 2, 3});
        g.add(iqa);
        IndexedTriangleStripArray its = new IndexedTriangleStripArray(4, GeometryArray.COORDINATES, 4, new int[] {4});
        its.setCoordinates(0, P);
        its.setCoordinateIndices(0, new int[] {0, 1, 3, 2});
        g.add(its);
        IndexedTriangleFanArray itf = new IndexedTriangleFanArray(4, GeometryArray.COORDINATES, 4, new int[] {4});
        itf.setCoordinates(0, P);
        itf.setCoordinateIndices(0, new int[] {0, 1, 2, 3});
        g.add(itf);
        // by reference: float[], double[]
        TriangleArray rf = new TriangleArray(6, GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE);
        rf.setCoordRefFloat(corners(0, 1, 2, 0, 2, 3));
        g.add(rf);
        IndexedTriangleArray rd = new IndexedTriangleArray(4, GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE, 6);
        double[] pd = new double[12];
        for (int i = 0; i < 12; i++) pd[i] = P[i];
        rd.setCoordRefDouble(pd);
        rd.setCoordinateIndices(0, new int[] {0, 1, 2, 0, 2, 3});
        g.add(rd);
        // indices by reference
        IndexedTriangleArray ri = new IndexedTriangleArray(4, GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE
            | GeometryArray.USE_COORD_INDEX_ONLY | GeometryArray.BY_REFERENCE_INDICES, 6);
        ri.setCoordRefFloat(P.clone());
        ri.setCoordIndicesRef(new int[] {0, 1, 2, 0, 2, 3});
        g.add(ri);
        // interleaved: normal (3) + coordinate (3) per vertex
        float[] inter = new float[6 * 4];
        for (int v = 0; v < 4; v++) {
            inter[6 * v + 2] = 1;
            System.arraycopy(P, 3 * v, inter, 6 * v + 3, 3);
        }
        QuadArray il = new QuadArray(4, GeometryArray.COORDINATES | GeometryArray.NORMALS | GeometryArray.BY_REFERENCE | GeometryArray.INTERLEAVED);
        il.setInterleavedVertices(inter);
        g.add(il);
        // NIO buffer
        TriangleArray nio = new TriangleArray(6, GeometryArray.COORDINATES | GeometryArray.BY_REFERENCE | GeometryArray.USE_NIO_BUFFER);
        FloatBuffer fb = java.nio.ByteBuffer.allocateDirect(4 * 18).order(java.nio.ByteOrder.nativeOrder()).asFloatBuffer();
        fb.put(corners(0, 1, 2, 0, 2, 3));
        nio.setCoordRefBuffer(new J3DBuffer(fb));
        g.add(nio);
        return g;
    }

    @Test
    void everyGeometryKindGivesTheSameSquare() {
        for (GeometryArray g : squares()) {
            BranchGroup bg = new BranchGroup();
            bg.addChild(new Shape3D(g));
            TessellationWalk.Result r = new TessellationWalk().run(bg);
            TriangleMesh m = r.merged();
            String what = g.getClass().getSimpleName() + " format " + g.getVertexFormat();
            assertEquals(2, m.triangleCount(), what);
            assertEquals(1.0, m.area(), TOL, what);
            for (int t = 0; t < 2; t++) assertEquals(1.0, m.normals()[3 * t + 2], TOL, what + ": counter-clockwise kept");
            assertEquals(1, r.shapes);
            assertEquals(0, r.degenerate);
        }
    }

    private static Shape3D square() {
        IndexedTriangleArray ita = new IndexedTriangleArray(4, GeometryArray.COORDINATES, 6);
        ita.setCoordinates(0, P);
        ita.setCoordinateIndices(0, new int[] {0, 1, 2, 0, 2, 3});
        return new Shape3D(ita);
    }

    private static TransformGroup tg(Transform3D t) {
        return new TransformGroup(t);
    }

    @Test
    void transformsAccumulateFromTheRoot() {
        // root: translate (10, 0, 0); child: scale 2 then rotate 90° about z: square ⇒ [8, 10] x [0, 2]
        Transform3D a = new Transform3D();
        a.setTranslation(new Vector3d(10, 0, 0));
        Transform3D b = new Transform3D();
        b.rotZ(Math.PI / 2);
        b.setScale(2);
        TransformGroup ta = tg(a), tb = tg(b);
        ta.addChild(tb);
        tb.addChild(square());
        BranchGroup bg = new BranchGroup();
        bg.addChild(ta);
        TriangleMesh m = new TessellationWalk().scale(0.5).run(bg).merged();
        double[][] box = m.bounds();
        assertEquals(4, box[0][0], 1e-9);
        assertEquals(5, box[1][0], 1e-9);
        assertEquals(0, box[0][1], 1e-9);
        assertEquals(1, box[1][1], 1e-9);
        assertEquals(1.0, m.area(), 1e-9, "scale 2 then walk scale 0.5");
    }

    @Test
    void mirrorCarriesTheFrontFaceAcross() {
        Transform3D t = new Transform3D(new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1});
        TransformGroup g = tg(t);
        g.addChild(square());
        BranchGroup bg = new BranchGroup();
        bg.addChild(g);
        TriangleMesh m = TessellationWalk.mesh(bg);
        // z ↦ −z maps the square onto itself and its front (+z) side to −z: the winding is reversed
        // so the normal follows the front side (for a closed solid: stays outward)
        for (int k = 0; k < 2; k++) assertEquals(-1.0, m.normals()[3 * k + 2], TOL);
    }

    @Test
    void switchesAndSharedGroups() {
        Switch sw = new Switch(1);
        sw.addChild(square());
        Transform3D up = new Transform3D();
        up.setTranslation(new Vector3d(0, 0, 5));
        TransformGroup shifted = tg(up);
        SharedGroup sg = new SharedGroup();
        sg.addChild(square());
        shifted.addChild(new Link(sg));
        sw.addChild(shifted);
        BranchGroup bg = new BranchGroup();
        bg.addChild(sw);
        bg.addChild(new Link(sg));
        TessellationWalk.Result r = new TessellationWalk().run(bg);
        assertEquals(2, r.shapes, "child 1 of the switch (one Link) plus the second Link");
        double[][] b = r.merged().bounds();
        assertEquals(0, b[0][2], TOL);
        assertEquals(5, b[1][2], TOL);
        sw.setWhichChild(Switch.CHILD_NONE);
        assertEquals(1, new TessellationWalk().run(bg).shapes);
        sw.setWhichChild(Switch.CHILD_ALL);
        assertEquals(3, new TessellationWalk().run(bg).shapes);
        assertEquals(6, TessellationWalk.expandedTriangles(bg), "the counting pass: three squares");
        java.util.BitSet mask = new java.util.BitSet();
        mask.set(0);
        sw.setChildMask(mask);
        sw.setWhichChild(Switch.CHILD_MASK);
        TessellationWalk.Result masked = new TessellationWalk().run(bg);
        assertEquals(2, masked.shapes, "mask {0}: the switch's own square plus the second Link");
        assertEquals(0, masked.merged().bounds()[1][2], TOL, "the shifted child is masked out");
        assertEquals(4, TessellationWalk.expandedTriangles(bg), "the counting pass: two squares");
    }

    @Test
    void degenerateTrianglesAreDroppedAndCounted() {
        IndexedTriangleArray g = new IndexedTriangleArray(5, GeometryArray.COORDINATES, 12);
        g.setCoordinates(0, new float[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 2, 0});
        // a good triangle, a repeated vertex, three collinear points (0,0)-(1,1)-(2,2), another good one
        g.setCoordinateIndices(0, new int[] {0, 1, 2, 0, 0, 1, 0, 2, 4, 0, 2, 3});
        BranchGroup bg = new BranchGroup();
        bg.addChild(new Shape3D(g));
        TessellationWalk.Result r = new TessellationWalk().run(bg);
        assertEquals(2, r.merged().triangleCount());
        assertEquals(2, r.degenerate);
        assertEquals(4, r.merged().vertexCount(), "vertex 4 is only used by a dropped triangle");
        // a zero scale makes everything degenerate
        Transform3D flat = new Transform3D();
        flat.setScale(new Vector3d(1, 0, 1));
        TransformGroup t = tg(flat);
        t.addChild(square());
        BranchGroup bg2 = new BranchGroup();
        bg2.addChild(t);
        TessellationWalk.Result r2 = new TessellationWalk().run(bg2);
        assertEquals(0, r2.merged().triangleCount());
        assertEquals(2, r2.degenerate);
    }

    @Test
    void linesArePassedOverAndCounted() {
        LineArray l = new LineArray(2, GeometryArray.COORDINATES);
        l.setCoordinates(0, new float[] {0, 0, 0, 1, 1, 1});
        BranchGroup bg = new BranchGroup();
        bg.addChild(new Shape3D(l));
        bg.addChild(square());
        TessellationWalk.Result r = new TessellationWalk().run(bg);
        assertEquals(1, r.skippedGeometries);
        assertEquals(1, r.shapes);
    }

    @Test
    void hundredThousandLevelsDeepIsWalkedWithoutRecursion() {
        BranchGroup bg = new BranchGroup();
        Group g = bg;
        for (int i = 0; i < 100_000; i++) {
            Transform3D t = new Transform3D();
            t.setTranslation(new Vector3d(0, 0, 1e-3));
            TransformGroup c = tg(t);
            g.addChild(c);
            g = c;
        }
        g.addChild(square());
        TriangleMesh m = TessellationWalk.mesh(bg);   // a recursive walk would overflow the stack
        assertEquals(100.0, m.bounds()[0][2], 1e-6);
    }

    @Test
    void multipliedSharingIsStoppedByTheTriangleLimit() {
        // each level links the previous shared group twice: 2^40 squares
        SharedGroup prev = new SharedGroup();
        prev.addChild(square());
        for (int i = 0; i < 40; i++) {
            SharedGroup next = new SharedGroup();
            next.addChild(new Link(prev));
            next.addChild(new Link(prev));
            prev = next;
        }
        BranchGroup bg = new BranchGroup();
        bg.addChild(new Link(prev));
        // refused by the counting pass (its message has the exact count), before any triangle is made
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> new TessellationWalk().run(bg));
        assertTrue(e.getMessage().contains("expands to 2199023255552 triangles, more than the limit of 20000000"), e.getMessage());
        assertEquals(2L << 40, TessellationWalk.expandedTriangles(bg));
    }

    @Test
    void java3dUtilityPrimitivesAreTessellated() {
        // Java3D's own Box/Sphere/Cylinder/Cone (Groups of Shape3Ds with strip or quad geometry)
        BranchGroup bg = new BranchGroup();
        bg.addChild(new org.jogamp.java3d.utils.geometry.Box(0.5f, 1f, 1.5f, null));
        TriangleMesh box = TessellationWalk.mesh(bg);
        assertEquals(2 * (1 * 2 + 2 * 3 + 1 * 3), box.area(), 1e-5);
        BranchGroup s = new BranchGroup();
        s.addChild(new org.jogamp.java3d.utils.geometry.Sphere(1f, org.jogamp.java3d.utils.geometry.Primitive.GENERATE_NORMALS, 64));
        TriangleMesh sphere = new MeshWelder().weld(TessellationWalk.mesh(s), 1e-6);
        assertEquals(4 * Math.PI, sphere.area(), 0.01 * 4 * Math.PI);
        assertTrue(sphere.isClosed(), "Java3D's sphere is closed once its pieces are welded");
        assertEquals(4.0 / 3 * Math.PI, sphere.signedVolume(), 0.01 * 4.0 / 3 * Math.PI);
        BranchGroup c = new BranchGroup();
        c.addChild(new org.jogamp.java3d.utils.geometry.Cylinder(1f, 2f, org.jogamp.java3d.utils.geometry.Primitive.GENERATE_NORMALS, 64, 1, null));
        c.addChild(new org.jogamp.java3d.utils.geometry.Cone(1f, 2f, org.jogamp.java3d.utils.geometry.Primitive.GENERATE_NORMALS, 64, 1, null));
        TessellationWalk.Result r = new TessellationWalk().grouping(TessellationWalk.Grouping.SHAPES).run(c);
        double cyl = 0, cone = 0;
        for (int i = 0; i < 3; i++) cyl += r.meshes().get(i).area();
        for (int i = 3; i < 5; i++) cone += r.meshes().get(i).area();
        assertEquals(5, r.meshes().size(), "cylinder: body, top, bottom; cone: body, bottom");
        assertEquals(2 * Math.PI + 4 * Math.PI, cyl, 0.01 * 6 * Math.PI);
        assertEquals(Math.PI + Math.PI * Math.sqrt(5), cone, 0.01 * 4 * Math.PI);
    }
}
