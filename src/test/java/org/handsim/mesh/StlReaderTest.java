package org.handsim.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The STL reader: the ASCII and binary forms of the same triangles give the same mesh, our
 * writer's files read back to the float32 values written, analytic volumes and areas, and every
 * malformed file is refused with its place (FILE:LINE:COL or FILE: byte N).
 */
class StlReaderTest {
    /** A right tetrahedron on the axes, edge 1, counter-clockwise seen from outside (volume 1/6). */
    static final double[][][] TETRA = {
        {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}},
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
    };

    static String ascii(double[][][] tris) {
        StringBuilder sb = new StringBuilder("solid tetra\n");
        for (double[][] t : tris) {
            sb.append("  facet normal 0 0 0\n    outer loop\n");
            for (double[] v : t) sb.append("      vertex ").append(v[0]).append(' ').append(v[1]).append(' ').append(v[2]).append('\n');
            sb.append("    endloop\n  endfacet\n");
        }
        return sb.append("endsolid tetra\n").toString();
    }

    /** Binary STL of the triangles, written here byte by byte (independent of StlWriter). */
    static byte[] binary(double[][][] tris, String header) {
        ByteBuffer b = ByteBuffer.allocate(84 + 50 * tris.length).order(ByteOrder.LITTLE_ENDIAN);
        byte[] h = header.getBytes(StandardCharsets.US_ASCII);
        b.put(h, 0, Math.min(80, h.length));
        b.position(80);
        b.putInt(tris.length);
        for (double[][] t : tris) {
            b.putFloat(0).putFloat(0).putFloat(0);
            for (double[] v : t) for (double c : v) b.putFloat((float) c);
            b.putShort((short) 0);
        }
        return b.array();
    }

    static StlReader.Result read(byte[] data) {
        return StlReader.read("t.stl", data, 1.0);
    }

    static String message(byte[] data) {
        return assertThrows(MeshFileException.class, () -> read(data)).getMessage();
    }

    @Test
    void asciiAndBinaryOfTheSameTrianglesGiveTheSameMesh() {
        StlReader.Result a = read(ascii(TETRA).getBytes(StandardCharsets.US_ASCII));
        StlReader.Result b = read(binary(TETRA, "a binary file"));
        assertFalse(a.binary());
        assertTrue(b.binary());
        assertEquals(4, a.facets());
        assertEquals(0, a.degenerate());
        assertArrayEquals(a.mesh().vertices(), b.mesh().vertices());
        assertArrayEquals(a.mesh().triangles(), b.mesh().triangles());
        // welded: 4 vertices, closed, volume 1/6 and area 3/2 + √3/2 by hand
        assertEquals(4, a.mesh().vertexCount());
        assertTrue(a.mesh().isClosed());
        assertEquals(1.0 / 6, a.mesh().signedVolume(), 1e-15);
        assertEquals(1.5 + Math.sqrt(3) / 2, a.mesh().area(), 1e-15);
    }

    @Test
    void aBinaryHeaderStartingWithSolidIsStillBinary() {
        // many exporters write "solid ..." into the binary header: the size and the control bytes decide
        StlReader.Result r = read(binary(TETRA, "solid exported by some CAD program"));
        assertTrue(r.binary());
        assertEquals(4, r.mesh().triangleCount());
    }

    @Test
    void scaleConvertsUnits() {
        StlReader.Result mm = StlReader.read("t.stl", binary(scaled(TETRA, 40), "mm"), 0.001);
        assertEquals(0.040 * 0.040 * 0.040 / 6, mm.mesh().signedVolume(), 1e-18);
    }

    static double[][][] scaled(double[][][] t, double s) {
        double[][][] o = new double[t.length][3][3];
        for (int i = 0; i < t.length; i++) for (int j = 0; j < 3; j++) for (int c = 0; c < 3; c++) o[i][j][c] = s * t[i][j][c];
        return o;
    }

    @Test
    void writerRoundTripGivesTheFloat32Values() throws Exception {
        Random rnd = new Random(345);
        double[] v = new double[3 * 50];
        for (int i = 0; i < v.length; i++) v[i] = rnd.nextDouble() - 0.5;
        int[] t = new int[3 * 80];
        for (int i = 0; i < 80; i++) {
            t[3 * i] = rnd.nextInt(50);
            t[3 * i + 1] = (t[3 * i] + 1 + rnd.nextInt(48)) % 50;
            do { t[3 * i + 2] = rnd.nextInt(50); } while (t[3 * i + 2] == t[3 * i] || t[3 * i + 2] == t[3 * i + 1]);
        }
        TriangleMesh m = new TriangleMesh("random", v, t);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        StlWriter.writeBinary(out, m, 1.0);
        byte[] bytes = out.toByteArray();
        assertEquals(84 + 50 * 80, bytes.length);
        assertFalse(new String(bytes, 0, 5, StandardCharsets.US_ASCII).equalsIgnoreCase("solid"));
        TriangleMesh back = read(bytes).mesh();
        assertEquals(80, back.triangleCount());
        for (int i = 0; i < 80; i++) {
            for (int k = 0; k < 3; k++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals((double) (float) v[3 * t[3 * i + k] + c], back.vertices()[3 * back.triangles()[3 * i + k] + c]);
                }
            }
        }
    }

    @Test
    void degenerateTrianglesAreDroppedAndCounted() {
        double[][][] tris = Arrays.copyOf(TETRA, 5);
        tris[4] = new double[][] {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};   // collinear: zero area
        StlReader.Result r = read(binary(tris, "x"));
        assertEquals(5, r.facets());
        assertEquals(1, r.degenerate());
        assertEquals(4, r.mesh().triangleCount());
        assertEquals(4, r.mesh().vertexCount(), "the dropped triangle's own corner (2,0,0) is not kept");
    }

    // ------------------------------------------------------------------ malformed binary files
    @Test
    void truncatedBinaryNamesTheByteWhereItEnds() {
        byte[] full = binary(TETRA, "x");
        byte[] cut = Arrays.copyOf(full, 84 + 50 * 2 + 17);
        String m = message(cut);
        assertTrue(m.startsWith("t.stl: byte 201: the file ends inside triangle 3 of the 4"), m);
        assertTrue(m.contains("truncated"), m);
    }

    @Test
    void aWrongTriangleCountIsRefused() {
        byte[] b = binary(TETRA, "x");
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(80, 3);   // says 3, has 4
        String m = message(b);
        assertTrue(m.startsWith("t.stl: byte 234: 50 bytes after the last of the 3 triangles"), m);
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(80, 20);   // 1 084 bytes expected: within 16 times the file's 284
        assertTrue(message(b).startsWith("t.stl: byte 284: the file ends inside triangle 5 of the 20"), message(b));
        // a count far from the size: the four bytes are no count, the file is no STL, and nothing of it is quoted
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(80, 1_000_000);
        assertEquals("t.stl: byte 80: not an STL file: not ASCII STL (text starting with 'solid') and its size, 284 bytes,"
            + " is far from 84 + 50 × the triangle count a binary STL has at byte 80", message(b));
    }

    @Test
    void aNanVertexNamesItsByte() {
        byte[] b = binary(TETRA, "x");
        // triangle 2, vertex 3, y: 84 + 50 + 12 + 4 * (6 + 1)
        int at = 84 + 50 + 12 + 4 * 7;
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putFloat(at, Float.NaN);
        assertEquals("t.stl: byte " + at + ": triangle 2, vertex 3, y coordinate is NaN", message(b));
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putFloat(at, Float.POSITIVE_INFINITY);
        assertEquals("t.stl: byte " + at + ": triangle 2, vertex 3, y coordinate is Infinity", message(b));
    }

    @Test
    void aFileTooShortForTheHeader() {
        String m = message(new byte[] {1, 2, 3});
        assertTrue(m.startsWith("t.stl: byte 3: the file ends inside the 84-byte header"), m);
        assertTrue(message(new byte[0]).startsWith("t.stl: byte 0: "), message(new byte[0]));
    }

    // ------------------------------------------------------------------ malformed ASCII files
    static String asciiMessage(String text) {
        return message(text.getBytes(StandardCharsets.US_ASCII));
    }

    /** A C1 control byte (NEL, 0x85, read as ISO-8859-1) inside a bad token is escaped: the message stays one line. */
    @Test
    void aControlByteInABadTokenIsEscaped() {
        byte[] text = ascii(TETRA).replaceFirst("vertex 0.0 1.0", "vertex 0.0 x\u00851.0").getBytes(StandardCharsets.ISO_8859_1);
        assertEquals("t.stl:5:18: vertex coordinate 'x\\u00851.0' is not a number", message(text));
    }

    @Test
    void asciiErrorsNameLineAndColumn() {
        String good = ascii(TETRA);
        // line 5 is the second vertex of the first facet: "      vertex 0.0 1.0 0.0"
        assertEquals("t.stl:5:18: vertex coordinate 'x1.0' is not a number", asciiMessage(good.replaceFirst("vertex 0.0 1.0", "vertex 0.0 x1.0")));
        assertEquals("t.stl:5:18: vertex coordinate is NaN: not a finite number", asciiMessage(good.replaceFirst("vertex 0.0 1.0", "vertex 0.0 NaN")));
        assertEquals("t.stl:5:18: vertex coordinate is 1e999: not a finite number", asciiMessage(good.replaceFirst("vertex 0.0 1.0", "vertex 0.0 1e999")));
        assertEquals("t.stl:5:7: expected 'vertex', found 'vertx'", asciiMessage(good.replaceFirst("      vertex 0.0 1.0", "      vertx 0.0 1.0")));
        assertEquals("t.stl:2:3: expected 'endsolid', found 'facett'", asciiMessage(good.replaceFirst("facet normal", "facett normal")));
    }

    @Test
    void aFacetWithoutThreeVerticesIsRefused() {
        String two = "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid a\n";
        assertEquals("t.stl:6:1: a facet needs 3 vertices, this one has 2", asciiMessage(two));
        String four = "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid a\n";
        assertEquals("t.stl:7:1: a facet has exactly 3 vertices (STL triangles), this one has more", asciiMessage(four));
    }

    @Test
    void aTruncatedAsciiFileSaysWhatWasExpected() {
        String m = asciiMessage("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0");
        assertTrue(m.startsWith("t.stl:5:11: the file ends where a vertex coordinate was expected"), m);
        m = asciiMessage("solid a\n");
        assertTrue(m.startsWith("t.stl:2:1: the file ends where 'endsolid' was expected"), m);
    }

    @Test
    void severalSolidsAndUpperCaseKeywords() {
        String two = ascii(new double[][][] {TETRA[0], TETRA[1]}) + ascii(new double[][][] {TETRA[2], TETRA[3]}).toUpperCase();
        StlReader.Result r = read(two.getBytes(StandardCharsets.US_ASCII));
        assertEquals(4, r.mesh().triangleCount());
        assertTrue(r.mesh().isClosed());
    }
}
