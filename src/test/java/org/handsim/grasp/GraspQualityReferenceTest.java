package org.handsim.grasp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.files.CsvInput;
import org.junit.jupiter.api.Test;

/**
 * ε, volume, force closure and facet count against qhull (SciPy's {@code ConvexHull}, options
 * {@code Qt Qx}) on the 224 seeded contact sets of {@code qhull-reference.csv}, made by
 * {@code tools/grasp/qhull_reference.py} (which says how each kind is drawn and why the 1e-9
 * comparison holds): random contacts on a sphere, a box and a cylinder, tilted normals, an
 * off-centre torque origin, and the degenerate kinds — every contact on one face, collinear and
 * coincident contacts, μ = 0, one or two contacts, antipodal pairs, the face centres of a cube
 * (exactly coplanar wrenches), pairs of contacts a hair apart (nearly coplanar facets).
 */
class GraspQualityReferenceTest {
    static final String HEADER = "case,kind,contacts,mu,edges,center,radius,points,normals,rank,force_closure,epsilon,volume,facets";
    static final double REL = 1e-9;

    /** One row of the reference file. */
    record RefCase(int id, String kind, int contacts, double mu, int edges, double[] center, double radius,
                   double[] points, double[] normals, int rank, boolean forceClosure, double epsilon, double volume, int facets) {
        double[] wrenches() {
            return GraspWrenches.of(contacts, points, normals, mu, edges, center, radius);
        }
    }

    static List<RefCase> cases() throws Exception {
        Path file = resource("qhull-reference.csv");
        List<RefCase> out = new ArrayList<>();
        try (CsvInput in = new CsvInput(file, HEADER)) {
            while (in.next()) {
                out.add(new RefCase(in.integer(0), in.text(1), in.integer(2), in.number(3), in.integer(4), list(in.text(5)),
                    in.number(6), list(in.text(7)), list(in.text(8)), in.integer(9), Boolean.parseBoolean(in.text(10)),
                    in.number(11), in.number(12), in.integer(13)));
            }
        }
        return out;
    }

    static Path resource(String name) throws URISyntaxException {
        return Path.of(GraspQualityReferenceTest.class.getResource(name).toURI());
    }

    static double[] list(String s) {
        String[] p = s.split(";");
        double[] v = new double[p.length];
        for (int i = 0; i < p.length; i++) v[i] = Double.parseDouble(p[i]);
        return v;
    }

    static void assertRel(double expected, double actual, double rel, String what) {
        double tol = rel * Math.abs(expected);
        assertTrue(Math.abs(expected - actual) <= tol || expected == actual,
            what + ": expected " + expected + ", got " + actual + " (rel. difference " + Math.abs(expected - actual) / Math.abs(expected) + ")");
    }

    @Test
    void everySetMatchesQhull() throws Exception {
        List<RefCase> all = cases();
        assertTrue(all.size() >= 200, "at least 200 sets, got " + all.size());
        int closure = 0, lower = 0;
        for (RefCase c : all) {
            String id = "case " + c.id() + " (" + c.kind() + ", " + c.contacts() + " contacts, mu " + c.mu() + ", m " + c.edges() + ")";
            GraspQuality q = WrenchSpace.quality(c.wrenches(), c.contacts() * c.edges(), c.contacts());
            assertEquals(c.forceClosure(), q.forceClosure(), id + " force closure");
            assertRel(c.epsilon(), q.epsilon(), REL, id + " epsilon");
            assertRel(c.volume(), q.volume(), REL, id + " volume");
            assertEquals(c.facets(), q.facets(), id + " facets");
            if (c.rank() < 6) {
                lower++;
                assertEquals(0.0, q.volume(), id + " lower-dimensional volume");
                assertEquals(0.0, q.epsilon(), id + " lower-dimensional epsilon");
            }
            if (c.forceClosure()) closure++;
        }
        assertTrue(closure >= 50 && lower >= 30, "the file covers both: " + closure + " force-closure sets, " + lower + " lower-dimensional");
    }

    @Test
    void epsilonAloneMatchesQhull() throws Exception {
        for (RefCase c : cases()) {
            String id = "case " + c.id() + " (" + c.kind() + ")";
            GraspQuality q = WrenchSpace.epsilon(c.wrenches(), c.contacts() * c.edges(), c.contacts());
            assertEquals(c.forceClosure(), q.forceClosure(), id + " force closure");
            assertRel(c.epsilon(), q.epsilon(), REL, id + " epsilon");
            assertTrue(Double.isNaN(q.volume()) && q.facets() == -1, id + ": the fast path computes no volume or facets");
        }
    }
}
