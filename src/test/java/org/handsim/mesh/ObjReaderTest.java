package org.handsim.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * OBJ through Java3D's ObjectFile and the tessellation walk: the same triangles as the STL twin,
 * polygons triangulated with their area kept (concave ones too), negative indices, groups, and
 * every malformed file refused with FILE:LINE:COL before ObjectFile sees it.
 */
class ObjReaderTest {
    static final String TETRA = "# right tetrahedron, edge 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
        + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

    static TriangleMesh mesh(String text) {
        return ObjReader.read("t.obj", text, 1.0).mesh();
    }

    static String message(String text) {
        return assertThrows(MeshFileException.class, () -> ObjReader.read("t.obj", text, 1.0)).getMessage();
    }

    @Test
    void sameTrianglesAsTheStlTwin() {
        TriangleMesh obj = new MeshWelder().weld(mesh(TETRA));
        TriangleMesh stl = StlReader.read("t.stl", StlReaderTest.ascii(StlReaderTest.TETRA).getBytes(StandardCharsets.US_ASCII), 1).mesh();
        assertEquals(4, obj.triangleCount());
        assertEquals(stl.signedVolume(), obj.signedVolume(), 1e-15);
        assertEquals(1.0 / 6, obj.signedVolume(), 1e-15);
        assertEquals(stl.area(), obj.area(), 1e-15);
        assertTrue(obj.isClosed());
    }

    @Test
    void polygonsAreTriangulatedKeepingTheirArea() {
        // a unit square and an L-shaped (concave) hexagon: areas 1 and 3 by hand
        TriangleMesh sq = mesh("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
        assertEquals(2, sq.triangleCount());
        assertEquals(1.0, sq.area(), 1e-15);
        TriangleMesh l = mesh("v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4 5 6\n");
        assertEquals(4, l.triangleCount());
        assertEquals(3.0, l.area(), 1e-15, "a fan from vertex 1 would give a wrong area for the concave L");
        for (int t = 0; t < l.triangleCount(); t++) assertEquals(1.0, l.normals()[3 * t + 2], 1e-15, "counter-clockwise: +z");
    }

    @Test
    void negativeIndicesGroupsObjectsAndContinuations() {
        String text = "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\ng second part\ns off\nv 0 0 1\nf 1 2 \\\n 4\n"
            + "vt 0 0\nvn 0 0 1\nusemtl red\nmtllib missing.mtl\nl 1 2\nf 1/1/1 3/1/1 4//1\n";
        ObjReader.Result r = ObjReader.read("t.obj", text, 2.0);
        assertEquals(4, r.vertices());
        assertEquals(3, r.faces());
        assertEquals(3, r.mesh().triangleCount());
        assertEquals(2, r.walk().shapes, "one shape per group ('o' is a group)");
        assertEquals(3 * 0.5 * 4, r.mesh().area(), 1e-12, "three right triangles of legs 2 (scale 2)");
    }

    @Test
    void errorsNameLineAndColumn() {
        assertEquals("t.obj:4:7: vertex index 9 is out of range: 3 vertices defined so far", message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"));
        assertEquals("t.obj:4:7: vertex index 0: OBJ indices start at 1 (negative ones count back)", message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n"));
        assertEquals("t.obj:4:3: vertex index -4 is out of range: 3 vertices defined so far", message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 2 3\n"));
        assertEquals("t.obj:2:5: vertex coordinate 'nan' is not a finite number", message("v 0 0 0\nv 1 nan 0\n"));
        assertEquals("t.obj:2:3: vertex coordinate 1e39 is beyond the range of a float (Java3D stores coordinates as float)", message("v 0 0 0\nv 1e39 0 0\n"));
        assertEquals("t.obj:1:5: vertex coordinate '1x' is not a number", message("v 0 1x 0\n"));
        assertEquals("t.obj:1:6: a vertex needs x y z (and optionally w, or r g b), found 2 numbers", message("v 0 1  \n"));
        assertEquals("t.obj:4:6: a face needs at least 3 corners, found 2", message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"));
        assertEquals("t.obj:4:5: texture coordinate index 1 is out of range: 0 texture coordinates defined so far",
            message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n"));
        assertEquals("t.obj:4:11: normal index 2 is out of range: 1 normal defined so far",
            message("v 0 0 0\nv 1 0 0\nvn 0 0 1\nf 1//1 2//2 1//1\n"));
        assertEquals("t.obj:2:3: vertex index 'a' is not an integer", message("v 0 0 0\nf a/b 1 1\n"));
        assertEquals("t.obj:2:3: '1/1/1/1' is not a vertex reference (v, v/t, v//n or v/t/n)", message("v 0 0 0\nf 1/1/1/1 1 1\n"));
    }

    @Test
    void unknownAndFreeFormStatementsAreNamed() {
        String m = message("v 0 0 0\n  foo 1 2 3\n");
        assertTrue(m.startsWith("t.obj:2:3: unknown statement 'foo' (known: v, vn, vt, f"), m);
        m = message("v 0 0 0\ncstype bspline\n");
        assertTrue(m.startsWith("t.obj:2:1: 'cstype': free-form curves and surfaces are not supported"), m);
    }

    /**
     * Faces whose triangles all have zero area are dropped as the file streams and counted as
     * the walk counted them when it dropped them itself (measured before: 4 triangles, 6
     * degenerate, 1 shape for this file): repeated corners, collinear corners, a quad of two
     * points. A group whose faces are all degenerate is still one shape.
     */
    @Test
    void degenerateFacesAreDroppedAndCountedAsTheWalkCountedThem() {
        String text = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 0 0 1\nv 1 0 0\n"
            + "f 1 1 1\nf 1 2 3\nf 1 2 3 1\nf 1 1 2 2\nf 1 2 4\nf 1 4 5\nf 2 4 5\nf 1 2 5\nf 2 6 1\n";
        ObjReader.Result r = ObjReader.read("t.obj", text, 1.0);
        assertEquals(4, r.mesh().triangleCount());
        assertEquals(7, r.degenerate(), "6, and f 2 6 1 whose corners 2 and 6 are the same point");
        assertEquals(9, r.faces());
        assertEquals(1, r.walk().shapes);
        ObjReader.Result none = ObjReader.read("t.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\ng a\nf 1 1 1\nf 1 2 3\ng b\nf 3 2 1\n", 1.0);
        assertEquals(0, none.mesh().triangleCount());
        assertEquals(3, none.degenerate());
        assertEquals(2, none.walk().shapes, "each group is a shape, as when the walk dropped its triangles");
    }

    /** A face of more corners than the limit is refused at the first corner beyond it, before anything is built. */
    @Test
    void aFaceBeyondTheCornerLimitIsRefused() {
        StringBuilder v = new StringBuilder();
        StringBuilder f = new StringBuilder("f");
        for (int i = 0; i < MeshLimits.MAX_FACE_CORNERS + 1; i++) {
            double a = 2 * Math.PI * i / (MeshLimits.MAX_FACE_CORNERS + 1);
            v.append("v ").append(Math.cos(a)).append(' ').append(Math.sin(a)).append(" 0\n");
            f.append(' ').append(i + 1);
        }
        String at = f.substring(0, f.lastIndexOf(" "));
        assertEquals(MeshLimits.MAX_FACE_CORNERS - 2, mesh(v + at + "\n").triangleCount(), "the limit itself is read");
        assertEquals("t.obj:" + (MeshLimits.MAX_FACE_CORNERS + 2) + ":" + (at.length() + 2) + ": a face of 1025 corners, more than the limit of 1024"
            + " corners per face", message(v + f.toString() + "\n"));
    }
}
