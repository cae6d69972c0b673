package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.Paint;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.jfree.chart.labels.XYItemLabelGenerator;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.plot.PlotRenderingInfo;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYItemRendererState;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.data.xy.XYDataset;

/**
 * Points and lines as {@link XYLineAndShapeRenderer} draws them, with item labels placed where
 * they collide with nothing: before a drawing, every point's marker and every drawn line
 * segment is reserved; each label then
 * takes the first free place among eight directions round its point (above, below, right, left,
 * the diagonals) at growing distances — beyond the nearest ring a thin leader line joins it to
 * its point — inside the plot. A label that finds no free place is left out, except a default
 * setting's, which is always drawn (bold, "(default)", in the series' colour, its point ringed).
 * Labels are placed in drawing order, so the first series' labels get the best places.
 */
final class LabelPlacingRenderer extends XYLineAndShapeRenderer {
    private static final long serialVersionUID = 1L;
    /** Distances from a point to its label tried, px. */
    private static final double[] RADII = {5, 12, 22, 34, 48};
    /** Half the side of the square reserved round every point, px. */
    private static final double MARKER_HALF = 5;

    private final Set<Long> defaults = new HashSet<>();
    private final java.util.Map<Long, java.awt.Shape> itemShapes = new java.util.HashMap<>();
    /** The default rings drawn so far: {x, y, radius} px (a second default on the same spot gets a wider ring). */
    private final transient List<double[]> rings = new ArrayList<>();
    private final transient List<Rectangle2D> taken = new ArrayList<>();
    private final transient List<Rectangle2D> labels = new ArrayList<>();
    /** The drawn lines (a Pareto front's segments), px: a label crosses none of them. */
    private final transient List<Line2D> segments = new ArrayList<>();
    private transient Rectangle2D area;

    /** Draws item {@code item} of series {@code series} with its own marker shape (the study's setting). */
    void setItemShape(int series, int item, java.awt.Shape shape) {
        itemShapes.put(((long) series << 32) | item, shape);
    }

    @Override
    public java.awt.Shape getItemShape(int series, int item) {
        java.awt.Shape s = itemShapes.get(((long) series << 32) | item);
        return s != null ? s : super.getItemShape(series, item);
    }

    /** Item {@code item} of series {@code series} is the default setting. */
    void markDefault(int series, int item) {
        defaults.add(((long) series << 32) | item);
    }

    @Override
    public XYItemRendererState initialise(Graphics2D g2, Rectangle2D dataArea, XYPlot plot, XYDataset data, PlotRenderingInfo info) {
        taken.clear();
        labels.clear();
        rings.clear();
        area = dataArea;
        segments.clear();
        for (int s = 0; s < data.getSeriesCount(); s++) {
            if (getItemLineVisible(s, 0)) {
                for (int i = 1; i < data.getItemCount(s); i++) {
                    segments.add(new Line2D.Double(
                        plot.getDomainAxis().valueToJava2D(data.getXValue(s, i - 1), dataArea, RectangleEdge.BOTTOM),
                        plot.getRangeAxis().valueToJava2D(data.getYValue(s, i - 1), dataArea, RectangleEdge.LEFT),
                        plot.getDomainAxis().valueToJava2D(data.getXValue(s, i), dataArea, RectangleEdge.BOTTOM),
                        plot.getRangeAxis().valueToJava2D(data.getYValue(s, i), dataArea, RectangleEdge.LEFT)));
                }
            }
            if (!getItemShapeVisible(s, 0)) continue;
            for (int i = 0; i < data.getItemCount(s); i++) {
                double x = plot.getDomainAxis().valueToJava2D(data.getXValue(s, i), dataArea, RectangleEdge.BOTTOM);
                double y = plot.getRangeAxis().valueToJava2D(data.getYValue(s, i), dataArea, RectangleEdge.LEFT);
                taken.add(new Rectangle2D.Double(x - MARKER_HALF, y - MARKER_HALF, 2 * MARKER_HALF, 2 * MARKER_HALF));
            }
        }
        return super.initialise(g2, dataArea, plot, data, info);
    }

