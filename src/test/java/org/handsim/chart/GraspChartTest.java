package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.handsim.grasp.GraspQuality;
import org.handsim.grasp.GraspAssessment;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.Test;

/** The grasp chart's axes name their units (ε in newtons, the wrench space's force unit, as the README says). */
class GraspChartTest {
    @Test
    void everyAxisHasItsUnit() {
        List<GraspAssessment> samples = List.of(
            new GraspAssessment(0.0, GraspQuality.none(0, 0), new double[6], 0, new double[3][3], 58.84, List.of(), new double[3], new double[3], 0.1, 0.5, 8,
                new double[3][3]),
            new GraspAssessment(0.1, GraspQuality.none(0, 0), new double[6], 0, new double[3][3], 58.84, List.of(), new double[3], new double[3], 0.1, 0.5, 8,
                new double[3][3]));
        JFreeChart c = GraspChart.epsilonAndHold(samples, new double[] {Double.NaN, Double.NaN, Double.NaN}, 58.84, "test");
        CombinedDomainXYPlot p = (CombinedDomainXYPlot) c.getPlot();
        assertEquals("time t (s)", p.getDomainAxis().getLabel());
        @SuppressWarnings("unchecked")
        List<XYPlot> panels = p.getSubplots();
        assertEquals("ε (N)", panels.get(0).getRangeAxis().getLabel());
        for (XYPlot panel : panels) {
            ValueAxis y = panel.getRangeAxis();
            assertTrue(y.getLabel().matches(".*\\([^)]+\\)$"), "a unit in parentheses: " + y.getLabel());
        }
    }
}
