package org.handsim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Decimal's table of recent texts never changes a text: every append equals the format computed afresh. */
class DecimalMemoTest {
    /**
     * A trace-like stream — columns that hold a value for a while, then change — mixed with values
     * chosen to share a slot (so entries are evicted and looked up again), each text compared with
     * {@link Decimal#appendUncached}.
     */
    @Test
    void repeatedAndCollidingValuesKeepTheirText() {
        Random rnd = new Random(345);
        List<Double> colliding = new ArrayList<>();
        int target = Decimal.slot(Double.doubleToRawLongBits(0.1));
        for (int i = 0; colliding.size() < 40; i++) {
            double v = 0.1 + i * 1e-9;
            if (Decimal.slot(Double.doubleToRawLongBits(v)) == target) colliding.add(v);
        }
        double[] columns = new double[40];
        StringBuilder got = new StringBuilder(), want = new StringBuilder();
        for (int row = 0; row < 20_000; row++) {
            got.setLength(0);
            want.setLength(0);
            for (int c = 0; c < columns.length; c++) {
                if (rnd.nextInt(10) == 0) {
                    columns[c] = switch (rnd.nextInt(4)) {
                        case 0 -> colliding.get(rnd.nextInt(colliding.size()));
                        case 1 -> (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(40) - 20);
                        case 2 -> -columns[c];
                        default -> Double.longBitsToDouble(rnd.nextLong() & 0x7fefffffffffffffL);   // any finite bits
                    };
                }
                double v = columns[c];
                if (v == 0 || (Math.abs(v) < 0x1p53 && v == (long) v)) continue;   // those never reach the table
                Decimal.append(got, v).append(',');
                Decimal.appendUncached(want, v).append(',');
            }
            assertEquals(want.toString(), got.toString(), "row " + row);
        }
        assertTrue(colliding.size() > 1);
    }
}
