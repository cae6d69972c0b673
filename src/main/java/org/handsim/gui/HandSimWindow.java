package org.handsim.gui;

import java.awt.BorderLayout;
import java.awt.CardLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JPopupMenu;
import javax.swing.JScrollPane;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.ToolTipManager;
import org.handsim.math.RigidTransform;
import org.handsim.sim.SceneGeometry;
import org.handsim.sim.Scenario;

/**
 * The HandSim window (paper Section V, Fig. 5): the four buttons of the paper at the top —
 * <b>Kinematics</b>, <b>Path Planning</b>, <b>Dynamics</b>, <b>Objects</b> — each opening its
 * panel on the left; Play / Pause / Step / Reset, the speed and the simulated time beside
 * them, as in an Easy-Java-Simulations program; the Java3D view of the hand in the centre;
 * live traces on the right; a status bar at the bottom where errors appear.
 *
 * <h2>Model, view, control</h2>
 * <ul>
 *   <li><b>Model</b>: a {@link SimulationRunner} steps the {@code HandModel} on its own thread
 *       and publishes immutable states and trace rows.</li>
 *   <li><b>View</b>: a {@link Timer} on the event dispatch thread, {@value #TICK_MS} ms apart,
 *       reads the newest state and shows it in the {@link SceneView}, the charts, the time label
 *       and the Dynamics table. Nothing waits for the model, so the window never freezes.</li>
 *   <li><b>Control</b>: the panels change the working {@link Scenario} (immutable copies:
 *       {@code withMotor}, {@code withObject}, {@code withGravity}, ...) and hand it to the
 *       runner with {@link #load}, or drive the runner directly (Play, Pause, Step, Reset).
 *       The Kinematics panel can show a pose of its own ({@link #preview}) until the next
 *       Play, Step, Reset or load.</li>
 * </ul>
 * Every method of this class runs on the event dispatch thread unless it says otherwise.
 */
public final class HandSimWindow {
    /** Milliseconds between view updates (~40 Hz). */
    public static final int TICK_MS = 25;
    /** While the simulation plays the charts are redrawn every this many ticks (~8 Hz). */
    static final int CHART_TICKS = 5;
    /** The four buttons of the paper, in order. */
    public static final List<String> TOOLS = List.of("Kinematics", "Path Planning", "Dynamics", "Objects");

    private final JFrame frame;
    private final SceneView view;
    private final TraceCharts charts = new TraceCharts();
    private final SimulationRunner runner;
    private final boolean interactive;
    private final Scenario original;
    private Scenario scenario;
    private final JLabel status = new JLabel(" ");
    private final JLabel time = new JLabel("t = 0.000 s");
    private final JComboBox<String> speed = new JComboBox<>(new String[] {"0.25x", "0.5x", "1x real time", "2x", "5x", "as fast as possible"});
    private final CardLayout cards = new CardLayout();
    private final JPanel toolPanel = new JPanel(cards);
    private final KinematicsPanel kinematics;
    private final PathPlanningPanel pathPlanning;
    private final DynamicsPanel dynamics;
    private final ObjectsPanel objects;
    private final Timer timer;
    private final CountDownLatch closed = new CountDownLatch(1);
    private Pose preview;
    private long shownPublication = -1;
    private int ticks;
    private boolean chartsDirty;
    private String shownError, shownNote;
    private MeshSource.Model objectModel;
    private Path objectFile;

