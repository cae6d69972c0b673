package org.handsim.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Stroke;
import org.jfree.chart.ChartPanel;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * Live traces beside the 3D view: joint angles, joint velocities, joint torques (joints k2
 * solid, k3 dashed, one colour per finger) and each finger's total contact force, against
 * simulated time, in one {@link CombinedDomainXYPlot}. The time axis shows
 * [0, {@link #WINDOW_S}] s and then the last {@link #WINDOW_S} seconds, so long runs scroll.
 *
 * <p>Rows come from {@link SimulationRunner#drainTrace}; they are added with
 * {@code XYSeries.add(x, y, false)} and each series is told once per {@link #flush()}
 * (STYLE.md item 16), so a burst of hundreds of rows costs one redraw. A row of a new
 * generation (the model was reset or rebuilt) clears the traces first. Event dispatch thread
 * only.
 */
public final class TraceCharts {
    /** Width of the scrolling time window, s (the time axis starts at [0, WINDOW_S]). */
    public static final double WINDOW_S = 10.0;
    /** Colours of fingers 1, 2, 3 (tests look for them in screenshots). */
    public static final int[] FINGER_RGB = {0x1F77B4, 0x2CA02C, 0xD62728};
    static final int MAX_ITEMS = 20_000;

    private final XYSeries[][] series = new XYSeries[4][];   // [plot][finger * 2 + joint] (force: [finger])
    private final JFreeChart chart;
    private final ChartPanel panel;
    private final NumberAxis time;
    private final double[] minimumRange = {5, 5, 0.1, 1};
    private long generation = -1;
    private double latest;
    private boolean dirty;

    public TraceCharts() {
        NumberAxis time = new NumberAxis("simulated time t (s)");
        time.setAutoRange(false);
        time.setRange(0, WINDOW_S);
        this.time = time;
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(time);
        plot.setGap(6);
        String[] labels = {"angle (°)", "velocity (°/s)", "torque (N·m)", "contact force (N)"};
        for (int p = 0; p < 4; p++) {
            XYSeriesCollection data = new XYSeriesCollection();
            boolean force = p == 3;
            series[p] = new XYSeries[force ? 3 : 6];
            XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, false);
            for (int k = 0; k < 3; k++) {
                for (int j = 0; j < (force ? 1 : 2); j++) {
                    int i = force ? k : 2 * k + j;
                    String name = force ? "finger " + (k + 1) : "θ" + (k + 1) + (j + 2);
                    XYSeries s = new XYSeries(name, false, true);
                    s.setMaximumItemCount(MAX_ITEMS);
                    series[p][i] = s;
                    data.addSeries(s);
                    r.setSeriesPaint(i, new Color(FINGER_RGB[k]));
                    r.setSeriesStroke(i, j == 0 ? new BasicStroke(2f) : dashed());
                    r.setSeriesVisibleInLegend(i, p == 0 || force);
                }
            }
            NumberAxis y = new NumberAxis(labels[p]);
            y.setAutoRangeIncludesZero(true);
            y.setAutoRangeMinimumSize(minimumRange[p]);
            y.setLabelFont(new Font("SansSerif", Font.PLAIN, 11));
            y.setTickLabelFont(new Font("SansSerif", Font.PLAIN, 10));
            XYPlot sub = new XYPlot(data, null, y, r);
            sub.setBackgroundPaint(Color.WHITE);
            sub.setDomainGridlinePaint(new Color(0xdddddd));
            sub.setRangeGridlinePaint(new Color(0xdddddd));
            plot.add(sub, 1);
        }
        chart = new JFreeChart(null, new Font("SansSerif", Font.BOLD, 12), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        chart.getLegend().setItemFont(new Font("SansSerif", Font.PLAIN, 10));
        panel = new ChartPanel(chart, 420, 600, 200, 200, 2000, 2000, true, true, true, true, true, true);
        panel.setName("charts");
    }

    private static Stroke dashed() {
        return new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);
    }

    /** The Swing component. */
    public ChartPanel panel() { return panel; }

    /** The chart (for export). */
    public JFreeChart chart() { return chart; }

    /** Adds one trace row of {@link SimulationRunner} (not yet drawn: call {@link #flush()}). */
    public void add(double[] row) {
        long gen = (long) row[0];
        if (gen != generation) {
            clear();
            generation = gen;
        }
        double t = row[1];
        latest = t;
        for (int k = 0; k < 3; k++) {
            int o = 2 + 7 * k;
            for (int j = 0; j < 2; j++) {
                series[0][2 * k + j].add(t, row[o + j], false);
                series[1][2 * k + j].add(t, row[o + 2 + j], false);
                series[2][2 * k + j].add(t, row[o + 4 + j], false);
            }
            series[3][k].add(t, row[o + 6], false);
        }
        dirty = true;
    }

    /** Tells the chart about the rows added since the last flush (one redraw). */
    public void flush() {
        if (!dirty) return;
        dirty = false;
        chart.setNotify(false);
        for (XYSeries[] ss : series) for (XYSeries s : ss) s.fireSeriesChanged();
        // the time axis shows [0, WINDOW_S] until the traces reach its end, then scrolls
        double hi = Math.max(WINDOW_S, latest);
        if (time.getUpperBound() != hi) time.setRange(hi - WINDOW_S, hi);
        chart.setNotify(true);
    }

    /** Number of points in the first series (for logs and tests). */
    public int points() { return series[0][0].getItemCount(); }

    private void clear() {
        for (XYSeries[] ss : series) for (XYSeries s : ss) s.clear();
        latest = 0;
        dirty = true;
    }
}
