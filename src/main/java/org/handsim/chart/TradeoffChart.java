package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.geom.Ellipse2D;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItem;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.axis.NumberTickUnit;
import org.jfree.chart.labels.XYItemLabelGenerator;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.ui.RectangleInsets;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * A speed-against-accuracy chart from a {@link StudyTable}: x and y on log axes, one colour per
 * series, each point labelled with its setting, each series' Pareto front drawn as a dashed
 * line through its non-dominated points (or, where x is a setting and not a cost,
 * {@link StudyTable#paretoFront}, a thin line through the points in the order of x), the default setting ringed and labelled in bold
 * "(default)". Values that are 0 (an exact answer) cannot sit on a log axis: they are drawn at
 * the floor of the axis (a tenth of the smallest positive value) and the subtitle says so; the
 * CSV keeps the 0.
 *
 * <p>Point labels never overlap each other or cover a point ({@link LabelPlacingRenderer}): the
 * series of a study often share their x values, so labels placed at a fixed offset ran into
 * each other. When the study has only a few settings, shared by every series (the k of the
 * k-DOPs), each setting gets its own marker shape, named in the legend, and no point is
 * labelled: many series' labels of the same few settings piled up in one cluster. The chart
 * keeps a right margin so the last tick label of the x axis is not cut. Log axes read 10⁻³, 10⁻²,
 * …; the study's notes are its caption, for the docs (tradeoff.json), not under the plot.
 */
public final class TradeoffChart {
    static final Color[] PALETTE = {
        new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c), new Color(0x9467bd),
        new Color(0xff7f0e), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf)};

    private TradeoffChart() {}

    /** Size of the chart, pixels. */
    public static final int WIDTH = 1000, HEIGHT = 700;

    /** Writes {@code dir/<id>.png}, {@code .svg} and {@code .csv}. */
    public static void write(StudyTable table, Path dir) throws IOException {
        table.writeCsv(dir.resolve(table.id() + ".csv"));
        ChartExport.write(create(table), dir.resolve(table.id()), WIDTH, HEIGHT);
    }

    public static JFreeChart create(StudyTable t) {
        double fx = floor(t, t.xColumn()), fy = floor(t, t.yColumn());
        boolean clamped = false;
        XYSeriesCollection data = new XYSeriesCollection();
        LabelPlacingRenderer r = new LabelPlacingRenderer();
        List<String> settings = sharedSettings(t);   // non-null: one marker shape per setting, no point labels
        List<List<String>> labels = new ArrayList<>();
        List<String> legendNames = new ArrayList<>();
        List<Boolean> hollow = new ArrayList<>();
        int s = 0;
        for (String name : t.series()) {
            List<StudyTable.Row> rows = t.rows(name);
            double[] x = new double[rows.size()], y = new double[rows.size()];
            XYSeries points = new XYSeries(name, false, true);
            List<String> pointLabels = new ArrayList<>();
            for (int i = 0; i < rows.size(); i++) {
                x[i] = rows.get(i).values()[t.xColumn()];
                y[i] = rows.get(i).values()[t.yColumn()];
            }
            List<Integer> onFront = ParetoFront.of(x, y);
            for (int i = 0; i < rows.size(); i++) {
                StudyTable.Row row = rows.get(i);
                double px = x[i] > 0 ? x[i] : fx, py = y[i] > 0 ? y[i] : fy;
                if (!Double.isFinite(x[i]) || !Double.isFinite(y[i])) continue;
                if (!(x[i] > 0) || !(y[i] > 0)) clamped = true;
                points.add(px, py);
                if (settings != null) r.setItemShape(data.getSeriesCount(), points.getItemCount() - 1, SHAPES[settings.indexOf(row.setting())]);
                pointLabels.add(settings != null ? null
                    : t.labelsEveryPoint() || row.isDefault() || onFront.contains(i) ? row.setting() : null);
                if (row.isDefault()) r.markDefault(data.getSeriesCount(), points.getItemCount() - 1);
            }
            XYSeries front = new XYSeries(name + " (Pareto front)", !t.drawsParetoFront(), true);
            if (t.drawsParetoFront()) {
                for (int i : onFront) front.add(x[i] > 0 ? x[i] : fx, y[i] > 0 ? y[i] : fy);
            } else {
                for (int i = 0; i < x.length; i++) {
                    if (Double.isFinite(x[i]) && Double.isFinite(y[i])) front.add(x[i] > 0 ? x[i] : fx, y[i] > 0 ? y[i] : fy);
                }
            }
            Color c = PALETTE[s % PALETTE.length];
            int pi = data.getSeriesCount();
            // a series drawn exactly over an earlier one (the cube's centre and normal errors,
            // both 0 on the floor) would be hidden under it: it gets a larger hollow marker round
            // the other's, and its legend entry says whose points it shares
            String under = coveredBy(data, points);
            data.addSeries(points);
            labels.add(pointLabels);
            r.setSeriesPaint(pi, c);
            r.setSeriesLinesVisible(pi, false);
            r.setSeriesShapesVisible(pi, true);
            r.setSeriesShape(pi, under == null ? new Ellipse2D.Double(-4, -4, 8, 8) : HOLLOW);
            if (under != null) r.setSeriesShapesFilled(pi, false);
            legendNames.add(under == null ? name : name + " (the same points as " + under + ")");
            hollow.add(under != null);
            r.setSeriesItemLabelsVisible(pi, true);
            data.addSeries(front);
            labels.add(List.of());
            r.setSeriesPaint(pi + 1, c);
            r.setSeriesLinesVisible(pi + 1, true);
            r.setSeriesShapesVisible(pi + 1, false);
            r.setSeriesStroke(pi + 1, t.drawsParetoFront()
                ? new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 1f, new float[] {6f, 4f}, 0f) : new BasicStroke(0.8f));
            r.setSeriesVisibleInLegend(pi + 1, s == 0);
            s++;
        }
        r.setDefaultItemLabelGenerator((XYItemLabelGenerator) (ds, series, item) -> {
            List<String> l = labels.get(series);
            return item < l.size() ? l.get(item) : null;
        });
        r.setDefaultItemLabelFont(new Font("SansSerif", Font.PLAIN, 10));
        r.setDefaultItemLabelsVisible(true);

        LogAxis xAxis = new LogAxis(t.xLabel());
        LogAxis yAxis = new LogAxis(t.yLabel() + (clamped ? ";  0 (exact) drawn on the floor" : ""));
        decades(xAxis, t, t.xColumn(), fx);
        decades(yAxis, t, t.yColumn(), fy);
        XYPlot plot = new XYPlot(data, xAxis, yAxis, r);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinePaint(new Color(0xdddddd));
        plot.setRangeGridlinePaint(new Color(0xdddddd));
        LegendItemCollection legend = new LegendItemCollection();
        for (int i = 0; i < t.series().size(); i++) {
            Color c = PALETTE[i % PALETTE.length];
            legend.add(hollow.get(i)
                ? new LegendItem(legendNames.get(i), null, null, null, true, HOLLOW, false, Color.WHITE, true, c, new BasicStroke(1.5f), false,
                    new java.awt.geom.Line2D.Double(), new BasicStroke(), Color.WHITE)
                : new LegendItem(legendNames.get(i), null, null, null, new Ellipse2D.Double(-4, -4, 8, 8), c));
        }
        // y is an error in some studies and a count of work in others (the k-DOPs' triangle tests):
        // the front is what no other point beats on both axes
        if (t.drawsParetoFront()) legend.add(PaperCharts.line(PARETO_LEGEND, Color.GRAY, DASHED));
        if (settings != null) {
            for (int i = 0; i < settings.size(); i++) {
                legend.add(new LegendItem(settings.get(i), null, null, null, SHAPES[i], Color.DARK_GRAY));
            }
        }
        // (String, description, tooltip, url, shapeVisible, shape, shapeFilled, fill, shapeOutlineVisible, outline, outlineStroke, lineVisible, line, lineStroke, linePaint)
        legend.add(new LegendItem("ringed: the default", null, null, null, true, new Ellipse2D.Double(-6, -6, 12, 12), false, Color.WHITE, true,
            Color.DARK_GRAY, new BasicStroke(1.5f), false, new java.awt.geom.Line2D.Double(), new BasicStroke(), Color.WHITE));
        plot.setFixedLegendItems(legend);
        JFreeChart chart = new JFreeChart(t.title(), new Font("SansSerif", Font.BOLD, 16), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        chart.setPadding(new RectangleInsets(4, 8, 4, 28));   // the last x tick label is centred on the axis end
        return chart;
    }

    /** The legend entry of the fronts: true whatever the y axis measures. */
    static final String PARETO_LEGEND = "Pareto front (no other point both faster and lower); lower left is better";

    /** The marker of a series drawn over an earlier one's points: hollow, around the other's. */
    static final java.awt.Shape HOLLOW = new java.awt.Rectangle(-7, -7, 14, 14);

    /**
     * The name of an earlier series of {@code data} (its point series, not fronts) that has every
     * point of {@code s} (the same coordinates as drawn), or null.
     */
    static String coveredBy(XYSeriesCollection data, XYSeries s) {
        if (s.getItemCount() == 0) return null;
        for (int i = 0; i < data.getSeriesCount(); i++) {
            XYSeries o = data.getSeries(i);
            if (o.getKey().toString().endsWith(" (Pareto front)")) continue;
            boolean all = true;
            for (int j = 0; j < s.getItemCount() && all; j++) {
                boolean found = false;
                for (int k = 0; k < o.getItemCount() && !found; k++) {
                    found = o.getX(k).doubleValue() == s.getX(j).doubleValue() && o.getY(k).doubleValue() == s.getY(j).doubleValue();
                }
                all = found;
            }
            if (all) return o.getKey().toString();
        }
        return null;
    }

    static final BasicStroke DASHED = new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 1f, new float[] {6f, 4f}, 0f);

    /** Marker shapes for the settings of a study with few settings (8 px across). */
    static final java.awt.Shape[] SHAPES = {
        new Ellipse2D.Double(-4, -4, 8, 8),
        new java.awt.Rectangle(-4, -4, 8, 8),
        poly(new double[] {0, 4.5, -4.5}, new double[] {-5, 3.5, 3.5}),          // triangle up
        poly(new double[] {0, 5, 0, -5}, new double[] {-5, 0, 5, 0}),             // diamond
        poly(new double[] {0, 4.5, -4.5}, new double[] {5, -3.5, -3.5}),          // triangle down
        poly(new double[] {-5, -1.5, 0, 1.5, 5, 1.5, 0, -1.5}, new double[] {0, -1.5, -5, -1.5, 0, 1.5, 5, 1.5}),   // star
    };

    private static java.awt.Shape poly(double[] x, double[] y) {
        java.awt.geom.Path2D.Double p = new java.awt.geom.Path2D.Double();
        p.moveTo(x[0], y[0]);
        for (int i = 1; i < x.length; i++) p.lineTo(x[i], y[i]);
        p.closePath();
        return p;
    }

    /**
     * The settings, in order of appearance, when there are at most {@link #SHAPES} of them and
     * each is used by more than one series (then shapes name them better than labels); else null.
     */
    static List<String> sharedSettings(StudyTable t) {
        if (t.series().size() < 2) return null;
        List<String> s = new ArrayList<>();
        for (StudyTable.Row row : t.rows()) if (!s.contains(row.setting())) s.add(row.setting());
        if (s.size() > SHAPES.length) return null;
        for (String setting : s) {
            if (t.rows().stream().filter(r -> r.setting().equals(setting)).map(StudyTable.Row::series).distinct().count() < 2) return null;
        }
        return s;
    }

    /**
     * Spans the axis over whole decades around the column's values (at least two labelled
     * ticks), labelled 10⁻³, 10⁻², …
     */
    static void decades(LogAxis a, StudyTable t, int column, double floor) {
        double lo = Double.POSITIVE_INFINITY, hi = 0;
        for (StudyTable.Row row : t.rows()) {
            double v = row.values()[column];
            if (!Double.isFinite(v)) continue;
            v = v > 0 ? v : floor;
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        if (!(hi > 0)) return;
        double l = Math.floor(Math.log10(lo)), h = Math.ceil(Math.log10(hi));
        if (h - l < 1) h = l + 1;
        a.setSmallestValue(Math.pow(10, l - 1));
        a.setRange(Math.pow(10, l), Math.pow(10, h));
        a.setTickUnit(new NumberTickUnit(Math.max(1, Math.ceil((h - l) / 10))));
        a.setNumberFormatOverride(new PowerOfTen());
        a.setTickLabelFont(new Font("SansSerif", Font.PLAIN, 13));   // superscript exponents need the size to be read
        a.setMinorTickMarksVisible(true);
        a.setLabelFont(new Font("SansSerif", Font.PLAIN, 13));
    }

    /** A tenth of the smallest positive finite value of a column (1e-16 if there is none). */
    static double floor(StudyTable t, int column) {
        double min = Double.POSITIVE_INFINITY;
        for (StudyTable.Row row : t.rows()) {
            double v = row.values()[column];
            if (v > 0 && Double.isFinite(v)) min = Math.min(min, v);
        }
        return Double.isFinite(min) ? min / 10 : 1e-16;
    }
}
