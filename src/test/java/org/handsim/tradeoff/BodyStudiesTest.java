package org.handsim.tradeoff;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.chart.StudyTable;
import org.junit.jupiter.api.Test;

/**
 * Charts 5 and 6 ({@link BodyRestStudy}, {@link BodyTumbleStudy}): where the free object's step
 * fails, against what the step's kinematics say by hand and the integrator's order.
 */
class BodyStudiesTest {
    static final double G = 9.80665;

    /**
     * Dropped from 10 mm at dt = 20 ms: the drift of step k moves g(k − ½)h² = 3.92(k − ½) mm, so
     * the box's bottom is at 8.04 mm after step 1 and 2.16 mm after step 2 — beyond the 1 mm
     * margin, no contact — and step 3 carries it 9.81 mm down, 7.65 mm into the table, deeper
     * than the 5 mm the query reports: it falls through. At 1 ms the same drop lands.
     */
    @Test
    void aDropFallsThroughTheTableWhenAStepOutrunsTheDeepestReportedPenetration() {
        double h = 0.02, bottom = 0.01;
        for (int k = 1; k <= 3; k++) bottom -= G * (k - 0.5) * h * h;
        assertEquals(-7.65e-3, bottom, 1e-5);
        BodyRestStudy.Measure coarse = BodyRestStudy.run(h, 0.01, 0.2);
        assertTrue(coarse.fellThrough(), "20 ms: " + coarse);
        assertTrue(coarse.tunnelling() > 0, "20 ms: " + coarse);
        BodyRestStudy.Measure fine = BodyRestStudy.run(0.001, 0.01, 0.3);
        assertTrue(!fine.fellThrough() && fine.penetration() < 1e-6, "1 ms: " + fine);
        assertEquals(0, fine.tunnelling(), "1 ms");
    }

    /** Resting 2 s: the box stays within 0.1 mm and 0.1° at the default step, and sinks less with a smaller step (10 s: BodySceneTest). */
    @Test
    void aRestingBoxStaysAndDriftsLessWithSmallerSteps() {
        BodyRestStudy.Measure d1 = BodyRestStudy.run(0.001, 0, 2), d2 = BodyRestStudy.run(0.002, 0, 2);
        assertTrue(d1.drift() < 1e-4 && d1.rotation() < Math.toRadians(0.1), "1 ms: " + d1);
        assertTrue(d2.drift() > 2 * d1.drift(), "2 ms " + d2.drift() + " vs 1 ms " + d1.drift());
    }

    /**
     * The tumble: energy and angular momentum kept to rounding at every step; the orientation
     * error falls at fourth order (× 10⁴ from 10 ms to 1 ms, within a factor of 2).
     */
    @Test
    void theTumblesErrorsAreRoundingAndFourthOrder() {
        double[] ref = BodyTumbleStudy.reference(BodyTumbleStudy.DURATION);
        BodyTumbleStudy.Measure a = BodyTumbleStudy.run(0.01, ref), b = BodyTumbleStudy.run(0.001, ref);
        for (BodyTumbleStudy.Measure m : new BodyTumbleStudy.Measure[] {a, b}) {
            assertTrue(m.worstEnergy() < 1e-13 && m.momentum() < 1e-13, m.toString());
        }
        double ratio = a.orientation() / b.orientation();
        assertTrue(ratio > 5e3 && ratio < 2e4, "orientation error ratio " + ratio + " (" + a.orientation() + ", " + b.orientation() + ")");
    }

    /** The quick runs give every series at every setting, x the step and y the error columns. */
    @Test
    void quickRunsFillTheirTables() {
        StudyTable rest = new BodyRestStudy().run(true, null), tumble = new BodyTumbleStudy().run(true, null);
        assertEquals(2 * BodyRestStudy.QUICK_DTS.length, rest.rows().size());
        assertEquals(3 * BodyTumbleStudy.QUICK_DTS.length, tumble.rows().size());
        assertEquals("dt_s", rest.columns().get(rest.xColumn()));
        assertEquals("error", tumble.columns().get(tumble.yColumn()));
        assertTrue(rest.notes().get("fell").contains("20 ms"), rest.notes().toString());
    }
}
