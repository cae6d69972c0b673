package org.handsim.scenario;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.handsim.mesh.MeshFileException;
import org.handsim.mesh.MeshLimits;
import org.handsim.files.InputFile;
import org.handsim.mesh.ObjReader;
import org.handsim.mesh.StlReader;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.vrml.VrmlLoader;
import org.handsim.vrml.VrmlParseException;
import org.handsim.vrml.VrmlScene;

/**
 * The one place where an object's file becomes a triangle mesh, by its type: scenarios
 * ({@link SceneMeshes#mesh}), the window, {@code handsim mesh} and {@code collide}, and the
 * planner all load through here.
 * <ul>
 *   <li><b>VRML97</b> ({@code .wrl}, {@code .wrz}, gzip or plain; the default for any other
 *       name): {@code VrmlLoader} ⇒ Java3D BranchGroup ⇒ {@link TessellationWalk};</li>
 *   <li><b>Wavefront OBJ</b> ({@code .obj}): Java3D's {@code ObjectFile} ⇒ BranchGroup ⇒ the same
 *       walk ({@link ObjReader});</li>
 *   <li><b>STL</b> ({@code .stl}, ASCII or binary): our strict reader ({@link StlReader}).</li>
 * </ul>
 * Errors are one {@link ScenarioException} whose message starts with the place:
 * {@code FILE:LINE:COL: message} (VRML, OBJ, ASCII STL) or {@code FILE: byte N: message}
 * (binary STL); the commands exit with code 3 on it.
 */
public final class MeshFiles {
    private MeshFiles() {}

    /** The file types, by name. */
    public enum Format {
        VRML("VRML97"), OBJ("Wavefront OBJ"), STL("STL");

        private final String label;

        Format(String label) { this.label = label; }

        /** What users call it. */
        public String label() { return label; }

        /** The type of a file, by its name ({@code .obj}, {@code .stl}; anything else is VRML97). */
        public static Format of(Path file) {
            String n = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
            if (n.endsWith(".obj")) return OBJ;
            if (n.endsWith(".stl")) return STL;
            return VRML;
        }
    }

    /** File name extensions a file chooser offers (without the dot). */
    public static final List<String> EXTENSIONS = List.of("wrl", "wrz", "gz", "obj", "stl");

    /**
     * A loaded file.
     *
     * @param mesh       the whole file as one mesh (metres after {@code scale}), not welded, no degenerate triangles
     * @param format     its type
     * @param shapes     Shape3D instances with triangles (VRML, OBJ: each group), 1 for STL
     * @param degenerate zero-area triangles dropped
     * @param warnings   loader warnings, one line each ({@code FILE:LINE:COL: warning: ...})
     */
    public record Loaded(TriangleMesh mesh, Format format, int shapes, long degenerate, List<String> warnings) {}

    /**
     * Loads a file (not cached: {@link SceneMeshes#mesh} caches).
     *
     * @param divisions segments round VRML Sphere, Cylinder and Cone nodes (VRML only)
     * @param scale     multiplies every coordinate (positive, finite)
     * @throws ScenarioException {@code FILE:LINE:COL: message} or {@code FILE: byte N: message}
     */
    public static Loaded load(Path file, int divisions, double scale) {
        String why = NotFound.problem(file);   // a FIFO or device is refused before it is opened
        if (why != null) throw new ScenarioException(file + ":1:1: cannot read the file: " + why);   // the VRML loader's words
        String scaleWhy = MeshLimits.scaleProblem(scale);
        if (scaleWhy != null) throw new IllegalArgumentException("scale " + scaleWhy);
        Loaded loaded = loadChecked(file, divisions, scale);
        String far = MeshLimits.coordinateProblem(loaded.mesh());
        if (far != null) throw new ScenarioException(file + ":1:1: " + far);
        return loaded;
    }

    /**
     * The bytes of an object file through the input gate ({@link InputFile}, with the limit of
     * object files), for a caller that needs them before the mesh (the mesh cache's key) and then
     * loads from them ({@link #load(Path, byte[], int, double)}): the file is read once.
     *
     * @throws ScenarioException naming the file as {@link #load(Path, int, double)} would (a file
     *         over the limit, a FIFO or a device, a read error)
     */
    public static byte[] read(Path file) {
        String why = NotFound.problem(file);
        if (why != null) throw new ScenarioException(file + ":1:1: cannot read the file: " + why);
        try {
            return InputFile.readBytes(file, MeshLimits.MAX_FILE_BYTES, MeshLimits.FILE_LIMIT);
        } catch (InputFile.InputFileException e) {
            String m = e.getMessage(), at = file + ": ";
            // the VRML loader names the place as FILE:1:1, the OBJ and STL readers as FILE
            if (Format.of(file) == Format.VRML && m.startsWith(at)) m = file + ":1:1: " + m.substring(at.length());
            throw new ScenarioException(m, e);
        }
    }

    /**
     * Loads a file from its bytes, read by {@link #read}: the same result as
     * {@link #load(Path, int, double)}, without reading the file again.
     */
    public static Loaded load(Path file, byte[] bytes, int divisions, double scale) {
        String scaleWhy = MeshLimits.scaleProblem(scale);
        if (scaleWhy != null) throw new IllegalArgumentException("scale " + scaleWhy);
        Loaded loaded = loadChecked(file, bytes, divisions, scale);
        String far = MeshLimits.coordinateProblem(loaded.mesh());
        if (far != null) throw new ScenarioException(file + ":1:1: " + far);
        return loaded;
    }

    private static Loaded loadChecked(Path file, int divisions, double scale) {
        return loadChecked(file, null, divisions, scale);
    }

    /** {@code bytes}: the file's, already read, or null to read it here. */
    private static Loaded loadChecked(Path file, byte[] bytes, int divisions, double scale) {
        String label = file.getFileName().toString();
        Format f = Format.of(file);
        try {
            switch (f) {
                case OBJ: {
                    ObjReader.Result r = bytes == null ? ObjReader.read(file, scale) : ObjReader.read(file, bytes, scale);
                    return new Loaded(r.mesh(), f, r.walk().shapes, r.degenerate(), List.of());
                }
                case STL: {
                    StlReader.Result r = bytes == null ? StlReader.read(file, scale) : StlReader.read(file.toString(), bytes, scale);
                    return new Loaded(r.mesh(), f, 1, r.degenerate(), List.of());
                }
                default: {
                    VrmlLoader loader = new VrmlLoader().divisions(divisions).normals(false);
                    VrmlScene scene = bytes == null ? loader.load(file) : loader.load(file, bytes);
                    TessellationWalk.Result r;
                    try {
                        r = new TessellationWalk().scale(scale).name(label).run(scene.getSceneGroup());
                    } catch (IllegalStateException | IllegalArgumentException e) {
                        throw new ScenarioException(file + ":1:1: " + e.getMessage(), e);
                    }
                    return new Loaded(r.merged(), f, r.shapes, r.degenerate, scene.warnings());
                }
            }
        } catch (VrmlParseException | MeshFileException e) {
            throw new ScenarioException(e.getMessage(), e);
        } catch (IOException e) {
            throw new ScenarioException(file + ":1:1: cannot read the file: " + e.getMessage(), e);
        } catch (InputFile.InputFileException e) {   // too large, or changed since the check
            throw new ScenarioException(e.getMessage(), e);
        }
    }
}
