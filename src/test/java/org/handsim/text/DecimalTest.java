package org.handsim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;

/** {@link Decimal}: ECMAScript's Number::toString layout of the shortest round-trip digits. */
class DecimalTest {
    @Test
    void workedExamples() {
        assertEquals("0", Decimal.format(0.0));
        assertEquals("0", Decimal.format(-0.0), "no -0");
        assertEquals("44732", Decimal.format(44732.0), "integers without a fraction");
        assertEquals("-3", Decimal.format(-3.0));
        assertEquals("8.947", Decimal.format(8.947));
        assertEquals("8.947000000000001", Decimal.format(8947 * 0.001), "a different double: its shortest digits");
        assertEquals("0.0005", Decimal.format(5.0E-4), "plain, not 5.0E-4");
        assertEquals("0.000001", Decimal.format(1e-6), "the smallest plain magnitude");
        assertEquals("1e-7", Decimal.format(1e-7), "below 1e-6: exponent form");
        assertEquals("-4.9e-19", Decimal.format(-4.9e-19));
        assertEquals("10000000", Decimal.format(1e7));
        assertEquals("100000000000000000000", Decimal.format(1e20));
        assertEquals("1e+21", Decimal.format(1e21), "from 1e21: exponent form");
        assertEquals("1.5e+300", Decimal.format(1.5e300));
        assertEquals("1e+23", Decimal.format(1e23), "Java 17's Double.toString writes 9.999999999999999E22");
        assertEquals("282879384806159000", Decimal.format(2.82879384806159E17), "Java 17 writes 2.82879384806159008E17");
        assertEquals("9007199254740992", Decimal.format(9007199254740992.0), "2^53: no shorter decimal reads back");
        assertEquals("123.456", Decimal.format(123.456));
        assertEquals("0.30000000000000004", Decimal.format(0.1 + 0.2));
        assertEquals("5e-324", Decimal.format(Double.MIN_VALUE), "one digit reads back (Java writes 4.9E-324)");
        assertEquals("1e-323", Decimal.format(2 * Double.MIN_VALUE));
        assertEquals("1.7976931348623157e+308", Decimal.format(Double.MAX_VALUE));
        assertThrows(IllegalArgumentException.class, () -> Decimal.format(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> Decimal.format(Double.POSITIVE_INFINITY));
        assertEquals("", Decimal.orEmpty(Double.NaN));
    }

    /**
     * Against an independent reference on 200 000 seeded doubles of every magnitude: the text
     * reads back as the same double, and has exactly as many significant digits as the shortest
     * decimal that does (found by trying 1, 2, ... 17 digits with {@code %.Ne} formatting).
     */
    @Test
    void roundTripAndShortestAgainstBruteForce() {
        Random rnd = new Random(20261124);
        for (int i = 0; i < TestEffort.cases(200_000); i++) {
            double d = i % 3 == 0 ? Double.longBitsToDouble(rnd.nextLong()) : rnd.nextGaussian() * Math.pow(10, rnd.nextInt(40) - 20);
            if (!Double.isFinite(d)) continue;
            String s = Decimal.format(d);
            assertEquals(d == 0 ? 0.0 : d, Double.parseDouble(s), s);
            assertEquals(shortestDigits(d), significantDigits(s), "shortest digits of " + d + ": " + s);
            assertTrue(s.indexOf('E') < 0 && !s.endsWith(".0") && !s.equals("-0"), s);
        }
    }

    /** The fewest significant digits of a decimal that reads back as d: both neighbours of d at p digits are tried. */
    private static int shortestDigits(double d) {
        if (d == 0) return 1;
        BigDecimal exact = new BigDecimal(d);
        for (int p = 1; p <= 17; p++) {
            for (java.math.RoundingMode rm : new java.math.RoundingMode[] {java.math.RoundingMode.FLOOR, java.math.RoundingMode.CEILING}) {
                if (exact.round(new java.math.MathContext(p, rm)).doubleValue() == d) return p;
            }
        }
        throw new AssertionError(d);
    }

    private static int significantDigits(String s) {
        String m = s.replace("-", "");
        int e = m.indexOf('e');
        if (e >= 0) m = m.substring(0, e);
        BigDecimal b = new BigDecimal(m).stripTrailingZeros();
        return Math.max(1, b.precision());
    }

    @Test
    void cleanMakesOnlyRoundingNoiseZero() {
        assertEquals(0.0, Decimal.clean(5.6400734893383965E-18));
        assertEquals(0.0, Decimal.clean(-4.9e-19));
        assertEquals(1e-11, Decimal.clean(1e-11));
        assertEquals(-0.025, Decimal.clean(-0.025));
        assertEquals("[0.1,0,0.09]", JsonWriter.write(Decimal.clean(new double[] {0.1, 2.2e-18, 0.09})));
    }
}
