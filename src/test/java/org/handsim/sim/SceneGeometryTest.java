package org.handsim.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.math.RigidTransform;
import org.junit.jupiter.api.Test;

/**
 * What a link/object pair costs (issue 8, "model no more than a scene needs"): a link far from
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
        assertEquals(0, g.lastResult().nodeTests + g.lastResult().kdopTests + g.lastResult().triangleTests);
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
        assertEquals(1, g.lastResult().kdopTests, "one root-against-root test");
        assertEquals(0, g.lastResult().triangleTests);
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
}
