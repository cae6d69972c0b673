package org.handsim.scenario;

import java.io.Reader;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.process.BoundedCache;
import org.handsim.process.CommandContext;
import org.handsim.vrml.VrmlLoader;
import org.handsim.vrml.VrmlScene;

/**
 * The meshes a scene is made of: an object's file (VRML97, OBJ or STL, {@link MeshFiles}) and the
 * hand's link and palm models ({@code vrml/hand/}), each loaded once per file, divisions and scale
 * and shared (immutable) through a bounded cache ({@link BoundedCache}, {@link #CACHE_TRIANGLES}),
 * however many threads ask.
 */
public final class SceneMeshes {
    private SceneMeshes() {}

    /** Divisions the hand's meshes (links and, in the window, the palm) are loaded at. */
    public static final int LINK_DIVISIONS = 32;

    /**
     * Bound of the mesh cache below and of the model's cache of shapes, in triangles (the weight of a mesh and of a shape): about
     * 60 bytes a triangle for a mesh, 250 for a shape (its mesh, its tree's nodes, placed
     * vertices and normals), so at most some 60 and 250 MB; the least recently used go first.
     */
    public static final long CACHE_TRIANGLES = 1_000_000;

    private static final BoundedCache<String, FileMesh> MESHES = new BoundedCache<>(CACHE_TRIANGLES, m -> m.mesh.triangleCount());

    /**
     * A cached mesh and the bytes of the file it was made from (null for a file whose mesh
     * depends on other files: VRML with Inline or EXTERNPROTO). A JVM that runs many commands
     * (the resident server) checks the file once per command ({@link CommandContext#generation()})
     * and makes the mesh again if the file has changed; a single command's JVM never needs to.
     */
    private static final class FileMesh {
        final Path file;
        final TriangleMesh mesh;
        final byte[] bytes;
        volatile long checked;

        FileMesh(Path file, TriangleMesh mesh, byte[] bytes, long checked) {
            this.file = file;
            this.mesh = mesh;
            this.bytes = bytes;
            this.checked = checked;
        }

        boolean unchanged() {
            long now = CommandContext.generation();
            if (checked == now) return true;
            if (bytes == null) return false;
            try {
                if (!java.util.Arrays.equals(read(file), bytes)) return false;
            } catch (RuntimeException e) {
                return false;   // gone, unreadable or too large now: load it again, and let the loader say why
            }
            checked = now;
            return true;
        }
    }

    /** The mesh file of link j (1..3) of every finger. */
    public static Path linkFile(int j) {
        return Home.handModels().resolve("finger_link" + j + ".wrl");
    }

    /** The palm's mesh file (palm frame). */
    public static Path palmFile() {
        return Home.handModels().resolve("palm.wrl");
    }

    /**
     * Loads (once per file, divisions and scale) an object's file — VRML97, OBJ or STL, by its
     * type ({@link MeshFiles}) — as one triangle mesh in metres, degenerate triangles dropped.
     *
     * @throws ScenarioException with the loader's {@code FILE:LINE:COL: message} (or
     *         {@code FILE: byte N: message} for binary STL)
     */
    public static TriangleMesh mesh(Path file, int divisions, double scale) {
        return MESHES.get(file.toAbsolutePath().normalize() + "|" + divisions + "|" + scale, FileMesh::unchanged, x -> {
            long generation = CommandContext.generation();
            byte[] bytes = read(file);
            TriangleMesh m = MeshCache.get(file, bytes, divisions, scale, () -> MeshFiles.load(file, bytes, divisions, scale).mesh());
            if (m.triangleCount() == 0) throw new ScenarioException(file + ":1:1: the file has no triangles to collide with");
            boolean alone;
            try {
                alone = MeshCache.selfContained(file, bytes);
            } catch (java.io.IOException e) {
                alone = false;
            }
            return new FileMesh(file, m, alone ? bytes : null, generation);
        }).mesh;
    }

    /** The files read in this command, newest last (at most {@link #READS_KEPT}). */
    private static final Map<Path, Read> READS = new LinkedHashMap<>();
    private static final int READS_KEPT = 4;

    private record Read(long generation, byte[] bytes) {}

    /**
     * The bytes of an object file, through the input gate ({@link MeshFiles#read}: the limit of
     * object files), read once per command: the meshes of one file at several scales (its units
     * judged at scale 1, then the scenario's) and the check that it has not changed share one read.
     */
    private static byte[] read(Path file) {
        Path key = file.toAbsolutePath().normalize();
        long generation = CommandContext.generation();
        synchronized (READS) {
            Read r = READS.get(key);
            if (r != null && r.generation == generation) return r.bytes;
        }
        byte[] b = MeshFiles.read(file);
        synchronized (READS) {
            READS.remove(key);
            READS.put(key, new Read(generation, b));
            for (java.util.Iterator<Path> i = READS.keySet().iterator(); READS.size() > READS_KEPT; ) {
                i.next();
                i.remove();
            }
        }
        return b;
    }

    /**
     * Loads VRML text the way {@link #mesh(Path, int, double)} loads a file, not cached (the
     * tradeoff studies' generated objects).
     *
     * @throws VrmlParseException naming {@code name}, line and column
     */
    public static TriangleMesh mesh(String name, Reader vrml, int divisions, double scale) {
        return walk(new VrmlLoader().divisions(divisions).normals(false).load(name, vrml), name, scale);
    }

    private static TriangleMesh walk(VrmlScene scene, String name, double scale) {
        return new TessellationWalk().scale(scale).name(name).run(scene.getSceneGroup()).merged();
    }
}
