package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.math.RigidTransform;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Test;

/**
 * What a link/object pair costs (the model does no more than a scene needs): a link far from
 * the object costs one bounding-sphere test (no node, k-DOP or triangle test); a link whose
 * bounding sphere overlaps the object's but whose root k-DOP does not costs one k-DOP test; a
 * link in the object costs triangle tests and returns contacts.
 */
class SceneGeometryTest {
    private static SceneGeometry cube() {
        return new SceneGeometry(new Scenario.ObjectPlacement(Home.dir().resolve("vrml/objects/cube.wrl"),
            RigidTransform.IDENTITY, 1.0, 24), SceneGeometry.DEFAULT_K);
    }

    private static double[] linkAt(double x, double y, double z) {
        double[] w = new double[12];
        RigidTransform.fromPose(x, y, z, 0, 0, 0).copyTo(w, 0);
        return w;
    }

    @Test
    void farLinkCostsOneSphereTest() {
        SceneGeometry g = cube();
        ContactSet cs = new ContactSet();
        assertEquals(0, g.collide(1, 2, linkAt(1, 0, 0), cs));
        assertEquals(0, g.lastResult().nodeTests + g.lastResult().triangleTests);
        assertEquals(0, cs.size());
    }

    @Test
    void nearLinkOutsideTheRootKdopCostsOneKdopTest() {
        SceneGeometry g = cube();
        ContactSet cs = new ContactSet();
        // link 2 spans x in [-0.081, 0.009], |y| <= 0.011, |z| <= 0.0125 of its frame; the cube is [-0.03, 0.03]^3.
        // Placed at (0.03, 0.045, 0.046) its box clears the cube's faces by 4 mm (y) and 3.5 mm (z), while the
        // centres of the bounding spheres (radii 0.048 and 0.052) are 0.065 apart.
        assertEquals(0, g.collide(1, 2, linkAt(0.03, 0.045, 0.046), cs));
        assertEquals(1, g.lastResult().nodeTests, "one root-against-root test");
        assertEquals(0, g.lastResult().triangleTests);
    }

    /**
     * Temporal coherence changes no contact: link 2 closing on the cube in 0.05 mm steps (with a
     * slow turn), from 6 mm away to 2 mm deep and back out, queried by a coherent and a
     * non-coherent instance: every contact's point, normal and area equal bit for bit, and
     * {@code touches} is exactly "collide finds a contact". The coherent one walks the trees
     * far less often.
     */
    @Test
    void coherentQueriesGiveTheSameContactsWithFewerWalks() {
        SceneGeometry on = cube(), off = cube().coherent(false);
        ContactSet a = new ContactSet(), b = new ContactSet();
        int queries = 0, withContacts = 0;
        for (int s = -160; s <= 160; s++) {
            double depth = 0.002 - Math.abs(s) * 0.00005;          // -6 mm .. 2 mm .. -6 mm
            double[] w = new double[12];
            RigidTransform.fromPose(0.03 + 1e-5 * s, 0.001, 0.03 + 0.0125 - depth, 0.002 * s / 160, 0, 0.01 * s / 160).copyTo(w, 0);
            a.clear();
            b.clear();
            int na = on.collide(1, 2, w, a), nb = off.collide(1, 2, w, b);
            queries++;
            assertEquals(nb, na, "contacts at step " + s);
            if (na > 0) withContacts++;
            for (int i = 0; i < na; i++) {
                assertArrayEquals(b.point(i), a.point(i), "point " + i + " at step " + s);
                assertArrayEquals(b.normal(i), a.normal(i), "normal " + i + " at step " + s);
                assertEquals(b.area(i), a.area(i), "area " + i + " at step " + s);
            }
            assertEquals(na > 0, on.touches(1, 2, w), "touches at step " + s);
            assertEquals(na > 0, off.touches(1, 2, w), "touches (not coherent) at step " + s);
        }
        assertTrue(withContacts > 50 && withContacts < queries - 50, withContacts + " of " + queries);
        long walks = on.counter(SceneGeometry.Counter.TREE_WALKS), reused = on.counter(SceneGeometry.Counter.COHERENT_QUERIES);
        assertEquals(2L * queries, off.counter(SceneGeometry.Counter.TREE_WALKS) + off.counter(SceneGeometry.Counter.SPHERE_APART));
        assertTrue(walks * 5 < reused, walks + " walks, " + reused + " answered from near pairs");
    }

