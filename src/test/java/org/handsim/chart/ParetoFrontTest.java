package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The Pareto front by hand, and against the definition on random points. */
class ParetoFrontTest {
    @Test
    void byHand() {
        //            0  1  2  3  4    5
        double[] x = {1, 2, 3, 4, 2, Double.NaN};
        double[] y = {5, 3, 4, 1, 3, 0};
        // 0 (fastest), 1 (better than 0), 2 dominated by 1, 3 (most exact); 4 duplicates 1; 5 not finite
        assertEquals(List.of(0, 1, 3), ParetoFront.of(x, y));
    }

    @Test
    void agreesWithTheDefinitionOnRandomPoints() {
        SplittableRandom r = new SplittableRandom(808);
        for (int trial = 0; trial < 200; trial++) {
            int n = 1 + r.nextInt(30);
            double[] x = new double[n], y = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = r.nextInt(10);
                y[i] = r.nextInt(10);
            }
            List<Integer> front = ParetoFront.of(x, y);
            for (int i = 0; i < n; i++) {
                boolean dominated = false, duplicateEarlier = false;
                for (int j = 0; j < n; j++) {
                    if (x[j] <= x[i] && y[j] <= y[i] && (x[j] < x[i] || y[j] < y[i])) dominated = true;
                    if (j < i && x[j] == x[i] && y[j] == y[i]) duplicateEarlier = true;
                }
                assertEquals(!dominated && !duplicateEarlier, front.contains(i), "trial " + trial + " point " + i);
            }
            for (int a = 1; a < front.size(); a++) {
                assertEquals(true, x[front.get(a)] > x[front.get(a - 1)] && y[front.get(a)] < y[front.get(a - 1)], "ordered by x, falling y");
            }
        }
    }
}
