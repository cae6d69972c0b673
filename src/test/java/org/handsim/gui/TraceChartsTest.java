package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.NumberTick;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.ui.RectangleEdge;
import org.junit.jupiter.api.Test;

/**
 * The live charts without a window: the time axis spans the run, long runs keep the whole run in
 * at most {@link TraceCharts#MAX_ITEMS} points, and no two tick labels overlap — within an axis,
 * or across the gap between neighbouring plots (the window's charts had the labels of one plot
 * running into the next) — at the window's sizes down to 1024 × 768's.
 */
class TraceChartsTest {
    /** Rows of a finger closing and opening, like the paper's run, for {@code seconds}. */
    static void feed(TraceCharts c, double seconds, long generation) {
        feed(c, seconds, generation, new double[] {60, 35, 1.26, 21.6});
    }

    /** The same with the peaks of angle, velocity, torque and force given. */
    static void feed(TraceCharts c, double seconds, long generation, double[] peak) {
        for (double t = 0; t <= seconds + 1e-9; t += SimulationRunner.TRACE_INTERVAL_S) {
            double[] row = new double[SimulationRunner.ROW_LENGTH];
            row[0] = generation;
            row[1] = t;
            for (int k = 0; k < 3; k++) {
                int o = 2 + 7 * k;
                double s = Math.sin(Math.PI * t / seconds);
                row[o] = peak[0] * s;
                row[o + 1] = peak[0] / 3 * s;
                row[o + 2] = peak[1] * Math.cos(Math.PI * t / seconds);
                row[o + 3] = peak[1] / 3 * Math.cos(Math.PI * t / seconds);
                row[o + 4] = k == 2 ? peak[2] * s : 0;
                row[o + 5] = k == 2 ? peak[2] * s : 0;
                row[o + 6] = k == 2 ? peak[3] * s : 0;
            }
            c.add(row);
        }
    }

    @Test
    void theTimeAxisSpansTheRunAndLongRunsStayWhole() throws Exception {
        try (TraceCharts c = new TraceCharts()) {
            c.setDuration(3.133);
            feed(c, 3.133, 1);
            c.awaitDrawn();
            assertArrayEquals(new double[] {0, 3.133}, c.timeRange());
            assertEquals(627, c.points(), "every row of a short run (0 to 3.133 s every 5 ms)");
            c.setDuration(1000);
            feed(c, 1000, 2);
            c.awaitDrawn();
            assertArrayEquals(new double[] {0, 1000}, c.timeRange());
            assertTrue(c.points() <= TraceCharts.MAX_ITEMS && c.points() > TraceCharts.MAX_ITEMS / 2, "thinned, not cut: " + c.points());
        }
    }

    @Test
    void noTickLabelsOverlap() throws Exception {
        // peaks that put a tick at a plot's top edge (50 = 47.62 plus the 5 % margin) as well as ordinary ones
        double[] peaks = {50 / 1.05, 47.619, 45 / 1.05, 100 / 1.05, 1.2 / 1.05, 1.26, 20 / 1.05, 21.6, 35, 4.2};
        java.util.Random rnd = new java.util.Random(345);
        for (int trial = 0; trial < 12; trial++) {
            int[] size = new int[][] {{439, 787}, {300, 600}, {270, 560}, {600, 900}}[trial % 4];
            double[] peak = {peaks[rnd.nextInt(peaks.length)], peaks[rnd.nextInt(peaks.length)], peaks[rnd.nextInt(peaks.length)],
                peaks[rnd.nextInt(peaks.length)]};
            try (TraceCharts c = new TraceCharts()) {
                c.setDuration(8.946);
                feed(c, 8.946, 1, peak);
                c.awaitDrawn();
                BufferedImage img = new BufferedImage(size[0], size[1], BufferedImage.TYPE_INT_RGB);
                Graphics2D g = img.createGraphics();
                ChartRenderingInfo info = c.drawInto(g, size[0], size[1]);
                List<double[]> boxes = new ArrayList<>();   // per label: plot, top, bottom
                List<XYPlot> plots = c.plots();
                for (int p = 0; p < plots.size(); p++) {
                    Rectangle2D area = info.getPlotInfo().getSubplotInfo(p).getDataArea();
                    NumberAxis y = (NumberAxis) plots.get(p).getRangeAxis();
                    double h = g.getFontMetrics(y.getTickLabelFont()).getHeight();
                    for (Object o : y.refreshTicks(g, new AxisState(), area, RectangleEdge.LEFT)) {
                        NumberTick t = (NumberTick) o;
                        if (t.getText() == null || t.getText().isEmpty()) continue;
                        double at = y.valueToJava2D(t.getValue(), area, RectangleEdge.LEFT);
                        boxes.add(new double[] {p, at - h / 2, at + h / 2, t.getValue()});
                    }
                }
                for (int i = 0; i < boxes.size(); i++) {
                    double[] a = boxes.get(i);
                    assertTrue(a[1] >= 0 && a[2] <= size[1], "label inside the chart " + java.util.Arrays.toString(a));
                    for (int j = i + 1; j < boxes.size(); j++) {
                        double[] b = boxes.get(j);
                        assertTrue(a[2] <= b[1] || b[2] <= a[1], String.format("%dx%d: tick labels %s (plot %d) and %s (plot %d) overlap",
                            size[0], size[1], a[3], (int) a[0], b[3], (int) b[0]));
                    }
                }
                g.dispose();
            }
        }
    }

    @Test
    void theLegendHasOneEntryPerFingerAndJointAndAClickHidesIt() throws Exception {
        try (TraceCharts c = new TraceCharts()) {
            c.setDuration(2);
            feed(c, 2, 1);
            c.awaitDrawn();
            BufferedImage img = new BufferedImage(440, 780, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = img.createGraphics();
            ChartRenderingInfo info = c.drawInto(g, 440, 780);
            g.dispose();
            List<String> keys = new ArrayList<>();
            java.awt.Point finger3 = null;
            for (Object o : info.getEntityCollection().getEntities()) {
                if (o instanceof org.jfree.chart.entity.LegendItemEntity) {
                    org.jfree.chart.entity.LegendItemEntity e = (org.jfree.chart.entity.LegendItemEntity) o;
                    keys.add(String.valueOf(e.getSeriesKey()));
                    if ("finger3".equals(e.getSeriesKey())) {
                        java.awt.Rectangle b = e.getArea().getBounds();
                        finger3 = new java.awt.Point((int) b.getCenterX(), (int) b.getCenterY());
                    }
                }
            }
            assertEquals(List.of("finger1", "finger2", "finger3", "joint2", "joint3"), keys);
            assertNotNull(finger3, "finger 3 has a legend entry");
            assertTrue(c.fingerVisible(3));
            c.toggle("finger3");
            c.awaitDrawn();
            assertTrue(!c.fingerVisible(3) && c.fingerVisible(1), "finger 3 hidden, the others shown");
        }
    }
}