    @Override
    protected void drawItemLabel(Graphics2D g2, PlotOrientation orientation, XYDataset dataset, int series, int item,
                                 double x, double y, boolean negative) {
        XYItemLabelGenerator gen = getItemLabelGenerator(series, item);
        String text = gen == null ? null : gen.generateLabel(dataset, series, item);
        boolean isDefault = defaults.contains(((long) series << 32) | item);
        Paint seriesPaint = lookupSeriesPaint(series);
        if (isDefault) {
            // ringed; defaults of several series on one spot get concentric rings, each visible
            double radius = 8;
            for (double[] ring : rings) if (Math.hypot(ring[0] - x, ring[1] - y) < 3) radius = Math.max(radius, ring[2] + 4);
            rings.add(new double[] {x, y, radius});
            g2.setPaint(seriesPaint);
            g2.setStroke(new BasicStroke(2f));
            g2.draw(new Ellipse2D.Double(x - radius, y - radius, 2 * radius, 2 * radius));
            taken.add(new Rectangle2D.Double(x - radius, y - radius, 2 * radius, 2 * radius));
        }
        if (text == null || text.isEmpty()) return;
        Font font = getItemLabelFont(series, item);
        if (isDefault) {
            text = text + " (default)";
            font = font.deriveFont(Font.BOLD, font.getSize2D() + 1);
        }
        g2.setFont(font);
        FontMetrics fm = g2.getFontMetrics();
        double w = fm.stringWidth(text), h = fm.getAscent() + fm.getDescent();
        Rectangle2D place = null;
        double placedRadius = 0;
        for (double r : RADII) {
            if (isDefault && r < 10) continue;   // outside its ring
            for (int d = 0; d < 8 && place == null; d++) {
                Rectangle2D c = candidate(d, r, x, y, w, h);
                if (area != null && !area.contains(c)) continue;
                boolean free = true;
                for (Rectangle2D t : taken) {
                    if (t.intersects(c)) {
                        free = false;
                        break;
                    }
                }
                for (int n = 0; free && n < segments.size(); n++) free = !segments.get(n).intersects(c);
                if (free) {
                    place = c;
                    placedRadius = r;
                }
            }
            if (place != null) break;
        }
        if (place == null) {
            if (!isDefault) return;
            place = candidate(0, 10, x, y, w, h);
            placedRadius = 10;
        }
        taken.add(place);
        labels.add(place);
        if (placedRadius > RADII[1]) {
            g2.setPaint(Color.GRAY);
            g2.setStroke(new BasicStroke(0.7f));
            double cx = Math.max(place.getMinX(), Math.min(x, place.getMaxX())), cy = Math.max(place.getMinY(), Math.min(y, place.getMaxY()));
            g2.draw(new Line2D.Double(x, y, cx, cy));
        }
        g2.setPaint(isDefault ? seriesPaint : Color.BLACK);
        g2.drawString(text, (float) place.getX(), (float) (place.getY() + fm.getAscent()));
    }

    /** The default rings of the last drawing, {x, y, radius} px (for tests). */
    List<double[]> ringsDrawn() { return new ArrayList<>(rings); }

    /** The boxes of the labels drawn in the last drawing, px (for tests). */
    List<Rectangle2D> labelBoxes() { return new ArrayList<>(labels); }

    /** The line segments of the last drawing, px (for tests). */
    List<Line2D> segmentsDrawn() { return new ArrayList<>(segments); }

    /** The plot area of the last drawing, px. */
    Rectangle2D dataArea() { return area; }

    /** The label's box in direction d (0 above, 1 below, 2 right, 3 left, 4..7 diagonals) at distance r. */
    private static Rectangle2D candidate(int d, double r, double x, double y, double w, double h) {
        switch (d) {
            case 0: return new Rectangle2D.Double(x - w / 2, y - r - h, w, h);
            case 1: return new Rectangle2D.Double(x - w / 2, y + r, w, h);
            case 2: return new Rectangle2D.Double(x + r, y - h / 2, w, h);
            case 3: return new Rectangle2D.Double(x - r - w, y - h / 2, w, h);
            case 4: return new Rectangle2D.Double(x + r * 0.7, y - r * 0.7 - h, w, h);
            case 5: return new Rectangle2D.Double(x + r * 0.7, y + r * 0.7, w, h);
            case 6: return new Rectangle2D.Double(x - r * 0.7 - w, y - r * 0.7 - h, w, h);
            default: return new Rectangle2D.Double(x - r * 0.7 - w, y + r * 0.7, w, h);
        }
    }

    @Override
    public boolean equals(Object o) {
        return super.equals(o) && o instanceof LabelPlacingRenderer && defaults.equals(((LabelPlacingRenderer) o).defaults);
    }

    @Override
    public int hashCode() {
        return super.hashCode();
    }
}
