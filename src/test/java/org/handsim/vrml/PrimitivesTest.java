package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.handsim.mesh.MeshWelder;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * Box, Sphere, Cylinder and Cone through the public path (VRML text ⇒ VrmlLoader ⇒ BranchGroup
 * ⇒ TessellationWalk ⇒ TriangleMesh) against their analytic area and volume. The curved ones
 * are inscribed polyhedra: the error must shrink as {@code divisions} doubles, by a factor close
 * to 4 (second order, as the inscribed n-gon's area πr²(1 − 2π²/(3n²) + ...)), which makes
 * the tessellation's order a test rather than a claim (docs/STYLE.md, item 11).
 */
class PrimitivesTest {
    private static final int[] DIVISIONS = {8, 16, 32, 64, 128, 256};

    private static TriangleMesh primitive(String geometry, int divisions) {
        VrmlScene s = VrmlTesting.load(new VrmlLoader().divisions(divisions), "Shape { geometry " + geometry + " }");
        TriangleMesh m = new TessellationWalk().run(s.getSceneGroup()).merged();
        assertTrue(m.isClosed(), geometry + " is closed as built (shared vertices)");
        assertEquals(0, m.degenerateCount());
        return m;
    }

    /** Relative errors of area and volume per division count; checks closedness, order and final accuracy. */
    private static void converges(String name, String geometry, double area, double volume) {
        double[] ea = new double[DIVISIONS.length], ev = new double[DIVISIONS.length];
        StringBuilder report = new StringBuilder(name + " (relative error area / volume):");
        for (int i = 0; i < DIVISIONS.length; i++) {
            TriangleMesh m = primitive(geometry, DIVISIONS[i]);
            ea[i] = Math.abs(m.area() - area) / area;
            ev[i] = Math.abs(m.signedVolume() - volume) / volume;
            assertTrue(m.signedVolume() > 0, "outward orientation");
            assertTrue(m.area() < area && m.signedVolume() < volume, "inscribed: below the analytic values");
            report.append(String.format(Locale.ROOT, " n=%d %.2e/%.2e", DIVISIONS[i], ea[i], ev[i]));
        }
        System.out.println(report);
        for (int i = 1; i < DIVISIONS.length; i++) {
            assertTrue(ea[i] < ea[i - 1] && ev[i] < ev[i - 1], name + ": error shrinks with divisions (" + report + ")");
            if (DIVISIONS[i] >= 32) {
                double ra = ea[i - 1] / ea[i], rv = ev[i - 1] / ev[i];
                assertTrue(ra > 3.5 && ra < 4.5, name + ": second-order area convergence, ratio " + ra);
                assertTrue(rv > 3.5 && rv < 4.5, name + ": second-order volume convergence, ratio " + rv);
            }
        }
        assertTrue(ea[DIVISIONS.length - 1] < 1e-3 && ev[DIVISIONS.length - 1] < 1e-3, name + " at n=256 within 0.1%");
    }

    @Test
    void sphereConverges() {
        double r = 0.05;
        converges("Sphere", "Sphere { radius 0.05 }", 4 * Math.PI * r * r, 4.0 / 3 * Math.PI * r * r * r);
    }

    @Test
    void cylinderConverges() {
        double r = 0.03, h = 0.1;
        converges("Cylinder", "Cylinder { radius 0.03 height 0.1 }", 2 * Math.PI * r * r + 2 * Math.PI * r * h, Math.PI * r * r * h);
    }

    @Test
    void coneConverges() {
        double r = 0.04, h = 0.08;
        converges("Cone", "Cone { bottomRadius 0.04 height 0.08 }", Math.PI * r * r + Math.PI * r * Math.hypot(r, h), Math.PI * r * r * h / 3);
    }

    @Test
    void boxIsExact() {
        TriangleMesh m = primitive("Box { size 0.05 0.06 0.07 }", 3);
        double x = 0.05f, y = 0.06f, z = 0.07f; // SFVec3f is single precision
        double a = 2 * (x * y + y * z + x * z);
        assertEquals(a, m.area(), a * VrmlTesting.EXACT);
        assertEquals(x * y * z, m.signedVolume(), x * y * z * VrmlTesting.EXACT);
        assertEquals(12, m.triangleCount());
        double[][] b = m.bounds();
        assertEquals(-0.025, b[0][0], 1e-9);
        assertEquals(0.035, b[1][2], 1e-9);
    }

    @Test
    void partsOfCylinderAndConeCanBeOmitted() {
        TriangleMesh tube = VrmlTesting.mesh("Shape { geometry Cylinder { radius 1 height 2 top FALSE bottom FALSE } }");
        assertEquals(2 * Math.PI * 2, tube.area(), 0.03 * 4 * Math.PI);
        assertTrue(!tube.isClosed(), "a tube without caps is open");
        TriangleMesh disk = VrmlTesting.mesh("Shape { geometry Cone { side FALSE } }");
        assertEquals(Math.PI, disk.area(), 0.01 * Math.PI);
        VrmlScene none = VrmlTesting.load("Shape { geometry Cylinder { side FALSE top FALSE bottom FALSE } }");
        assertEquals(0, none.getSceneGroup().numChildren(), "no part: no shape");
    }

    @Test
    void weldingKeepsPrimitivesClosed() {
        TriangleMesh m = primitive("Sphere { radius 1 }", 24);
        TriangleMesh w = new MeshWelder().weld(m);
        assertEquals(m.vertexCount(), w.vertexCount(), "nothing to weld: vertices are already shared");
        assertTrue(w.isClosed());
    }
}
