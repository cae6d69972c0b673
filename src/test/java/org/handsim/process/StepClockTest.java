package org.handsim.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;
import org.handsim.text.Decimal;
import org.junit.jupiter.api.Test;

/** {@link StepClock}: step × dt as the double nearest the exact decimal product. */
class StepClockTest {
    @Test
    void theTimesPeopleWrite() {
        assertEquals(8.947, new StepClock(0.001).at(8947), "not 8947 * 0.001 = 8.947000000000001");
        assertEquals(0.3, new StepClock(0.1).at(3), "not 3 * 0.1 = 0.30000000000000004");
        assertEquals(0.9, new StepClock(0.3).at(3));
        assertEquals(1000.0, new StepClock(0.001).at(1_000_000));
        assertEquals(0.0, new StepClock(5e-4).at(0));
        assertEquals("0.0005", Decimal.format(new StepClock(5e-4).at(1)));
        assertThrows(IllegalArgumentException.class, () -> new StepClock(0));
        assertThrows(IllegalArgumentException.class, () -> new StepClock(Double.NaN));
    }

    /** Against BigDecimal (exact product, one rounding) for seeded steps and time steps, including the slow path. */
    @Test
    void matchesTheExactDecimalProductRoundedOnce() {
        Random rnd = new Random(15);
        double[] dts = {0.001, 0.0005, 1e-4, 2.5e-3, 0.02, 0.1, 0.3, 1.0 / 3, 1e-9, 7.3e-5, 0.05};
        for (double dt : dts) {
            StepClock c = new StepClock(dt);
            BigDecimal exact = new BigDecimal(Decimal.format(dt));
            for (int i = 0; i < 20_000; i++) {
                long n = i < 1000 ? i : (long) (rnd.nextDouble() * (i % 2 == 0 ? 1e7 : 1e15));
                double want = exact.multiply(BigDecimal.valueOf(n)).doubleValue();
                assertEquals(want, c.at(n), "dt " + dt + ", step " + n);
                assertTrue(Math.abs(c.at(n) - n * dt) <= Math.ulp(n * dt) * 1.0000001, "within one rounding of n*dt");
            }
        }
    }
}
