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
            Run r = run("quality", f.toString(), "--radius", "0.052", "--edges", "4", "--repeat", "1");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().matches("\\{\"contacts\":6,\"wrenches\":24,\"force_closure\":true,\"epsilon\":[0-9.eE-]+,"
                + "\"volume\":[0-9.eE-]+,\"facets\":148,\"time_us_median\":[0-9.eE-]+\\}"), r.out());
            @SuppressWarnings("unchecked")
            Map<String, Object> m = (Map<String, Object>) Json.parse("out", r.out());
            double eps = ((Number) m.get("epsilon")).doubleValue();
            assertEquals(0.5 * 0.03 / 0.052 / Math.sqrt(3), eps, 1e-15);
            assertTrue(((Number) m.get("time_us_median")).doubleValue() > 0);
            // μ = 0: six frictionless contacts are six wrenches, at most 5-dimensional
            r = run("quality", f.toString(), "--friction", "0", "--repeat", "1");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("{\"contacts\":6,\"wrenches\":48,\"force_closure\":false,\"epsilon\":0,\"volume\":0,\"facets\":0,"), r.out());
            // the torque origin off-centre by more than the ball: no longer symmetric, still closure with more edges
            r = run("quality", f.toString(), "--center", "0.001,0,0", "--radius", "0.052", "--edges", "8", "--friction", "1", "--repeat", "1");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().contains("\"force_closure\":true"), r.out());
        } finally {
            Files.delete(f);
        }
    }

    @Test
    void noContactsIsNoClosure() throws IOException {
        Path f = temp("x,y,z,nx,ny,nz\n");
        try {
            Run r = run("quality", f.toString(), "--repeat", "1");
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
                Run r = run("quality", f.toString(), "--repeat", "1");
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
                {"--repeat", "0", "--repeat must be in 1..1000"},
            };
            for (String[] c : cases) {
                Run r = run("quality", f.toString(), c[0], c[1]);
                assertEquals(2, r.code(), String.join(" ", c));
                assertTrue(r.err().contains(c[2]), r.err());
            }
        } finally {
            Files.delete(f);
        }
        Run r = run("quality", "/nonexistent/contacts.csv");
        assertEquals(3, r.code());
        assertTrue(r.err().contains("no such file"), r.err());
    }

    @Test
    void helpHasTheContractAndAnExample() {
        Run r = run("quality", "--help");
        assertEquals(0, r.code());
        for (String s : new String[] {"x,y,z,nx,ny,nz", "\"force_closure\"", "time_us_median", "--friction", "--edges", "--center", "--radius", "--repeat", "0.16654334688162284"}) {
            assertTrue(r.out().contains(s), s + " in " + r.out());
        }
    }
}
