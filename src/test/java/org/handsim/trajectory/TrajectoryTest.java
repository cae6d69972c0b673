package org.handsim.trajectory;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class TrajectoryTest {
    private static final double[] S = new double[3];

    private static double[] at(Trajectory t, double time) {
        t.sample(time, S);
        return S.clone();
    }

    /** Velocity is the derivative of position, acceleration of velocity (central differences). */
    private static void assertConsistent(Trajectory t, double tol) {
        double h = 1e-6;
        for (int i = 1; i < 400; i++) {
            double time = t.duration() * i / 400.0;
            double[] a = at(t, time - h), b = at(t, time + h), c = at(t, time);
            assertEquals(c[1], (b[0] - a[0]) / (2 * h), tol * Math.max(1, Math.abs(c[1])), "velocity at " + time);
        }
    }

    @Test
    void trapezoidByHand() {
        // 0 -> 17500 with v = 5000, a = 25000: ramps 0.2 s / 500 counts, cruise 3.3 s, total 3.7 s
        Trapezoid t = new Trapezoid(0, 17500, 5000, 25000);
        assertEquals(3.7, t.duration(), 1e-12);
        assertEquals(500, at(t, 0.2)[0], 1e-9);
        assertEquals(5000, at(t, 1.0)[1], 1e-9);
        assertEquals(25000, at(t, 0.1)[2], 1e-9);
        assertEquals(-25000, at(t, 3.6)[2], 1e-9);
        assertEquals(17500, at(t, 3.7)[0], 1e-9);
        assertEquals(17500, at(t, 9)[0], 1e-9);
        assertEquals(0, at(t, 9)[1]);
        assertConsistent(t, 1e-4);
    }

    @Test
    void shortMoveIsTriangular() {
        // 100 counts at a = 10000: peak velocity sqrt(100*10000) = 1000, total 2*0.1 s
        Trapezoid t = new Trapezoid(200, 100, 5000, 10000);
        assertTrue(t.triangular());
        assertEquals(1000, t.peakVelocity(), 1e-9);
        assertEquals(0.2, t.duration(), 1e-12);
        assertEquals(150, at(t, 0.1)[0], 1e-9);
        assertEquals(-1000, at(t, 0.1)[1], 1e-9);
        assertConsistent(t, 1e-4);
    }

    @Test
    void quinticRestToRest() {
        Quintic q = new Quintic(1000, 3000, 2.0);
        assertEquals(2000, at(q, 1.0)[0], 1e-9);
        assertEquals(1.875 * 2000 / 2.0, at(q, 1.0)[1], 1e-9);
        assertEquals(0, at(q, 0)[1]);
        assertEquals(0, at(q, 2.0)[2]);
        double tPeak = 2.0 * (0.5 - Math.sqrt(3) / 6);
        assertEquals(5.773502691896258 * 2000 / 4.0, at(q, tPeak)[2], 1e-6);
        assertConsistent(q, 1e-5);
    }

    @Test
    void sequenceCloseHoldOpen() {
        Trapezoid close = new Trapezoid(0, 9000, 5000, 25000);
        Sequence s = new Sequence(List.of(close, new Hold(9000, 0.5), new Quintic(9000, 0, 1.0)));
        assertEquals(close.duration() + 1.5, s.duration(), 1e-12);
        assertEquals(9000, at(s, close.duration() + 0.25)[0], 1e-9);
        assertEquals(4500, at(s, close.duration() + 1.0)[0], 1e-9);
        assertEquals(0, at(s, 100)[0], 1e-9);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> new Sequence(List.of(close, new Hold(8000, 1))));
        assertTrue(e.getMessage().contains("segment 1 starts at 8000.0"), e.getMessage());
    }

    @Test
    void badParametersNameTheValue() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new Trapezoid(0, 1, -1, 1)).getMessage().contains("-1"));
        assertThrows(IllegalArgumentException.class, () -> new Quintic(0, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> new Hold(0, Double.NaN));
    }

    @Test
    void cartesianLineFollowsTheCoupledCurveWhereItCan() {
        // a target on the coupled curve itself: the line's end is reached exactly
        org.handsim.kinematics.Transmission tr = org.handsim.kinematics.Transmission.barrettHand();
        double[] end = org.handsim.kinematics.FingerKinematics.of(3).fingertip(tr.joints(3, 9000, 0, null));
        CartesianLine line = new CartesianLine(3, 2000, 0, end, 1.5);
        assertEquals(2000, line.start(), 1e-12);
        assertEquals(9000, line.end(), 1e-9);
        assertEquals(9000, at(line, 1.5)[0], 1e-9);
        double prev = -1;
        for (int i = 0; i <= 300; i++) {
            double q = at(line, 1.5 * i / 300)[0];
            assertTrue(q >= prev - 1e-9, "monotone");
            prev = q;
        }
        // the line is the chord of the coupled curve between q = 2000 and 9000: the deviation is
        // about the sagitta, the largest distance of the curve from its chord
        double[] a = org.handsim.kinematics.FingerKinematics.of(3).fingertip(tr.joints(3, 2000, 0, null));
        double sagitta = 0;
        for (int q = 2000; q <= 9000; q += 10) {
            double[] c = org.handsim.kinematics.FingerKinematics.of(3).fingertip(tr.joints(3, q, 0, null));
            double[] u = {end[0] - a[0], end[1] - a[1], end[2] - a[2]};
            double[] w = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            double[] x = new double[3];
            org.handsim.math.Vec3.cross(u, w, x);
            sagitta = Math.max(sagitta, org.handsim.math.Vec3.norm(x) / org.handsim.math.Vec3.norm(u));
        }
        assertTrue(line.maxDeviationM() <= sagitta + 1e-4 && line.maxDeviationM() >= 0.5 * sagitta,
            "deviation " + line.maxDeviationM() + ", sagitta " + sagitta);
        assertConsistent(line, 1e-3);
    }
}
