package org.handsim.mesh;

import org.handsim.files.InputFile;
import org.handsim.text.SafeText;
import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
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
     * @param walk     the tessellation walk's result (meshes, shapes, degenerate triangles dropped)
     * @param vertices {@code v} statements in the file
     * @param faces    {@code f}/{@code fo} statements in the file
     */
    public record Result(TessellationWalk.Result walk, int vertices, int faces) {
        /** All triangles in one mesh. */
        public TriangleMesh mesh() { return walk.merged(); }
    }

    /**
     * Reads an OBJ file into triangles, coordinates multiplied by {@code scale}.
     *
     * @throws MeshFileException {@code FILE:LINE:COL: message}
     * @throws IOException       if the file cannot be read at all
     */
    public static Result read(Path file, double scale) throws IOException {
        byte[] b = InputFile.readBytes(file, MeshLimits.MAX_FILE_BYTES, MeshLimits.FILE_LIMIT);
        return read(file.toString(), new String(b, StandardCharsets.UTF_8), scale);
    }

    /** Reads OBJ text; {@code name} names it in messages and the mesh. */
    public static Result read(String name, String text, double scale) {
        Checked c = check(name, text);
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
        return new Result(r, c.vertices, c.faces);
    }

    /** The text as checked: counts, and the copy ObjectFile reads. */
    private record Checked(String normalised, int vertices, int faces) {}

    private static final List<String> KNOWN = List.of("v", "vn", "vt", "f", "fo", "l", "p", "g", "o", "s",
        "mtllib", "usemtl", "maplib", "usemap");
    private static final List<String> FREE_FORM = List.of("vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
        "parm", "trim", "hole", "scrv", "sp", "end", "con", "mg", "bevel", "c_interp", "d_interp", "lod", "shadow_obj",
        "trace_obj", "ctech", "stech");

    /** Checks every line; returns the counts and the normalised copy. */
    private static Checked check(String name, String text) {
        StringBuilder out = new StringBuilder(text.length());
        int nv = 0, nvt = 0, nvn = 0, faces = 0, groups = 0;
        long triangles = 0;
        boolean model = false;   // a known statement seen: the file is an OBJ file, its tokens may be quoted
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            int lineNo = i + 1;
            // join continuation lines (a backslash at the end), keeping the first line's number
            StringBuilder joined = new StringBuilder(strip(lines[i]));
            List<Integer> starts = new ArrayList<>();
            starts.add(0);
            while (joined.length() > 0 && joined.charAt(joined.length() - 1) == '\\' && i + 1 < lines.length) {
                joined.setLength(joined.length() - 1);
                joined.append(' ');
                i++;
                joined.append(strip(lines[i]));
            }
            String line = joined.toString();
            int hash = line.indexOf('#');
            if (hash >= 0) line = line.substring(0, hash);
            List<int[]> spans = tokens(line);
            if (spans.isEmpty()) {
                out.append('\n');
                continue;
            }
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
                    for (int t = 1; t <= n; t++) number(name, lineNo, line, spans.get(t), "vertex coordinate");
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
                    StringBuilder f = new StringBuilder(face ? "f" : "");
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
                        out.append(f).append('\n');
                    } else {
                        out.append('\n');
                    }
                    break;
                }
                case "o":
                case "g":
                    if (++groups > MeshLimits.MAX_SHAPES) {
                        throw MeshFileException.at(name, lineNo, 1, "more than " + MeshLimits.MAX_SHAPES + " groups (the limit of shapes per object file)");
                    }
                    out.append(n == 0 ? "g" : "g " + line.substring(spans.get(1)[0]).trim()).append('\n');
                    break;
                case "s":
                    out.append(line.trim()).append('\n');
                    break;
                default:   // materials and maps: not needed for geometry
                    out.append('\n');
            }
        }
        return new Checked(out.toString(), nv, faces);
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

    private static void number(String name, int lineNo, String line, int[] span, String what) {
        String s = line.substring(span[0], span[1]);
        if (!DECIMAL.matcher(s).matches()) {
            boolean nonFinite = s.toLowerCase(Locale.ROOT).matches("[-+]?(nan|inf|infinity)");
            throw MeshFileException.at(name, lineNo, span[0] + 1, what + " '" + SafeText.quote(s) + "' is not " + (nonFinite ? "a finite number" : "a number"));
        }
        if (!(Math.abs(Double.parseDouble(s)) <= Float.MAX_VALUE)) {
            throw MeshFileException.at(name, lineNo, span[0] + 1, what + " " + s + " is beyond the range of a float (Java3D stores coordinates as float)");
        }
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
