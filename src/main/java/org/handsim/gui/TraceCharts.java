package org.handsim.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.Shape;
import java.awt.Stroke;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import javax.swing.JComponent;
import org.handsim.chart.ChartExport;
import org.jfree.chart.ChartRenderingInfo;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.LegendItem;
import org.jfree.chart.LegendItemCollection;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.entity.ChartEntity;
import org.jfree.chart.entity.LegendItemEntity;
import org.jfree.chart.plot.CombinedDomainXYPlot;
import org.jfree.chart.plot.SeriesRenderingOrder;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.SamplingXYLineRenderer;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleInsets;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * Live traces beside the 3D view: joint angles, joint velocities, joint torques and each
 * finger's total contact force, against simulated time, in one {@link CombinedDomainXYPlot}.
 *
 * <h2>Reading them</h2>
 * <ul>
 *   <li>The time axis spans the run: [0, the scenario's duration] ({@link #setDuration}).</li>
 *   <li>One colour and one marker shape per finger (finger 1 circles, 2 squares, 3 triangles);
 *       joints k2 solid, k3 dashed. The markers of the three fingers sit at different times
 *       (about {@value #MARKERS} per series over the run, each finger's shifted by a third of
 *       the spacing), so
 *       fingers that move alike — fingers 1 and 2 often do — stay distinguishable where their
 *       lines coincide.</li>
 *   <li>The legend has one entry per finger and per joint: clicking one hides or shows those
 *       series (the View menu's "Chart series" does the same).</li>
 *   <li>Neighbouring plots are {@value #GAP} px apart, more than a tick label's height, so the
 *       top label of one plot never runs into the bottom label of the next.</li>
 * </ul>
 *
 * <h2>Drawn off the event dispatch thread</h2>
 * A chart of four plots and 21 series takes tens of milliseconds to draw — too long for the
 * event dispatch thread at display rate on a loaded machine. So the chart, its datasets and
 * its drawing belong to one thread of their own ({@code handsim-charts}, low priority):
 * {@link #add} queues rows from any thread; {@link #flush} asks for a redraw; the chart thread
 * moves the queued rows into the series with {@code XYSeries.add(x, y, false)} (docs/STYLE.md, item
 * 16), tells each series once, draws the whole chart into a new image of the component's size
 * and hands it over (a volatile field); the Swing component only paints that image. Redraw
 * requests that arrive while a drawing is under way are merged into one. A row of a new
 * generation (the model was reset or rebuilt) clears the traces first. Settings (duration,
 * visibility) and exports are tasks run on the chart thread before its next drawing.
 *
 * <p>Series are kept sorted so that only the visible points are visited, drawn by a
 * {@link SamplingXYLineRenderer} (at most a few segments per pixel column), and hold at most
 * {@link #MAX_ITEMS} points: a longer run keeps every n-th sample, so the whole run stays in view.
 */
public final class TraceCharts implements AutoCloseable {
    /** Colours of fingers 1, 2, 3 (tests look for them in screenshots). */
    public static final int[] FINGER_RGB = {0x1F77B4, 0x2CA02C, 0xD62728};
    /** Points kept per series. */
    static final int MAX_ITEMS = 4000;
    /** Markers per series over the run's duration (about). */
    static final int MARKERS = 14;
    /** Pixels between neighbouring plots. */
    static final int GAP = 16;
    private static final double[] MINIMUM_RANGE = {5, 5, 0.1, 1};
    private static final Line2D LEGEND_LINE = new Line2D.Double(-10, 0, 10, 0);
    private static final String[] LABELS = {"angle (°)", "velocity (°/s)", "torque (N·m)", "contact force (N)"};

    // chart thread only
    private final XYSeries[][] series = new XYSeries[4][];   // [plot][finger * 2 + joint] (force: [finger])
    private final XYSeries[][] markers = new XYSeries[4][];
    private final SamplingXYLineRenderer[] lineRenderers = new SamplingXYLineRenderer[4];
    private final XYLineAndShapeRenderer[] markerRenderers = new XYLineAndShapeRenderer[4];
    private final JFreeChart chart;
    private final NumberAxis time;
    private long generation = -1;
    private long rowIndex;
    private int stride = 1;
    private long markerEvery = 40;
    private double duration = 10;
    private final boolean[] fingerVisible = {true, true, true};
    private final boolean[] jointVisible = {true, true};

    // shared
    private final ConcurrentLinkedQueue<double[]> pending = new ConcurrentLinkedQueue<>();
    private final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    private final Object lock = new Object();
    private long requested, drawn;          // guarded by lock
    private boolean closed;                 // guarded by lock
    private volatile BufferedImage image;
    private volatile ChartRenderingInfo info;
    private volatile int width, height;
    private final JComponent view;
    private final Thread thread;

    public TraceCharts() {
        time = new NumberAxis("simulated time t (s)");
        time.setAutoRange(false);
        time.setRange(0, duration);
        CombinedDomainXYPlot plot = new CombinedDomainXYPlot(time);
        plot.setGap(GAP);
        for (int p = 0; p < 4; p++) {
            boolean force = p == 3;
            XYSeriesCollection data = new XYSeriesCollection(), marks = new XYSeriesCollection();
            series[p] = new XYSeries[force ? 3 : 6];
            markers[p] = new XYSeries[force ? 3 : 6];
            SamplingXYLineRenderer r = new SamplingXYLineRenderer();
            XYLineAndShapeRenderer m = new XYLineAndShapeRenderer(false, true);
            m.setUseFillPaint(true);
            m.setDrawOutlines(true);
            m.setUseOutlinePaint(false);
            for (int k = 0; k < 3; k++) {
                for (int j = 0; j < (force ? 1 : 2); j++) {
                    int i = force ? k : 2 * k + j;
                    String name = force ? "F" + (k + 1) : "θ" + (k + 1) + (j + 2);
                    XYSeries s = new XYSeries(name, true, true);   // sorted: only visible points are visited
                    s.setMaximumItemCount(MAX_ITEMS);
                    series[p][i] = s;
                    data.addSeries(s);
                    XYSeries ms = new XYSeries(name + " markers", true, true);
                    ms.setMaximumItemCount(MAX_ITEMS);
                    markers[p][i] = ms;
                    marks.addSeries(ms);
                    Color c = new Color(FINGER_RGB[k]);
                    r.setSeriesPaint(i, c);
                    r.setSeriesStroke(i, j == 0 ? new BasicStroke(2f) : dashed());
                    m.setSeriesPaint(i, c);
                    m.setSeriesFillPaint(i, Color.WHITE);
                    m.setSeriesShape(i, shape(k));
                    m.setSeriesOutlineStroke(i, new BasicStroke(1.5f));
                    m.setSeriesStroke(i, new BasicStroke(1.5f));
                }
            }
            lineRenderers[p] = r;
            markerRenderers[p] = m;
            NumberAxis y = new NumberAxis(LABELS[p]);
            y.setAutoRangeIncludesZero(true);
            y.setAutoRangeMinimumSize(MINIMUM_RANGE[p]);
            y.setLabelFont(new Font("SansSerif", Font.PLAIN, 11));
            y.setTickLabelFont(new Font("SansSerif", Font.PLAIN, 10));
            XYPlot sub = new XYPlot(data, null, y, r);
            sub.setDataset(1, marks);
            sub.setRenderer(1, m);
            sub.setSeriesRenderingOrder(SeriesRenderingOrder.FORWARD);   // finger 3 (the paper's) on top
            sub.setBackgroundPaint(Color.WHITE);
            sub.setDomainGridlinePaint(new Color(0xdddddd));
            sub.setRangeGridlinePaint(new Color(0xdddddd));
            plot.add(sub, 1);
        }
        plot.setFixedLegendItems(legend());
        chart = new JFreeChart(null, new Font("SansSerif", Font.BOLD, 12), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        chart.setPadding(new RectangleInsets(4, 4, 4, 14));   // room for the time axis's last tick label
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
        view.setToolTipText("click a legend entry to hide or show its series");
        view.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                width = view.getWidth();
                height = view.getHeight();
                flush();
            }
        });
        view.addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                String key = legendKeyAt(e.getX(), e.getY());
                if (key != null) toggle(key);
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

    /** Finger k's marker (0..2): circle, square, triangle, 7 px. */
    static Shape shape(int k) {
        switch (k) {
            case 0: return new Ellipse2D.Double(-3.5, -3.5, 7, 7);
            case 1: return new Rectangle2D.Double(-3, -3, 6, 6);
            default: {
                Path2D t = new Path2D.Double();
                t.moveTo(0, -4);
                t.lineTo(4, 3);
                t.lineTo(-4, 3);
                t.closePath();
                return t;
            }
        }
    }

    /** The legend: per finger its colour and marker, per joint its line style (greyed when hidden). */
    private LegendItemCollection legend() {
        LegendItemCollection items = new LegendItemCollection();
        for (int k = 0; k < 3; k++) {
            Color c = fingerVisible[k] ? new Color(FINGER_RGB[k]) : Color.LIGHT_GRAY;
            LegendItem li = new LegendItem("finger " + (k + 1), null, null, null, true, shape(k), false, Color.WHITE, true, c,
                new BasicStroke(1.5f), true, LEGEND_LINE, new BasicStroke(2f), c);
            li.setSeriesKey("finger" + (k + 1));
            if (!fingerVisible[k]) li.setLabelPaint(Color.GRAY);
            items.add(li);
        }
        for (int j = 0; j < 2; j++) {
            Color c = jointVisible[j] ? Color.DARK_GRAY : Color.LIGHT_GRAY;
            LegendItem li = new LegendItem("joints k" + (j + 2), null, null, null, false, LEGEND_LINE, false, Color.WHITE, false, c,
                new BasicStroke(0f), true, LEGEND_LINE, j == 0 ? new BasicStroke(2f) : dashed(), c);
            li.setSeriesKey("joint" + (j + 2));
            if (!jointVisible[j]) li.setLabelPaint(Color.GRAY);
            items.add(li);
        }
        return items;
    }

    /** The Swing component (paints the latest drawing; clicks on the legend toggle series). */
    public JComponent panel() { return view; }

    /** Queues one trace row of {@link SimulationRunner} (drawn at the next {@link #flush()}). Any thread. */
    public void add(double[] row) {
        pending.add(row);
    }

    /** The time axis spans [0, {@code seconds}] (the run's duration). Any thread. */
    public void setDuration(double seconds) {
        double d = seconds > 0 && Double.isFinite(seconds) ? seconds : 1;
        tasks.add(() -> {
            duration = d;
            stride = (int) Math.max(1, Math.ceil(d / SimulationRunner.TRACE_INTERVAL_S / (MAX_ITEMS - 2)));
            markerEvery = Math.max(6, Math.round(d / SimulationRunner.TRACE_INTERVAL_S / stride / MARKERS));
            time.setRange(0, d);
        });
        flush();
    }

    /** Shows or hides finger k's (1..3) series. Any thread. */
    public void setFingerVisible(int k, boolean on) {
        tasks.add(() -> {
            fingerVisible[k - 1] = on;
            applyVisibility();
        });
        flush();
    }

    /** Shows or hides the series of joints k2 ({@code joint} = 2) or k3 (3). Any thread. */
    public void setJointVisible(int joint, boolean on) {
        tasks.add(() -> {
            jointVisible[joint - 2] = on;
            applyVisibility();
        });
        flush();
    }

    /** Toggles a legend entry ("finger1".."finger3", "joint2", "joint3"). Any thread. */
    public void toggle(String key) {
        tasks.add(() -> {
            if (key.startsWith("finger")) {
                int k = Integer.parseInt(key.substring(6)) - 1;
                fingerVisible[k] = !fingerVisible[k];
            } else {
                int j = Integer.parseInt(key.substring(5)) - 2;
                jointVisible[j] = !jointVisible[j];
            }
            applyVisibility();
        });
        flush();
    }

    /** The legend entry at (x, y) of the component in the last drawing, or null. */
    String legendKeyAt(int x, int y) {
        ChartRenderingInfo i = info;
        if (i == null) return null;
        for (Object o : i.getEntityCollection().getEntities()) {
            ChartEntity e = (ChartEntity) o;
            if (e instanceof LegendItemEntity && e.getArea().contains(x, y)) return String.valueOf(((LegendItemEntity) e).getSeriesKey());
        }
        return null;
    }

    /** The centres of the legend entries in the last drawing, by key (for tests and scripts). */
    public java.util.Map<String, java.awt.Point> legendEntries() {
        java.util.Map<String, java.awt.Point> out = new java.util.LinkedHashMap<>();
        ChartRenderingInfo i = info;
        if (i == null) return out;
        for (Object o : i.getEntityCollection().getEntities()) {
            if (o instanceof LegendItemEntity) {
                Rectangle b = ((LegendItemEntity) o).getArea().getBounds();
                out.put(String.valueOf(((LegendItemEntity) o).getSeriesKey()), new java.awt.Point((int) b.getCenterX(), (int) b.getCenterY()));
            }
        }
        return out;
    }

    /** Whether finger k's (1..3) series are shown (as last applied on the chart thread). */
    public boolean fingerVisible(int k) {
        synchronized (lock) {
            return fingerVisible[k - 1];
        }
    }

    private void applyVisibility() {
        synchronized (lock) {
            for (int p = 0; p < 4; p++) {
                for (int i = 0; i < series[p].length; i++) {
                    boolean force = p == 3;
                    int k = force ? i : i / 2, j = force ? 0 : i % 2;
                    boolean on = fingerVisible[k] && jointVisible[j];
                    lineRenderers[p].setSeriesVisible(i, on, false);
                    markerRenderers[p].setSeriesVisible(i, on, false);
                }
            }
            ((XYPlot) chart.getPlot()).setFixedLegendItems(legend());
        }
    }

    /**
     * Saves the charts as PNG or SVG (by the file name's extension) at the component's size, on
     * the chart thread. Any thread.
     */
    public CompletableFuture<Path> save(Path file) {
        CompletableFuture<Path> done = new CompletableFuture<>();
        String n = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!n.endsWith(".png") && !n.endsWith(".svg")) {
            done.completeExceptionally(new IllegalArgumentException("the charts are saved as .png or .svg, not " + file.getFileName()));
            return done;
        }
        tasks.add(() -> {
            try {
                moveRows();
                int w = Math.max(width, 400), h = Math.max(height, 500);
                if (n.endsWith(".svg")) ChartExport.writeSvg(chart, file, w, h);
                else ChartExport.writePng(chart, file, w, h);
                done.complete(file);
            } catch (java.io.IOException | RuntimeException e) {
                done.completeExceptionally(e);
            }
        });
        flush();
        return done;
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

    /** The time axis's range as last drawn, s. */
    public double[] timeRange() {
        synchronized (lock) {
            return new double[] {time.getLowerBound(), time.getUpperBound()};
        }
    }

    /**
     * Draws the chart as the chart thread does, for tests (after {@link #awaitDrawn()}): returns
     * where everything went.
     */
    ChartRenderingInfo drawInto(Graphics2D g, int w, int h) {
        ChartRenderingInfo ri = new ChartRenderingInfo();
        synchronized (lock) {
            chart.draw(g, new Rectangle(0, 0, w, h), ri);
        }
        return ri;
    }

    /** The chart's plots, top to bottom (for tests). */
    List<XYPlot> plots() {
        return ((CombinedDomainXYPlot) chart.getPlot()).getSubplots();
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
                    while (requested == drawn && tasks.isEmpty() && !closed) lock.wait();
                    if (closed) return;
                    want = requested;
                }
                for (Runnable t; (t = tasks.poll()) != null; ) {
                    synchronized (lock) {
                        t.run();
                    }
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

    /** Moves the queued rows into the series (chart thread). */
    private void moveRows() {
        boolean changed = false;
        synchronized (lock) {   // points() reads the series
            for (double[] row; (row = pending.poll()) != null; changed = true) addRow(row);
            if (changed) {
                chart.setNotify(false);
                for (XYSeries[] ss : series) for (XYSeries s : ss) s.fireSeriesChanged();
                for (XYSeries[] ss : markers) for (XYSeries s : ss) s.fireSeriesChanged();
                chart.setNotify(true);
            }
        }
    }

    private BufferedImage draw() {
        moveRows();
        int w = width, h = height;
        if (w <= 0 || h <= 0) return image;
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        ChartRenderingInfo ri = new ChartRenderingInfo();
        try {
            synchronized (lock) {
                chart.draw(g, new Rectangle(0, 0, w, h), ri);
            }
        } finally {
            g.dispose();
        }
        info = ri;
        return img;
    }

    private void addRow(double[] row) {
        long gen = (long) row[0];
        if (gen != generation) {
            for (XYSeries[] ss : series) for (XYSeries s : ss) s.clear();
            for (XYSeries[] ss : markers) for (XYSeries s : ss) s.clear();
            generation = gen;
            rowIndex = 0;
        }
        long r = rowIndex++;
        if (r % stride != 0) return;
        long sample = r / stride;
        double t = row[1];
        for (int k = 0; k < 3; k++) {
            int o = 2 + 7 * k;
            boolean mark = sample % markerEvery == (long) k * markerEvery / 3;
            for (int j = 0; j < 2; j++) {
                for (int p = 0; p < 3; p++) {
                    series[p][2 * k + j].add(t, row[o + 2 * p + j], false);
                    if (mark) markers[p][2 * k + j].add(t, row[o + 2 * p + j], false);
                }
            }
            series[3][k].add(t, row[o + 6], false);
            if (mark) markers[3][k].add(t, row[o + 6], false);
        }
    }
}
