package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.util.List;
import java.util.Locale;
import org.handsim.hold.DirectionResult;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * The hold test against time: the object's displacement (top) and rotation (bottom) from its
 * place at release for each of the six pushes, on log axes — a held object moves micrometres, a
 * dropped one centimetres — with the pass thresholds dashed. A push that stopped once the
 * object had settled is drawn flat from there.
 */
public final class HoldTestChart {
    /** One colour per direction, in the test's order −x, +x, −y, +y, −z, +z (pairs share a hue: light for −, dark for +). */
    static final Color[] COLORS = {new Color(0xff7f0e), new Color(0xd62728), new Color(0x2ca02c), new Color(0x17becf),
        new Color(0x9467bd), new Color(0x1f77b4)};
    static final Color THRESHOLD = new Color(0x7f7f7f);
    /** The log axes' floor: displacements below 1 nm and rotations below 1e-6° are drawn there. */
    static final double FLOOR_M = 1e-9, FLOOR_DEG = 1e-6;

    private HoldTestChart() {}

    /**
     * @param pushes         the six pushes
     * @param maxDisplacementM the displacement threshold, m
     * @param maxRotationDeg the rotation threshold, degrees
     */
    public static JFreeChart displacementAndRotation(List<DirectionResult> pushes, double maxDisplacementM, double maxRotationDeg, String title) {
        XYSeriesCollection disp = new XYSeriesCollection(), rot = new XYSeriesCollection();
        for (DirectionResult d : pushes) {
            String key = d.direction() + (d.passed() ? " held" : " failed");
            XYSeries a = new XYSeries(key, false, true), b = new XYSeries(key, false, true);
            double[] t = d.times(), x = d.displacements(), r = d.rotations();
            for (int i = 1; i < t.length; i++) {
                a.add(t[i], Math.max(FLOOR_M, x[i]) * 1000, false);
                b.add(t[i], Math.max(FLOOR_DEG, r[i]), false);
            }
            disp.addSeries(a);
            rot.addSeries(b);
        }
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(new NumberAxis("time since release t (s)"));
        plot.setGap(10);
        XYPlot top = panel(disp, "displacement (mm, log)", FLOOR_M * 1000, maxDisplacementM * 1000);
        XYPlot bottom = panel(rot, "rotation (°, log)", FLOOR_DEG, maxRotationDeg);
        BasicStroke dashed = new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);
        top.addRangeMarker(new ValueMarker(maxDisplacementM * 1000, THRESHOLD, dashed));
        bottom.addRangeMarker(new ValueMarker(maxRotationDeg, THRESHOLD, dashed));
        LegendItemCollection legend = new LegendItemCollection();
        for (int i = 0; i < pushes.size(); i++) {
            legend.add(PaperCharts.line(disp.getSeriesKey(i).toString(), COLORS[i % COLORS.length], PaperCharts.SOLID));
        }
        legend.add(PaperCharts.line(String.format(Locale.ROOT, "thresholds %s mm, %s°", trim(maxDisplacementM * 1000), trim(maxRotationDeg)),
            THRESHOLD, dashed));
        plot.setFixedLegendItems(legend);
        plot.add(top, 1);
        plot.add(bottom, 1);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /** A log panel from a decade below its smallest value (not below {@code floor}) to a decade above the threshold or the data. */
    private static XYPlot panel(XYSeriesCollection data, String label, double floor, double threshold) {
        LogAxis y = new LogAxis(label);
        y.setBase(10);
        y.setSmallestValue(floor);
        double lo = Double.POSITIVE_INFINITY, hi = threshold;
        for (int i = 0; i < data.getSeriesCount(); i++) {
            XYSeries s = data.getSeries(i);
            if (s.getItemCount() == 0) continue;
            lo = Math.min(lo, s.getMinY());
            hi = Math.max(hi, s.getMaxY());
        }
        if (!(lo < hi)) lo = floor;
        y.setRange(Math.max(floor, Math.pow(10, Math.floor(Math.log10(lo)))), Math.pow(10, Math.ceil(Math.log10(hi)) + 0.3));
        y.setTickUnit(new org.jfree.chart.axis.NumberTickUnit(1));
        y.setMinorTickMarksVisible(true);
        y.setNumberFormatOverride(new java.text.DecimalFormat("0E0", java.text.DecimalFormatSymbols.getInstance(Locale.ROOT)));
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, false);
        r.setDrawSeriesLineAsPath(true);
        for (int i = 0; i < data.getSeriesCount(); i++) {
            r.setSeriesPaint(i, COLORS[i % COLORS.length]);
            r.setSeriesStroke(i, new BasicStroke(2f));
        }
        XYPlot p = new XYPlot(data, null, y, r);
        PaperCharts.style(p);
        return p;
    }

    private static String trim(double v) {
        return org.handsim.text.Decimal.format(v);
    }
}
