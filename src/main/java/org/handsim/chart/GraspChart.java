package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.handsim.grasp.GraspAssessment;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * The grasp against time, two panels over one time axis: the Ferrari–Canny ε of the
 * grasp wrench space (top) and the smallest load the grasp holds over the six world directions
 * (bottom, with the hand's rated load, the largest hold reported, dashed), from
 * {@link GraspAssessment}s sampled along a run; the fingers' breakaways marked.
 */
public final class GraspChart {
    /**
     * The ε axis: newtons, since every cone edge has a normal component of 1 N and the torques are
     * divided by R (the wrench space's force unit, README "handsim quality").
     */
    static final String EPSILON_AXIS = "ε (N)";
    static final Color EPSILON = new Color(0x1f77b4), HOLD = new Color(0xd62728), CAP = new Color(0x7f7f7f);

    private GraspChart() {}

    /**
     * @param samples        assessments in time order
     * @param breakawayTimes the breakaway time of each finger 1..3 (NaN: none)
     * @param capN           the largest hold reported (the hand's rating), newtons
     */
    public static JFreeChart epsilonAndHold(List<GraspAssessment> samples, double[] breakawayTimes, double capN, String title) {
        XYSeries eps = new XYSeries("ε (Ferrari–Canny, wrench torques / R)", false, true);
        XYSeries hold = new XYSeries("smallest hold over ±x, ±y, ±z", false, true);
        for (GraspAssessment g : samples) {
            eps.add(g.timeS(), g.quality().epsilon(), false);
            hold.add(g.timeS(), g.holdMinN(), false);
        }
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(new NumberAxis("time t (s)"));
        plot.setGap(10);
        XYPlot top = panel(eps, EPSILON_AXIS, EPSILON);
        XYPlot bottom = panel(hold, "smallest hold (N)", HOLD);
        // nothing over the data: the rated load's and the breakaways' dashed lines are named in the legend
        bottom.addRangeMarker(new ValueMarker(capN, CAP, dashed(1.2f)));
        ((NumberAxis) bottom.getRangeAxis()).setUpperBound(capN * 1.12);
        LegendItemCollection legend = new LegendItemCollection();
        legend.add(PaperCharts.line(eps.getKey().toString(), EPSILON, PaperCharts.SOLID));
        legend.add(PaperCharts.line(hold.getKey().toString(), HOLD, PaperCharts.SOLID));
        legend.add(PaperCharts.line(String.format(Locale.ROOT, "hand's rated load %.2f N", capN), CAP, dashed(1.2f)));
        // one line per distinct breakaway time, naming its fingers
        Map<Double, List<String>> at = new TreeMap<>();
        for (int k = 0; k < breakawayTimes.length; k++) {
            if (!Double.isNaN(breakawayTimes[k])) at.computeIfAbsent(breakawayTimes[k], x -> new ArrayList<>()).add(Integer.toString(k + 1));
        }
        for (Map.Entry<Double, List<String>> e : at.entrySet()) {
            String label = (e.getValue().size() == 1 ? "breakaway, finger " : "breakaway, fingers ") + String.join(", ", e.getValue());
            top.addDomainMarker(marker(e.getKey()));
            bottom.addDomainMarker(marker(e.getKey()));
            legend.add(PaperCharts.line(label + String.format(Locale.ROOT, " at %.3f s", e.getKey()), PaperCharts.BREAK, PaperCharts.DASHED));
        }
        plot.setFixedLegendItems(legend);
        plot.add(top, 1);
        plot.add(bottom, 1);
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    private static XYPlot panel(XYSeries s, String label, Color c) {
        NumberAxis y = new NumberAxis(label);
        y.setAutoRangeIncludesZero(true);
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, false);
        r.setDrawSeriesLineAsPath(true);
        r.setSeriesPaint(0, c);
        r.setSeriesStroke(0, new BasicStroke(2f));
        XYPlot p = new XYPlot(new XYSeriesCollection(s), null, y, r);
        PaperCharts.style(p);
        return p;
    }

    private static ValueMarker marker(double t) {
        return new ValueMarker(t, PaperCharts.BREAK, PaperCharts.DASHED);
    }

    private static BasicStroke dashed(float width) {
        return new BasicStroke(width, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);
    }
}
