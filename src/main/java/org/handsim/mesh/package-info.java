/**
 * Triangle meshes for collision and contact (paper Section III-B): {@link
 * org.handsim.mesh.TriangleMesh} on primitive arrays, the {@link org.handsim.mesh.TessellationWalk}
 * that takes a Java3D scene graph (as built by {@code org.handsim.vrml.VrmlLoader}, or by hand from
 * Java3D primitives) apart into meshes with every transform applied, {@link
 * org.handsim.mesh.MeshWelder} to merge coincident vertices, and {@link org.handsim.mesh.ObjWriter}
 * for Wavefront OBJ output.
 *
 * <p>Units: metres (the walk's {@code scale} converts files in other units). Orientation:
 * counter-clockwise seen from outside, so normals point out and the signed volume of a closed
 * mesh is positive.
 *
 * <p>May use {@code files}, {@code math} and {@code text} (and Java3D; docs/DESIGN.md, "Modules").
 */
package org.handsim.mesh;
