/**
 * Collision detection between triangle meshes (paper Section IV, first step): which triangles
 * of two placed meshes intersect, and along which segments.
 *
 * <ul>
 *   <li>{@link org.handsim.collision.Kdop}: k-DOP bounding volumes, k = 6, 14, 18, 26, bounds in
 *       a {@code double[]} with a documented slot table;</li>
 *   <li>{@link org.handsim.collision.KdopTree}: a binary k-DOP hierarchy over a
 *       {@link org.handsim.mesh.TriangleMesh} on flat arrays (median or SAH split, refit);</li>
 *   <li>{@link org.handsim.collision.TreeQuery}: the walk between two trees with a rigid
 *       transform between them (B placed on demand or by refit), into a
 *       {@link org.handsim.collision.CollisionResult};</li>
 *   <li>{@link org.handsim.collision.TriangleIntersector}: Guigue–Devillers triangle–triangle
 *       intersection with segments, decided exactly by {@link org.handsim.collision.Predicates}
 *       (Shewchuk's filtered orientation predicates with an expansion-arithmetic fallback);</li>
 *   <li>{@link org.handsim.collision.BruteForce}: the all-pairs reference;</li>
 *   <li>{@link org.handsim.collision.NearPairs} and {@link org.handsim.collision.CoherentQuery}:
 *       temporal coherence for a query repeated as bodies move a little (the triangle pairs near
 *       at an anchor pose, the full query's result from them while the motion stays below their
 *       clearance).</li>
 * </ul>
 *
 * <p>Typical use (B placed in A's frame by {@code pose}; trees built once, query objects one per
 * thread, results reused):
 * <pre>
 * KdopTree a = KdopTree.build(meshA, 18), b = KdopTree.build(meshB, 18);
 * TreeQuery q = new TreeQuery();
 * CollisionResult r = new CollisionResult();
 * q.collide(a, b, pose, r);            // r.pairCount(), r.triangleA(i), r.segments(), counters
 * </pre>
 * Patches and point contacts are made from a result by {@code org.handsim.contact.ContactPatches}.
 *
 * <p>Units: metres; every array of coordinates is x, y, z per point. Allocates nothing per query once its buffers have grown.
 *
 * <p>May use {@code mesh} and {@code math} (docs/DESIGN.md, "Modules").
 */
package org.handsim.collision;
