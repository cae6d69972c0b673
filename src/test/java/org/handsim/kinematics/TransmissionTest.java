package org.handsim.kinematics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import org.junit.jupiter.api.Test;

class TransmissionTest {
    private final Transmission tr = Transmission.barrettHand();

    /** The correctly rounded double of the rational q/d. */
    private static double exact(int q, int d) {
        return new BigDecimal(q).divide(new BigDecimal(d), MathContext.DECIMAL128).doubleValue();
    }

    @Test
    void innerAndOuterDegreesExactAtEveryIntegerCount() {
        for (int q = 0; q <= 17500; q++) {
            assertEquals(exact(q, 125), tr.innerDegrees(q), "eq (3) at q = " + q);
            assertEquals(exact(q, 375), tr.outerDegrees(q), "eq (4) at q = " + q);
            // counts -> angle -> counts returns the same integer, and within 1e-9 counts
            double back2 = tr.countsForInner(tr.innerAngle(q));
            double back3 = tr.countsForOuter(tr.outerAngle(q));
            assertEquals(q, Math.round(back2));
            assertEquals(q, Math.round(back3));
            assertEquals(q, back2, 1e-9);
            assertEquals(q, back3, 1e-9);
        }
    }

    @Test
    void spreadExactAtEveryIntegerCount() {
        for (int q = 0; q <= 3150; q++) {
            double deg = Math.toDegrees(tr.spreadAngle(2, q));
            assertEquals(2.0 * q / 35.0, deg, 1e-12, "eq (2) at q = " + q);
            assertEquals(-tr.spreadAngle(2, q), tr.spreadAngle(1, q), "eq (1) mirrors eq (2)");
            assertEquals(0.0, tr.spreadAngle(3, q), "finger 3 has no spread");
            assertEquals(q, Math.round(tr.countsForSpread(1, tr.spreadAngle(1, q))));
            assertEquals(q, tr.countsForSpread(2, tr.spreadAngle(2, q)), 1e-9);
        }
    }

    @Test
    void endOfRangeValuesFromTheIssue() {
        assertEquals(140.0, tr.innerDegrees(17500));
        assertEquals(46.666666666666664, tr.outerDegrees(17500));
        assertEquals(Math.PI, tr.spreadAngle(2, 3150), 1e-15);
        assertEquals(-Math.PI, tr.spreadAngle(1, 3150), 1e-15);
    }

    @Test
    void breakawayFormIsContinuousAndFourTimesSteeper() {
        double qb = 9000;
        assertEquals(tr.outerAngle(qb), tr.outerAngleBroken(qb, qb), 1e-15, "eq (10) equals eq (4) at the breakaway");
        double slope = (tr.outerAngleBroken(qb + 1000, qb) - tr.outerAngleBroken(qb, qb)) / 1000;
        assertEquals(Math.toRadians(4.0 / 375), slope, 1e-15);
        assertEquals(4 * tr.outerRadPerCount(false), tr.outerRadPerCount(true), 1e-18);
        // eq (10) by hand: q = 12000, qb = 9000 -> (48000 - 27000)/375 = 56 degrees
        assertEquals(Math.toRadians(56.0), tr.outerAngleBroken(12000, 9000), 1e-15);
    }

    @Test
    void outOfRangeCountsAreRefusedWithTheValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> tr.innerAngle(17501));
        assertTrue(e.getMessage().contains("17501"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> tr.innerAngle(-1));
        assertThrows(IllegalArgumentException.class, () -> tr.outerAngle(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> tr.spreadAngle(1, 3151));
        assertThrows(IllegalArgumentException.class, () -> tr.countsForSpread(3, 0.1));
    }
}
