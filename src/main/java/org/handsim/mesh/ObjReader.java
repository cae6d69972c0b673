package org.handsim.mesh;

import org.handsim.files.InputFile;
import org.handsim.text.SafeText;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.loaders.Scene;
import org.jogamp.java3d.loaders.objectfile.ObjectFile;

/**
 * Wavefront OBJ files through Java3D's own loader, {@link ObjectFile} (java3d-utils): it builds
 * a {@link BranchGroup} that goes through the same {@link TessellationWalk} as a VRML scene (the
 * paper's path, Section III-B), so an OBJ object is collided exactly as its VRML twin would be.
 *
 * <h2>Strict, with line and column</h2>
 * {@code ObjectFile} reports few errors and without a place ("Unrecognized token, line 4";
 * "For input string: nan"), and an out-of-range face index makes it throw
 * {@code ArrayIndexOutOfBoundsException}. So the text is checked first, line by line, and every
 * error is a {@link MeshFileException} {@code FILE:LINE:COL: message}:
 * <ul>
 *   <li>statements: {@code v x y z [w]} (also {@code v x y z r g b}, vertex colours), {@code vn},
 *       {@code vt}, {@code f}/{@code fo} with at least three corners {@code v}, {@code v/t},
 *       {@code v//n} or {@code v/t/n}, {@code l}, {@code p}, {@code g}, {@code o}, {@code s},
 *       {@code mtllib}, {@code usemtl}, {@code maplib}, {@code usemap}, comments {@code #} and
 *       line continuations {@code \}; anything else (free-form curves and surfaces among them)
 *       is an error naming the statement;</li>
 *   <li>every number finite (no NaN, no infinity); every index an integer, not 0, and in range
 *       (negative indices count back from the last element defined so far, as the format says).</li>
 * </ul>
 * Then {@code ObjectFile} (flag {@code TRIANGULATE}: concave polygons are triangulated, not
 * fanned) reads a copy of the text with what it does not know or need rewritten: {@code o NAME}
 * becomes the equivalent {@code g NAME}; material and map statements and lines and points (no
 * area) are left out, so nothing else is read from disk — HandSim needs the geometry only.
 * Java3D keeps coordinates as {@code float}: values are rounded to float32 (about 7
 * significant digits).
 */
public final class ObjReader {
    private ObjReader() {}

    /**
     * What was read.
     *
     * @param walk       the tessellation walk's result (meshes, shapes, degenerate triangles dropped)
     * @param vertices   {@code v} statements in the file
     * @param faces      {@code f}/{@code fo} statements in the file
     * @param degenerate zero-area triangles dropped: those of faces dropped as the file was read
     *                   and those the walk dropped
     */
    public record Result(TessellationWalk.Result walk, int vertices, int faces, long degenerate) {
        /** All triangles in one mesh. */
        public TriangleMesh mesh() { return walk.merged(); }
    }

    /**
     * Reads an OBJ file into triangles, coordinates multiplied by {@code scale}. The file is read
     * a line at a time: what is kept is the checked copy of what ObjectFile needs, never the
     * whole text.
     *
     * @throws MeshFileException {@code FILE:LINE:COL: message}
     * @throws IOException       if the file cannot be read at all
     */
    public static Result read(Path file, double scale) throws IOException {
        InputFile.require(file);
        long size = Files.size(file);
        if (size > MeshLimits.MAX_FILE_BYTES) {
            throw new InputFile.InputFileException(file + ": is " + size + " bytes, more than " + MeshLimits.FILE_LIMIT + " ("
                + MeshLimits.MAX_FILE_BYTES + " bytes)");
        }
        Checked c;
        try (InputFile.Lines lines = new InputFile.Lines(file, MeshLimits.MAX_LINE_BYTES, false)) {
            c = check(file.toString(), lines::next);
        } catch (InputFile.InputFileException e) {   // a line too long: the reader's words, as the mesh readers say it
            throw new MeshFileException(e.getMessage(), e);
        }
        return build(file.toString(), c, scale);
    }

