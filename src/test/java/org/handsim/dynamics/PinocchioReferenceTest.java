package org.handsim.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import org.handsim.text.Json;
import org.junit.jupiter.api.Test;

/**
 * The finger's dynamics against Pinocchio (Carpentier et al.), which shares none of our code
 * and none of our reading of Table III: {@code tools/dynamics/pinocchio_reference.py} builds
 * finger 1 from the hand description's DH table and Table III (about each link frame's origin,
 * products +∫xy dm) with Pinocchio's joints and spatial inertias and writes
 * {@code pinocchio-reference.json}: D by the composite rigid body algorithm, τ by recursive
 * Newton–Euler, a 1 s free swing by RK4 on the articulated-body algorithm. Our three
 * algorithms must give the same numbers to rounding.
 */
class PinocchioReferenceTest {
    /** Relative to the largest entry: both sides are double precision, different algorithms. */
    private static final double ROUNDING = 1e-12;

    @SuppressWarnings("unchecked")
    private static Map<String, Object> reference() throws IOException {
        try (InputStream in = PinocchioReferenceTest.class.getResourceAsStream("pinocchio-reference.json")) {
            return (Map<String, Object>) Json.parse("pinocchio-reference.json", new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }

    @SuppressWarnings("unchecked")
    private static double[] vector(Object o) {
        List<Object> l = (List<Object>) o;
        double[] v = new double[l.size()];
        for (int i = 0; i < v.length; i++) v[i] = ((Number) l.get(i)).doubleValue();
        return v;
    }

    @SuppressWarnings("unchecked")
    private static double[] matrix(Object o) {
        List<Object> rows = (List<Object>) o;
        int n = rows.size();
        double[] m = new double[n * n];
        for (int i = 0; i < n; i++) System.arraycopy(vector(rows.get(i)), 0, m, n * i, n);
        return m;
    }

    private static ChainDynamics[] algorithms(LinkChain chain) {
        return new ChainDynamics[] {new LagrangeEuler(chain), new NewtonEuler(chain), new ClosedFormFinger(chain)};
    }

    /**
     * The mass matrix at q = 0 has the diagonal (1.25577e-3, 3.42415e-4, 2.55485e-5) kg·m² (it
     * was (1.40949e-3, 4.72587e-4, 7.07261e-5) with Table III read about the centres of mass).
     */
    @Test
    @SuppressWarnings("unchecked")
    void theMassMatrixAtRestIsPinocchios() throws IOException {
        double[] ref = matrix(((Map<String, Object>) ((List<Object>) reference().get("states")).get(0)).get("D"));
        double[] diag = {1.25577e-3, 3.42415e-4, 2.55485e-5};
        for (int i = 0; i < 3; i++) assertEquals(diag[i], ref[4 * i], 5e-6 * diag[i], "the reference file's D" + (i + 1) + (i + 1));
        for (ChainDynamics d : algorithms(LinkChain.finger(1))) {
            double[] m = d.massMatrix(new double[3], null);
            for (int i = 0; i < 3; i++) assertEquals(diag[i], m[4 * i], 5e-6 * diag[i], d.getClass().getSimpleName() + " D" + (i + 1) + (i + 1));
            assertTrue(DynamicsTesting.relative(m, ref) <= ROUNDING, d.getClass().getSimpleName() + ": " + DynamicsTesting.relative(m, ref));
        }
    }

    /**
     * Every state of the file: D(q) and τ(q, q̇, q̈, g) from Lagrange–Euler, Newton–Euler and the
     * closed form equal Pinocchio's to 1e-12 of their largest entry; finger 3 (joint 1 fixed at 0)
     * equals the lower right block where the file's state has q1 = q̇1 = q̈1 = 0.
     */
    @Test
    @SuppressWarnings("unchecked")
    void everyStateAgreesWithPinocchio() throws IOException {
        List<Object> states = (List<Object>) reference().get("states");
        assertEquals(6, states.size());
        int finger3Checked = 0;
        for (Object o : states) {
            Map<String, Object> s = (Map<String, Object>) o;
            double[] q = vector(s.get("q")), qd = vector(s.get("qd")), qdd = vector(s.get("qdd")), g = vector(s.get("gravity"));
            double[] tau = vector(s.get("tau")), dRef = matrix(s.get("D"));
            double tauScale = Math.max(DynamicsTesting.maxAbs(tau), 1e-3);
            for (ChainDynamics d : algorithms(LinkChain.finger(1))) {
                String what = d.getClass().getSimpleName() + " at q = " + java.util.Arrays.toString(q);
                assertTrue(DynamicsTesting.relative(d.massMatrix(q, null), dRef) <= ROUNDING, what + " D");
                assertTrue(DynamicsTesting.relative(d.inverseDynamics(q, qd, qdd, g, null), tau, tauScale) <= ROUNDING, what + " tau");
            }
            if (q[0] == 0 && qd[0] == 0 && qdd[0] == 0) {
                finger3Checked++;
                double[] dBlock = {dRef[4], dRef[5], dRef[7], dRef[8]};
                double[] tauBlock = {tau[1], tau[2]};
                double[] q3 = {q[1], q[2]}, qd3 = {qd[1], qd[2]}, qdd3 = {qdd[1], qdd[2]};
                for (ChainDynamics d : algorithms(LinkChain.finger(3))) {
                    String what = d.getClass().getSimpleName() + " finger 3 at q = " + java.util.Arrays.toString(q);
                    assertTrue(DynamicsTesting.relative(d.massMatrix(q3, null), dBlock) <= ROUNDING, what + " D");
                    assertTrue(DynamicsTesting.relative(d.inverseDynamics(q3, qd3, qdd3, g, null), tauBlock, tauScale) <= ROUNDING, what + " tau");
                }
            }
        }
        assertEquals(3, finger3Checked);
    }

    /**
     * The free swing of `handsim swing`'s defaults (finger 1 from rest at q = 0, g = (0, 0, −9.81),
     * zero torques, RK4 at 1 ms for 1 s) ends where Pinocchio's does: q = (0.00413, −2.85197,
     * 4.63327) rad (with Table III about the centres of mass it ended at (−0.01182, −3.22805,
     * −15.99297)). The finger whips round (q̇3 ≈ −40 rad/s at the end), so the tolerance is
     * looser than one evaluation's rounding: 1e-9 rad.
     */
    @Test
    @SuppressWarnings("unchecked")
    void theFreeSwingEndsWherePinocchiosDoes() throws IOException {
        Map<String, Object> swing = (Map<String, Object>) reference().get("swing");
        double[] qEnd = vector(swing.get("q_final")), qdEnd = vector(swing.get("qd_final"));
        assertEquals(4.633268, qEnd[2], 1e-6);
        FingerDynamicsOde ode = new FingerDynamicsOde(new ClosedFormFinger(LinkChain.finger(1)),
            vector(swing.get("gravity")), FingerDynamicsOde.Torques.ZERO);
        double[] y = new double[6];
        FreeSwing.Result r = FreeSwing.run(ode, new RungeKutta4(6), y, ((Number) swing.get("dt_s")).doubleValue(),
            ((Number) swing.get("duration_s")).doubleValue(), null, null);
        assertEquals(1000, r.steps());
        for (int i = 0; i < 3; i++) {
            assertEquals(qEnd[i], y[i], 1e-9, "q" + (i + 1));
            assertEquals(qdEnd[i], y[3 + i], 1e-7, "qd" + (i + 1));
        }
        assertEquals(((Number) swing.get("energy_final_J")).doubleValue(), r.finalEnergy(), 1e-12);
    }
}