    /**
     * Builds the window (not yet visible). Event dispatch thread.
     *
     * @param scenario    the scenario to open
     * @param hand        the palm and link meshes ({@link #loadHand()}, read beforehand off this thread)
     * @param interactive false in scripted mode: no modal dialogs
     */
    public HandSimWindow(Scenario scenario, MeshSource.Model[] hand, boolean interactive) {
        this.original = scenario;
        this.scenario = scenario;
        this.interactive = interactive;
        // the Canvas3D is heavyweight: menus and tool tips must be too, or they hide behind it
        JPopupMenu.setDefaultLightWeightPopupEnabled(false);
        ToolTipManager.sharedInstance().setLightWeightPopupEnabled(false);

        view = new SceneView(hand[0], new MeshSource.Model[] {hand[1], hand[2], hand[3]});
        view.lookAt(scenario.worldFromPalm());
        runner = new SimulationRunner();

        frame = new JFrame("HandSim — BarrettHand simulator");
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                shutdown();
            }
        });

        kinematics = new KinematicsPanel(this);
        pathPlanning = new PathPlanningPanel(this);
        dynamics = new DynamicsPanel(this);
        objects = new ObjectsPanel(this);
        toolPanel.add(scroll(kinematics.component()), TOOLS.get(0));
        toolPanel.add(scroll(pathPlanning.component()), TOOLS.get(1));
        toolPanel.add(scroll(dynamics.component()), TOOLS.get(2));
        toolPanel.add(scroll(objects.component()), TOOLS.get(3));
        toolPanel.setPreferredSize(new Dimension(360, 600));

        JPanel content = new JPanel(new BorderLayout());
        content.add(toolbar(), BorderLayout.NORTH);
        content.add(toolPanel, BorderLayout.WEST);
        JPanel centre = new JPanel(new BorderLayout());
        centre.setName("view");
        centre.add(view.canvas(), BorderLayout.CENTER);
        centre.setMinimumSize(new Dimension(300, 300));
        content.add(centre, BorderLayout.CENTER);
        charts.panel().setPreferredSize(new Dimension(410, 600));
        content.add(charts.panel(), BorderLayout.EAST);
        status.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        status.setName("status");
        content.add(status, BorderLayout.SOUTH);
        frame.setContentPane(content);
        frame.setSize(1280, 860);

        timer = new Timer(TICK_MS, e -> tick());
        timer.setCoalesce(true);
        load(scenario);
        timer.start();
    }

    /**
     * Reads the hand's meshes, {@code vrml/hand/palm.wrl} and {@code finger_link1..3.wrl}
     * (palm, links 1–3). Not on the event dispatch thread ({@link MeshSource}).
     */
    public static MeshSource.Model[] loadHand() throws IOException {
        MeshSource.Model[] m = new MeshSource.Model[4];
        m[0] = MeshSource.load(SceneGeometry.palmFile(), SceneGeometry.LINK_DIVISIONS);
        for (int j = 1; j <= 3; j++) m[j] = MeshSource.load(SceneGeometry.linkFile(j), SceneGeometry.LINK_DIVISIONS);
        return m;
    }

    private static JScrollPane scroll(JComponent c) {
        JScrollPane s = new JScrollPane(c, JScrollPane.VERTICAL_SCROLLBAR_AS_NEEDED, JScrollPane.HORIZONTAL_SCROLLBAR_NEVER);
        s.setBorder(BorderFactory.createEmptyBorder());
        s.getVerticalScrollBar().setUnitIncrement(16);
        return s;
    }

    private JToolBar toolbar() {
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        ButtonGroup group = new ButtonGroup();
        for (String t : TOOLS) {
            JToggleButton b = new JToggleButton(t);
            b.setName("tool." + t);
            b.setFont(b.getFont().deriveFont(Font.BOLD));
            b.addActionListener(e -> cards.show(toolPanel, t));
            group.add(b);
            bar.add(b);
            if (t.equals(TOOLS.get(0))) b.setSelected(true);
        }
        bar.addSeparator(new Dimension(24, 10));
        bar.add(Widgets.button("play", "Play", this::play));
        bar.add(Widgets.button("pause", "Pause", this::pause));
        bar.add(Widgets.button("step", "Step", this::step));
        bar.add(Widgets.button("reset", "Reset", this::reset));
        bar.addSeparator();
        JPanel sp = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        sp.add(new JLabel("speed"));
        speed.setName("speed");
        speed.setSelectedIndex(2);
        speed.addActionListener(e -> runner.setSpeed(speedFactor()));
        sp.add(speed);
        sp.setMaximumSize(new Dimension(260, 40));
        bar.add(sp);
        bar.addSeparator();
        time.setName("time");
        time.setFont(new Font(Font.MONOSPACED, Font.BOLD, 13));
        bar.add(time);
        return bar;
    }

    private double speedFactor() {
        switch (speed.getSelectedIndex()) {
            case 0: return 0.25;
            case 1: return 0.5;
            case 3: return 2;
            case 4: return 5;
            case 5: return 0;
            default: return 1;
        }
    }

    // ------------------------------------------------------------------ API for panels and scripts
    public JFrame frame() { return frame; }
    public SceneView view() { return view; }
    public TraceCharts charts() { return charts; }
    public SimulationRunner runner() { return runner; }
    public DynamicsPanel dynamics() { return dynamics; }
    public KinematicsPanel kinematics() { return kinematics; }
    public ObjectsPanel objectsPanel() { return objects; }
    /** The working scenario (what Play runs). */
    public Scenario scenario() { return scenario; }
    /** The scenario the window was opened with. */
    public Scenario originalScenario() { return original; }

    /** Makes the window visible. */
    public void show() {
        frame.setLocationByPlatform(interactive);
        if (!interactive) frame.setLocation(0, 0);
        frame.setVisible(true);
    }

    /** Builds a model for {@code s}, shows its t = 0 and makes it the working scenario. */
    public void load(Scenario s) {
        Scenario.ObjectPlacement before = scenario.object(), after = s.object();
        scenario = s;
        preview = null;
        runner.load(s);
        runner.setSpeed(speedFactor());
        if (after == null) {
            objectModel = null;
            objectFile = null;
            view.setObject(null, null, 1);
        } else if (objectModel == null || !after.file().equals(objectFile)) {
            loadObjectMesh(after.file(), after.divisions());
        } else if (before == null || !samePlacement(before, after)) {
            view.placeObject(after.worldFromObject(), after.scale());
        }
        objects.showPlacement(after);
    }

    private static boolean samePlacement(Scenario.ObjectPlacement a, Scenario.ObjectPlacement b) {
        return a.scale() == b.scale() && java.util.Arrays.equals(a.worldFromObject().toArray(), b.worldFromObject().toArray());
    }

    /**
     * Reads an object's mesh off the event dispatch thread and shows it at the working
     * scenario's placement when done. The future completes (on the EDT) after the view has it,
     * or exceptionally with the load error, which is also shown in the window.
     */
    CompletableFuture<MeshSource.Model> loadObjectMesh(Path file, int divisions) {
        objectFile = file;
        status("loading " + file.getFileName() + " ...", false);
        CompletableFuture<MeshSource.Model> done = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                MeshSource.Model m = MeshSource.load(file, divisions);
                SwingUtilities.invokeLater(() -> {
                    if (!file.equals(objectFile)) { done.complete(m); return; }   // superseded
                    objectModel = m;
                    Scenario.ObjectPlacement p = scenario.object();
                    view.setObject(m, p != null ? p.worldFromObject() : RigidTransform.IDENTITY, p != null ? p.scale() : 1);
                    status(file.getFileName() + ": " + m.mesh().triangleCount() + " triangles", false);
                    objects.showMesh(file, m);
                    done.complete(m);
                });
            } catch (IOException | RuntimeException e) {
                SwingUtilities.invokeLater(() -> {
                    error("cannot load " + file + ": " + e.getMessage(), "Object not loaded");
                    done.completeExceptionally(e);
                });
            }
        }, "handsim-mesh-loader");
        t.setDaemon(true);
        t.start();
        return done;
    }

    /** Plays from where the model is (drops a Kinematics preview). */
    public void play() { preview = null; runner.setSpeed(speedFactor()); runner.play(); }
    /** Plays until the simulated time reaches {@code t} seconds (or the end). */
    public void playUntil(double t) { preview = null; runner.setSpeed(speedFactor()); runner.playUntil(t); }
    public void pause() { runner.pause(); }
    public void step() { preview = null; runner.step(); }
    public void reset() { preview = null; runner.reset(); }
    /** Sets the speed list: 0 = as fast as possible, else the nearest listed factor. */
    public void setSpeed(double factor) {
        if (factor == 0) {
            speed.setSelectedIndex(5);
            return;
        }
        double[] f = {0.25, 0.5, 1, 2, 5};
        int best = 0;
        for (int i = 1; i < f.length; i++) {
            if (Math.abs(Math.log(f[i] / factor)) < Math.abs(Math.log(f[best] / factor))) best = i;
        }
        speed.setSelectedIndex(best);
    }

    /** Pauses the model and shows a pose of the panels' own until the next Play, Step, Reset or load. */
    public void preview(Pose p) {
        runner.pause();
        preview = p;
        view.show(p);
    }

    /** Motor counts M1..M4 the hand is at now (the newest state, else the scenario's start). */
    public double[] currentCounts() {
        SimulationRunner.State s = runner.latest();
        double[] q = new double[4];
        if (s.snapshot() != null && s.scenario() == scenario) {
            for (int k = 0; k < 3; k++) q[k] = s.snapshot().fingers()[k].motorCounts();
            q[3] = s.snapshot().spreadCounts();
        } else {
            for (int m = 0; m < 4; m++) q[m] = scenario.startCounts(m);
        }
        return q;
    }

    /** Triangles in the scene: palm, nine links, object. */
    public int triangleCount() {
        return view.handTriangles() + (objectModel != null ? objectModel.mesh().triangleCount() : 0);
    }

    /** Shows a message in the status bar (red for errors). */
    public void status(String message, boolean isError) {
        status.setForeground(isError ? Widgets.ERROR : Color.DARK_GRAY);
        status.setText(message);
    }

    /** The status bar text. */
    public String statusText() { return status.getText(); }

    /** An error: status bar, and a dialog when interactive. */
    public void error(String message, String title) {
        status(message, true);
        System.err.println("handsim gui: " + message);
        if (interactive) JOptionPane.showMessageDialog(frame, message, title, JOptionPane.ERROR_MESSAGE);
    }

    /** Regions of the window (relative to its top-left corner) for screenshot checks: view, charts. */
    public List<java.awt.Rectangle> regions() {
        List<java.awt.Rectangle> r = new ArrayList<>();
        for (Component c : new Component[] {view.canvas(), charts.panel()}) {
            java.awt.Point p = SwingUtilities.convertPoint(c.getParent(), c.getLocation(), frame);
            r.add(new java.awt.Rectangle(p.x, p.y, c.getWidth(), c.getHeight()));
        }
        return r;
    }

    /** Blocks until the window is closed (any thread but the EDT). */
    public void awaitClosed() throws InterruptedException { closed.await(); }

    /** Closes the window and stops the simulation and rendering threads. */
    public void dispose() {
        frame.dispose();
        shutdown();
    }

    private void shutdown() {
        if (closed.getCount() == 0) return;
        timer.stop();
        runner.close();
        charts.close();
        view.dispose();
        closed.countDown();
    }

    // ------------------------------------------------------------------ the view update
    /** One tick of the view: newest state → 3D view, labels, panels; trace rows → charts. */
    void tick() {
        ticks++;
        SimulationRunner.State s = runner.latest();
        if (s.publication() != shownPublication) {
            shownPublication = s.publication();
            if (s.snapshot() != null && preview == null) view.show(Pose.of(s.snapshot(), s.scenario().worldFromPalm()));
            dynamics.update(s);
            runner.drainEvents(dynamics::event);
            kinematics.follow(s);
            time.setText(String.format(Locale.ROOT, "t = %.3f s / %.3f s  %s", s.time(),
                s.scenario() == null ? 0 : s.scenario().duration(),
                s.error() != null ? "STOPPED" : s.playing() ? "playing" : s.finished() ? "end" : "paused"));
            if (!Objects.equals(s.error(), shownError)) {
                shownError = s.error();
                if (s.error() != null) error(s.error(), "Simulation stopped");
            }
            if (!Objects.equals(s.note(), shownNote)) {
                shownNote = s.note();
                if (s.note() != null) status(s.note(), true);
            }
        }
        if (runner.drainTrace(charts::add) > 0) chartsDirty = true;
        // the charts are drawn on their own thread: ask for a redraw every CHART_TICKS ticks while playing
        if (chartsDirty && (!s.playing() || ticks % CHART_TICKS == 0)) {
            charts.flush();
            chartsDirty = false;
        }
    }

    /** Runs the view update now and draws the charts (scripts call it before a screenshot). */
    public void refreshNow() {
        tick();
        charts.flush();
    }
}
