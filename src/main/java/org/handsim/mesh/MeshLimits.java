package org.handsim.mesh;

/**
 * The limits every object file meets (VRML97, OBJ, STL), counted <em>while</em> the file is
 * read, so a hostile file — a 126 KB gzip of two million {@code Shape { geometry Box {} }}, an
 * STL header announcing four billion triangles — is refused after reading about as much as the
 * limit allows, never after building its whole scene.
 *
 * <table>
 *   <caption>Limits and their reasons</caption>
 *   <tr><th>limit</th><th>value</th><th>why</th></tr>
 *   <tr><td>{@link #MAX_FILE_BYTES}</td><td>256 MiB</td><td>file size, and a gzip VRML file's
 *       expanded size: the largest model of the VRML corpus is 7 MB expanded; the VRML and STL
 *       parsers hold the whole text, so memory is a small multiple of this; the OBJ reader
 *       holds one line and the checked copy of what Java3D needs (degenerate faces dropped)</td></tr>
 *   <tr><td>{@link #MAX_TRIANGLES}</td><td>20 million</td><td>the triangles of one file (VRML:
 *       IndexedFaceSet polygons as written and the primitives' tessellations, counted as each
 *       node is parsed; DEF/USE sharing is multiplied out by {@link TessellationWalk}); a
 *       BarrettHand grasp needs thousands, the corpus's largest file has 84 000</td></tr>
 *   <tr><td>{@link #MAX_FACE_CORNERS}</td><td>1 024</td><td>corners of one OBJ face (Java3D's triangulator):
 *       triangulating a polygon takes more than linear time and memory (10 000 corners 3 s,
 *       100 000 corners 83 s and 722 MB); the VRML corpus's largest polygon has 144</td></tr>
 *   <tr><td>{@link #MAX_LINE_BYTES}</td><td>1 MiB</td><td>one OBJ line (continuations joined): the
 *       reader holds one line at a time, never the whole text</td></tr>
 *   <tr><td>{@link #MAX_NODES}</td><td>1 million</td><td>VRML nodes parsed (each about 100
 *       bytes; the corpus's largest file has a few thousand)</td></tr>
 *   <tr><td>{@link #MAX_SHAPES}</td><td>50 000</td><td>VRML {@code Shape} nodes and OBJ groups:
 *       each becomes a Java3D Shape3D of several kilobytes (measured: 50 000 boxes take 416 MB
 *       and 5 s to load); the corpus's largest file has 726</td></tr>
 *   <tr><td>{@link #MAX_COORDINATE_M}</td><td>1e6 m</td><td>the largest coordinate after the
 *       units and scale: a hand 0.3 m long grasps nothing near that, and squares and cross
 *       products of coordinates (areas, normals, distances) stay finite far beyond it, where a
 *       3e38 STL overflows them to infinity</td></tr>
 * </table>
 * A refusal is one line naming the file and the place where the count passed the limit
 * ({@code FILE:LINE:COL: ...}, binary STL {@code FILE: byte N: ...}); the commands exit with
 * code 3.
 */
public final class MeshLimits {
    /** Largest object file, and largest expanded gzip VRML text, bytes. */
    public static final long MAX_FILE_BYTES = 256L << 20;
    /** The words for {@link #MAX_FILE_BYTES} in messages. */
    public static final String FILE_LIMIT = "the limit of object files";
    /** Most triangles one file may describe. */
    public static final long MAX_TRIANGLES = 20_000_000L;
    /** The words for {@link #MAX_TRIANGLES} in messages. */
    public static final String TRIANGLE_LIMIT = "the limit of " + MAX_TRIANGLES + " triangles per object file";
    /**
     * Most corners of one OBJ face: Java3D's triangulator, which ObjectFile uses, takes time and
     * memory that grow faster than the corners (measured: 10 000 corners 3 s, 100 000 corners
     * 83 s and 722 MB); the VRML corpus's largest polygon has 144. (VRML polygons go through our
     * own ear clipping, whose work per face is bounded.)
     */
    public static final int MAX_FACE_CORNERS = 1024;
    /** The words for {@link #MAX_FACE_CORNERS} in messages. */
    public static final String FACE_LIMIT = "the limit of " + MAX_FACE_CORNERS + " corners per face";
    /** Longest line of a text object file (OBJ), bytes: a face at the corner limit with long references fits many times. */
    public static final int MAX_LINE_BYTES = 1 << 20;
    /** Most VRML nodes one load may parse. */
    public static final long MAX_NODES = 1_000_000L;
    /** Most VRML Shape nodes (OBJ groups) one file may hold. */
    public static final int MAX_SHAPES = 50_000;
    /** Largest coordinate magnitude of a loaded mesh, metres (after units and scale). */
    public static final double MAX_COORDINATE_M = 1e6;
    /**
     * The range of a scale factor (scenario {@code object.scale}, {@code handsim mesh --scale}):
     * [1e-6, 1e6]. Beyond it a millimetre model becomes a nanometre speck whose triangles all
     * round to zero area, or a kilometre one beyond every physical meaning of the hand.
     */
    public static final double MIN_SCALE = 1e-6, MAX_SCALE = 1e6;

    /** Why {@code s} is not a usable scale factor, or null when it lies in [{@link #MIN_SCALE}, {@link #MAX_SCALE}]. */
    public static String scaleProblem(double s) {
        if (s >= MIN_SCALE && s <= MAX_SCALE) return null;
        return "must be in [1e-6, 1e6], got " + org.handsim.text.Decimal.format(s);
    }

    /**
     * Refuses a mesh with a coordinate beyond {@link #MAX_COORDINATE_M}.
     *
     * @return null, or the message (without the file) naming the largest magnitude
     */
    public static String coordinateProblem(TriangleMesh m) {
        double worst = 0;
        for (double v : m.vertices()) {
            double c = Math.abs(v);
            if (!(c <= worst)) worst = c;   // NaN too
        }
        if (worst <= MAX_COORDINATE_M) return null;
        return "coordinates reach " + (Double.isFinite(worst) ? org.handsim.text.Decimal.format(worst) : String.valueOf(worst))
            + " m from the file's origin (after units and scale), more than the limit of 1e6 m";
    }

    private MeshLimits() {}
}
