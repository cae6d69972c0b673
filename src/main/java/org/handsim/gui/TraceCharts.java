package org.handsim.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.Stroke;
import java.awt.event.ComponentAdapter;
import java.awt.geom.Line2D;
import java.awt.event.ComponentEvent;
import java.awt.image.BufferedImage;
import java.util.concurrent.ConcurrentLinkedQueue;
import javax.swing.JComponent;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItem;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.SeriesRenderingOrder;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.SamplingXYLineRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * Live traces beside the 3D view: joint angles, joint velocities, joint torques (joints k2
 * solid, k3 dashed, one colour per finger) and each finger's total contact force, against
 * simulated time, in one {@link CombinedDomainXYPlot}. The time axis shows [0, {@link #WINDOW_S}]
 * s and then the last {@link #WINDOW_S} seconds, so long runs scroll.
 *
 * <h2>Drawn off the event dispatch thread</h2>
 * A chart of four plots and 21 series takes tens of milliseconds to draw — too long for the
 * event dispatch thread at display rate on a loaded machine. So the chart, its datasets and
 * its drawing belong to one thread of their own ({@code handsim-charts}, low priority):
 * {@link #add} queues rows from any thread; {@link #flush} asks for a redraw; the chart thread
 * moves the queued rows into the series with {@code XYSeries.add(x, y, false)} (STYLE.md item
 * 16), tells each series once, draws the whole chart into a new image of the component's size
 * and hands it over (a volatile field); the Swing component only paints that image. Redraw
 * requests that arrive while a drawing is under way are merged into one. A row of a new
 * generation (the model was reset or rebuilt) clears the traces first.
 *
 * <p>Series are kept sorted so that only the visible points are visited, drawn by a
 * {@link SamplingXYLineRenderer} (at most a few segments per pixel column), and hold at most
 * {@link #MAX_ITEMS} points.
 */
public final class TraceCharts implements AutoCloseable {
    /** Width of the scrolling time window, s. */
    public static final double WINDOW_S = 10.0;
    /** Colours of fingers 1, 2, 3 (tests look for them in screenshots). */
    public static final int[] FINGER_RGB = {0x1F77B4, 0x2CA02C, 0xD62728};
    /** Points kept per series: twice the visible window at the trace interval (older points drop off). */
    static final int MAX_ITEMS = (int) (2 * WINDOW_S / SimulationRunner.TRACE_INTERVAL_S);
    private static final double[] MINIMUM_RANGE = {5, 5, 0.1, 1};
    private static final Line2D LEGEND_LINE = new Line2D.Double(-9, 0, 9, 0);

    // chart thread only
    private final XYSeries[][] series = new XYSeries[4][];   // [plot][finger * 2 + joint] (force: [finger])
    private final JFreeChart chart;
    private final NumberAxis time;
    private long generation = -1;
    private double latest;

    // shared
    private final ConcurrentLinkedQueue<double[]> pending = new ConcurrentLinkedQueue<>();
    private final Object lock = new Object();
    private long requested, drawn;          // guarded by lock
    private boolean closed;                 // guarded by lock
    private volatile BufferedImage image;
    private volatile int width, height;
    private final JComponent view;
    private final Thread thread;

    public TraceCharts() {
        time = new NumberAxis("simulated time t (s)");
        time.setAutoRange(false);
        time.setRange(0, WINDOW_S);
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(time);
        plot.setGap(6);
        String[] labels = {"angle (°)", "velocity (°/s)", "torque (N·m)", "contact force (N)"};
        for (int p = 0; p < 4; p++) {
            XYSeriesCollection data = new XYSeriesCollection();
            boolean force = p == 3;
            series[p] = new XYSeries[force ? 3 : 6];
            SamplingXYLineRenderer r = new SamplingXYLineRenderer() {
                private static final long serialVersionUID = 1L;

                @Override
                public LegendItem getLegendItem(int datasetIndex, int s) {
                    // the sampling renderer's own legend item shows no line: draw one in the series' colour and stroke
                    LegendItem li = super.getLegendItem(datasetIndex, s);
                    if (li == null) return null;
                    return new LegendItem(li.getLabel(), null, null, null, false, LEGEND_LINE, false, Color.WHITE, false,
                        Color.WHITE, new BasicStroke(0f), true, LEGEND_LINE, lookupSeriesStroke(s), lookupSeriesPaint(s));
                }
            };
            for (int k = 0; k < 3; k++) {
                for (int j = 0; j < (force ? 1 : 2); j++) {
                    int i = force ? k : 2 * k + j;
                    String name = force ? "finger " + (k + 1) : "θ" + (k + 1) + (j + 2);
                    XYSeries s = new XYSeries(name, true, true);   // sorted: only visible points are visited
                    s.setMaximumItemCount(MAX_ITEMS);
                    series[p][i] = s;
                    data.addSeries(s);
                    r.setSeriesPaint(i, new Color(FINGER_RGB[k]));
                    r.setSeriesStroke(i, j == 0 ? new BasicStroke(2f) : dashed());
                    r.setSeriesVisibleInLegend(i, p == 0 || force);
                }
            }
            NumberAxis y = new NumberAxis(labels[p]);
            y.setAutoRangeIncludesZero(true);
            y.setAutoRangeMinimumSize(MINIMUM_RANGE[p]);
            y.setLabelFont(new Font("SansSerif", Font.PLAIN, 11));
            y.setTickLabelFont(new Font("SansSerif", Font.PLAIN, 10));
            XYPlot sub = new XYPlot(data, null, y, r);
            sub.setSeriesRenderingOrder(SeriesRenderingOrder.FORWARD);   // finger 3 (the paper's) on top
            sub.setBackgroundPaint(Color.WHITE);
            sub.setDomainGridlinePaint(new Color(0xdddddd));
            sub.setRangeGridlinePaint(new Color(0xdddddd));
            plot.add(sub, 1);
        }
        chart = new JFreeChart(null, new Font("SansSerif", Font.BOLD, 12), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        chart.getLegend().setItemFont(new Font("SansSerif", Font.PLAIN, 10));

        view = new JComponent() {
            private static final long serialVersionUID = 1L;

            @Override
            protected void paintComponent(Graphics g) {
                BufferedImage img = image;
                g.setColor(Color.WHITE);
                g.fillRect(0, 0, getWidth(), getHeight());
                if (img != null) g.drawImage(img, 0, 0, null);
            }
        };
        view.setName("charts");
        view.setOpaque(true);
        view.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                width = view.getWidth();
                height = view.getHeight();
                flush();
            }
        });
        thread = new Thread(this::loop, "handsim-charts");
        thread.setDaemon(true);
        thread.setPriority(Thread.NORM_PRIORITY - 2);
        thread.start();
    }

    private static Stroke dashed() {
        return new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f);
    }

    /** The Swing component (paints the latest drawing). */
    public JComponent panel() { return view; }

    /** Queues one trace row of {@link SimulationRunner} (drawn at the next {@link #flush()}). Any thread. */
    public void add(double[] row) {
        pending.add(row);
    }

    /** Asks for a redraw with every row queued so far. Any thread; returns at once. */
    public void flush() {
        synchronized (lock) {
            requested++;
            lock.notifyAll();
        }
    }

    /** Blocks until a drawing requested no earlier than this call has been drawn (call it off the EDT; at most 10 s). */
    public void awaitDrawn() throws InterruptedException {
        synchronized (lock) {
            long want = ++requested;
            lock.notifyAll();
            long deadline = System.currentTimeMillis() + 10_000;
            while (drawn < want && !closed) {
                long left = deadline - System.currentTimeMillis();
                if (left <= 0) break;
                lock.wait(left);
            }
        }
    }

    /** Number of points in the first series, as last drawn (for logs and tests). */
    public int points() {
        synchronized (lock) {
            return series[0][0].getItemCount();
        }
    }

    @Override
    public void close() {
        synchronized (lock) {
            closed = true;
            lock.notifyAll();
        }
    }

    // ------------------------------------------------------------------ the chart thread
    private void loop() {
        try {
            while (true) {
                long want;
                synchronized (lock) {
                    while (requested == drawn && !closed) lock.wait();
                    if (closed) return;
                    want = requested;
                }
                BufferedImage img = draw();
                image = img;
                view.repaint();
                synchronized (lock) {
                    drawn = Math.max(drawn, want);
                    lock.notifyAll();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private BufferedImage draw() {
        boolean changed = false;
        synchronized (lock) {   // points() reads the series
            for (double[] row; (row = pending.poll()) != null; changed = true) addRow(row);
            if (changed) {
                chart.setNotify(false);
                for (XYSeries[] ss : series) for (XYSeries s : ss) s.fireSeriesChanged();
                // the time axis shows [0, WINDOW_S] until the traces reach its end, then scrolls
                double hi = Math.max(WINDOW_S, latest);
                if (time.getUpperBound() != hi) time.setRange(hi - WINDOW_S, hi);
                chart.setNotify(true);
            }
        }
        int w = width, h = height;
        if (w <= 0 || h <= 0) return image;
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            chart.draw(g, new Rectangle(0, 0, w, h));
        } finally {
            g.dispose();
        }
        return img;
    }

    private void addRow(double[] row) {
        long gen = (long) row[0];
        if (gen != generation) {
            for (XYSeries[] ss : series) for (XYSeries s : ss) s.clear();
            latest = 0;
            generation = gen;
        }
        double t = row[1];
        latest = t;
        for (int k = 0; k < 3; k++) {
            int o = 2 + 7 * k;
            for (int j = 0; j < 2; j++) {
                series[0][2 * k + j].add(t, row[o + j], false);
                series[1][2 * k + j].add(t, row[o + 2 + j], false);
                series[2][2 * k + j].add(t, row[o + 4 + j], false);
            }
            series[3][k].add(t, row[o + 6], false);
        }
    }
}
