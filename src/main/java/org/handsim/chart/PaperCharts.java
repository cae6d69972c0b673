package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.util.function.IntToDoubleFunction;
import org.handsim.trace.Recorder;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItem;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * The paper's Fig. 7 (angle, velocity, acceleration and torque of joints k2 and k3 against time,
 * the breakaway marked) and Fig. 8 (contact force on the finger against time), from a
 * {@link Recorder}. Traces with more points than a chart can show are thinned to at most
 * {@value #MAX_POINTS} points (every n-th row, keeping the last).
 *
 * <p>Velocity jumps — a contact stopping a link, the breakaway freeing one — are impulses of the
 * acceleration: the acceleration panel draws each as an arrow labelled with the jump
 * ({@link VelocityJumps}), where the sampled trace alone shows 0. Nothing is written over the
 * data: the breakaway's dashed line is named in the legend, with its time.
 */
public final class PaperCharts {
    static final int MAX_POINTS = Recorder.CHART_POINTS;
    /** Pixels between the stacked plots of Fig. 7. */
    static final int GAP = 18;
    static final Color J2 = new Color(0x1f77b4), J3 = new Color(0xd62728), BREAK = new Color(0x2ca02c);
    /**
     * Smallest velocity change within one trace interval, beyond what the recorded acceleration
     * accounts for, that is drawn as a jump: 1°/s (0.017 rad/s). A smooth ramp's change is
     * accounted for by its acceleration to far better than this; the jumps of a contact or a
     * breakaway are tens of degrees per second.
     */
    static final double JUMP_RAD_S = Math.toRadians(1.0);

    private PaperCharts() {}

    /** Fig. 7 for finger k; {@code breakawayTime} NaN for none. */
    public static JFreeChart figure7(Recorder r, int k, double breakawayTime, String title) {
        NumberAxis time = new NumberAxis("time t (s)");
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(time);
        plot.setGap(GAP);   // more than a tick label's height: the labels of neighbouring plots never meet
        plot.add(panel(r, k, Recorder.TH2, Recorder.TH3, "angle (deg)", Math.toDegrees(1), breakawayTime), 1);
        plot.add(panel(r, k, Recorder.DTH2, Recorder.DTH3, "velocity (deg/s)", Math.toDegrees(1), breakawayTime), 1);
        XYPlot acc = panel(r, k, Recorder.DDTH2, Recorder.DDTH3, "acceleration (deg/s²)", Math.toDegrees(1), breakawayTime);
        List<VelocityJumps.Jump> jumps = new ArrayList<>();
        jumps.addAll(jumps(r, k, Recorder.DTH2, Recorder.DDTH2, 0, J2));
        jumps.addAll(jumps(r, k, Recorder.DTH3, Recorder.DDTH3, 1, J3));
        jumps.sort(Comparator.comparingDouble(VelocityJumps.Jump::t));
        if (!jumps.isEmpty()) {
            acc.addAnnotation(new VelocityJumps(jumps, "°/s"));
            NumberAxis y = (NumberAxis) acc.getRangeAxis();
            // room for the arrows on both sides of the zero line
            org.jfree.data.Range data = y.getRange();
            double span = Math.max(Math.abs(data.getUpperBound()), Math.abs(data.getLowerBound()));
            if (!(span > 0)) span = 1;
            boolean neg = jumps.stream().anyMatch(j -> j.delta() < 0), pos = jumps.stream().anyMatch(j -> j.delta() > 0);
            y.setAutoRange(false);
            y.setRange(Math.min(data.getLowerBound(), neg ? -span : 0), Math.max(data.getUpperBound(), pos ? span : 0) * 1.02);
        }
        plot.add(acc, 1);
        plot.add(panel(r, k, Recorder.TAU2, Recorder.TAU3, "torque (N·m)", 1, breakawayTime), 1);
        LegendItemCollection legend = new LegendItemCollection();
        legend.add(line("joint " + k + "2", J2, SOLID));
        legend.add(line("joint " + k + "3", J3, SOLID));
        if (!Double.isNaN(breakawayTime)) legend.add(line(breakawayName(breakawayTime), BREAK, DASHED));
        if (!jumps.isEmpty()) legend.add(new LegendItem("velocity jump (an impulse of the acceleration; the jump beside it)", null, null, null,
            arrowShape(), Color.DARK_GRAY));
        plot.setFixedLegendItems(legend);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        chart.setPadding(new org.jfree.chart.ui.RectangleInsets(4, 4, 4, 16));   // room for the last time tick label
        return chart;
    }

    private static XYPlot panel(Recorder r, int k, int c2, int c3, String label, double scale, double tb) {
        XYSeriesCollection data = new XYSeriesCollection();
        data.addSeries(series(r, "joint " + k + "2", row -> r.get(k, c2, row) * scale));
        data.addSeries(series(r, "joint " + k + "3", row -> r.get(k, c3, row) * scale));
        NumberAxis y = new NumberAxis(label);
        y.setAutoRangeIncludesZero(true);
        XYPlot p = new XYPlot(data, null, y, renderer());
        style(p);
        mark(p, tb);
        return p;
    }

    /**
     * The velocity jumps of finger k's joint (velocity column {@code vel}, acceleration column
     * {@code acc}) in the recorded rows: the intervals whose velocity change exceeds what the
     * recorded accelerations at their ends account for (the trapezoid rule) by more than
     * {@link #JUMP_RAD_S}; each in degrees per second at the interval's end.
     */
    static List<VelocityJumps.Jump> jumps(Recorder r, int k, int vel, int acc, int series, Color colour) {
        List<VelocityJumps.Jump> out = new ArrayList<>();
        for (int row = 1; row < r.rows(); row++) {
            double dt = r.time(row) - r.time(row - 1);
            double dv = r.get(k, vel, row) - r.get(k, vel, row - 1);
            double smooth = 0.5 * (r.get(k, acc, row) + r.get(k, acc, row - 1)) * dt;
            double jump = dv - smooth;
            if (Math.abs(jump) > JUMP_RAD_S) out.add(new VelocityJumps.Jump(r.time(row), Math.toDegrees(jump), series, colour));
        }
        return out;
    }

    /** Fig. 8: total contact force on finger k against time. */
    public static JFreeChart figure8(Recorder r, int k, double breakawayTime, String title) {
        XYSeriesCollection data = new XYSeriesCollection();
        data.addSeries(series(r, "contact force, finger " + k, row -> r.force(k, row)));
        NumberAxis x = new NumberAxis("time t (s)");
        NumberAxis y = new NumberAxis("contact force (N)");
        XYPlot p = new XYPlot(data, x, y, renderer());
        style(p);
        mark(p, breakawayTime);
        LegendItemCollection legend = new LegendItemCollection();
        legend.add(line("contact force, finger " + k, J2, SOLID));
        if (!Double.isNaN(breakawayTime)) legend.add(line(breakawayName(breakawayTime), BREAK, DASHED));
        p.setFixedLegendItems(legend);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), p, true);
        chart.setPadding(new org.jfree.chart.ui.RectangleInsets(4, 4, 4, 16));
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /**
     * The free object's motion relative to the palm against time (the trace's {@code obj_disp_m}
     * and {@code obj_rot_deg}): displacement of its centre of mass (mm) above, rotation (degrees)
     * below, the release ({@code releasedAt}) and a drop ({@code droppedAt}; NaN: none) marked:
     * how far the object moved in the hand, what a lift or a push is judged by.
     */
    public static JFreeChart objectMotion(Recorder r, double releasedAt, double droppedAt, String title) {
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(new NumberAxis("time t (s)"));
        plot.setGap(10);
        XYSeriesCollection d = new XYSeriesCollection();
        d.addSeries(series(r, "displacement relative to the palm", row -> 1e3 * r.object(Recorder.OBJ_DISP, row)));
        XYPlot top = new XYPlot(d, null, new NumberAxis("displacement (mm)"), renderer());
        XYSeriesCollection a = new XYSeriesCollection();
        a.addSeries(series(r, "rotation relative to the palm", row -> r.object(Recorder.OBJ_ROT, row)));
        XYLineAndShapeRenderer rr = renderer();
        rr.setSeriesPaint(0, J3);
        XYPlot bottom = new XYPlot(a, null, new NumberAxis("rotation (°)"), rr);
        LegendItemCollection legend = new LegendItemCollection();
        legend.add(line("displacement of the centre of mass, relative to the palm", J2, SOLID));
        legend.add(line("rotation, relative to the palm", J3, SOLID));
        for (XYPlot p : new XYPlot[] {top, bottom}) {
            style(p);
            NumberAxis y = (NumberAxis) p.getRangeAxis();
            y.setAutoRangeIncludesZero(true);
            y.setAutoRangeMinimumSize(1e-3);   // an object that does not turn: a flat line, not ticks of 1e-9
            if (!Double.isNaN(releasedAt)) p.addDomainMarker(new ValueMarker(releasedAt, Color.GRAY, DASHED));
            if (!Double.isNaN(droppedAt)) p.addDomainMarker(new ValueMarker(droppedAt, BREAK, DASHED));
            plot.add(p, 1);
        }
        if (!Double.isNaN(releasedAt)) legend.add(line(String.format(java.util.Locale.ROOT, "released at %.3f s", releasedAt), Color.GRAY, DASHED));
        if (!Double.isNaN(droppedAt)) legend.add(line(String.format(java.util.Locale.ROOT, "dropped at %.3f s", droppedAt), BREAK, DASHED));
        plot.setFixedLegendItems(legend);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, true);
        chart.setPadding(new org.jfree.chart.ui.RectangleInsets(4, 4, 4, 16));
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /** The legend's name of the breakaway line. */
    static String breakawayName(double tb) {
        return String.format(java.util.Locale.ROOT, "breakaway at %.3f s", tb);
    }

    static final BasicStroke SOLID = new BasicStroke(2f);
    static final BasicStroke DASHED = new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);

    /** A legend entry drawn as a line in the given colour and stroke. */
    static LegendItem line(String name, Color c, BasicStroke stroke) {
        LegendItem li = new LegendItem(name, null, null, null, new java.awt.geom.Line2D.Double(-12, 0, 12, 0), stroke, c);
        return li;
    }

    private static java.awt.Shape arrowShape() {
        java.awt.geom.GeneralPath a = new java.awt.geom.GeneralPath();
        a.moveTo(-1, 7);
        a.lineTo(1, 7);
        a.lineTo(1, -2);
        a.lineTo(4, -2);
        a.lineTo(0, -8);
        a.lineTo(-4, -2);
        a.lineTo(-1, -2);
        a.closePath();
        return a;
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
        rr.setSeriesStroke(0, SOLID);
        rr.setSeriesStroke(1, SOLID);
        return rr;
    }

    static void style(XYPlot p) {
        p.setBackgroundPaint(Color.WHITE);
        p.setDomainGridlinePaint(new Color(0xdddddd));
        p.setRangeGridlinePaint(new Color(0xdddddd));
        p.getRangeAxis().setLabelFont(new Font("SansSerif", Font.PLAIN, 13));
    }

    /** A dashed line at the breakaway (named in the legend, not over the data). */
    private static void mark(XYPlot p, double tb) {
        if (Double.isNaN(tb)) return;
        p.addDomainMarker(new ValueMarker(tb, BREAK, DASHED));
    }
}
