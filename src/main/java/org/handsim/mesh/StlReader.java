package org.handsim.mesh;

import org.handsim.files.InputFile;
import org.handsim.text.SafeText;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * A strict reader of STL (stereolithography) files, ASCII and binary, into one
 * {@link TriangleMesh}. There is no well-kept STL reader for Java on Maven Central (checked;
 * docs/DESIGN.md), and the format is small, so this is ours.
 *
 * <h2>The two forms</h2>
 * <ul>
 *   <li><b>Binary</b>: an 80-byte header, a little-endian uint32 triangle count N at byte 80,
 *       then N records of 50 bytes: the facet normal (3 float32), the three vertices (9
 *       float32, counter-clockwise seen from outside) and a 2-byte attribute. The file is
 *       exactly 84 + 50·N bytes.</li>
 *   <li><b>ASCII</b>: {@code solid NAME}, then per triangle {@code facet normal nx ny nz /
 *       outer loop / vertex x y z} (three times) {@code / endloop / endfacet}, and
 *       {@code endsolid NAME}; several solids may follow each other. Keywords are matched
 *       without regard to case.</li>
 * </ul>
 * A file is read as ASCII when it starts with {@code solid} and is text (no control bytes);
 * otherwise as binary — binary files whose 80-byte header happens to start with "solid" are
 * common, and their float data always holds control bytes.
 *
 * <h2>Strict</h2>
 * Every error names where it is: {@code FILE:LINE:COL: message} (ASCII), {@code FILE: byte N:
 * message} (binary), as a {@link MeshFileException}: a file too short for its header, a triangle
 * count that does not match the file's length (truncated, or data after the last triangle), a
 * vertex coordinate that is NaN or infinite, a missing or unexpected keyword, a facet without
 * exactly three vertices, a number that is not one.
 *
 * <h2>What is kept</h2>
 * The vertices, scaled; identical vertices (bit for bit after scaling, −0 = +0) are merged so the
 * mesh is connected as the file's triangles are. The stored facet normals are ignored (writers
 * often leave them zero); the normal comes from the winding, as everywhere in HandSim. Zero-area
 * triangles are dropped and counted ({@link Result#degenerate()}).
 */
public final class StlReader {
    private StlReader() {}

    /** Bytes of a binary STL header (then the uint32 count). */
    public static final int HEADER_BYTES = 80;
    /** Bytes per binary STL triangle record. */
    public static final int RECORD_BYTES = 50;
    /**
     * A binary STL whose size is within this factor of 84 + 50 × its triangle count is an STL
     * with a wrong count or truncated (the message gives the count); farther off, the four bytes
     * at 80 are not a count and the file is not an STL (the message quotes nothing of it).
     */
    static final long PLAUSIBLE_SIZE_RATIO = 16;

    /**
     * What was read.
     *
     * @param mesh       the triangles (degenerate ones dropped), welded, scaled, named after the file
     * @param binary     true for the binary form
     * @param facets     triangles in the file
     * @param degenerate zero-area triangles dropped
     */
    public record Result(TriangleMesh mesh, boolean binary, int facets, int degenerate) {}

    /**
     * Reads an STL file.
     *
     * @param scale multiplies every coordinate (e.g. 0.001 for millimetres); positive, finite
     * @throws MeshFileException naming the file and the line and column, or the byte offset
     * @throws IOException       if the file cannot be read at all
     */
    public static Result read(Path file, double scale) throws IOException {
        return read(file.toString(), InputFile.readBytes(file, MeshLimits.MAX_FILE_BYTES, MeshLimits.FILE_LIMIT), scale);
    }

    /** Reads STL bytes; {@code name} names them in messages and the mesh. */
    public static Result read(String name, byte[] data, double scale) {
        if (!(scale > 0) || !Double.isFinite(scale)) throw new IllegalArgumentException("scale must be a positive finite number, got " + scale);
        boolean sizeMatches = data.length >= HEADER_BYTES + 4
            && HEADER_BYTES + 4 + (long) RECORD_BYTES * countAt(data) == data.length;
        if (startsWithSolid(data) && (!sizeMatches || isText(data))) return new Ascii(name, data, scale).read();
        return binary(name, data, scale);
    }

    private static long countAt(byte[] d) {
        return ByteBuffer.wrap(d, HEADER_BYTES, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xffffffffL;
    }

    private static boolean startsWithSolid(byte[] d) {
        int i = 0;
        while (i < d.length && (d[i] == ' ' || d[i] == '\t' || d[i] == '\r' || d[i] == '\n')) i++;
        if (d.length - i < 5) return false;
        return new String(d, i, 5, StandardCharsets.ISO_8859_1).equalsIgnoreCase("solid");
    }

    private static boolean isText(byte[] d) {
        for (byte b : d) {
            int c = b & 0xff;
            if (c < 32 && c != '\t' && c != '\n' && c != '\r' && c != '\f') return false;
        }
        return true;
    }

    // ------------------------------------------------------------------ binary
    private static Result binary(String name, byte[] d, double scale) {
        if (d.length < HEADER_BYTES + 4) {
            throw MeshFileException.atByte(name, d.length, "the file ends inside the 84-byte header of a binary STL (" + d.length
                + " bytes; an ASCII STL starts with 'solid')");
        }
        long count = countAt(d);
        long expected = HEADER_BYTES + 4 + RECORD_BYTES * count;
        if (expected != d.length && !(expected <= PLAUSIBLE_SIZE_RATIO * d.length && d.length <= PLAUSIBLE_SIZE_RATIO * expected)) {
            // the four bytes at 80 are no triangle count of this file: it is not an STL, so none of its content is quoted
            throw MeshFileException.atByte(name, HEADER_BYTES, "not an STL file: not ASCII STL (text starting with 'solid') and its size, "
                + d.length + " bytes, is far from 84 + 50 × the triangle count a binary STL has at byte 80");
        }
        if (expected > d.length) {
            long inside = (d.length - HEADER_BYTES - 4) / RECORD_BYTES;
            throw MeshFileException.atByte(name, d.length, String.format(Locale.ROOT,
                "the file ends inside triangle %d of the %d the header announces at byte 80 (binary STL: 84 + 50 × %d = %d bytes expected, the file has %d): truncated",
                inside + 1, count, count, expected, d.length));
        }
        if (count > MeshLimits.MAX_TRIANGLES) {
            throw MeshFileException.atByte(name, HEADER_BYTES, count + " triangles, more than " + MeshLimits.TRIANGLE_LIMIT);
        }
        if (expected < d.length) {
            throw MeshFileException.atByte(name, expected, String.format(Locale.ROOT,
                "%d bytes after the last of the %d triangles the header announces at byte 80 (84 + 50 × %d = %d): a wrong triangle count or trailing data",
                d.length - expected, count, count, expected));
        }
        ByteBuffer b = ByteBuffer.wrap(d).order(ByteOrder.LITTLE_ENDIAN);
        Builder out = new Builder(name, scale, (int) count);
        double[] p = new double[9];
        for (int t = 0; t < count; t++) {
            int at = HEADER_BYTES + 4 + RECORD_BYTES * t + 12;
            for (int i = 0; i < 9; i++) {
                float f = b.getFloat(at + 4 * i);
                if (!Float.isFinite(f)) {
                    throw MeshFileException.atByte(name, at + 4 * i, String.format(Locale.ROOT, "triangle %d, vertex %d, %s coordinate is %s",
                        t + 1, i / 3 + 1, "xyz".charAt(i % 3), f));
                }
                p[i] = f;
            }
            out.triangle(p);
        }
        return out.result(true);
    }

    // ------------------------------------------------------------------ ASCII
    /** The ASCII form, token by token with line and column. */
    private static final class Ascii {
        private final String name;
        private final byte[] text;   // read as ISO-8859-1, byte by byte: no second copy of the file as a String
        private final Builder out;
        private int pos, line = 1, lineStart;
        private int tokLine, tokCol;
        private String tok;

        Ascii(String name, byte[] data, double scale) {
            this.name = name;
            this.text = data;
            this.out = new Builder(name, scale, Math.max(16, data.length / 250));
        }

        Result read() {
            double[] p = new double[9];
            next();
            while (tok != null) {
                expect("solid");
                restOfLine();
                next();
                while (tok != null && tok.equalsIgnoreCase("facet")) {
                    next();
                    expect("normal");
                    for (int i = 0; i < 3; i++) number("facet normal component");
                    next();
                    expect("outer");
                    next();
                    expect("loop");
                    for (int v = 0; v < 3; v++) {
                        next();
                        if (tok != null && tok.equalsIgnoreCase("endloop")) throw error("a facet needs 3 vertices, this one has " + v);
                        expect("vertex");
                        for (int i = 0; i < 3; i++) {
                            double x = number("vertex coordinate");
                            if (!Double.isFinite(x)) throw error("vertex coordinate is " + tok + ": not a finite number");
                            p[3 * v + i] = x;
                        }
                    }
                    next();
                    if (tok != null && tok.equalsIgnoreCase("vertex")) throw error("a facet has exactly 3 vertices (STL triangles), this one has more");
                    expect("endloop");
                    next();
                    expect("endfacet");
                    if (out.facets >= MeshLimits.MAX_TRIANGLES) throw error("more than " + MeshLimits.TRIANGLE_LIMIT);
                    out.triangle(p);
                    next();
                }
                expect("endsolid");
                restOfLine();
                next();
            }
            return out.result(false);
        }

        private void expect(String word) {
            if (tok == null) throw MeshFileException.at(name, line, pos - lineStart + 1, "the file ends where '" + word + "' was expected");
            if (!tok.equalsIgnoreCase(word)) throw error("expected '" + word + "', found '" + SafeText.quote(tok) + "'");
        }

        private double number(String what) {
            next();
            if (tok == null) throw MeshFileException.at(name, line, pos - lineStart + 1, "the file ends where a " + what + " was expected");
            try {
                return Double.parseDouble(tok);
            } catch (NumberFormatException e) {
                throw error(what + " '" + SafeText.quote(tok) + "' is not a number");
            }
        }

        private MeshFileException error(String message) {
            return MeshFileException.at(name, tokLine, tokCol, message);
        }

        /** Skips to the end of the line (the solid's name). */
        private void restOfLine() {
            while (pos < text.length && text[pos] != '\n') pos++;
        }

        /** The next whitespace-separated token, or null at the end. */
        private void next() {
            int n = text.length;
            while (pos < n) {
                char c = (char) (text[pos] & 0xff);
                if (c == '\n') {
                    line++;
                    lineStart = pos + 1;
                } else if (c != ' ' && c != '\t' && c != '\r' && c != '\f') {
                    break;
                }
                pos++;
            }
            if (pos >= n) {
                tok = null;
                return;
            }
            int s = pos;
            while (pos < n && !Character.isWhitespace((char) (text[pos] & 0xff))) pos++;
            tok = new String(text, s, pos - s, StandardCharsets.ISO_8859_1);
            tokLine = line;
            tokCol = s - lineStart + 1;
        }
    }

    // ------------------------------------------------------------------ mesh building
    /** Collects triangles, merging identical vertices, dropping zero-area triangles. */
    private static final class Builder {
        private final String name;
        private final double scale;
        private final Map<Vertex, Integer> index = new HashMap<>();
        private double[] v;
        private int[] tri;
        private int nv, nt, facets, degenerate;
        private final int[] corner = new int[3];
        private final double[] s = new double[9];

        private record Vertex(double x, double y, double z) {}

        Builder(String name, double scale, int expected) {
            this.name = name;
            this.scale = scale;
            v = new double[3 * Math.max(8, Math.min(expected, 1 << 16))];
            tri = new int[3 * Math.max(8, Math.min(expected, 1 << 16))];
        }

        /** One triangle; a degenerate one is counted before any of its corners is kept (a file of them holds no memory). */
        void triangle(double[] p) {
            facets++;
            for (int i = 0; i < 9; i++) s[i] = p[i] * scale + 0.0;   // + 0.0 turns −0 into +0
            double ux = s[3] - s[0], uy = s[4] - s[1], uz = s[5] - s[2];
            double wx = s[6] - s[0], wy = s[7] - s[1], wz = s[8] - s[2];
            double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
            if (!(cx * cx + cy * cy + cz * cz > 0)) {
                degenerate++;
                return;
            }
            for (int c = 0; c < 3; c++) corner[c] = vertex(s[3 * c], s[3 * c + 1], s[3 * c + 2]);
            if (3 * nt + 3 > tri.length) tri = Arrays.copyOf(tri, 2 * tri.length);
            tri[3 * nt] = corner[0];
            tri[3 * nt + 1] = corner[1];
            tri[3 * nt + 2] = corner[2];
            nt++;
        }

        private int vertex(double x, double y, double z) {
            Vertex key = new Vertex(x + 0.0, y + 0.0, z + 0.0);   // + 0.0 turns −0 into +0
            Integer i = index.get(key);
            if (i != null) return i;
            if (3 * nv + 3 > v.length) v = Arrays.copyOf(v, 2 * v.length);
            v[3 * nv] = key.x();
            v[3 * nv + 1] = key.y();
            v[3 * nv + 2] = key.z();
            index.put(key, nv);
            return nv++;
        }

        Result result(boolean binary) {
            // keep only the vertices a kept triangle uses (a degenerate triangle's own corners go)
            int[] map = new int[nv];
            Arrays.fill(map, -1);
            int used = 0;
            double[] kept = new double[3 * nv];
            int[] t = Arrays.copyOf(tri, 3 * nt);
            for (int i = 0; i < t.length; i++) {
                int o = t[i];
                if (map[o] < 0) {
                    map[o] = used;
                    System.arraycopy(v, 3 * o, kept, 3 * used, 3);
                    used++;
                }
                t[i] = map[o];
            }
            String label = name.contains("/") ? name.substring(name.lastIndexOf('/') + 1) : name;
            return new Result(new TriangleMesh(label, Arrays.copyOf(kept, 3 * used), t), binary, facets, degenerate);
        }
    }
}