    /**
     * Reads the bytes of an OBJ file that the caller read through the input gate (the mesh
     * cache's key needs them first), a line at a time as {@link #read(Path, double)} reads the file.
     *
     * @throws MeshFileException {@code FILE:LINE:COL: message}
     */
    public static Result read(Path file, byte[] bytes, double scale) throws IOException {
        Checked c;
        try (InputFile.Lines lines = new InputFile.Lines(file.toString(), bytes, MeshLimits.MAX_LINE_BYTES, false)) {
            c = check(file.toString(), lines::next);
        } catch (InputFile.InputFileException e) {   // a line too long: the reader's words, as the mesh readers say it
            throw new MeshFileException(e.getMessage(), e);
        }
        return build(file.toString(), c, scale);
    }

    /** Reads OBJ text; {@code name} names it in messages and the mesh. */
    public static Result read(String name, String text, double scale) {
        int[] at = {0};
        Checked c;
        try {
            c = check(name, () -> {
                if (at[0] > text.length() || at[0] == text.length() && text.endsWith("\n")) return null;
                int end = text.indexOf('\n', at[0]);
                if (end < 0) end = text.length();
                String line = text.substring(at[0], end);
                at[0] = end + 1;
                return line;
            });
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);   // a string is never unreadable
        }
        return build(name, c, scale);
    }

    private static Result build(String name, Checked c, double scale) {
        BranchGroup group;
        try {
            Scene scene = new ObjectFile(ObjectFile.TRIANGULATE).load(new StringReader(c.normalised));
            group = scene.getSceneGroup();
        } catch (java.io.FileNotFoundException | RuntimeException e) {
            // the check above should leave nothing for ObjectFile to refuse; say so if it does
            throw new MeshFileException(name + ":1:1: Java3D's OBJ loader refused the file: " + e, e);
        }
        String label = name.contains("/") ? name.substring(name.lastIndexOf('/') + 1) : name;
        TessellationWalk.Result r;
        try {
            r = new TessellationWalk().scale(scale).name(label).run(group);
        } catch (IllegalStateException | IllegalArgumentException e) {
            throw new MeshFileException(name + ":1:1: " + e.getMessage(), e);
        }
        return new Result(r, c.vertices, c.faces, r.degenerate + c.dropped);
    }

    /** The next line of the text without its line end, or null at its end. */
    private interface LineSource {
        String next() throws IOException;
    }

    /** The text as checked: counts, the copy ObjectFile reads, and the triangles of faces dropped as degenerate. */
    private record Checked(String normalised, int vertices, int faces, long dropped) {}

    private static final List<String> KNOWN = List.of("v", "vn", "vt", "f", "fo", "l", "p", "g", "o", "s",
        "mtllib", "usemtl", "maplib", "usemap");
    private static final List<String> FREE_FORM = List.of("vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
        "parm", "trim", "hole", "scrv", "sp", "end", "con", "mg", "bevel", "c_interp", "d_interp", "lod", "shadow_obj",
        "trace_obj", "ctech", "stech");

    /**
     * Checks every line as it comes; returns the counts and the normalised copy. A face whose
     * triangles all have zero area — fewer than three distinct corner positions, or a triangle
     * whose corners are collinear as the tessellation walk computes it — is counted and dropped
     * here, so a file of millions of them holds no memory; the triangles it would have given are
     * the walk's degenerate ones, counted the same. The first face of each group is kept
     * whatever it is, so the groups give the same shapes as before.
     */
    private static Checked check(String name, LineSource lines) throws IOException {
        StringBuilder out = new StringBuilder();
        int nv = 0, nvt = 0, nvn = 0, faces = 0, groups = 0;
        long triangles = 0, dropped = 0;
        float[] pos = new float[3 * 1024];   // the vertices read so far, as float (as Java3D keeps them)
        boolean model = false;   // a known statement seen: the file is an OBJ file, its tokens may be quoted
        boolean groupHasFace = false;   // a face of the group since its g or o statement was kept
        int physical = 0;
        String next = lines.next();
        while (next != null) {
            physical++;
            int lineNo = physical;
            // join continuation lines (a backslash at the end), keeping the first line's number
            String line = strip(next);
            next = lines.next();
            if (line.endsWith("\\") && next != null) {
                StringBuilder joined = new StringBuilder(line);
                while (joined.length() > 0 && joined.charAt(joined.length() - 1) == '\\' && next != null) {
                    joined.setLength(joined.length() - 1);
                    joined.append(' ');
                    joined.append(strip(next));
                    physical++;
                    next = lines.next();
                    if (joined.length() > MeshLimits.MAX_LINE_BYTES) {
                        throw MeshFileException.at(name, lineNo, 1, "a statement longer than " + MeshLimits.MAX_LINE_BYTES
                            + " characters (the limit of OBJ lines)");
                    }
                }
                line = joined.toString();
            }
            int hash = line.indexOf('#');
            if (hash >= 0) line = line.substring(0, hash);
            List<int[]> spans = tokens(line);
            if (spans.isEmpty()) continue;
            String kw = line.substring(spans.get(0)[0], spans.get(0)[1]);
            String key = kw.toLowerCase(Locale.ROOT);
            int n = spans.size() - 1;
            if (!KNOWN.contains(key)) {
                if (!model && !FREE_FORM.contains(key)) {
                    // no OBJ statement yet: this is not an OBJ file, and nothing of it is quoted
                    throw MeshFileException.at(name, lineNo, spans.get(0)[0] + 1, "not a Wavefront OBJ file: its first statement is none of "
                        + String.join(", ", KNOWN));
                }
                if (FREE_FORM.contains(key)) {
                    throw MeshFileException.at(name, lineNo, spans.get(0)[0] + 1, "'" + kw
                        + "': free-form curves and surfaces are not supported: export the model as triangles or polygons");
                }
                throw MeshFileException.at(name, lineNo, spans.get(0)[0] + 1, "unknown statement '" + SafeText.quote(kw) + "' (known: "
                    + String.join(", ", KNOWN) + ")");
            }
            model = true;
            switch (key) {
                case "v":
                    if (n != 3 && n != 4 && n != 6 && n != 7) throw at(name, lineNo, line, spans, n, "a vertex needs x y z (and optionally w, or r g b), found " + n + " numbers");
                    if (3 * nv + 3 > pos.length) pos = Arrays.copyOf(pos, 2 * pos.length);
                    for (int t = 1; t <= n; t++) {
                        double x = number(name, lineNo, line, spans.get(t), "vertex coordinate");
                        if (t <= 3) pos[3 * nv + t - 1] = (float) x;
                    }
                    nv++;
                    out.append("v");
                    for (int t = 1; t <= 3; t++) out.append(' ').append(line, spans.get(t)[0], spans.get(t)[1]);
                    out.append('\n');
                    break;
                case "vn":
                    if (n != 3) throw at(name, lineNo, line, spans, n, "a normal needs 3 numbers, found " + n);
                    for (int t = 1; t <= n; t++) number(name, lineNo, line, spans.get(t), "normal component");
                    nvn++;
                    out.append(line).append('\n');
                    break;
                case "vt":
                    if (n < 1 || n > 3) throw at(name, lineNo, line, spans, n, "a texture coordinate needs 1 to 3 numbers, found " + n);
                    for (int t = 1; t <= n; t++) number(name, lineNo, line, spans.get(t), "texture coordinate");
                    nvt++;
                    out.append(line).append('\n');
                    break;
                case "f":
                case "fo":
                case "l":
                case "p": {
                    boolean face = key.startsWith("f");
                    int min = face ? 3 : key.equals("l") ? 2 : 1;
                    if (n < min) {
                        throw at(name, lineNo, line, spans, n, (face ? "a face needs at least 3 corners" : key.equals("l") ? "a line needs at least 2 points" : "a point statement needs a vertex") + ", found " + n);
                    }
                    if (face && n > MeshLimits.MAX_FACE_CORNERS) {
                        throw MeshFileException.at(name, lineNo, spans.get(MeshLimits.MAX_FACE_CORNERS + 1)[0] + 1, "a face of " + n
                            + " corners, more than " + MeshLimits.FACE_LIMIT);
                    }
                    StringBuilder f = new StringBuilder(face ? "f" : "");
                    int[] corners = new int[n];
                    for (int t = 1; t <= n; t++) {
                        int[] s = spans.get(t);
                        String ref = line.substring(s[0], s[1]);
                        String[] parts = ref.split("/", -1);
                        if (parts.length > 3 || parts[0].isEmpty()) {
                            throw MeshFileException.at(name, lineNo, s[0] + 1, "'" + SafeText.quote(ref) + "' is not a vertex reference (v, v/t, v//n or v/t/n)");
                        }
                        int[] counts = {nv, nvt, nvn};
                        String[] what = {"vertex", "texture coordinate", "normal"};
                        int col = s[0] + 1;
                        int[] resolved = new int[3];
                        for (int part = 0; part < parts.length; part++) {
                            if (part > 0 && parts[part].isEmpty()) {
                                col += 1;
                                continue;
                            }
                            resolved[part] = index(name, lineNo, col, parts[part], counts[part], what[part]);
                            col += parts[part].length() + 1;
                        }
                        corners[t - 1] = resolved[0] - 1;
                        if (face) {
                            // absolute indices: ObjectFile resolves negative ones differently in places
                            f.append(' ').append(resolved[0]);
                            if (parts.length > 1) f.append('/').append(parts[1].isEmpty() ? "" : String.valueOf(resolved[1]));
                            if (parts.length > 2) f.append('/').append(parts[2].isEmpty() ? "" : String.valueOf(resolved[2]));
                        }
                    }
                    if (face) {
                        faces++;
                        triangles += n - 2;
                        if (triangles > MeshLimits.MAX_TRIANGLES) throw MeshFileException.at(name, lineNo, 1, "more than " + MeshLimits.TRIANGLE_LIMIT);
                        // the first face of a group stays whatever it is: the group's shape is there as before
                        if (groupHasFace && degenerate(pos, corners)) {
                            dropped += n - 2;
                        } else {
                            out.append(f).append('\n');
                            groupHasFace = true;
                        }
                    }
                    break;
                }
                case "o":
                case "g":
                    if (++groups > MeshLimits.MAX_SHAPES) {
                        throw MeshFileException.at(name, lineNo, 1, "more than " + MeshLimits.MAX_SHAPES + " groups (the limit of shapes per object file)");
                    }
                    out.append(n == 0 ? "g" : "g " + line.substring(spans.get(1)[0]).trim()).append('\n');
                    groupHasFace = false;
                    break;
                case "s":
                    out.append(line.trim()).append('\n');
                    break;
                default:   // materials and maps: not needed for geometry
                    break;
            }
        }
        return new Checked(out.toString(), nv, faces, dropped);
    }

    /**
     * Whether every triangle of a face has zero area whatever the triangulation: fewer than three
     * distinct corner positions, or a triangle whose corners the tessellation walk's test finds
     * collinear in each of its three orders (so the walk would drop it in any).
     */
    static boolean degenerate(float[] pos, int[] corners) {
        int a = corners[0], b = -1, c = -1;
        for (int i = 1; i < corners.length && c < 0; i++) {
            int k = corners[i];
            if (same(pos, k, a) || b >= 0 && same(pos, k, b)) continue;
            if (b < 0) b = k; else c = k;
        }
        if (c < 0) return true;
        if (corners.length > 3) return false;
        return zeroArea(pos, a, b, c) && zeroArea(pos, b, c, a) && zeroArea(pos, c, a, b);
    }

    private static boolean same(float[] pos, int i, int j) {
        return pos[3 * i] == pos[3 * j] && pos[3 * i + 1] == pos[3 * j + 1] && pos[3 * i + 2] == pos[3 * j + 2];
    }

    /** {@link TessellationWalk}'s test: the cross product of the two edges from the first corner has no length. */
    private static boolean zeroArea(float[] p, int a, int b, int c) {
        double ux = (double) p[3 * b] - p[3 * a], uy = (double) p[3 * b + 1] - p[3 * a + 1], uz = (double) p[3 * b + 2] - p[3 * a + 2];
        double wx = (double) p[3 * c] - p[3 * a], wy = (double) p[3 * c + 1] - p[3 * a + 1], wz = (double) p[3 * c + 2] - p[3 * a + 2];
        double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
        return !(nx * nx + ny * ny + nz * nz > 0);
    }

    private static String strip(String s) {
        return s.endsWith("\r") ? s.substring(0, s.length() - 1) : s;
    }

    /** Start and end of each whitespace-separated token. */
    private static List<int[]> tokens(String line) {
        List<int[]> out = new ArrayList<>();
        int i = 0, n = line.length();
        while (i < n) {
            while (i < n && Character.isWhitespace(line.charAt(i))) i++;
            if (i >= n) break;
            int s = i;
            while (i < n && !Character.isWhitespace(line.charAt(i))) i++;
            out.add(new int[] {s, i});
        }
        return out;
    }

    private static MeshFileException at(String name, int lineNo, String line, List<int[]> spans, int n, String message) {
        int col = n + 1 < spans.size() ? spans.get(n + 1)[0] + 1 : spans.get(spans.size() - 1)[1] + 1;
        return MeshFileException.at(name, lineNo, Math.min(col, line.length() + 1), message);
    }

    private static final java.util.regex.Pattern DECIMAL = java.util.regex.Pattern.compile("[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");

    private static double number(String name, int lineNo, String line, int[] span, String what) {
        String s = line.substring(span[0], span[1]);
        if (!DECIMAL.matcher(s).matches()) {
            boolean nonFinite = s.toLowerCase(Locale.ROOT).matches("[-+]?(nan|inf|infinity)");
            throw MeshFileException.at(name, lineNo, span[0] + 1, what + " '" + SafeText.quote(s) + "' is not " + (nonFinite ? "a finite number" : "a number"));
        }
        double x = Double.parseDouble(s);
        if (!(Math.abs(x) <= Float.MAX_VALUE)) {
            throw MeshFileException.at(name, lineNo, span[0] + 1, what + " " + SafeText.quote(s) + " is beyond the range of a float (Java3D stores coordinates as float)");
        }
        return x;
    }

    /** A 1-based (or negative, relative) index resolved to 1-based, or an error at {@code col}. */
    private static int index(String name, int lineNo, int col, String s, int count, String what) {
        int i;
        try {
            i = Integer.parseInt(s);
        } catch (NumberFormatException e) {
            throw MeshFileException.at(name, lineNo, col, what + " index '" + SafeText.quote(s) + "' is not an integer");
        }
        if (i == 0) throw MeshFileException.at(name, lineNo, col, what + " index 0: OBJ indices start at 1 (negative ones count back)");
        int abs = i > 0 ? i : count + 1 + i;
        if (abs < 1 || abs > count) {
            String plural = what.equals("vertex") ? "vertices" : what + "s";
            throw MeshFileException.at(name, lineNo, col, what + " index " + i + " is out of range: " + count + " "
                + (count == 1 ? what : plural) + " defined so far");
        }
        return abs;
    }
}
