package org.handsim.chart;

import java.awt.Color;
import java.awt.Font;
import java.awt.Paint;
import org.handsim.plan.DirectionMap;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.NumberTickUnit;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.PaintScale;
import org.jfree.chart.renderer.xy.XYBarRenderer;
import org.jfree.chart.renderer.xy.StandardXYBarPainter;
import org.jfree.chart.renderer.xy.XYBlockRenderer;
import org.jfree.chart.title.PaintScaleLegend;
import org.jfree.chart.title.TextTitle;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.RectangleInsets;
import org.jfree.data.xy.DefaultIntervalXYDataset;
import org.jfree.data.xy.DefaultXYZDataset;

/**
 * The two charts of {@code handsim plan}: the distribution of the Ferrari–Canny ε
 * over the trials, and ε over the approach directions (a map of azimuth and elevation, each
 * cell coloured by the best ε of its trials). Built from binned counts and a grid, so their
 * cost does not grow with the number of trials.
 */
public final class PlanCharts {
    private static final Color BAR = new Color(0x1f77b4);
    private static final Color NO_CLOSURE = new Color(0xd9d9d9);

    private PlanCharts() {}

    /**
     * @param width      bin width (ε units); bins start at 0
     * @param counts     force-closure trials per bin
     * @param noClosure  trials without force closure (not drawn; in the subtitle)
     * @param failed     failed trials (in the subtitle)
     */
    public static JFreeChart epsilonHistogram(String title, double width, long[] counts, long noClosure, long failed) {
        DefaultIntervalXYDataset data = new DefaultIntervalXYDataset();
        int n = counts.length;
        double[][] s = new double[6][n];
        long closure = 0;
        for (int b = 0; b < n; b++) {
            double w = Double.isNaN(width) ? 0 : width;
            s[0][b] = (b + 0.5) * w;
            s[1][b] = b * w;
            s[2][b] = (b + 1) * w;
            s[3][b] = counts[b];
            s[4][b] = counts[b];
            s[5][b] = counts[b];
            closure += counts[b];
        }
        data.addSeries("force-closure trials", s);
        NumberAxis x = new NumberAxis("ε (Ferrari–Canny, L1 grasp wrench space, N of scaled wrench)");
        NumberAxis y = new NumberAxis("trials");
        y.setStandardTickUnits(NumberAxis.createIntegerTickUnits());
        if (width > 0 && n > 0) x.setRange(0, n * width); else x.setRange(0, 1);
        XYBarRenderer r = new XYBarRenderer(0.05);
        r.setBarPainter(new StandardXYBarPainter());
        r.setShadowVisible(false);
        r.setSeriesPaint(0, BAR);
        XYPlot plot = new XYPlot(data, x, y, r);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(new Color(0xcccccc));
        plot.setDomainGridlinePaint(new Color(0xcccccc));
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, false);
        chart.setBackgroundPaint(Color.WHITE);
        chart.addSubtitle(new TextTitle(String.format(java.util.Locale.ROOT,
            "%d trials with force closure (drawn), %d without (ε = 0), %d failed", closure, noClosure, failed),
            new Font("SansSerif", Font.PLAIN, 12)));
        return chart;
    }

    /**
     * The best ε over the approach directions, on the equal-area cells of a {@link DirectionMap}:
     * azimuth across, the approach's z = sin(elevation) up (Lambert's cylindrical equal-area
     * projection, so every cell covers the same solid angle and holds about the same number of
     * trials), the axis ticked in degrees of elevation. A cell whose trials have no force
     * closure is grey, a cell without trials (only with very few trials) white.
     */
    public static JFreeChart directionMap(String title, DirectionMap map) {
        double[][] best = map.best();
        int[][] count = map.count();
        int na = map.azimuthCells(), nz = map.zCells();
        double w = 360.0 / na, hz = 2.0 / nz;
        int cells = 0;
        double max = 0;
        for (int i = 0; i < na; i++) {
            for (int j = 0; j < nz; j++) {
                if (count[i][j] > 0) cells++;
                max = Math.max(max, best[i][j]);
            }
        }
        double[][] s = new double[3][cells];
        int c = 0;
        for (int i = 0; i < na; i++) {
            for (int j = 0; j < nz; j++) {
                if (count[i][j] == 0) continue;
                s[0][c] = -180 + (i + 0.5) * w;
                s[1][c] = -1 + (j + 0.5) * hz;
                s[2][c] = best[i][j];
                c++;
            }
        }
        DefaultXYZDataset data = new DefaultXYZDataset();
        data.addSeries("best ε", s);
        NumberAxis x = new NumberAxis("approach azimuth atan2(a_y, a_x), degrees");
        x.setRange(-180, 180);
        x.setTickUnit(new NumberTickUnit(45));
        NumberAxis y = new ElevationAxis("approach elevation asin(a_z), degrees (equal-area scale)");
        XYBlockRenderer r = new XYBlockRenderer();
        r.setBlockWidth(w);
        r.setBlockHeight(hz);
        double upper = max > 0 ? max : 1;
        Viridis scale = new Viridis(upper);
        r.setPaintScale(scale);
        XYPlot plot = new XYPlot(data, x, y, r);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinesVisible(false);
        plot.setRangeGridlinesVisible(false);
        // the cells' borders, thin and white: cells of equal colour stay countable
        for (int i = 1; i < na; i++) plot.addDomainMarker(new org.jfree.chart.plot.ValueMarker(-180 + i * w, Color.WHITE, new java.awt.BasicStroke(0.6f)));
        for (int j = 1; j < nz; j++) plot.addRangeMarker(new org.jfree.chart.plot.ValueMarker(-1 + j * hz, Color.WHITE, new java.awt.BasicStroke(0.6f)));
        JFreeChart chart = new JFreeChart(title, new Font("SansSerif", Font.BOLD, 16), plot, false);
        chart.setBackgroundPaint(Color.WHITE);
        NumberAxis za = new NumberAxis(String.format(java.util.Locale.ROOT, "best ε of the cell's trials (about %d a cell; grey: none in force closure)",
            DirectionMap.TRIALS_PER_CELL));
        za.setRange(0, upper);
        PaintScaleLegend legend = new PaintScaleLegend(scale, za);
        legend.setPosition(RectangleEdge.RIGHT);
        legend.setMargin(new RectangleInsets(5, 5, 5, 5));
        legend.setStripWidth(15);
        legend.setBackgroundPaint(Color.WHITE);
        chart.addSubtitle(legend);
        return chart;
    }

    /** A z = sin(elevation) axis from −1 to 1, ticked every 30° of elevation. */
    private static final class ElevationAxis extends NumberAxis {
        private static final long serialVersionUID = 1L;

        ElevationAxis(String label) {
            super(label);
            setRange(-1, 1);
        }

        @Override
        @SuppressWarnings("rawtypes")
        public java.util.List refreshTicks(java.awt.Graphics2D g2, org.jfree.chart.axis.AxisState state, java.awt.geom.Rectangle2D area,
                                          RectangleEdge edge) {
            java.util.List<org.jfree.chart.axis.NumberTick> ticks = new java.util.ArrayList<>();
            for (int deg = -90; deg <= 90; deg += 30) {
                ticks.add(new org.jfree.chart.axis.NumberTick(org.jfree.chart.axis.TickType.MAJOR, Math.sin(Math.toRadians(deg)),
                    (deg > 0 ? "+" : deg < 0 ? "−" : "") + Math.abs(deg) + "°", org.jfree.chart.ui.TextAnchor.CENTER_RIGHT,
                    org.jfree.chart.ui.TextAnchor.CENTER, 0.0));
            }
            return ticks;
        }
    }

    /** Viridis-like colours from 0 to the upper bound; 0 itself (no force closure) is grey. */
    private static final class Viridis implements PaintScale {
        private static final int[] STOPS = {0x440154, 0x3b528b, 0x21918c, 0x5ec962, 0xfde725};
        private final double upper;

        Viridis(double upper) { this.upper = upper; }

        @Override public double getLowerBound() { return 0; }
        @Override public double getUpperBound() { return upper; }

        @Override
        public Paint getPaint(double v) {
            if (!(v > 0)) return NO_CLOSURE;
            double t = Math.max(0, Math.min(1, v / upper)) * (STOPS.length - 1);
            int i = Math.min(STOPS.length - 2, (int) Math.floor(t));
            double f = t - i;
            int a = STOPS[i], b = STOPS[i + 1];
            int red = (int) Math.round(((a >> 16) & 255) * (1 - f) + ((b >> 16) & 255) * f);
            int green = (int) Math.round(((a >> 8) & 255) * (1 - f) + ((b >> 8) & 255) * f);
            int blue = (int) Math.round((a & 255) * (1 - f) + (b & 255) * f);
            return new Color(red, green, blue);
        }
    }
}
