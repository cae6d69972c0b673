package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class TrialSamplerTest {
    @Test
    void fibonacciPointsByHand() {
        // N = 4, i = 0: z = 1 − 1/4 = 0.75, azimuth 0 → (√(1 − 0.5625), 0, 0.75)
        double[] p = TrialSampler.fibonacci(0, 4);
        assertEquals(Math.sqrt(0.4375), p[0], 1e-15);
        assertEquals(0, p[1], 1e-15);
        assertEquals(0.75, p[2], 1e-15);
        // i = 3: z = 1 − 7/4 = −0.75, azimuth 3·π(3 − √5)
        double[] q = TrialSampler.fibonacci(3, 4);
        double phi = 3 * Math.PI * (3 - Math.sqrt(5));
        assertEquals(Math.sqrt(0.4375) * Math.cos(phi), q[0], 1e-15);
        assertEquals(Math.sqrt(0.4375) * Math.sin(phi), q[1], 1e-15);
        assertEquals(-0.75, q[2], 1e-15);
    }

    /** Unit approaches spread over the sphere: the mean of N Fibonacci points is near 0, every hemisphere gets about half. */
    @Test
    void approachesCoverTheSphere() {
        int n = 2000;
        TrialSampler s = new TrialSampler(n, 42, null);
        double[] mean = new double[3];
        int up = 0, east = 0;
        for (int i = 0; i < n; i++) {
            double[] a = s.sample(i).approach();
            assertEquals(1, Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), 1e-14);
            for (int j = 0; j < 3; j++) mean[j] += a[j] / n;
            if (a[2] > 0) up++;
            if (a[0] > 0) east++;
        }
        for (int j = 0; j < 3; j++) assertEquals(0, mean[j], 2e-3, "mean component " + j);
        assertEquals(n / 2.0, up, 0.02 * n);
        assertEquals(n / 2.0, east, 0.02 * n);
    }

    @Test
    void sameSeedSameTrialsWhateverTheOrder() {
        TrialSampler a = new TrialSampler(100, 7, null), b = new TrialSampler(100, 7, null);
        for (int i = 99; i >= 0; i--) {
            TrialParameters p = a.sample(i), q = b.sample(99 - (99 - i));
            assertArrayEquals(p.approach(), q.approach());
            assertEquals(p.roll(), q.roll());
            assertEquals(p.spreadCounts(), q.spreadCounts());
            assertEquals(p.wrap(), q.wrap());
            assertEquals(p.depth(), q.depth());
        }
        // sampling order does not matter: trial 50 alone equals trial 50 after the others
        TrialSampler c = new TrialSampler(100, 7, null);
        assertEquals(a.sample(50).roll(), c.sample(50).roll());
    }

    @Test
    void parametersStayInTheirRanges() {
        TrialSampler s = new TrialSampler(3000, 3, null);
        boolean zero = false, max = false;
        int wraps = 0;
        for (int i = 0; i < 3000; i++) {
            TrialParameters p = s.sample(i);
            assertTrue(p.roll() >= 0 && p.roll() < 2 * Math.PI);
            assertTrue(p.spreadCounts() >= 0 && p.spreadCounts() <= TrialSampler.SPREAD_COUNTS_USED);
            assertTrue(p.depth() >= 0 && p.depth() < 1);
            zero |= p.spreadCounts() < 20;
            max |= p.spreadCounts() > TrialSampler.SPREAD_COUNTS_USED - 20;
            wraps += p.wrap() ? 1 : 0;
        }
        assertTrue(zero && max, "the spread reaches both ends of its range");
        assertEquals(StandoffRule.WRAP_SHARE * 3000, wraps, 0.03 * 3000, "the share of wraps without a shape");
    }

    @Test
    void otherSeedOtherTrials() {
        TrialParameters a = new TrialSampler(10, 1, null).sample(3), b = new TrialSampler(10, 2, null).sample(3);
        assertNotEquals(a.roll(), b.roll());
        assertNotEquals(a.approach()[0], b.approach()[0]);
    }

    @Test
    void indexOutOfRangeIsRefused() {
        TrialSampler s = new TrialSampler(10, 1, null);
        assertThrows(IllegalArgumentException.class, () -> s.sample(10));
        assertThrows(IllegalArgumentException.class, () -> s.sample(-1));
    }
}
