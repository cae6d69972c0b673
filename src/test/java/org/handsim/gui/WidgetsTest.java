package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The panels' number formats, by hand. */
class WidgetsTest {
    @Test
    void significantDigitsAreRoundedHalfUpAndWrittenInFull() {
        assertEquals("0.1984", Widgets.significant(0.19837397687762737, 4));   // an ε the mug grasp once had
        assertEquals("0.08472", Widgets.significant(0.08472302422835801, 4));
        assertEquals("58.84", Widgets.significant(58.8399, 4));
        assertEquals("0.0000123", Widgets.significant(1.2345e-5, 3));          // no exponent
        assertEquals("100000", Widgets.significant(99999.7, 4));
        assertEquals("-2.500", Widgets.significant(-2.5, 4));
        assertEquals("0", Widgets.significant(0.0, 4));
        assertEquals("0", Widgets.significant(-0.0, 4));
        assertEquals("NaN", Widgets.significant(Double.NaN, 4));
        assertEquals("0.13", Widgets.significant(0.125, 2));                   // 0.125 is exact: half up
    }

    /**
     * A field holding a 1 MB line (a window script's {@code set fk3.counts xxx...}): the refusal
     * quotes it short and on one line (it was the whole megabyte).
     */
    @Test
    void aNumberFieldQuotesWhatItRefusesShort() {
        String typed = "x".repeat(1_000_000) + "\n";
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
            () -> Widgets.number(new javax.swing.JTextField(typed), "finger 3 counts"));
        assertEquals("finger 3 counts: 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...xxxxxxxxxxxxxxxxx' is not a number", e.getMessage());
    }
}
