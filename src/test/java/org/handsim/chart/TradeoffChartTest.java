package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.Test;

/** The table behind a chart and the chart: CSV contract, log axes over whole decades, zero errors, labels. */
class TradeoffChartTest {
    private static StudyTable table() {
        return new StudyTable("9-test", "test", List.of("cost_s", "error"), "cost_s", "error", "cost", "error")
            .add("a", "fast", false, 1e-4, 1e-2)
            .add("a", "default", true, 1e-3, 1e-5)
            .add("a", "slow and worse", false, 1e-2, 1e-3)
            .add("b", "exact", false, 2e-3, 0.0);
    }

    @Test
    void csvHasTheContractHeaderAndEveryRow() throws Exception {
        Path dir = Files.createTempDirectory("tradeoff");
        TradeoffChart.write(table(), dir);
        List<String> lines = Files.readAllLines(dir.resolve("9-test.csv"));
        assertEquals("series,setting,default,cost_s,error", lines.get(0));
        assertEquals("a,default,true,0.001,0.00001", lines.get(2), "text.Decimal: plain decimals from 1e-6");
        assertEquals("b,exact,false,0.002,0", lines.get(4), "a zero error stays 0 in the CSV");
        assertTrue(Files.size(dir.resolve("9-test.png")) > 1000);
        assertTrue(Files.readString(dir.resolve("9-test.svg")).contains("<svg"));
    }

    @Test
    void axesSpanWholeDecadesAndZeroIsDrawnAtTheFloor() {
        JFreeChart c = TradeoffChart.create(table());
        XYPlot p = c.getXYPlot();
        LogAxis x = (LogAxis) p.getDomainAxis(), y = (LogAxis) p.getRangeAxis();
        assertEquals(1e-4, x.getLowerBound(), 1e-18);
        assertEquals(1e-2, x.getUpperBound(), 1e-16);
        // y: the smallest positive error is 1e-5, so 0 is drawn at 1e-6; the axis spans 1e-6 .. 1e-2
        assertEquals(1e-6, y.getLowerBound(), 1e-20);
        assertEquals(1e-2, y.getUpperBound(), 1e-16);
        assertEquals(1e-6, p.getDataset().getYValue(2, 0), 1e-20, "series b's point");
        assertTrue(y.getLabel().contains("0 (exact) drawn on the floor"), "the chart says where 0 is drawn: " + y.getLabel());
        assertEquals(0, c.getSubtitleCount() - 1, "no caption under the plot, only the legend");
    }

    @Test
    void theFrontSkipsTheDominatedPointAndCrowdedChartsLabelOnlyIt() {
        StudyTable t = table();
        XYPlot p = TradeoffChart.create(t).getXYPlot();
        // series 0: a's points; series 1: a's front (fast, default — not "slow and worse")
        assertEquals(3, p.getDataset().getItemCount(0));
        assertEquals(2, p.getDataset().getItemCount(1));
        var gen = p.getRenderer().getDefaultItemLabelGenerator();
        assertEquals("slow and worse", gen.generateLabel(p.getDataset(), 0, 2));
        XYPlot q = TradeoffChart.create(t.labelEveryPoint(false)).getXYPlot();
        var gen2 = q.getRenderer().getDefaultItemLabelGenerator();
        assertEquals("fast", gen2.generateLabel(q.getDataset(), 0, 0));
        assertEquals("default", gen2.generateLabel(q.getDataset(), 0, 1));
        assertEquals(null, gen2.generateLabel(q.getDataset(), 0, 2));
    }

