package org.handsim.gui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.ScenarioException;
import org.handsim.model.SceneGeometry;
import org.handsim.files.InputFile;
import org.handsim.scenario.SceneMeshes;

/**
 * Where the view gets its triangle meshes: {@link SceneMeshes#mesh}, the meshes the model
 * collides (VRML, OBJ or STL file ⇒ {@code scenario.MeshFiles} ⇒ TriangleMesh, DESIGN.md),
 * from the same cache — so the view shows exactly the triangles of the simulation, and a file
 * imported in the window is read once for both. The one place to change if the view should
 * show something else (e.g. the loader's BranchGroup with its own appearances).
 *
 * <p>Colour, for display only: the first {@code diffuseColor} written in a VRML file (plain text
 * files; none for gzip), the first {@code Kd} of an OBJ file's material library, else the
 * caller's default.
 *
 * <p>Thread-safe, and <b>never on the event dispatch thread</b>: the loader works on a worker
 * thread and waits for it, and the first Java3D use initialises JOGL, which itself waits for
 * the event dispatch thread — a deadlock if that thread is the one waiting. {@link #load}
 * fails fast there instead.
 */
public final class MeshSource {
    private MeshSource() {}

    private static final Pattern DIFFUSE = Pattern.compile("diffuseColor\\s+([-+0-9.eE]+)[\\s,]+([-+0-9.eE]+)[\\s,]+([-+0-9.eE]+)");

    /**
     * A mesh and its display colour.
     *
     * @param mesh   the whole file as one mesh, transforms applied, metres, unscaled
     * @param colour RGB in [0, 1], or null when the file names none
     */
    public record Model(TriangleMesh mesh, float[] colour) {}

    /**
     * Reads an object file (VRML97, OBJ, STL) into one triangle mesh (the file's own units and frame).
     *
     * @param divisions segments round Sphere, Cylinder and Cone nodes (the scenario's value)
     * @throws IOException {@code FILE:LINE:COL: message} when the file cannot be loaded
     */
    public static Model load(Path file, int divisions) throws IOException {
        if (javax.swing.SwingUtilities.isEventDispatchThread()) {
            throw new IllegalStateException("MeshSource.load(" + file + ") called on the event dispatch thread (it would deadlock)");
        }
        TriangleMesh mesh;
        try {
            mesh = SceneMeshes.mesh(file, divisions, 1.0);
        } catch (ScenarioException e) {
            throw new IOException(e.getMessage(), e);
        }
        return new Model(mesh, colour(file));
    }

    private static final Pattern MTLLIB = Pattern.compile("(?m)^\\s*mtllib\\s+(\\S+)");
    private static final Pattern KD = Pattern.compile("(?m)^\\s*Kd\\s+([-+0-9.eE]+)\\s+([-+0-9.eE]+)\\s+([-+0-9.eE]+)");

    /**
     * The first diffuseColor in a plain-text VRML file, or the first {@code Kd} of the material
     * library an OBJ file names ({@code mtllib}, beside it), or null (STL has no colour).
     */
    static float[] colour(Path file) {
        String name = file.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
        if (name.endsWith(".stl")) return null;
        if (name.endsWith(".obj")) {
            try {
                // heads only, regular files only (files.InputFile): an mtllib naming a FIFO or /dev/zero costs nothing
                Matcher lib = MTLLIB.matcher(new String(InputFile.head(file, SNIFF_BYTES), java.nio.charset.StandardCharsets.ISO_8859_1));
                if (!lib.find()) return null;
                Path mtl = file.toAbsolutePath().getParent().resolve(lib.group(1));
                Matcher kd = KD.matcher(new String(InputFile.head(mtl, SNIFF_BYTES), java.nio.charset.StandardCharsets.ISO_8859_1));
                return kd.find() ? rgb(kd) : null;
            } catch (RuntimeException e) {
                return null;
            }
        }
        try {
            byte[] head = InputFile.head(file, SNIFF_BYTES);
            if (head.length > 1 && (head[0] & 0xff) == 0x1f && (head[1] & 0xff) == 0x8b) return null;   // gzip
            Matcher m = DIFFUSE.matcher(new String(head, java.nio.charset.StandardCharsets.ISO_8859_1));
            return m.find() ? rgb(m) : null;
        } catch (InputFile.InputFileException | NumberFormatException e) {
            return null;
        }
    }

    /** Bytes of a file's head searched for its colour. */
    private static final int SNIFF_BYTES = 1 << 20;

    private static float[] rgb(Matcher m) {
        float[] c = new float[3];
        for (int i = 0; i < 3; i++) c[i] = Math.max(0f, Math.min(1f, Float.parseFloat(m.group(i + 1))));
        return c;
    }
}
