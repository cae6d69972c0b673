/**
 * HandSim's VRML97 loader for Java3D (paper Section III: objects and hand links come from
 * VRML97 files). No maintained VRML97 loader for Java3D 1.7 exists, so this one is ours.
 *
 * <p>Entry point: {@link org.handsim.vrml.VrmlLoader} (a Java3D
 * {@link org.jogamp.java3d.loaders.Loader}); result: {@link org.handsim.vrml.VrmlScene} (a Java3D
 * {@link org.jogamp.java3d.loaders.Scene} with warnings); the only error:
 * {@link org.handsim.vrml.VrmlParseException} ({@code FILE:LINE:COL: message}). Triangles are
 * taken out of the scene by {@code org.handsim.mesh.TessellationWalk}.
 *
 * <p>Inside: {@code VrmlText} (bytes, gzip, header, positions) ⇒ {@code VrmlLexer} (tokens on a
 * byte buffer, hand-written number parsing) ⇒ {@code VrmlParser} (grammar, DEF/USE scopes,
 * PROTO/EXTERNPROTO, {@code Builtins} = the 54 node interfaces of ISO/IEC 14772-1 clause 6) ⇒
 * {@code ProtoExpander} ⇒ {@code SceneBuilder} (Java3D nodes), {@code GeometryBuilder}
 * (IndexedFaceSet with {@code FaceTriangulator} ear clipping, ElevationGrid, Extrusion),
 * {@code Primitives} (Box, Sphere, Cylinder, Cone with a resolution), {@code Normals}.
 *
 * <p>Reference: ISO/IEC 14772-1:1997, "The Virtual Reality Modeling Language", Part 1
 * (clauses 4 concepts, 5 field types, 6 nodes, Annex A grammar).
 *
 * <p>May use {@code mesh}, {@code files} and {@code text} (and Java3D; docs/DESIGN.md, "Modules").
 */
package org.handsim.vrml;