    @Test
    void pointLabelsNeverOverlapAndTheLastTickLabelIsNotCut() {
        // three series on the same x values with y values close together: labels at a fixed offset collided
        StudyTable t = new StudyTable("9-crowd", "crowd", List.of("cost_s", "error"), "cost_s", "error", "cost", "error");
        double[] xs = {2.6e-4, 2.9e-4, 3.1e-4, 4e-4, 8e-4, 1.6e-3, 3.7e-3, 7.3e-3, 1.1e-2};
        String[] names = {"20 ms", "10 ms", "5 ms", "2 ms", "1 ms", "0.5 ms", "0.2 ms", "0.1 ms", "0.05 ms"};
        for (String series : new String[] {"breakaway", "peak force", "peak torque"}) {
            for (int i = 0; i < xs.length; i++) {
                double y = series.equals("peak torque") ? 2e-15 : (series.equals("breakaway") ? 4e-14 : 6e-14) * (1 - 0.05 * i);
                t.add(series, names[i], i == 4, xs[i], y);
            }
        }
        JFreeChart c = TradeoffChart.create(t.labelEveryPoint(true));
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(1000, 700, java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = img.createGraphics();
        c.draw(g, new java.awt.Rectangle(0, 0, 1000, 700));
        LabelPlacingRenderer r = (LabelPlacingRenderer) c.getXYPlot().getRenderer();
        List<java.awt.geom.Rectangle2D> boxes = r.labelBoxes();
        assertTrue(boxes.size() >= 20, "most of the 27 labels find a place: " + boxes.size());
        for (int i = 0; i < boxes.size(); i++) {
            assertTrue(r.dataArea().contains(boxes.get(i)), "inside the plot: " + boxes.get(i));
            for (int j = i + 1; j < boxes.size(); j++) {
                assertTrue(!boxes.get(i).intersects(boxes.get(j)), "labels " + boxes.get(i) + " and " + boxes.get(j) + " overlap");
            }
            for (java.awt.geom.Line2D l : r.segmentsDrawn()) {
                assertTrue(!l.intersects(boxes.get(i)), "label " + boxes.get(i) + " crosses a Pareto front's line");
            }
        }
        // the x axis ends on a labelled decade: half its label must fit right of the plot
        LogAxis x = (LogAxis) c.getXYPlot().getDomainAxis();
        String last = x.getNumberFormatOverride().format(x.getUpperBound());
        double half = g.getFontMetrics(x.getTickLabelFont()).stringWidth(last) / 2.0;
        assertTrue(r.dataArea().getMaxX() + half <= 1000, "the last tick label " + last + " ends at " + (r.dataArea().getMaxX() + half));
        g.dispose();
    }

    /** Log axes read as a paper writes them. */
    @Test
    void logTicksArePowersOfTen() {
        PowerOfTen f = new PowerOfTen();
        assertEquals("10⁻¹²", f.format(1e-12));
        assertEquals("10⁰", f.format(1));
        assertEquals("10³", f.format(1000));
        assertEquals("2×10⁻³", f.format(0.002));
        JFreeChart c = TradeoffChart.create(table());
        assertEquals("10⁻⁶", ((LogAxis) c.getXYPlot().getRangeAxis()).getNumberFormatOverride().format(1e-6));
    }

    /**
     * A study whose few settings every series shares (the k of the k-DOPs over seven objects):
     * a marker shape per setting, named in the legend, and no point labels — labels of seven
     * series' "k=18 (default)" and "k=26" piled up in one cluster. Two defaults on one spot get
     * rings of different sizes, both seen.
     */
    @Test
    void fewSharedSettingsAreShapesInTheLegendAndCoincidentDefaultsBothShow() {
        StudyTable t = new StudyTable("9-k", "k", List.of("cost_s", "tests"), "cost_s", "tests", "cost", "tests");
        String[] ks = {"k=6", "k=14", "k=18", "k=26", "brute force"};
        String[] objects = {"cone", "cube", "mug", "ring", "sphere", "lblock", "cylinder"};
        for (int o = 0; o < objects.length; o++) {
            String object = objects[o];
            for (int i = 0; i < ks.length; i++) {
                double x = i == 4 ? 1e-2 * (1 + 0.2 * o) : 1e-4 * (1 + 0.1 * i), y = i == 4 ? 1e6 : 200 * (1 + o);
                // cube and mug: the same default point
                if (i == 2 && (object.equals("cube") || object.equals("mug"))) { x = 1.3e-4; y = 70; }
                t.add(object, ks[i], i == 2, x, y);
            }
        }
        JFreeChart c = TradeoffChart.create(t);
        XYPlot p = c.getXYPlot();
        LabelPlacingRenderer r = (LabelPlacingRenderer) p.getRenderer();
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(1000, 700, java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = img.createGraphics();
        c.draw(g, new java.awt.Rectangle(0, 0, 1000, 700));
        g.dispose();
        assertEquals(0, r.labelBoxes().size(), "no point labels");
        java.util.Set<String> legend = new java.util.HashSet<>();
        for (int i = 0; i < p.getLegendItems().getItemCount(); i++) legend.add(p.getLegendItems().get(i).getLabel());
        for (String k : ks) assertTrue(legend.contains(k), "legend names " + k + ": " + legend);
        // each setting its own shape, the same in every series
        java.util.Set<String> shapes = new java.util.HashSet<>();
        for (int i = 0; i < ks.length; i++) shapes.add(r.getItemShape(0, i).getBounds2D().toString() + r.getItemShape(0, i).getClass());
        assertEquals(ks.length, shapes.size());
        assertEquals(r.getItemShape(0, 3).getBounds2D(), r.getItemShape(2 * 6, 3).getBounds2D());
        // seven defaults ringed; the cube's and the mug's on one spot with different radii
        List<double[]> rings = r.ringsDrawn();
        assertEquals(7, rings.size());
        int together = 0;
        for (int i = 0; i < rings.size(); i++) {
            for (int k = i + 1; k < rings.size(); k++) {
                double[] a = rings.get(i), b = rings.get(k);
                if (Math.hypot(a[0] - b[0], a[1] - b[1]) < 1) {
                    together++;
                    assertTrue(Math.abs(a[2] - b[2]) >= 3, "concentric rings of different sizes: " + a[2] + ", " + b[2]);
                }
            }
        }
        assertEquals(1, together, "the cube's and the mug's defaults share one spot");
    }

    /**
     * Every series the legend names is visible: a series whose points all lie on an earlier
     * series' points (the tessellation study's cube centre and normal, both exact, on the floor)
     * is drawn with a larger hollow marker around them, and the legend says whose points it shares.
     * The fronts' legend claims nothing about errors (the k-DOP chart's y is a count of tests).
     */
    @Test
    void aSeriesOnAnotherSeriesPointsIsDrawnAroundThemAndTheLegendSaysSo() {
        StudyTable t = new StudyTable("9-same", "same", List.of("cost_s", "error"), "cost_s", "error", "cost", "error")
            .add("centre", "1", true, 1e-5, 0.0).add("centre", "2", false, 2e-5, 0.0)
            .add("normal", "1", true, 1e-5, 0.0).add("normal", "2", false, 2e-5, 0.0)
            .add("other", "1", true, 1e-5, 1e-3);
        JFreeChart c = TradeoffChart.create(t);
        XYPlot p = c.getXYPlot();
        var r = (org.jfree.chart.renderer.xy.XYLineAndShapeRenderer) p.getRenderer();
        // series 0, 2, 4: the points of centre, normal, other (1, 3, 5: their fronts)
        assertEquals(TradeoffChart.HOLLOW, r.getSeriesShape(2));
        assertEquals(Boolean.FALSE, r.getSeriesShapesFilled(2));
        assertTrue(r.getSeriesShapesFilled(0) == null || r.getSeriesShapesFilled(0), "the first one stays filled");
        assertTrue(r.getSeriesShapesFilled(4) == null || r.getSeriesShapesFilled(4), "a series with its own points stays filled");
        List<String> legend = new java.util.ArrayList<>();
        org.jfree.chart.LegendItemCollection items = p.getFixedLegendItems();
        for (int i = 0; i < items.getItemCount(); i++) legend.add(items.get(i).getLabel());
        assertTrue(legend.contains("normal (the same points as centre)"), legend.toString());
        assertTrue(legend.contains("centre") && legend.contains("other"), legend.toString());
        assertTrue(legend.contains(TradeoffChart.PARETO_LEGEND), legend.toString());
        for (String l : legend) assertTrue(!l.contains("exact"), "the legend speaks of no error: " + l);
    }
}
