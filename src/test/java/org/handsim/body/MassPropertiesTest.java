package org.handsim.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.collision.TestMeshes;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/** {@link MassProperties}: boxes integrated by hand, how the tensor moves with the body, and every refusal. */
class MassPropertiesTest {
    /** The class comment's worked example: a 0.1 × 0.06 × 0.04 m box of 1000 kg/m³, I = m/12·(b² + c²) about each axis. */
    @Test
    void aBoxAsIntegratedByHand() {
        for (int div = 1; div <= 3; div++) {
            MassProperties p = MassProperties.ofSolid(TestMeshes.box(0.05, 0.03, 0.02, div), 1000);
            assertEquals(0.24, p.mass(), 1e-15);
            assertEquals(2.4e-4, p.volume(), 1e-18);
            double[] in = p.inertia();
            double[] want = {1.04e-4, 0, 0, 0, 2.32e-4, 0, 0, 0, 2.72e-4};
            for (int i = 0; i < 9; i++) assertEquals(want[i], in[i], 1e-17, "entry " + i + ", div " + div);
            for (double c : p.centreOfMass()) assertEquals(0, c, 1e-17);
        }
    }

    /**
     * The box moved by (t, R): the centre of mass moves to R·0 + t and the tensor about it turns
     * to R·I·Rᵀ (nothing of the shift may remain: the parallel-axis step must undo it; 2e-12
     * relative is the rounding of m|c|² = 120 × I).
     * The mass given instead of the density scales the tensor.
     */
    @Test
    void theTensorTurnsAndMovesWithTheBody() {
        RigidTransform t = RigidTransform.fromPose(0.3, -0.2, 0.15, 0.4, -0.7, 1.1);
        TriangleMesh moved = TestMeshes.box(0.05, 0.03, 0.02, 2).transformed(t);
        MassProperties p = MassProperties.ofSolidWithMass(moved, 0.48);
        assertEquals(0.48, p.mass(), 1e-15);
        double[] c = p.centreOfMass();
        assertEquals(0.3, c[0], 1e-15);
        assertEquals(-0.2, c[1], 1e-15);
        assertEquals(0.15, c[2], 1e-15);
        double[] d = {2.08e-4, 4.64e-4, 5.44e-4};
        double[] in = p.inertia();
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double want = 0;
                for (int k = 0; k < 3; k++) want += t.get(i, k) * d[k] * t.get(j, k);
                assertEquals(want, in[3 * i + j], 1e-15, "I[" + i + "][" + j + "]");
            }
        }
        double[] pm = p.principalMoments();
        for (int k = 0; k < 3; k++) assertEquals(d[k], pm[k], 1e-15);
    }

    /** A grid is open: refused, naming the mesh and the fields to give instead. */
    @Test
    void anOpenMeshIsRefusedNamingWhatToAdd() {
        TriangleMesh open = TestMeshes.grid(0.05, 4);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MassProperties.ofSolid(open, 1000));
        assertTrue(e.getMessage().startsWith(open.name() + ": the surface is not closed (16 edges"), e.getMessage());
        assertTrue(e.getMessage().contains("give \"mass_kg\" and \"inertia_kg_m2\""), e.getMessage());
    }

    /** Two triangles back to back close up (every edge used twice, once each way) around no volume. */
    @Test
    void aClosedSurfaceAroundNoVolumeIsRefused() {
        TriangleMesh flat = new TriangleMesh("flat.stl", new double[] {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0}, new int[] {0, 1, 2, 0, 2, 1});
        assertTrue(flat.isClosed());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MassProperties.ofSolid(flat, 1000));
        assertTrue(e.getMessage().startsWith("flat.stl: the closed surface encloses no volume"), e.getMessage());
        assertTrue(e.getMessage().contains("give \"mass_kg\""), e.getMessage());
    }

    /** A box with its triangles turned inside out bounds a negative volume: refused, saying so. */
    @Test
    void inwardFacesAreRefused() {
        TriangleMesh box = TestMeshes.box(0.05, 0.03, 0.02, 1);
        int[] t = box.triangles().clone();
        for (int i = 0; i < t.length; i += 3) { int s = t[i + 1]; t[i + 1] = t[i + 2]; t[i + 2] = s; }
        TriangleMesh inside = new TriangleMesh("inside.obj", box.vertices().clone(), t);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MassProperties.ofSolid(inside, 1000));
        assertTrue(e.getMessage().startsWith("inside.obj: the surface's triangles face inwards"), e.getMessage());
    }

    @Test
    void givenPropertiesThatAreNoBodyAreRefusedNamingTheField() {
        double[] com = {0, 0, 0};
        double[] ok = {1e-4, 0, 0, 0, 2e-4, 0, 0, 0, 2.5e-4};
        assertEquals(0.1, MassProperties.of(0.1, com, ok).mass());
        message("mass_kg must be a finite number above 0, got 0", () -> MassProperties.of(0, com, ok));
        message("mass_kg must be a finite number above 0, got -1", () -> MassProperties.of(-1, com, ok));
        message("mass_kg must be a finite number above 0, got NaN", () -> MassProperties.of(Double.NaN, com, ok));
        message("com_m[1] must be a finite number, got Infinity", () -> MassProperties.of(0.1, new double[] {0, Double.POSITIVE_INFINITY, 0}, ok));
        message("inertia_kg_m2[1][1] must be a finite number, got NaN",
            () -> MassProperties.of(0.1, com, new double[] {1e-4, 0, 0, 0, Double.NaN, 0, 0, 0, 1e-4}));
        message("inertia_kg_m2 must be symmetric: [0][1] = 0.00001 but [1][0] = 0",
            () -> MassProperties.of(0.1, com, new double[] {1e-4, 1e-5, 0, 0, 1e-4, 0, 0, 0, 1e-4}));
        message("inertia_kg_m2 must be positive definite (principal moments -0.00001, 0.0001, 0.0001 kg·m²)",
            () -> MassProperties.of(0.1, com, new double[] {-1e-5, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4}));
        // positive definite but no body: a "rod" whose largest moment exceeds the other two together
        message("inertia_kg_m2 breaks the triangle inequality: the two smaller principal moments must add up to at least the largest"
            + " (principal moments 0.0001, 0.0001, 0.0003 kg·m²); no body has such an inertia",
            () -> MassProperties.of(0.1, com, new double[] {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 3e-4}));
        // a thin plate is the limit (I1 + I2 = I3) and is accepted
        assertEquals(0.1, MassProperties.of(0.1, com, new double[] {1e-4, 0, 0, 0, 2e-4, 0, 0, 0, 3e-4}).mass());
        message("density_kg_m3 must be a finite number above 0, got 0", () -> MassProperties.ofSolid(TestMeshes.box(0.1, 0.1, 0.1, 1), 0));
    }

    private static void message(String want, Runnable r) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, r::run);
        assertEquals(want, e.getMessage());
    }
}
