package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.handsim.dynamics.HandDynamics;
import org.handsim.hand.HandDescription;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class IdCommandTest {
    private Path dir;
    private String out, err;

    @BeforeEach
    void makeDir() throws IOException {
        dir = Files.createTempDirectory("handsim-id");
    }

    @AfterEach
    void removeDir() throws IOException {
        VrmlTesting.deleteTree(dir);
    }

    private int run(String... args) {
        CliTesting.Run r = CliTesting.run(args);
        out = r.out();
        err = r.err();
        return r.code();
    }

    @SuppressWarnings("unchecked")
    private static double[] vector(Object o) {
        List<Object> l = (List<Object>) o;
        double[] v = new double[l.size()];
        for (int i = 0; i < v.length; i++) v[i] = ((Number) l.get(i)).doubleValue();
        return v;
    }

    @Test
    @SuppressWarnings("unchecked")
    void printsTauDhcOfOneState() {
        assertEquals(0, run("id", "--finger", "1", "--q", "0.1,0.5,0.3", "--qd", "1,2,3", "--qdd", "4,-5,6", "--gravity", "0,0,-9.81"), err);
        assertTrue(out.startsWith("{\"finger\":1,\"tau\":["), out);
        java.util.Map<String, Object> m = (java.util.Map<String, Object>) Json.parse("out", out);
        assertEquals(List.of("finger", "tau", "D", "H", "C"), List.copyOf(m.keySet()));
        double[] tau = vector(m.get("tau")), h = vector(m.get("H")), c = vector(m.get("C"));
        List<Object> rows = (List<Object>) m.get("D");
        assertEquals(3, rows.size());
        double[] qdd = {4, -5, 6};
        double[] expect = new double[3];
        HandDynamics.of(HandDescription.barrettHand(), HandDynamics.Method.LAGRANGE_EULER)
            .inverseDynamics(1, new double[] {0.1, 0.5, 0.3}, new double[] {1, 2, 3}, qdd, new double[] {0, 0, -9.81}, expect);
        for (int i = 0; i < 3; i++) {
            double[] d = vector(rows.get(i));
            double s = h[i] + c[i];
            for (int k = 0; k < 3; k++) s += d[k] * qdd[k];
            assertEquals(expect[i], tau[i], 1e-15);
            assertEquals(tau[i], s, 1e-14);
        }
        // Newton–Euler prints the same within rounding
        assertEquals(0, run("id", "--finger", "1", "--q", "0.1,0.5,0.3", "--qd", "1,2,3", "--qdd", "4,-5,6", "--gravity", "0,0,-9.81", "--method", "ne"));
        double[] tauNe = vector(((java.util.Map<String, Object>) Json.parse("out", out)).get("tau"));
        for (int i = 0; i < 3; i++) assertEquals(tau[i], tauNe[i], 1e-12 * 0.05);
    }

    /**
     * Finger 1 at rest, q = 0, no gravity: D's diagonal is Pinocchio's, (1.25577e-3, 3.42415e-4,
     * 2.55485e-5) kg·m² to the six digits given, and its full value in the reference file
     * ({@code tools/dynamics/pinocchio_reference.py}: D11 = 1.255772807353028e-3, D22 =
     * 3.424152480848599e-4, D33 = 2.554845134857281e-5) to 1e-6 relative, by both methods. (Table
     * III about each link frame's origin; about the centres of mass it was 1.40949e-3, 4.72587e-4,
     * 7.07261e-5.)
     */
    @Test
    @SuppressWarnings("unchecked")
    void theMassMatrixAtRestHasPinocchiosDiagonal() {
        double[] sixDigits = {1.25577e-3, 3.42415e-4, 2.55485e-5};
        double[] pinocchio = {1.255772807353028e-3, 3.424152480848599e-4, 2.554845134857281e-5};
        for (String method : new String[] {"le", "ne"}) {
            assertEquals(0, run("id", "--finger", "1", "--q", "0,0,0", "--qd", "0,0,0", "--qdd", "0,0,0", "--gravity", "0,0,0",
                "--method", method), err);
            List<Object> rows = (List<Object>) ((java.util.Map<String, Object>) Json.parse("out", out)).get("D");
            for (int i = 0; i < 3; i++) {
                double d = vector(rows.get(i))[i];
                assertEquals(pinocchio[i], d, 1e-6 * pinocchio[i], method + " D" + (i + 1) + (i + 1));
                assertEquals(sixDigits[i], new java.math.BigDecimal(d).round(new java.math.MathContext(6)).doubleValue(),
                    method + " D" + (i + 1) + (i + 1) + " = " + d);
            }
        }
    }

    @Test
    @SuppressWarnings("unchecked")
    void fingerThreeHasTwoJointsAndNoSpread() {
        assertEquals(0, run("id", "--finger", "3", "--q", "0,0.5,0.3", "--qd", "0,2,3", "--qdd", "0,1,1", "--gravity", "0,0,-9.81"), err);
        java.util.Map<String, Object> m = (java.util.Map<String, Object>) Json.parse("out", out);
        assertEquals(2, vector(m.get("tau")).length);
        assertEquals(2, ((List<Object>) m.get("D")).size());
        assertEquals(2, vector(((List<Object>) m.get("D")).get(0)).length);

        assertEquals(2, run("id", "--finger", "3", "--q", "0.1,0.5,0.3", "--qd", "0,2,3", "--qdd", "0,1,1", "--gravity", "0,0,-9.81"));
        assertTrue(err.contains("q1 (value 1 of --q) must be 0, got 0.1"), err);
        assertEquals(2, run("id", "--finger", "3", "--q", "0,0.5,0.3", "--qd", "2,2,3", "--qdd", "0,1,1", "--gravity", "0,0,-9.81"));
        assertTrue(err.contains("qd1"), err);
        assertEquals("", out);
    }

    @Test
    void badArgumentsExitTwoNamingThem() {
        assertEquals(2, run("id", "--finger", "4", "--q", "0,0,0", "--qd", "0,0,0", "--qdd", "0,0,0", "--gravity", "0,0,-9.81"));
        assertTrue(err.contains("--finger"), err);
        assertEquals(2, run("id", "--finger", "1", "--q", "0,x,0", "--qd", "0,0,0", "--qdd", "0,0,0", "--gravity", "0,0,-9.81"));
        assertTrue(err.contains("--q") && err.contains("'x'"), err);
        assertEquals(2, run("id", "--finger", "1", "--q", "0,0,0", "--qd", "0,0,0", "--qdd", "0,0,0"));
        assertTrue(err.contains("missing --gravity"), err);
        assertEquals(2, run("id", "--finger", "1", "--q", "0,0,0", "--qd", "0,0,0", "--qdd", "0,0,0", "--gravity", "0,0,-9.81", "--method", "rnea"));
        assertTrue(err.contains("--method"), err);
        assertEquals(2, run("id", "--finger", "1", "--q", "0,0,NaN", "--qd", "0,0,0", "--qdd", "0,0,0", "--gravity", "0,0,-9.81"));
        assertEquals(0, run("id", "--help"));
        assertTrue(out.contains("--gravity"), out);
    }

    @Test
    void bulkAddsTheTorques() throws IOException {
        Path in = dir.resolve("in.csv"), outCsv = dir.resolve("out.csv");
        Files.writeString(in, IdCommand.IN_HEADER + "\n"
            + "1,0.1,0.5,0.3,1,2,3,4,-5,6,0,0,-9.81\n"
            + "\n"
            + "2, 0.2, 0.4, 0.1, 0, 0, 0, 0, 0, 0, 0, -9.81, 0\n"
            + "3,0,0.5,0.3,0,2,3,0,1,1,0,0,-9.81\n");
        assertEquals(0, run("id", "--input", in.toString(), "--output", outCsv.toString(), "--method", "ne"), err);
        List<String> lines = Files.readAllLines(outCsv);
        assertEquals(4, lines.size());
        assertEquals("finger,q1,q2,q3,qd1,qd2,qd3,qdd1,qdd2,qdd3,gx,gy,gz,tau1,tau2,tau3", lines.get(0), "the README's header");
        HandDynamics hd = HandDynamics.of(HandDescription.barrettHand(), HandDynamics.Method.NEWTON_EULER);
        double[] tau = new double[3];
        hd.inverseDynamics(1, new double[] {0.1, 0.5, 0.3}, new double[] {1, 2, 3}, new double[] {4, -5, 6}, new double[] {0, 0, -9.81}, tau);
        assertEquals("1,0.1,0.5,0.3,1,2,3,4,-5,6,0,0,-9.81," + tau[0] + "," + tau[1] + "," + tau[2], lines.get(1));
        assertTrue(lines.get(2).startsWith("2,0.2,0.4,0.1,0,0,0,0,0,0,0,-9.81,0,"), lines.get(2));
        String[] f3 = lines.get(3).split(",", -1);
        assertEquals(16, f3.length);
        assertEquals("", f3[13], "finger 3: tau1 empty");
        hd.inverseDynamics(3, new double[] {0, 0.5, 0.3}, new double[] {0, 2, 3}, new double[] {0, 1, 1}, new double[] {0, 0, -9.81}, tau);
        assertEquals(tau[1], Double.parseDouble(f3[14]), "round-trip decimal");
        assertTrue(err.contains("3 rows"), err);
    }

    @Test
    void aBadRowStopsWithItsLineAndLeavesNoOutput() throws IOException {
        Path in = dir.resolve("in.csv"), outCsv = dir.resolve("out.csv");
        Files.writeString(in, IdCommand.IN_HEADER + "\n"
            + "1,0.1,0.5,0.3,1,2,3,4,-5,6,0,0,-9.81\n"
            + "1,0.1,0.5,0.3,1,2,3,4,-5,6,0,0,-9.81\n"
            + "1,0.1,abc,0.3,1,2,3,4,-5,6,0,0,-9.81\n");
        assertEquals(2, run("id", "--input", in.toString(), "--output", outCsv.toString()));
        assertTrue(err.contains("in.csv:4: column q2 = 'abc' is not a number"), err);
        assertFalse(Files.exists(outCsv));
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(1, s.count(), "only the input is left: no partial output");
        }

        Files.writeString(in, IdCommand.IN_HEADER + "\n3,0.2,0.5,0.3,0,2,3,0,1,1,0,0,-9.81\n");
        assertEquals(2, run("id", "--input", in.toString(), "--output", outCsv.toString()));
        assertTrue(err.contains("in.csv:2:") && err.contains("column q1 must be 0, got 0.2"), err);

        Files.writeString(in, IdCommand.IN_HEADER + "\n4,0,0,0,0,0,0,0,0,0,0,0,0\n");
        assertEquals(2, run("id", "--input", in.toString(), "--output", outCsv.toString()));
        assertTrue(err.contains("in.csv:2: finger must be 1, 2 or 3"), err);

        Files.writeString(in, "finger,q1,q2\n1,0,0\n");
        assertEquals(2, run("id", "--input", in.toString(), "--output", outCsv.toString()));
        assertTrue(err.contains("in.csv:1: header must be exactly"), err);

        Files.writeString(in, IdCommand.IN_HEADER + "\n1,0,0,0,0,0,0,0,0,0,0,0\n");
        assertEquals(2, run("id", "--input", in.toString(), "--output", outCsv.toString()));
        assertTrue(err.contains("in.csv:2: expected 13 columns, got 12"), err);
        assertFalse(Files.exists(outCsv));

        assertEquals(3, run("id", "--input", dir.resolve("missing.csv").toString(), "--output", outCsv.toString()));
        assertEquals(2, run("id", "--input", in.toString()));
        assertEquals(2, run("id", "--input", in.toString(), "--output", outCsv.toString(), "--finger", "1"));
    }
}
