package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.util.List;
import java.util.Locale;
import org.handsim.sim.GraspAssessment;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleAnchor;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * The grasp against time (issue 12): the Ferrari–Canny ε of the grasp wrench space (left axis)
 * and the smallest load the grasp holds over the six world directions (right axis), from
 * {@link GraspAssessment}s sampled along a run; the fingers' breakaways marked.
 */
public final class GraspChart {
    static final Color EPSILON = new Color(0x1f77b4), HOLD = new Color(0xd62728);

    private GraspChart() {}

    /**
     * @param samples        assessments in time order
     * @param breakawayTimes the breakaway time of each finger (NaN: none)
     */
    public static JFreeChart epsilonAndHold(List<GraspAssessment> samples, double[] breakawayTimes, String title) {
        XYSeries eps = new XYSeries("ε (Ferrari–Canny, scaled wrench)", false, true);
        XYSeries hold = new XYSeries("smallest hold over ±x, ±y, ±z (N)", false, true);
        for (GraspAssessment g : samples) {
            eps.add(g.timeS(), g.quality().epsilon(), false);
            hold.add(g.timeS(), g.holdMinN(), false);
        }
        NumberAxis time = new NumberAxis("time t (s)");
        NumberAxis left = new NumberAxis("ε");
        NumberAxis right = new NumberAxis("smallest hold (N)");
        left.setAutoRangeIncludesZero(true);
        right.setAutoRangeIncludesZero(true);
        left.setLabelPaint(EPSILON);
        right.setLabelPaint(HOLD);
        XYPlot p = new XYPlot(new XYSeriesCollection(eps), time, left, renderer(EPSILON));
        p.setRangeAxis(1, right);
        p.setDataset(1, new XYSeriesCollection(hold));
        p.setRenderer(1, renderer(HOLD));
        p.mapDatasetToRangeAxis(1, 1);
        PaperCharts.style(p);
        for (int k = 0; k < breakawayTimes.length; k++) {
            double tb = breakawayTimes[k];
            if (Double.isNaN(tb)) continue;
            ValueMarker m = new ValueMarker(tb, PaperCharts.BREAK,
                new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f));
            m.setLabel(String.format(Locale.ROOT, "breakaway %d", k + 1));
            m.setLabelFont(new Font("SansSerif", Font.PLAIN, 11));
            m.setLabelAnchor(RectangleAnchor.TOP_LEFT);
            m.setLabelTextAnchor(TextAnchor.TOP_RIGHT);
            p.addDomainMarker(m);
        }
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), p, true);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    private static XYLineAndShapeRenderer renderer(Color c) {
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, false);
        r.setDrawSeriesLineAsPath(true);
        r.setSeriesPaint(0, c);
        r.setSeriesStroke(0, new BasicStroke(2f));
        return r;
    }
}
