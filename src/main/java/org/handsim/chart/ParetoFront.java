package org.handsim.chart;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * The Pareto front of points that minimise both coordinates: a point is on the front when no
 * other point is at least as good in both and better in one.
 */
public final class ParetoFront {
    private ParetoFront() {}

    /**
     * Indices of the points on the front, by increasing x. Points with a non-finite coordinate
     * are never on it; of exact duplicates the first is kept.
     *
     * @param x cost of each point
     * @param y error of each point
     */
    public static List<Integer> of(double[] x, double[] y) {
        if (x.length != y.length) throw new IllegalArgumentException("x and y differ in length: " + x.length + " vs " + y.length);
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < x.length; i++) if (Double.isFinite(x[i]) && Double.isFinite(y[i])) order.add(i);
        order.sort(Comparator.<Integer>comparingDouble(i -> x[i]).thenComparingDouble(i -> y[i]).thenComparingInt(i -> i));
        List<Integer> front = new ArrayList<>();
        double best = Double.POSITIVE_INFINITY;
        for (int i : order) {
            if (y[i] < best) {
                front.add(i);
                best = y[i];
            }
        }
        return front;
    }
}