    /**
     * Scratch taken over from a retired instance changes no number: the mug grasp run on new
     * scratch, and again on scratch that first served the paper's cube experiment and then a
     * mug grasp (grown, its near pairs and hints left from those runs), records the same trace
     * bit for bit and the same collision counters; the retired instance refuses queries.
     */
    @Test
    void scratchTakenOverFromARetiredInstanceChangesNoNumber() {
        Scenario mug = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        Scenario cube = Scenario.load(Home.paperScenario());
        SceneGeometry fresh = new SceneGeometry(mug.object(), SceneGeometry.DEFAULT_K);
        HandModel a = new HandModel(mug, fresh, org.handsim.dynamics.HandDynamics.barrettHand()::inverseDynamics, true);
        a.run(null);
        SceneGeometry first = new SceneGeometry(cube.object(), SceneGeometry.DEFAULT_K);
        new HandModel(cube, first, org.handsim.dynamics.HandDynamics.barrettHand()::inverseDynamics, false).run(null);
        SceneGeometry second = new SceneGeometry(mug.object(), SceneGeometry.DEFAULT_K, first);
        new HandModel(mug, second, org.handsim.dynamics.HandDynamics.barrettHand()::inverseDynamics, false).run(null);
        SceneGeometry reused = new SceneGeometry(mug.object(), SceneGeometry.DEFAULT_K, second);
        HandModel b = new HandModel(mug, reused, org.handsim.dynamics.HandDynamics.barrettHand()::inverseDynamics, true);
        b.run(null);
        Recorder ra = a.recorder(), rb = b.recorder();
        assertEquals(ra.rows(), rb.rows());
        for (int row = 0; row < ra.rows(); row++) {
            for (int k = 1; k <= 3; k++) {
                for (int c = Recorder.Q; c <= Recorder.TAU3; c++) {
                    assertEquals(ra.get(k, c, row), rb.get(k, c, row), "finger " + k + " column " + c + " row " + row);
                }
                assertEquals(ra.force(k, row), rb.force(k, row), "force, finger " + k + " row " + row);
            }
        }
        assertEquals(fresh.counters(), reused.counters());
        assertTrue(fresh.counter(SceneGeometry.Counter.TREE_WALKS) > 0);
        assertThrows(IllegalStateException.class, () -> first.touches(1, 2, linkAt(0.03, 0, 0.04)));
        assertThrows(IllegalStateException.class, () -> second.collide(1, 2, linkAt(0.03, 0, 0.04), new ContactSet()));
        assertThrows(IllegalStateException.class, () -> new SceneGeometry(mug.object(), SceneGeometry.DEFAULT_K, first));
    }

    @Test
    void penetratingLinkCostsTriangleTestsAndGivesContacts() {
        SceneGeometry g = cube();
        ContactSet cs = new ContactSet();
        // link 2's bottom face (z = -0.0125) 2 mm inside the cube's top face z = 0.03
        int n = g.collide(1, 2, linkAt(0.03, 0, 0.03 + 0.0125 - 0.002), cs);
        assertTrue(n >= 1, "contacts " + n);
        assertTrue(g.lastResult().triangleTests > 0);
        double nz = cs.normal(0)[2];
        assertTrue(nz > 0.99, "the cube's top face pushes up: normal z " + nz);
    }

    /**
     * The shared meshes and trees are keyed by the placement's mesh scale (units × scale), not
     * its scale alone: the cube in metres and the same file in millimetres at scale 1 000 are
     * one mesh; in millimetres at scale 1 it is another, 1 000 times smaller (the 60 mm cube's
     * diagonal 60√3 mm, its thinnest width 60 mm, its centroid's reach 30√3 mm become µm-sized).
     */
    @Test
    void sharedGeometryIsKeyedByTheMeshScale() {
        java.nio.file.Path file = Home.dir().resolve("vrml/objects/cube.wrl");
        SceneGeometry metres = new SceneGeometry(new Scenario.ObjectPlacement(file, RigidTransform.IDENTITY, 1.0, 24), SceneGeometry.DEFAULT_K);
        SceneGeometry mmTimes1000 = new SceneGeometry(new Scenario.ObjectPlacement(file, RigidTransform.IDENTITY, 1000.0, 24,
            Scenario.Units.MM, null), SceneGeometry.DEFAULT_K);
        SceneGeometry mm = new SceneGeometry(new Scenario.ObjectPlacement(file, RigidTransform.IDENTITY, 1.0, 24,
            Scenario.Units.MM, null), SceneGeometry.DEFAULT_K);
        assertSame(metres.objectMesh(), mmTimes1000.objectMesh());
        assertSame(metres.objectTree(), mmTimes1000.objectTree());
        assertNotSame(metres.objectMesh(), mm.objectMesh());
        // the file's coordinates are single-precision floats: 0.03 to 1e-8
        assertEquals(0.06 * Math.sqrt(3), metres.objectMesh().diagonal(), 1e-7);
        assertEquals(0.06, metres.minThickness(), 1e-7);
        assertEquals(0.03 * Math.sqrt(3), metres.centroidAndRadius()[3], 1e-7);
        assertEquals(metres.objectMesh().diagonal() * 1e-3, mm.objectMesh().diagonal(), 1e-15);
        assertEquals(metres.minThickness() * 1e-3, mm.minThickness(), 1e-15);
        assertEquals(metres.centroidAndRadius()[3] * 1e-3, mm.centroidAndRadius()[3], 1e-15);
        assertSame(metres.linkTree(2), mm.linkTree(2), "the links' trees are shared by every scene");
    }
}
