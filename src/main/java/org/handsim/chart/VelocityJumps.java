package org.handsim.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.GeneralPath;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jfree.chart.annotations.AbstractXYAnnotation;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.PlotRenderingInfo;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.data.xy.XYDataset;

/**
 * Velocity jumps drawn in an acceleration panel as what they are: impulses. Where a contact
 * stops a link, or the breakaway frees one, the joint velocity changes within one step, so the
 * acceleration is a Dirac impulse of area Δθ̇ there — not the 0 (or one tall sample) a sampled
 * trace shows. Each jump is an arrow from the zero line, up for a positive jump and down for a
 * negative one, in its joint's colour, labelled with Δθ̇ ("+45°/s"), the convention of
 * signals-and-systems plots for δ-functions.
 *
 * <p>Labels are placed where they cover no data and no other label or arrow: before drawing,
 * the panel's data points (in pixels) and every arrow are reserved; each label then takes the
 * first free place beside its arrow's tip (right, left, then further out along the arrow), as
 * {@link LabelPlacingRenderer} does for point labels.
 */
final class VelocityJumps extends AbstractXYAnnotation {
    private static final long serialVersionUID = 1L;
    /** Arrow length as a share of the space between the zero line and the panel's edge. */
    private static final double REACH = 0.55;
    private static final Font FONT = new Font("SansSerif", Font.PLAIN, 11);

    /**
     * A jump: at time {@code t} the velocity of the joint of series {@code series} changed by
     * {@code delta} (in the panel's units per second, e.g. °/s) more than its acceleration accounts for.
     */
    record Jump(double t, double delta, int series, Color colour) {}

    private final List<Jump> jumps;
    private final String unit;
    private final transient List<Rectangle2D> labelBoxes = new ArrayList<>();

    VelocityJumps(List<Jump> jumps, String unit) {
        this.jumps = List.copyOf(jumps);
        this.unit = unit;
    }

    List<Jump> jumps() { return jumps; }

    /** The label of a jump, e.g. {@code +45°/s}. */
    String label(Jump j) {
        return String.format(Locale.ROOT, "%+.0f%s", j.delta(), unit).replace('-', '\u2212');
    }

    /** The boxes of the labels of the last drawing, px (for tests). */
    List<Rectangle2D> labelBoxes() { return new ArrayList<>(labelBoxes); }

    @Override
    public void draw(Graphics2D g2, XYPlot plot, Rectangle2D area, ValueAxis domain, ValueAxis range, int index, PlotRenderingInfo info) {
        labelBoxes.clear();
        RectangleEdge xe = RectangleEdge.BOTTOM, ye = RectangleEdge.LEFT;
        double zero = range.valueToJava2D(0, area, ye);
        double up = (zero - area.getMinY()) * REACH, down = (area.getMaxY() - zero) * REACH;
        List<Rectangle2D> taken = new ArrayList<>();
        // the data: every point of every series, a small box each
        for (int d = 0; d < plot.getDatasetCount(); d++) {
            XYDataset ds = plot.getDataset(d);
            if (ds == null) continue;
            for (int s = 0; s < ds.getSeriesCount(); s++) {
                for (int i = 0; i < ds.getItemCount(s); i++) {
                    double x = domain.valueToJava2D(ds.getXValue(s, i), area, xe), y = range.valueToJava2D(ds.getYValue(s, i), area, ye);
                    taken.add(new Rectangle2D.Double(x - 2, y - 2, 4, 4));
                }
            }
        }
        g2.setFont(FONT);
        FontMetrics fm = g2.getFontMetrics();
        double h = fm.getAscent() + fm.getDescent();
        List<double[]> arrows = new ArrayList<>();
        for (Jump j : jumps) {
            double x = domain.valueToJava2D(j.t(), area, xe);
            // jumps of both joints at one time (a contact stops the coupled outer link too): side by side
            for (double[] a : arrows) if (Math.abs(a[0] - x) < 7 && (a[1] < zero) == (j.delta() > 0)) x = a[0] + 7;
            double tip = j.delta() > 0 ? zero - up : zero + down;
            arrows.add(new double[] {x, tip});
            taken.add(new Rectangle2D.Double(x - 4, Math.min(zero, tip), 8, Math.abs(tip - zero)));
        }
        for (int n = 0; n < jumps.size(); n++) {
            Jump j = jumps.get(n);
            double x = arrows.get(n)[0], tip = arrows.get(n)[1];
            g2.setPaint(j.colour());
            g2.setStroke(new BasicStroke(2f));
            g2.draw(new Line2D.Double(x, zero, x, tip));
            double dir = j.delta() > 0 ? 1 : -1;   // arrowhead pointing away from the zero line
            GeneralPath head = new GeneralPath();
            head.moveTo(x, tip);
            head.lineTo(x - 4, tip + dir * 8);
            head.lineTo(x + 4, tip + dir * 8);
            head.closePath();
            g2.fill(head);
            String text = label(j);
            double w = fm.stringWidth(text);
            // beside the tip, then back along the arrow (never past the zero line: a label stays on
            // its arrow's side), then beyond the tip; right of the arrow first, then left
            List<Double> ys = new ArrayList<>();
            double first = tip - (dir > 0 ? 0 : h);
            for (int step = 0; step < 12; step++) {
                double y = first + dir * step * (h + 1);
                if (dir > 0 ? y + h > zero : y < zero) break;
                ys.add(y);
            }
            for (int step = 1; step < 6; step++) ys.add(first - dir * step * (h + 1));
            Rectangle2D place = null;
            for (double y : ys) {
                for (Rectangle2D c : new Rectangle2D[] {new Rectangle2D.Double(x + 6, y, w, h), new Rectangle2D.Double(x - 6 - w, y, w, h)}) {
                    if (place == null && area.contains(c) && taken.stream().noneMatch(c::intersects)) place = c;
                }
                if (place != null) break;
            }
            if (place == null) place = new Rectangle2D.Double(x + 6, tip - (dir > 0 ? 0 : h), w, h);
            taken.add(place);
            labelBoxes.add(place);
            g2.drawString(text, (float) place.getX(), (float) (place.getY() + fm.getAscent()));
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof VelocityJumps v && v.jumps.equals(jumps) && v.unit.equals(unit) && super.equals(o);
    }

    @Override
    public int hashCode() {
        return jumps.hashCode();
    }
}
