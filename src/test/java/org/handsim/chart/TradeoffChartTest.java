package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.title.TextTitle;
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
        assertEquals("a,default,true,0.001,0.00001", lines.get(2), "util.Decimal: plain decimals from 1e-6");
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
        boolean said = false;
        for (int i = 0; i < c.getSubtitleCount(); i++) {
            if (c.getSubtitle(i) instanceof TextTitle && ((TextTitle) c.getSubtitle(i)).getText().contains("0 (exact)")) said = true;
        }
        assertTrue(said, "the chart says where 0 is drawn");
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
}
