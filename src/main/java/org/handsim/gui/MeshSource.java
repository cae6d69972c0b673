package org.handsim.gui;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.mesh.TriangleMesh;

/**
 * Where the view gets its triangle meshes: the one place to change when the project's VRML
 * loader and tessellation walk ({@code org.handsim.vrml}, {@code org.handsim.mesh}) or the
 * model's {@code sim.SceneGeometry} take over (DESIGN.md: "VRML file ⇒ VrmlLoader ⇒ Java3D
 * BranchGroup ⇒ tessellation walk ⇒ TriangleMesh").
 *
 * <p><b>Interim reader.</b> Until then {@link #load(Path)} reads the subset of VRML97 that
 * HandSim's own generated models use ({@code vrml/README.md}, "Conventions of every file"):
 * every {@code Coordinate { point [...] }} followed by its {@code coordIndex [...]} (polygons
 * are fanned into triangles), and the first {@code diffuseColor} as the colour. It applies no
 * {@code Transform}s and reads no {@code Inline}s, so a general VRML97 file may appear wrong;
 * a file with no {@code IndexedFaceSet} at all is an error naming the file. Pure and
 * thread-safe: call it off the event dispatch thread for big files.
 */
public final class MeshSource {
    private MeshSource() {}

    /** A mesh and its display colour (RGB in [0, 1], null when the file names none). */
    public record Model(TriangleMesh mesh, float[] colour) {}

    /**
     * Reads a VRML97 file into one triangle mesh (metres, the file's own frame).
     *
     * @throws IOException naming the file and, for a syntax problem, the token
     */
    public static Model load(Path file) throws IOException {
        String text = Files.readString(file);
        if (!text.startsWith("#VRML V2.0")) {
            throw new IOException(file + ": not a VRML97 file (the first line must start with '#VRML V2.0')");
        }
        String src = stripComments(text);
        List<TriangleMesh> parts = new ArrayList<>();
        int at = 0;
        while (true) {
            int c = src.indexOf("Coordinate", at);
            if (c < 0) break;
            int p = src.indexOf("point", c);
            double[] points = numbers(file, src, p, "point");
            int ci = src.indexOf("coordIndex", c);
            if (ci < 0) throw new IOException(file + ": a Coordinate node without a coordIndex");
            double[] idx = numbers(file, src, ci, "coordIndex");
            parts.add(new TriangleMesh(file.getFileName().toString(), points, fan(file, idx, points.length / 3)));
            at = ci + 10;
        }
        if (parts.isEmpty()) throw new IOException(file + ": no IndexedFaceSet with coordinates found");
        TriangleMesh mesh = parts.size() == 1 ? parts.get(0) : TriangleMesh.concat(file.getFileName().toString(), parts);
        return new Model(mesh.withoutDegenerate(), colour(src));
    }

    private static String stripComments(String text) {
        StringBuilder sb = new StringBuilder(text.length());
        boolean inString = false, inComment = false;
        for (int i = 0; i < text.length(); i++) {
            char ch = text.charAt(i);
            if (inComment) {
                if (ch == '\n' || ch == '\r') { inComment = false; sb.append(ch); }
                continue;
            }
            if (ch == '"') inString = !inString;
            if (ch == '#' && !inString) { inComment = true; continue; }
            sb.append(ch);
        }
        return sb.toString();
    }

    /** The numbers inside the first [...] after {@code from} (commas are white space in VRML). */
    private static double[] numbers(Path file, String src, int from, String field) throws IOException {
        int open = src.indexOf('[', from), close = open < 0 ? -1 : src.indexOf(']', open);
        if (from < 0 || open < 0 || close < 0) throw new IOException(file + ": field " + field + ": missing [ ... ]");
        String[] tok = src.substring(open + 1, close).trim().split("[\\s,]+");
        if (tok.length == 1 && tok[0].isEmpty()) return new double[0];
        double[] out = new double[tok.length];
        for (int i = 0; i < tok.length; i++) {
            try {
                out[i] = Double.parseDouble(tok[i]);
            } catch (NumberFormatException e) {
                throw new IOException(file + ": field " + field + ": '" + tok[i] + "' is not a number");
            }
        }
        if (field.equals("point") && out.length % 3 != 0) {
            throw new IOException(file + ": field point: " + out.length + " numbers is not a multiple of 3");
        }
        return out;
    }

    private static int[] fan(Path file, double[] idx, int vertexCount) throws IOException {
        List<Integer> tri = new ArrayList<>();
        List<Integer> poly = new ArrayList<>();
        for (int i = 0; i <= idx.length; i++) {
            int v = i < idx.length ? (int) idx[i] : -1;
            if (v < 0) {
                for (int k = 1; k + 1 < poly.size(); k++) {
                    tri.add(poly.get(0));
                    tri.add(poly.get(k));
                    tri.add(poly.get(k + 1));
                }
                poly.clear();
            } else {
                if (v >= vertexCount) throw new IOException(file + ": coordIndex " + v + " outside [0, " + vertexCount + ")");
                poly.add(v);
            }
        }
        int[] out = new int[tri.size()];
        for (int i = 0; i < out.length; i++) out[i] = tri.get(i);
        return out;
    }

    private static float[] colour(String src) {
        int d = src.indexOf("diffuseColor");
        if (d < 0) return null;
        String[] tok = src.substring(d + "diffuseColor".length()).trim().split("[\\s,]+", 4);
        try {
            return new float[] {Float.parseFloat(tok[0]), Float.parseFloat(tok[1]), Float.parseFloat(tok[2])};
        } catch (RuntimeException e) {
            return null;
        }
    }
}
