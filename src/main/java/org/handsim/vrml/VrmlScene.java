package org.handsim.vrml;

import java.util.Collections;
import java.util.List;
import org.jogamp.java3d.loaders.SceneBase;

/**
 * What {@link VrmlLoader} returns: Java3D's {@link SceneBase} (scene group, DEF names in
 * {@link #getNamedObjects()}, view groups, lights, backgrounds, fogs, description) plus what a
 * geometry pipeline wants to know about the load.
 *
 * <ul>
 *   <li>{@link #warnings()}: every warning, one line each, {@code FILE:LINE:COL: warning: ...}
 *       (unknown fields skipped, missing textures, unresolved EXTERNPROTOs, faces with fewer
 *       than three vertices, ...). Warnings never stop a load; callers print them.</li>
 *   <li>{@link #files()}: the files read, top file first, then Inline and EXTERNPROTO files,
 *       each once.</li>
 *   <li>{@link #writtenIfsTriangles()}: IndexedFaceSet triangles as written, Σ(n−2) over the
 *       faces of every IndexedFaceSet in every file read, counted once per node in the text
 *       (not per USE or PROTO instance) — the convention of the corpus manifest, useful to
 *       check a load against an independent count.</li>
 * </ul>
 *
 * <p>DEF names of the top-level file map to the Java3D object built for the node (a
 * TransformGroup, Group, Switch, Shape3D, Appearance, Material or Geometry). DEF names also
 * become the {@link org.jogamp.java3d.SceneGraphObject#setName name} of scene-graph nodes, in
 * every file, which is how the tessellation walk groups triangles into named parts.
 */
public final class VrmlScene extends SceneBase {
    private List<String> warnings = List.of();
    private List<String> files = List.of();
    private long writtenIfsTriangles;

    VrmlScene() {}

    void finish(List<String> warnings, List<String> files, long ifsTriangles) {
        this.warnings = Collections.unmodifiableList(warnings);
        this.files = Collections.unmodifiableList(files);
        this.writtenIfsTriangles = ifsTriangles;
    }

    /** Warnings, {@code FILE:LINE:COL: warning: message} each, in the order met. */
    public List<String> warnings() { return warnings; }

    /** Files read (top file first). */
    public List<String> files() { return files; }

    /** IndexedFaceSet triangles as written (n-gon = n−2), summed over the files read. */
    public long writtenIfsTriangles() { return writtenIfsTriangles; }
}
