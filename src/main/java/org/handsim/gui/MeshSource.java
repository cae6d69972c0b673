package org.handsim.gui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.vrml.VrmlLoader;
import org.handsim.vrml.VrmlParseException;
import org.handsim.vrml.VrmlScene;
import org.jogamp.java3d.Appearance;
import org.jogamp.java3d.Group;
import org.jogamp.java3d.Link;
import org.jogamp.java3d.Material;
import org.jogamp.java3d.Node;
import org.jogamp.java3d.Shape3D;
import org.jogamp.vecmath.Color3f;

/**
 * Where the view gets its triangle meshes: the project's pipeline (DESIGN.md, "VRML file ⇒
 * VrmlLoader ⇒ Java3D BranchGroup ⇒ tessellation walk ⇒ TriangleMesh"), so the view shows the
 * very triangles the collision back end works on. The one place to change if the view should
 * show something else (e.g. the loader's BranchGroup with its own appearances).
 *
 * <p>Thread-safe (a new loader per call) and <b>never on the event dispatch thread</b>: the
 * loader works on a worker thread and waits for it, and the first Java3D use initialises JOGL,
 * which itself waits for the event dispatch thread — a deadlock if that thread is the one
 * waiting. {@link #load} fails fast there instead.
 */
public final class MeshSource {
    private MeshSource() {}

    /**
     * A mesh, its display colour and the loader's warnings.
     *
     * @param mesh     the whole file as one mesh, transforms applied, metres
     * @param colour   the first Material's diffuse colour (RGB in [0, 1]), or null when none
     * @param warnings what the loader found sloppy but usable
     */
    public record Model(TriangleMesh mesh, float[] colour, List<String> warnings) {}

    /**
     * Reads a VRML97 file into one triangle mesh (metres, the file's own frame).
     *
     * @throws IOException {@code FILE:LINE:COL: message} when the file cannot be loaded, or
     *                     naming the file when it holds no triangles
     */
    public static Model load(Path file) throws IOException {
        if (javax.swing.SwingUtilities.isEventDispatchThread()) {
            throw new IllegalStateException("MeshSource.load(" + file + ") called on the event dispatch thread (it would deadlock)");
        }
        VrmlScene scene;
        try {
            scene = new VrmlLoader().load(file);
        } catch (VrmlParseException e) {
            throw new IOException(e.getMessage(), e);
        }
        TriangleMesh mesh = new TessellationWalk().name(file.getFileName().toString()).run(scene.getSceneGroup()).merged();
        if (mesh.triangleCount() == 0) throw new IOException(file + ": no triangles (no surface geometry in the file)");
        return new Model(mesh, colour(scene.getSceneGroup()), List.copyOf(scene.warnings()));
    }

    /** The diffuse colour of the first Shape3D with a Material, depth first. */
    private static float[] colour(Node root) {
        Deque<Node> todo = new ArrayDeque<>();
        todo.push(root);
        while (!todo.isEmpty()) {
            Node n = todo.pop();
            if (n instanceof Shape3D) {
                Appearance a = ((Shape3D) n).getAppearance();
                Material m = a == null ? null : a.getMaterial();
                if (m != null) {
                    Color3f c = new Color3f();
                    m.getDiffuseColor(c);
                    return new float[] {c.x, c.y, c.z};
                }
            } else if (n instanceof Group) {
                Group g = (Group) n;
                for (int i = g.numChildren() - 1; i >= 0; i--) todo.push(g.getChild(i));
            } else if (n instanceof Link && ((Link) n).getSharedGroup() != null) {
                todo.push(((Link) n).getSharedGroup());
            }
        }
        return null;
    }
}
