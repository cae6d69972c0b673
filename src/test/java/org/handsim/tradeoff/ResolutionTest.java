package org.handsim.tradeoff;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.handsim.scenario.Home;
import org.junit.jupiter.api.Test;

/** {@code handsim run --tolerance}: lengths, the committed table, and the choice it makes. */
class ResolutionTest {
    @Test
    void parsesLengthsWithUnits() {
        assertEquals(5e-4, Resolution.parseLength("0.5mm"), 1e-18);
        assertEquals(5e-4, Resolution.parseLength("0.5 mm"), 1e-18);
        assertEquals(5e-4, Resolution.parseLength(" 0.0005m "), 1e-18);
        assertEquals(1e-3, Resolution.parseLength("1e-3"), 1e-18);
        assertEquals(0.02, Resolution.parseLength("2cm"), 1e-15);
        assertEquals(5e-4, Resolution.parseLength("500um"), 1e-18);
        assertEquals(5e-4, Resolution.parseLength(".5mm"), 1e-18);
        for (String bad : new String[] {"abc", "0.5 furlongs", "mm", "", "0.5mmm", "1,5mm", "-1mm", "0", "0mm", "1e999"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Resolution.parseLength(bad), bad);
            assertTrue(e.getMessage().contains("'" + bad + "'"), e.getMessage());
            assertFalse(e.getMessage().contains("\n"));
        }
    }

    /** The committed resource is chart 2's data: a recomputation at a few divisions gives the same errors. */
    @Test
    void committedTableAgreesWithARecomputation() {
        List<Resolution.Entry> table = Resolution.table();
        assertEquals(TessellationStudy.ROUND.length, table.size(), "one entry per divisions of the full run");
        TessellationStudy st = new TessellationStudy();
        int checked = 0;
        for (Resolution.Entry e : table) {
            if (e.divisions() != 12 && e.divisions() != 24 && e.divisions() != 64) continue;
            double sphere = st.measure(TessellationStudy.Shape.SPHERE, e.divisions(), false, true).centreWorst() / TessellationStudy.Shape.SPHERE.radius;
            double cyl = st.measure(TessellationStudy.Shape.CYLINDER, e.divisions(), false, true).centreWorst() / TessellationStudy.Shape.CYLINDER.radius;
            assertEquals(sphere, e.sphere(), 1e-9 * sphere, "sphere at " + e.divisions());
            assertEquals(cyl, e.cylinder(), 1e-9 * cyl, "cylinder at " + e.divisions());
            checked++;
        }
        assertEquals(3, checked);
        assertTrue(Double.isInfinite(table.get(0).relativeError()), "divisions 6 misses the plate in some poses: never chosen");
    }

    /** A looser tolerance never asks for more divisions; each choice is the coarsest that meets it. */
    @Test
    void choiceIsMonotoneInTheTolerance() {
        List<Resolution.Entry> table = Resolution.table();
        int prev = Integer.MAX_VALUE;
        int distinct = 0;
        for (double tol = 1e-6; tol < 0.05; tol *= 1.2) {
            Resolution.Choice c = Resolution.choose(table, 0.04, tol, d -> d);
            if (!c.met()) {
                assertEquals(Integer.MAX_VALUE, prev, "unmeetable only below every met tolerance");
                continue;
            }
            assertTrue(c.expectedErrorM() <= tol);
            assertTrue(c.divisions() <= prev, "tolerance " + tol + " chose " + c.divisions() + " after " + prev);
            for (Resolution.Entry e : table) {
                if (e.divisions() < c.divisions()) assertTrue(e.relativeError() * 0.04 > tol, "a coarser divisions " + e.divisions() + " meets " + tol);
            }
            if (c.divisions() != prev) distinct++;
            prev = c.divisions();
        }
        assertTrue(distinct >= 5, "the tolerances span several choices: " + distinct);
    }

    /** A Sphere primitive of radius 40 mm at 0.5 mm: the chosen divisions really meets it (measured), the next coarser does not. */
    @Test
    void curvedPrimitiveGetsTheCoarsestDivisionsMeetingTheTolerance() throws Exception {
        Path dir = Files.createTempDirectory("handsim-tol");
        Path f = dir.resolve("ball.wrl");
        Files.writeString(f, "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.04 } }\n");
        Resolution.Choice c = Resolution.choose(f, 1.0, 5e-4);
        assertFalse(c.fixedMesh());
        assertTrue(c.met());
        assertEquals(0.04, c.sizeM(), 1e-7);
        assertEquals(32, c.divisions(), "chart 2: 24 gives 0.55 mm, 32 gives 0.30 mm on a 40 mm sphere");
        TessellationStudy st = new TessellationStudy();
        assertTrue(st.measure(TessellationStudy.Shape.SPHERE, c.divisions(), false, true).centreWorst() <= 5e-4);
        assertTrue(st.measure(TessellationStudy.Shape.SPHERE, 24, false, true).centreWorst() > 5e-4);
        // scale 2: twice the size, a finer choice
        Resolution.Choice c2 = Resolution.choose(f, 2.0, 5e-4);
        assertEquals(0.08, c2.sizeM(), 2e-7);
        assertTrue(c2.divisions() > c.divisions());
    }

    @Test
    void fixedMeshesAreReportedNotChanged() {
        Resolution.Choice cube = Resolution.choose(Home.dir().resolve("vrml/objects/cube.wrl"), 1.0, 5e-4);
        assertTrue(cube.fixedMesh());
        assertEquals(12, cube.triangles());
        Resolution.Choice sphere = Resolution.choose(Home.dir().resolve("vrml/objects/sphere.wrl"), 1.0, 5e-4);
        assertTrue(sphere.fixedMesh(), "the pre-tessellated UV sphere does not change with divisions");
        assertEquals(960, sphere.triangles());
    }

    @Test
    void unmeetableToleranceGivesTheBestAchievable() throws Exception {
        Path dir = Files.createTempDirectory("handsim-tol");
        Path f = dir.resolve("can.wrl");
        Files.writeString(f, "#VRML V2.0 utf8\nShape { geometry Cylinder { radius 0.03 height 0.12 } }\n");
        Resolution.Choice c = Resolution.choose(f, 1.0, 1e-7);
        assertFalse(c.met());
        assertFalse(c.fixedMesh());
        List<Resolution.Entry> table = Resolution.table();
        double best = Double.POSITIVE_INFINITY;
        for (Resolution.Entry e : table) best = Math.min(best, e.relativeError());
        double size = Math.hypot(0.03, 0.06);   // bounding sphere of the cylinder
        assertEquals(size, c.sizeM(), 1e-7);
        assertEquals(best * size, c.expectedErrorM(), 1e-9);
        assertTrue(c.expectedErrorM() > 1e-7);
    }
}
