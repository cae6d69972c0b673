package org.handsim.hold;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.body.MassProperties;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * The mass a fixed object gets when the hold test frees it, against values worked by hand: a
 * closed box at the default density (m = ρ·a·b·c, I = m/12·(b² + c²), …), the thin shell of a
 * cube's surface (I = 5/18·m·a² about every axis through its centre: two faces across the axis
 * at m/6·a²/6 each, four along it at m/6·(a²/12 + a²/4) each), and an open surface without a
 * mass refused naming the mesh and what to give.
 */
class ObjectMassTest {
    /** An axis-aligned box of sides a, b, c centred at the origin, outward faces (12 triangles). */
    static TriangleMesh box(String name, double a, double b, double c, boolean open) {
        double x = a / 2, y = b / 2, z = c / 2;
        double[] v = {-x, -y, -z, x, -y, -z, x, y, -z, -x, y, -z, -x, -y, z, x, -y, z, x, y, z, -x, y, z};
        int[] all = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
        int[] t = open ? java.util.Arrays.copyOf(all, all.length - 6) : all;   // open: without the −x face
        return new TriangleMesh(name, v, t);
    }

    @Test
    void aClosedBoxAtTheDefaultDensity() {
        MassProperties m = ObjectMass.of(box("box", 0.1, 0.06, 0.04, false), Double.NaN, Double.NaN);
        double mass = 1000 * 0.1 * 0.06 * 0.04;
        assertEquals(0.24, mass, 1e-15);
        assertEquals(mass, m.mass(), 1e-15);
        double[] in = m.inertia();
        assertEquals(mass / 12 * (0.06 * 0.06 + 0.04 * 0.04), in[0], 1e-15);
        assertEquals(mass / 12 * (0.1 * 0.1 + 0.04 * 0.04), in[4], 1e-15);
        assertEquals(mass / 12 * (0.1 * 0.1 + 0.06 * 0.06), in[8], 1e-15);
        assertEquals(0.5, ObjectMass.of(box("box", 0.1, 0.06, 0.04, false), 0.5, Double.NaN).mass(), 1e-15, "a given mass");
        assertEquals(0.24 * 2.5, ObjectMass.of(box("box", 0.1, 0.06, 0.04, false), Double.NaN, 2500).mass(), 1e-15, "a given density");
    }

    @Test
    void anOpenMeshWithAMassIsAThinShell() {
        double a = 0.08, mass = 0.3;
        // the whole surface of a cube as a shell: the formula by hand
        MassProperties closedShell = ObjectMass.shell(box("cube", a, a, a, false), mass);
        for (int i = 0; i < 3; i++) assertEquals(5.0 / 18 * mass * a * a, closedShell.inertia()[4 * i], 1e-15);
        for (double c : closedShell.centreOfMass()) assertEquals(0, c, 1e-15);
        // without its −x face: five faces of m/5, the centre of mass moved to +x by a/2 · (1/5), by hand
        MassProperties open = ObjectMass.of(box("open", a, a, a, true), mass, Double.NaN);
        assertEquals(mass, open.mass(), 1e-15);
        assertEquals(a / 2 / 5, open.centreOfMass()[0], 1e-15);
        // about x through the centre of mass: the +x face m/5·a²/6, four side faces m/5·(a²/12 + a²/4)
        assertEquals(mass / 5 * a * a / 6 + 4 * mass / 5 * (a * a / 12 + a * a / 4), open.inertia()[0], 1e-15);
    }

    @Test
    void anOpenMeshWithoutAMassIsRefusedNamingItAndWhatToGive() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> ObjectMass.of(box("lid.obj", 0.08, 0.08, 0.08, true), Double.NaN, Double.NaN));
        assertTrue(e.getMessage().startsWith("lid.obj: the surface is not closed"), e.getMessage());
        assertTrue(e.getMessage().contains("its mass cannot be known at the default density of 1000 kg/m³: give \"mass_kg\""), e.getMessage());
        IllegalArgumentException both = assertThrows(IllegalArgumentException.class,
            () -> ObjectMass.of(box("b", 0.1, 0.1, 0.1, false), 1, 1000));
        assertEquals("give the object's mass or its density, not both", both.getMessage());
    }
}
