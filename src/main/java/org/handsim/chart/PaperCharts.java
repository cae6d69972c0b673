package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.util.function.IntToDoubleFunction;
import org.handsim.sim.Recorder;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleAnchor;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * The paper's Fig. 7 (angle, velocity, acceleration and torque of joints k2 and k3 against time,
 * the breakaway marked) and Fig. 8 (contact force on the finger against time), from a
 * {@link Recorder}. Traces with more points than a chart can show are thinned to at most
 * {@value #MAX_POINTS} points (every n-th row, keeping the last).
 */
public final class PaperCharts {
    static final int MAX_POINTS = Recorder.CHART_POINTS;
    /** Pixels between the stacked plots of Fig. 7. */
    static final int GAP = 18;
    static final Color J2 = new Color(0x1f77b4), J3 = new Color(0xd62728), BREAK = new Color(0x2ca02c);

    private PaperCharts() {}

    /** Fig. 7 for finger k; {@code breakawayTime} NaN for none. */
    public static JFreeChart figure7(Recorder r, int k, double breakawayTime, String title) {
        NumberAxis time = new NumberAxis("time t (s)");
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(time);
        plot.setGap(GAP);   // more than a tick label's height: the labels of neighbouring plots never meet
        plot.add(panel(r, k, Recorder.TH2, Recorder.TH3, "angle (deg)", Math.toDegrees(1), breakawayTime, true), 1);
        plot.add(panel(r, k, Recorder.DTH2, Recorder.DTH3, "velocity (deg/s)", Math.toDegrees(1), breakawayTime, false), 1);
        plot.add(panel(r, k, Recorder.DDTH2, Recorder.DDTH3, "acceleration (deg/s²)", Math.toDegrees(1), breakawayTime, false), 1);
        plot.add(panel(r, k, Recorder.TAU2, Recorder.TAU3, "torque (N·m)", 1, breakawayTime, false), 1);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        chart.setPadding(new org.jfree.chart.ui.RectangleInsets(4, 4, 4, 16));   // room for the last time tick label
        return chart;
    }

    private static XYPlot panel(Recorder r, int k, int c2, int c3, String label, double scale, double tb, boolean legend) {
        XYSeriesCollection data = new XYSeriesCollection();
        data.addSeries(series(r, "joint " + k + "2", row -> r.get(k, c2, row) * scale));
        data.addSeries(series(r, "joint " + k + "3", row -> r.get(k, c3, row) * scale));
        NumberAxis y = new NumberAxis(label);
        y.setAutoRangeIncludesZero(true);
        XYLineAndShapeRenderer rr = renderer();
        rr.setDefaultSeriesVisibleInLegend(legend);
        XYPlot p = new XYPlot(data, null, y, rr);
        style(p);
        mark(p, legend ? tb : Double.NaN, tb);
        return p;
    }

    /** Fig. 8: total contact force on finger k against time. */
    public static JFreeChart figure8(Recorder r, int k, double breakawayTime, String title) {
        XYSeriesCollection data = new XYSeriesCollection();
        data.addSeries(series(r, "contact force, finger " + k, row -> r.force(k, row)));
        NumberAxis x = new NumberAxis("time t (s)");
        NumberAxis y = new NumberAxis("contact force (N)");
        XYPlot p = new XYPlot(data, x, y, renderer());
        style(p);
        mark(p, breakawayTime, breakawayTime);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), p, true);
        chart.setPadding(new org.jfree.chart.ui.RectangleInsets(4, 4, 4, 16));
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /**
     * A Fig. 7 of a few made-up rows, built as the real ones are: what {@link ChartSet#start}
     * draws and throws away to set up fonts, Java2D and JFreeChart while a run goes on.
     */
    public static JFreeChart warmUp() {
        Recorder r = new Recorder();
        for (int i = 0; i < 8; i++) {
            r.beginRow(i * 0.1);
            for (int c = Recorder.Q; c <= Recorder.TAU3; c++) r.set(1, c, Math.sin(i + c));
            r.setContacts(1, i % 3, i);
        }
        return figure7(r, 1, 0.35, "Joints 12 and 13 (warm-up)");
    }

    /** A recorded value against time, thinned to every n-th row (at most {@value #MAX_POINTS}), keeping the last. */
    private static XYSeries series(Recorder r, String name, IntToDoubleFunction valueAtRow) {
        XYSeries s = new XYSeries(name, false, true);
        int step = Math.max(1, r.rows() / MAX_POINTS);
        for (int row = 0; row < r.rows(); row += step) s.add(r.time(row), valueAtRow.applyAsDouble(row), false);
        if (r.rows() > 0) s.add(r.time(r.rows() - 1), valueAtRow.applyAsDouble(r.rows() - 1), false);
        return s;
    }

    static XYLineAndShapeRenderer renderer() {
        XYLineAndShapeRenderer rr = new XYLineAndShapeRenderer(true, false);
        rr.setDrawSeriesLineAsPath(true); // one SVG path per series, not one element per segment
        rr.setSeriesPaint(0, J2);
        rr.setSeriesPaint(1, J3);
        rr.setSeriesStroke(0, new BasicStroke(2f));
        rr.setSeriesStroke(1, new BasicStroke(2f));
        return rr;
    }

    static void style(XYPlot p) {
        p.setBackgroundPaint(Color.WHITE);
        p.setDomainGridlinePaint(new Color(0xdddddd));
        p.setRangeGridlinePaint(new Color(0xdddddd));
        p.getRangeAxis().setLabelFont(new Font("SansSerif", Font.PLAIN, 13));
    }

    /** A dashed line at the breakaway; labelled only where {@code labelAt} is not NaN. */
    private static void mark(XYPlot p, double labelAt, double tb) {
        if (Double.isNaN(tb)) return;
        ValueMarker m = new ValueMarker(tb, BREAK, new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f));
        if (!Double.isNaN(labelAt)) m.setLabel(String.format(java.util.Locale.ROOT, "breakaway %.3f s", tb));
        m.setLabelFont(new Font("SansSerif", Font.PLAIN, 11));
        m.setLabelAnchor(RectangleAnchor.TOP_RIGHT);
        m.setLabelTextAnchor(TextAnchor.TOP_LEFT);
        p.addDomainMarker(m);
    }
}
