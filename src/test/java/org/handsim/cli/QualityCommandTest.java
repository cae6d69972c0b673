package org.handsim.cli;

import static org.handsim.cli.CliTesting.run;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.handsim.cli.CliTesting.Run;
import org.handsim.text.Json;
import org.junit.jupiter.api.Test;

/** {@code handsim quality}: the JSON contract, the hand-derived cube grasp, bad input. */
class QualityCommandTest {
    static final String CUBE = "x,y,z,nx,ny,nz\n0.03,0,0,-1,0,0\n-0.03,0,0,1,0,0\n0,0.03,0,0,-1,0\n0,-0.03,0,0,1,0\n0,0,0.03,0,0,-1\n0,0,-0.03,0,0,1\n";

    static Path temp(String text) throws IOException {
        Path f = Files.createTempFile("contacts", ".csv");
        Files.writeString(f, text);
        return f;
    }

    /**
     * The --help example: the face centres of a 60 mm cube, R = 0.052, μ = 0.5, m = 4 give
     * ε = μa/(√3 R) (derived in WrenchSpaceTest); the keys in the contract's order.
     */
    @Test
    void cubeFaceCentresGiveTheDerivedEpsilonInTheContractsKeys() throws IOException {
        Path f = temp(CUBE);
        try {
            Run r = run("quality", f.toString(), "--radius", "0.052", "--edges", "4");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().matches("\\{\"contacts\":6,\"wrenches\":24,\"force_closure\":true,\"epsilon\":[0-9.eE-]+,"
                + "\"volume\":[0-9.eE-]+,\"facets\":148,\"center_m\":\\[0,0,0\\],\"radius_m\":0.052\\}\n?"), r.out());
            @SuppressWarnings("unchecked")
            Map<String, Object> m = (Map<String, Object>) Json.parse("out", r.out());
            double eps = ((Number) m.get("epsilon")).doubleValue();
            assertEquals(0.5 * 0.03 / 0.052 / Math.sqrt(3), eps, 1e-15);
            assertEquals("", r.err(), "no note: the radius was given");
            // timed only when asked: the same object plus time_us_median
            Run timed = run("quality", f.toString(), "--radius", "0.052", "--edges", "4", "--timing", "--repeat", "1");
            assertEquals(0, timed.code(), timed.err());
            @SuppressWarnings("unchecked")
            Map<String, Object> t = (Map<String, Object>) Json.parse("out", timed.out());
            assertTrue(((Number) t.remove("time_us_median")).doubleValue() > 0, timed.out());
            assertEquals(m, t);
            // μ = 0: six frictionless contacts are six wrenches, at most 5-dimensional
            r = run("quality", f.toString(), "--friction", "0");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("{\"contacts\":6,\"wrenches\":48,\"force_closure\":false,\"epsilon\":0,\"volume\":0,\"facets\":0,"), r.out());
            // the torque origin off-centre by more than the ball: no longer symmetric, still closure with more edges
            r = run("quality", f.toString(), "--center", "0.001,0,0", "--radius", "0.052", "--edges", "8", "--friction", "1");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().contains("\"force_closure\":true"), r.out());
        } finally {
            Files.delete(f);
        }
    }

    private static String f0() throws IOException {
        Path f = temp(CUBE);
        f.toFile().deleteOnExit();
        return f.toString();
    }

    /**
     * Without a radius the torques are divided by 1 m and a note says so; {@code --object}
     * scales as {@code handsim grasp} does: the 60 mm cube file's centroid (its centre) and the
     * distance to a corner, 0.03·√3 m, found from the mesh.
     */
    @Test
    void theScalingComesFromTheOptionsTheObjectOrIsOneMetreWithANote() throws IOException {
        Path f = temp(CUBE);
        Path dir = Files.createTempDirectory("quality");
        try {
            Run r = run("quality", f.toString(), "--edges", "4");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().contains("\"center_m\":[0,0,0],\"radius_m\":1}"), r.out());
            assertTrue(r.err().startsWith("handsim quality: torques divided by R = 1 m"), r.err());
            Path cube = dir.resolve("cube.obj");
            StringBuilder obj = new StringBuilder();
            for (int i = 0; i < 8; i++) obj.append(String.format(java.util.Locale.ROOT, "v %s %s %s%n", (i & 1) == 0 ? "-0.03" : "0.03",
                (i & 2) == 0 ? "-0.03" : "0.03", (i & 4) == 0 ? "-0.03" : "0.03"));
            int[][] faces = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
            for (int[] q : faces) obj.append("f ").append(q[0]).append(' ').append(q[1]).append(' ').append(q[2]).append(' ').append(q[3]).append('\n');
            Files.writeString(cube, obj);
            r = run("quality", f.toString(), "--edges", "4", "--object", cube.toString(), "--units", "m");
            assertEquals(0, r.code(), r.err());
            @SuppressWarnings("unchecked")
            Map<String, Object> m = (Map<String, Object>) Json.parse("out", r.out());
            double radius = ((Number) m.get("radius_m")).doubleValue();
            assertEquals(0.03 * Math.sqrt(3), radius, 1e-8, "the OBJ loader keeps coordinates as floats");
            assertEquals(0.5 * 0.03 / radius / Math.sqrt(3), ((Number) m.get("epsilon")).doubleValue(), 1e-13);
            assertEquals("", r.err());
            // an explicit radius wins over the object's
            r = run("quality", f.toString(), "--edges", "4", "--object", cube.toString(), "--units", "m", "--radius", "0.052");
            assertTrue(r.out().contains("\"epsilon\":0.1665433468816228"), r.out());
        } finally {
            Files.delete(f);
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void noContactsIsNoClosure() throws IOException {
        Path f = temp("x,y,z,nx,ny,nz\n");
        try {
            Run r = run("quality", f.toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("{\"contacts\":0,\"wrenches\":0,\"force_closure\":false,\"epsilon\":0,\"volume\":0,\"facets\":0,"), r.out());
        } finally {
            Files.delete(f);
        }
    }

    @Test
    void badRowsExitTwoNamingTheLine() throws IOException {
        String[][] cases = {
            {"x,y,z,nx,ny,nz\n0,0,0,1,0,0\n0,0,zero,1,0,0\n", ":3: column z = 'zero' is not a number"},
            {"x,y,z,nx,ny,nz\n0,0,0,0,0,0\n", ":2: the normal (0, 0, 0) must be a finite non-zero vector"},
            {"x,y,z,nx,ny,nz\n0,0,0,1,0\n", ":2: expected 6 columns, got 5"},
            {"x,y,z,nx,ny\n", ":1: header must be exactly 'x,y,z,nx,ny,nz'"},
            {"x,y,z,nx,ny,nz\n1e300,0,0,0,1,0\n", "contact 1 gives a wrench coordinate beyond 1e30"},
        };
        for (String[] c : cases) {
            Path f = temp(c[0]);
            try {
                Run r = run("quality", f.toString());
                assertEquals(2, r.code(), c[0]);
                assertTrue(r.err().contains(c[1]) && !r.err().contains("\n") && r.out().isEmpty(), r.err());
            } finally {
                Files.delete(f);
            }
        }
    }

    @Test
    void badArgumentsExitTwoAndAMissingFileThree() throws IOException {
        Path f = temp(CUBE);
        try {
            String[][] cases = {
                {"--friction", "-0.1", "--friction must be in [0, 10] (measured coefficients stay below 2; beyond 10 the friction cone is numerically a half-space), got -0.1"},
                {"--friction", "nan", "'nan' is not a number"},
                {"--edges", "0", "--edges must be between 1 and 1024"},
                {"--edges", "2.5", "is not an integer"},
                {"--radius", "0", "--radius must be > 0"},
                {"--center", "1,2", "--center needs 3 comma-separated numbers"},
                {"--repeat", "1", "--repeat needs --timing"},
                {"--units", "mm", "--units needs --object"},
            };
            for (String[] c : cases) {
                Run r = run("quality", f.toString(), c[0], c[1]);
                assertEquals(2, r.code(), String.join(" ", c));
                assertTrue(r.err().contains(c[2]), r.err());
            }
        } finally {
            Files.delete(f);
        }
        Run rep = run("quality", f0(), "--timing", "--repeat", "0");
        assertEquals(2, rep.code());
        assertTrue(rep.err().contains("--repeat must be in 1..1000"), rep.err());
        Run r = run("quality", "/nonexistent/contacts.csv");
        assertEquals(3, r.code());
        assertTrue(r.err().contains("no such file"), r.err());
    }

    @Test
    void helpHasTheContractAndAnExample() {
        Run r = run("quality", "--help");
        assertEquals(0, r.code());
        for (String s : new String[] {"x,y,z,nx,ny,nz", "\"force_closure\"", "time_us_median", "--friction", "--edges", "--center", "--radius",
                "--object", "--timing", "--repeat", "0.16654334688162284", "center_m", "radius_m"}) {
            assertTrue(r.out().contains(s), s + " in " + r.out());
        }
    }
}
