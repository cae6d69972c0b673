package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import org.handsim.TestPaths;
import org.handsim.hand.HandDescription;
import org.handsim.model.HandModel;
import org.handsim.trace.Recorder;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.Marker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.data.xy.XYDataset;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Fig. 7 and 8 of the paper's experiment as paper-ready charts: the velocity jumps are impulses
 * in the acceleration panel (where the sampled trace alone reads 0), and no text covers data or
 * other text — the breakaway is named in the legend, the jumps' labels are placed clear.
 */
class PaperChartsTest {
    private static HandModel model;
    private static Recorder rec;

    @BeforeAll
    static void runThePaperExperiment() {
        model = Simulation.model(Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json")), true);
        model.run(null);
        rec = model.recorder();
    }

    private static double velocityDeg(int col, double t) {
        int row = 0;
        while (row + 1 < rec.rows() && rec.time(row + 1) <= t) row++;
        return Math.toDegrees(rec.get(3, col, row));
    }

    /**
     * Joint 32 stops when the inner link meets the cube (t ≈ 1.506 s) and again when the opened
     * finger's clutch re-engages (7.44 s); joint 33 jumps at the contact, at the breakaway (1.8 s),
     * when the outer link is stopped (2.113 s) and back on the way out. Each jump equals the
     * difference of the flat velocities 50 ms either side of it (read from the trace, not by the
     * detector's rule), and joint 32's first one is the motor's speed through the inner joint's
     * transmission, v_max / (counts per degree): the closing speed it stops from.
     */
    @Test
    void theVelocityJumpsAreFoundWithTheirSize() {
        List<VelocityJumps.Jump> j2 = PaperCharts.jumps(rec, 3, Recorder.DTH2, Recorder.DDTH2, 0, PaperCharts.J2);
        List<VelocityJumps.Jump> j3 = PaperCharts.jumps(rec, 3, Recorder.DTH3, Recorder.DDTH3, 1, PaperCharts.J3);
        double[] t2 = {1.506, 7.44}, t3 = {1.506, 1.8, 2.113, 6.834, 7.147, 7.44};
        assertEquals(t2.length, j2.size(), j2.toString());
        assertEquals(t3.length, j3.size(), j3.toString());
        for (int i = 0; i < t2.length; i++) assertEquals(t2[i], j2.get(i).t(), 0.01, "joint 32 jump " + i);
        for (int i = 0; i < t3.length; i++) assertEquals(t3[i], j3.get(i).t(), 0.01, "joint 33 jump " + i);
        List<VelocityJumps.Jump> all = new ArrayList<>(j2);
        all.addAll(j3);
        for (VelocityJumps.Jump j : all) {
            int col = j.series() == 0 ? Recorder.DTH2 : Recorder.DTH3;
            double across = velocityDeg(col, j.t() + 0.05) - velocityDeg(col, j.t() - 0.05);
            assertEquals(across, j.delta(), 0.02 * Math.abs(across) + 0.1, "jump at " + j.t());
            assertTrue(Math.abs(j.delta()) > 10, "tens of degrees per second: " + j.delta());
        }
        double vMax = Scenario.load(TestPaths.root().resolve("scenarios/paper-breakaway.json")).json().object("motors")
            .objectAt("M3", 0).number("v_max");
        assertEquals(-vMax / HandDescription.barrettHand().innerCountsPerDeg(), j2.get(0).delta(), 0.5, "joint 32 stops from v_max");
        assertEquals(1.8, model.breakawayTime(3), 1e-3);
    }

    /** What the acceleration panel shows at the jumps: an arrow each, labelled with its size. */
    @Test
    void figure7MarksTheJumpsAndNamesTheBreakawayInTheLegend() {
        JFreeChart c = PaperCharts.figure7(rec, 3, model.breakawayTime(3), "Fig. 7");
        CombinedDomainXYPlot plot = (CombinedDomainXYPlot) c.getPlot();
        @SuppressWarnings("unchecked")
        List<XYPlot> panels = plot.getSubplots();
        XYPlot acc = panels.get(2);
        assertEquals(1, acc.getAnnotations().size());
        VelocityJumps marks = (VelocityJumps) acc.getAnnotations().get(0);
        assertEquals(8, marks.jumps().size());
        assertEquals("+45°/s", marks.label(marks.jumps().stream().filter(j -> Math.abs(j.t() - 1.8) < 0.01).findFirst().get()));
        assertTrue(acc.getRangeAxis().getLowerBound() < 0 && acc.getRangeAxis().getUpperBound() > 0, "room for arrows up and down");
        // the breakaway: a dashed line in every panel, its name and time in the legend, no label on the data
        for (XYPlot p : panels) {
            for (Object m : p.getDomainMarkers(org.jfree.chart.ui.Layer.FOREGROUND)) assertNull(((Marker) m).getLabel());
        }
        List<String> legend = new ArrayList<>();
        for (int i = 0; i < plot.getLegendItems().getItemCount(); i++) legend.add(plot.getLegendItems().get(i).getLabel());
        assertTrue(legend.contains("breakaway at 1.800 s"), legend.toString());
        assertTrue(legend.contains("joint 32") && legend.contains("joint 33"), legend.toString());
        assertTrue(legend.stream().anyMatch(l -> l.startsWith("velocity jump")), legend.toString());

        // drawn: the jump labels inside the panel, clear of each other and of every data point
        ChartRenderingInfo info = new ChartRenderingInfo();
        c.createBufferedImage(900, 1100, info);
        Rectangle2D area = info.getPlotInfo().getSubplotInfo(2).getDataArea();
        List<Rectangle2D> boxes = marks.labelBoxes();
        assertEquals(8, boxes.size());
        XYDataset d = acc.getDataset();
        for (int i = 0; i < boxes.size(); i++) {
            Rectangle2D b = boxes.get(i);
            assertTrue(area.contains(b), "inside the panel: " + b);
            for (int k = i + 1; k < boxes.size(); k++) assertFalse(b.intersects(boxes.get(k)), "labels overlap: " + b + " " + boxes.get(k));
            for (int s = 0; s < d.getSeriesCount(); s++) {
                for (int n = 0; n < d.getItemCount(s); n++) {
                    double x = plot.getDomainAxis().valueToJava2D(d.getXValue(s, n), area, RectangleEdge.BOTTOM);
                    double y = acc.getRangeAxis().valueToJava2D(d.getYValue(s, n), area, RectangleEdge.LEFT);
                    assertFalse(b.contains(x, y), "label " + b + " covers the data point at t = " + d.getXValue(s, n));
                }
            }
        }
    }

    @Test
    void figure8NamesTheBreakawayInTheLegend() {
        JFreeChart c = PaperCharts.figure8(rec, 3, model.breakawayTime(3), "Fig. 8");
        XYPlot p = c.getXYPlot();
        for (Object m : p.getDomainMarkers(org.jfree.chart.ui.Layer.FOREGROUND)) assertNull(((Marker) m).getLabel());
        List<String> legend = new ArrayList<>();
        for (int i = 0; i < p.getLegendItems().getItemCount(); i++) legend.add(p.getLegendItems().get(i).getLabel());
        assertEquals(List.of("contact force, finger 3", "breakaway at 1.800 s"), legend);
    }
}
