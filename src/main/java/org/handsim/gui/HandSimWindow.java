package org.handsim.gui;

import java.awt.BorderLayout;
import java.awt.CardLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.GraphicsEnvironment;
import java.awt.KeyEventDispatcher;
import java.awt.KeyboardFocusManager;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import javax.swing.AbstractButton;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JPopupMenu;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.ToolTipManager;
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.swing.text.JTextComponent;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.files.AtomicFile;
import org.handsim.text.JsonWriter;

/**
 * The HandSim window (paper Section V, Fig. 5): the four buttons of the paper at the top —
 * <b>Kinematics</b>, <b>Path Planning</b>, <b>Dynamics</b>, <b>Objects</b> — each opening its
 * panel on the left; Play / Pause / Step / Reset, the speed and the simulated time beside
 * them, as in an Easy-Java-Simulations program; the simulator ({@link HandSimPanel}: the Java3D
 * view and the model) in the centre; live traces on the right, beside it in a split pane; a
 * status bar at the bottom: messages on the left, what the run is doing on the right.
 *
 * <h2>Menus and keys</h2>
 * <ul>
 *   <li><b>File</b>: Open scenario (Ctrl+O), Save scenario (Ctrl+S: the window's state as a
 *       scenario file that {@code handsim run} reproduces to the last digit), Import object
 *       (Ctrl+I: VRML97, OBJ, STL), Export traces (Ctrl+E: trace.csv of the run so far, the
 *       {@code handsim run} contract), Save charts (PNG or SVG), Screenshot (F12), Close (Ctrl+W).</li>
 *   <li><b>View</b>: camera Home (H), Fit to the scene (F), Front (1), Top (2), Side (3);
 *       contact points, normals, the object, friction cones (off at first); per finger and
 *       joint the chart series.</li>
 *   <li><b>Run</b>: Play/Pause (Space), Step (→), Reset (R).</li>
 * </ul>
 * Keys without Ctrl act only while no text field has the keyboard focus (so typing an "r" into
 * a field does not reset the run).
 *
 * <h2>Model, view, control</h2>
 * <ul>
 *   <li><b>Model</b>: the panel's {@link SimulationRunner} steps the {@code HandModel} on its own
 *       thread and publishes immutable states and trace rows.</li>
 *   <li><b>View</b>: the panel's timer on the event dispatch thread shows each newer state in the
 *       3D view and tells this window ({@link HandSimPanel.StepListener}): charts, the time, the
 *       run state, the Dynamics table. Nothing waits for the model, so the window never freezes.</li>
 *   <li><b>Control</b>: the panels change the working {@link Scenario} (immutable copies) and
 *       hand it over with {@link #load}, or drive the model (Play, Pause, Step, Reset).</li>
 * </ul>
 * Every method of this class runs on the event dispatch thread unless it says otherwise.
 */
public final class HandSimWindow {
    /** While the simulation plays the charts are redrawn every this many ticks (~8 Hz). */
    static final int CHART_TICKS = 5;
    /** The four buttons of the paper, in order. */
    public static final List<String> TOOLS = List.of("Kinematics", "Path Planning", "Dynamics", "Objects");
    /** The smallest window size the layout is made for. */
    public static final Dimension MINIMUM = new Dimension(1024, 700);
    /** Colour of warnings in the status bar. */
    static final Color WARNING = new Color(0xA05A00);

    private final JFrame frame;
    private final HandSimPanel sim;
    private final TraceCharts charts = new TraceCharts();
    private final boolean interactive;
    private Scenario original;
    private final JLabel status = new JLabel(" ");
    private final JLabel runState = new JLabel(" ");
    private final JLabel time = new JLabel("t = 0.000 s");
    private final JComboBox<String> speed = new JComboBox<>(new String[] {"0.25x", "0.5x", "1x real time", "2x", "5x", "as fast as possible"});
    private final CardLayout cards = new CardLayout();
    private final JPanel toolPanel = new JPanel(cards);
    private final KinematicsPanel kinematics;
    private final PathPlanningPanel pathPlanning;
    private final DynamicsPanel dynamics;
    private final ObjectsPanel objects;
    private final CountDownLatch closing = new CountDownLatch(1), closed = new CountDownLatch(1);
    private boolean shuttingDown;
    private final Map<String, AbstractButton> menuItems = new LinkedHashMap<>();
    private final KeyEventDispatcher keys = this::plainKey;
    private int ticks;
    private boolean chartsDirty;
    private long shownGeneration = -1, shownGraspSerial = -1;
    private String shownError, shownNote;
    private Path scenarioFile;

    /**
     * Builds the window (not yet visible). Event dispatch thread.
     *
     * @param scenario    the scenario to open
     * @param hand        the palm and link meshes ({@link HandSimPanel#loadHand()}, read beforehand off this thread)
     * @param interactive false in scripted mode: no modal dialogs
     */
    public HandSimWindow(Scenario scenario, MeshSource.Model[] hand, boolean interactive) {
        this.original = scenario;
        this.scenarioFile = scenario.file();
        this.interactive = interactive;
        // the Canvas3D is heavyweight: menus and tool tips must be too, or they hide behind it
        JPopupMenu.setDefaultLightWeightPopupEnabled(false);
        ToolTipManager.sharedInstance().setLightWeightPopupEnabled(false);

        sim = new HandSimPanel(scenario, hand);
        sim.setMessages(this::status);
        sim.addStepListener(this::update);
        sim.addTickHook(this::tickCharts);
        sim.addTickHook(this::tickGrasp);
        charts.setDuration(org.handsim.model.HandModel.endTime(scenario));   // the time label's end, handsim run's

        frame = new JFrame("HandSim — BarrettHand simulator");
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                closing.countDown();
            }

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
        toolPanel.setPreferredSize(new Dimension(350, 600));
        toolPanel.setMinimumSize(new Dimension(300, 200));

        JPanel content = new JPanel(new BorderLayout());
        content.add(toolbar(), BorderLayout.NORTH);
        content.add(toolPanel, BorderLayout.WEST);
        JPanel centre = new JPanel(new BorderLayout());
        centre.setName("view");
        centre.add(sim, BorderLayout.CENTER);
        centre.setMinimumSize(new Dimension(250, 250));
        charts.panel().setPreferredSize(new Dimension(400, 600));
        charts.panel().setMinimumSize(new Dimension(250, 250));
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, centre, charts.panel());
        split.setName("split");
        split.setResizeWeight(0.55);
        split.setContinuousLayout(true);
        split.setBorder(BorderFactory.createEmptyBorder());
        content.add(split, BorderLayout.CENTER);
        JPanel bar = new JPanel(new BorderLayout());
        status.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        status.setName("status");
        status.setMinimumSize(new Dimension(10, 10));
        runState.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        runState.setName("runstate");
        runState.setFont(runState.getFont().deriveFont(Font.BOLD));
        bar.add(status, BorderLayout.CENTER);
        bar.add(runState, BorderLayout.EAST);
        content.add(bar, BorderLayout.SOUTH);
        frame.setContentPane(content);
        frame.setJMenuBar(menus());
        frame.setMinimumSize(MINIMUM);
        Rectangle screen = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        frame.setSize(Math.min(1280, screen.width), Math.min(860, screen.height));
        KeyboardFocusManager.getCurrentKeyboardFocusManager().addKeyEventDispatcher(keys);
        objects.showPlacement(scenario);
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
        bar.addSeparator(new Dimension(16, 10));
        bar.add(Widgets.button("play", "Play", this::play));
        bar.add(Widgets.button("pause", "Pause", this::pause));
        bar.add(Widgets.button("step", "Step", this::step));
        bar.add(Widgets.button("reset", "Reset", this::reset));
        bar.addSeparator();
        JPanel sp = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        sp.add(new JLabel("speed"));
        speed.setName("speed");
        speed.setSelectedIndex(2);
        speed.addActionListener(e -> sim.setSpeed(speedFactor()));
        sp.add(speed);
        sp.setMaximumSize(new Dimension(230, 40));
        bar.add(sp);
        bar.addSeparator();
        time.setName("time");
        time.setFont(new Font(Font.MONOSPACED, Font.BOLD, 13));
        bar.add(time);
        return bar;
    }

    // ------------------------------------------------------------------ menus and keys
    private JMenuBar menus() {
        JMenuBar mb = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(item("file.open", "Open scenario…", KeyStroke.getKeyStroke(KeyEvent.VK_O, InputEvent.CTRL_DOWN_MASK), this::chooseScenario));
        file.add(item("file.save", "Save scenario…", KeyStroke.getKeyStroke(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK), this::chooseSaveScenario));
        file.addSeparator();
        file.add(item("file.import", "Import object (VRML, OBJ, STL)…", KeyStroke.getKeyStroke(KeyEvent.VK_I, InputEvent.CTRL_DOWN_MASK), objects::choose));
        file.add(item("file.export", "Export traces (trace.csv)…", KeyStroke.getKeyStroke(KeyEvent.VK_E, InputEvent.CTRL_DOWN_MASK), this::chooseExport));
        file.add(item("file.charts", "Save charts (PNG or SVG)…", null, this::chooseSaveCharts));
        file.add(item("file.screenshot", "Screenshot (PNG)…", KeyStroke.getKeyStroke(KeyEvent.VK_F12, 0), this::chooseScreenshot));
        file.addSeparator();
        file.add(item("file.close", "Close", KeyStroke.getKeyStroke(KeyEvent.VK_W, InputEvent.CTRL_DOWN_MASK), this::dispose));
        mb.add(file);

        JMenu view = new JMenu("View");
        view.setMnemonic(KeyEvent.VK_V);
        for (SceneView.Camera c : SceneView.Camera.values()) {
            view.add(item("view.camera." + c.id(), c.label() + "  (" + c.key() + ")", null, () -> camera(c)));
        }
        view.addSeparator();
        view.add(check("view.contacts", "Contact points", true, on -> sim.view().setVisible(SceneView.Part.CONTACTS, on)));
        view.add(check("view.normals", "Contact normals", true, on -> sim.view().setVisible(SceneView.Part.NORMALS, on)));
        view.add(check("view.object", "Object", true, on -> sim.view().setVisible(SceneView.Part.OBJECT, on)));
        JCheckBoxMenuItem cones = check("view.cones", "Friction cones", false, on -> sim.view().setVisible(SceneView.Part.CONES, on));
        cones.setToolTipText("the linearised friction cone at each contact, in its finger's colour (the object's friction μ)");
        view.add(cones);
        view.addSeparator();
        JMenu series = new JMenu("Chart series");
        for (int k = 1; k <= 3; k++) {
            int finger = k;
            series.add(check("view.series.finger" + k, "Finger " + k, true, on -> charts.setFingerVisible(finger, on)));
        }
        series.addSeparator();
        for (int j = 2; j <= 3; j++) {
            int joint = j;
            series.add(check("view.series.joint" + j, "Joints k" + j + (j == 2 ? " (solid)" : " (dashed)"), true, on -> charts.setJointVisible(joint, on)));
        }
        view.add(series);
        mb.add(view);

        JMenu run = new JMenu("Run");
        run.setMnemonic(KeyEvent.VK_R);
        run.add(item("run.toggle", "Play / Pause  (Space)", null, this::togglePlay));
        run.add(item("run.step", "Step  (→)", null, this::step));
        run.add(item("run.reset", "Reset  (R)", null, this::reset));
        mb.add(run);
        return mb;
    }

    private JMenuItem item(String name, String label, KeyStroke key, Runnable action) {
        JMenuItem i = new JMenuItem(label);
        i.setName(name);
        if (key != null) i.setAccelerator(key);
        i.addActionListener(e -> action.run());
        menuItems.put(name, i);
        return i;
    }

    private JCheckBoxMenuItem check(String name, String label, boolean on, java.util.function.Consumer<Boolean> action) {
        JCheckBoxMenuItem i = new JCheckBoxMenuItem(label, on);
        i.setName(name);
        i.addActionListener(e -> action.accept(i.isSelected()));
        menuItems.put(name, i);
        return i;
    }

    /** The menu items by name (file.save, view.camera.fit, run.toggle, view.series.finger1, ...). */
    public Map<String, AbstractButton> menuItems() { return menuItems; }

    /**
     * Keys without a modifier: Space plays or pauses, → steps, R resets, H/F/1/2/3 move the camera
     * — only when the window is focused and no text field has the focus.
     */
    private boolean plainKey(KeyEvent e) {
        if (e.getID() != KeyEvent.KEY_PRESSED || e.getModifiersEx() != 0) return false;
        if (!frame.isFocused()) return false;
        Component owner = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
        if (owner instanceof JTextComponent || owner instanceof JComboBox && ((JComboBox<?>) owner).isEditable()) return false;
        return shortcut(e.getKeyCode());
    }

    /** Does what a plain key does; false if the key means nothing. */
    boolean shortcut(int keyCode) {
        switch (keyCode) {
            case KeyEvent.VK_SPACE: togglePlay(); return true;
            case KeyEvent.VK_RIGHT: step(); return true;
            case KeyEvent.VK_R: reset(); return true;
            default:
                for (SceneView.Camera c : SceneView.Camera.values()) {
                    if (KeyEvent.getExtendedKeyCodeForChar(c.key().charAt(0)) == keyCode) {
                        camera(c);
                        return true;
                    }
                }
                return false;
        }
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
    /** The embeddable simulator component in the centre. */
    public HandSimPanel simulator() { return sim; }
    public SceneView view() { return sim.view(); }
    public TraceCharts charts() { return charts; }
    public SimulationRunner runner() { return sim.runner(); }
    public DynamicsPanel dynamics() { return dynamics; }
    public KinematicsPanel kinematics() { return kinematics; }
    public ObjectsPanel objectsPanel() { return objects; }
    public PathPlanningPanel pathPlanning() { return pathPlanning; }
    /** The working scenario (what Play runs). */
    public Scenario scenario() { return sim.scenario(); }
    /** The scenario the window was opened with (or the last one opened from the File menu). */
    public Scenario originalScenario() { return original; }

    /** Makes the window visible. */
    public void show() {
        frame.setLocationByPlatform(interactive);
        if (!interactive) frame.setLocation(0, 0);
        frame.setVisible(true);
    }

    /** Builds a model for {@code s}, shows its t = 0 and makes it the working scenario. */
    public void load(Scenario s) {
        sim.load(s);
        sim.setSpeed(speedFactor());
        charts.setDuration(org.handsim.model.HandModel.endTime(s));
        objects.showPlacement(s);
        pathPlanning.show(s);
        kinematics.previewChanged();
    }


    /** Plays from where the model is (drops a Kinematics preview). */
    public void play() { sim.setSpeed(speedFactor()); sim.play(); }
    /** Plays until the simulated time reaches {@code t} seconds (or the end). */
    public void playUntil(double t) { sim.setSpeed(speedFactor()); sim.playUntil(t); }
    public void pause() {
        sim.pause();
        status(PAUSED, false);   // a message about a run that played (Path Planning's) is no longer true
    }

    /** The status bar's message after Pause. */
    static final String PAUSED = "paused (Play or Space to go on, Step or → for one step)";
    public void step() { sim.step(); }
    public void reset() { sim.reset(); }

    /** Play when paused, pause when playing; at the end, play again from t = 0. */
    public void togglePlay() {
        SimulationRunner.State s = sim.state();
        if (s.playing()) {
            pause();
        } else {
            if (s.finished()) reset();
            play();
        }
    }

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

    /** Moves the camera (View menu, keys H, F, 1, 2, 3, script {@code camera}). */
    public void camera(SceneView.Camera c) {
        sim.view().camera(c, scenario(), sim.objectModel());
        status("camera: " + c.label().toLowerCase(Locale.ROOT), false);
    }

    /** Pauses the model and shows a pose of the panels' own until the next Play, Step, Reset or load. */
    public void preview(Pose p) {
        sim.preview(p);
    }

    /** Motor counts M1..M4 the hand is at now (the newest state, else the scenario's start). */
    public double[] currentCounts() {
        SimulationRunner.State s = sim.state();
        double[] q = new double[4];
        if (s.snapshot() != null && s.scenario() == scenario()) {
            for (int k = 0; k < 3; k++) q[k] = s.snapshot().fingers()[k].motorCounts();
            q[3] = s.snapshot().spreadCounts();
        } else {
            for (int m = 0; m < 4; m++) q[m] = scenario().startCounts(m);
        }
        return q;
    }

    /** Triangles in the scene: palm, nine links, object. */
    public int triangleCount() {
        MeshSource.Model o = sim.objectModel();
        return sim.view().handTriangles() + (o != null ? o.mesh().triangleCount() : 0);
    }

    /** Shows a message in the status bar (red for errors). */
    public void status(String message, boolean isError) {
        statusSerial++;
        statusRefused = false;
        status.setForeground(isError ? Widgets.ERROR : Color.DARK_GRAY);
        status.setText(message);
        status.setToolTipText(message);
    }

    /** Shows a warning in the status bar (orange). */
    public void warning(String message) {
        statusSerial++;
        statusRefused = false;
        status.setForeground(WARNING);
        status.setText("warning: " + message);
        status.setToolTipText(message);
    }

    /** The status bar text. */
    public String statusText() { return status.getText(); }

    // what the script's 'set' checks after typing a value: did the panel refuse it in the status bar?
    private int statusSerial;
    private boolean statusRefused;

    /**
     * Shows, in red, why a panel refused a value typed into one of its fields (not a number, out
     * of range): the script's {@code set} fails on it, where an error that is a result (an
     * unreachable IK target) leaves the {@code set} done.
     */
    public void refused(String message) {
        status(message, true);
        statusRefused = true;
    }

    /** Counts the messages shown in the status bar (event dispatch thread). */
    int statusSerial() { return statusSerial; }

    /** Whether the last status message was a refused value ({@link #refused}; event dispatch thread). */
    boolean statusRefused() { return statusRefused; }

    /** What the run is doing, as the status bar's right end says: running, paused, finished, reset, ... */
    public String runStateText() { return runState.getText(); }

    /**
     * An error: status bar, and when interactive a dialog and one line on standard error. A
     * script reports the error itself (the action that failed names it, or expect-error wanted it),
     * so under a script the window does not print it too.
     */
    public void error(String message, String title) {
        status(message, true);
        if (interactive) {
            System.err.println("handsim gui: " + message);
            JOptionPane.showMessageDialog(frame, message, title, JOptionPane.ERROR_MESSAGE);
        }
    }

    /** Regions of the window (relative to its top-left corner) for screenshot checks: view, charts, status bar, tool panel. */
    public List<Rectangle> regions() {
        List<Rectangle> r = new ArrayList<>();
        for (Component c : new Component[] {sim.view().canvas(), charts.panel(), status.getParent(), toolPanel}) {
            java.awt.Point p = SwingUtilities.convertPoint(c.getParent(), c.getLocation(), frame);
            r.add(new Rectangle(p.x, p.y, c.getWidth(), c.getHeight()));
        }
        return r;
    }

    /** Blocks until the window is closed (any thread but the EDT). */
    public void awaitClosed() throws InterruptedException { closed.await(); }

    /**
     * Blocks until the window has begun to close: the user asked to close it, or
     * {@link #dispose()} began (any thread but the EDT).
     */
    public void awaitClosing() throws InterruptedException { closing.await(); }

    /**
     * Waits at most {@code ms} for the window to be closed (its simulation and rendering threads
     * stopped); true when it is (any thread but the EDT).
     */
    public boolean awaitClosed(long ms) throws InterruptedException { return closed.await(ms, TimeUnit.MILLISECONDS); }

    /** Closes the window and stops the simulation and rendering threads. */
    public void dispose() {
        closing.countDown();
        frame.dispose();
        shutdown();
    }

    private void shutdown() {
        if (shuttingDown) return;   // a second call while the first is still under way (windowClosed during dispose)
        shuttingDown = true;
        closing.countDown();
        KeyboardFocusManager.getCurrentKeyboardFocusManager().removeKeyEventDispatcher(keys);
        sim.dispose();
        charts.close();
        closed.countDown();
    }

    // ------------------------------------------------------------------ files
    private JFileChooser chooser(Path start, String description, String... extensions) {
        JFileChooser fc = new JFileChooser(start != null && Files.isDirectory(start) ? start.toFile() : null);
        if (extensions.length > 0) fc.setFileFilter(new FileNameExtensionFilter(description, extensions));
        return fc;
    }

    private void chooseScenario() {
        JFileChooser fc = chooser(scenarioFile != null ? scenarioFile.getParent() : Home.scenarios(), "Scenarios (*.json)", "json");
        if (fc.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) openScenario(fc.getSelectedFile().toPath());
    }

    /** Opens a scenario file: it becomes the working and the original scenario. */
    public boolean openScenario(Path file) {
        try {
            Scenario s = Scenario.load(file);
            original = s;
            scenarioFile = file;
            load(s);
            String units = s.unitNotice("opened " + file);   // the unit rule's notice, when the size chose
            status(units != null ? units : "opened " + file, false);
            return true;
        } catch (ScenarioException e) {
            error("cannot open " + file + ": " + e.getMessage(), "Scenario not opened");
            return false;
        }
    }

    private void chooseSaveScenario() {
        JFileChooser fc = chooser(scenarioFile != null ? scenarioFile.getParent() : Home.scenarios(), "Scenarios (*.json)", "json");
        fc.setSelectedFile(new java.io.File(scenario().name() + ".json"));
        if (fc.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) saveScenario(withExtension(fc.getSelectedFile().toPath(), ".json"));
    }

    /**
     * Writes the working scenario (what Play runs: trajectories, object, gravity, time step)
     * as a scenario file; {@code handsim run FILE} reproduces the window's run to the last digit.
     */
    public boolean saveScenario(Path file) {
        try {
            Path dir = file.toAbsolutePath().getParent();
            if (dir != null) Files.createDirectories(dir);
            AtomicFile.writeString(file, JsonWriter.pretty(scenario().toJson(dir)));
            scenarioFile = file;
            status("scenario saved to " + file + " (handsim run " + file.getFileName() + " reproduces this run)", false);
            return true;
        } catch (IOException | RuntimeException e) {
            error("cannot save the scenario to " + file + ": " + e.getMessage(), "Scenario not saved");
            return false;
        }
    }

    private void chooseExport() {
        JFileChooser fc = chooser(Path.of("").toAbsolutePath(), "CSV (*.csv)", "csv");
        fc.setSelectedFile(new java.io.File("trace.csv"));
        if (fc.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) exportTraces(withExtension(fc.getSelectedFile().toPath(), ".csv"));
    }

    /**
     * Writes the trace of the run so far (t = 0 to now, every step) in the trace.csv contract of
     * {@code handsim run}. The future completes with the rows written (on the EDT, after the
     * status bar says so) or exceptionally.
     */
    public CompletableFuture<Integer> exportTraces(Path file) {
        CompletableFuture<Integer> done = new CompletableFuture<>();
        sim.runner().exportTrace(file).whenComplete((rows, e) -> SwingUtilities.invokeLater(() -> {
            if (e != null) {
                Throwable c = e instanceof java.util.concurrent.CompletionException && e.getCause() != null ? e.getCause() : e;
                error("cannot export the traces to " + file + ": " + c.getMessage(), "Traces not exported");
                done.completeExceptionally(c);
            } else {
                status("exported " + rows + " rows of the trace to " + file, false);
                done.complete(rows);
            }
        }));
        return done;
    }

    private void chooseSaveCharts() {
        JFileChooser fc = chooser(Path.of("").toAbsolutePath(), "PNG or SVG (*.png, *.svg)", "png", "svg");
        fc.setSelectedFile(new java.io.File("charts.png"));
        if (fc.showSaveDialog(frame) == JFileChooser.APPROVE_OPTION) saveCharts(withExtension(fc.getSelectedFile().toPath(), ".png"));
    }

    /** Saves the charts as PNG or SVG (by the name's extension) at the size they have on screen. */
    public CompletableFuture<Path> saveCharts(Path file) {
        CompletableFuture<Path> done = charts.save(file);
        done.whenComplete((p, e) -> SwingUtilities.invokeLater(() -> {
            if (e != null) error("cannot save the charts to " + file + ": " + e.getMessage(), "Charts not saved");
            else status("charts saved to " + file, false);
        }));
        return done;
    }

    private void chooseScreenshot() {
        JFileChooser fc = chooser(Path.of("").toAbsolutePath(), "PNG (*.png)", "png");
        fc.setSelectedFile(new java.io.File("handsim.png"));
        if (fc.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) return;
        Path f = withExtension(fc.getSelectedFile().toPath(), ".png");
        // after the dialog has gone from the screen
        Thread t = new Thread(() -> {
            try {
                Thread.sleep(300);
                BufferedImage img = capture();
                writePng(img, f);
                SwingUtilities.invokeLater(() -> status("screenshot saved to " + f, false));
            } catch (Exception e) {
                SwingUtilities.invokeLater(() -> error("cannot save the screenshot: " + e.getMessage(), "Screenshot not saved"));
            }
        }, "handsim-screenshot");
        t.setDaemon(true);
        t.start();
    }

    /**
     * The window as it is on the screen. The Java3D canvas is a heavyweight OpenGL surface that
     * {@code paint} into an image would leave blank, so the screen's pixels are read
     * ({@link Robot}). Any thread but the EDT.
     */
    BufferedImage capture() throws Exception {
        Rectangle bounds = ScriptRunner.edt(() -> {
            java.awt.Point p = frame.getLocationOnScreen();
            return new Rectangle(p.x, p.y, frame.getWidth(), frame.getHeight());
        });
        return new Robot().createScreenCapture(bounds);
    }

    static void writePng(BufferedImage img, Path file) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ImageIO.write(img, "png", bytes);
        if (file.toAbsolutePath().getParent() != null) Files.createDirectories(file.toAbsolutePath().getParent());
        try (AtomicFile af = new AtomicFile(file)) {
            bytes.writeTo(af.stream());
            af.commit();
        }
    }

    private static Path withExtension(Path p, String ext) {
        String n = p.getFileName().toString();
        return n.contains(".") ? p : p.resolveSibling(n + ext);
    }

    // ------------------------------------------------------------------ the view update
    /** A newer state of the model (the panel's step listener): labels, panels, run state. */
    private void update(SimulationRunner.State s) {
        if (s.generation() != shownGeneration) {
            shownGeneration = s.generation();
            charts.setDuration(s.scenario() != null ? org.handsim.model.HandModel.endTime(s.scenario()) : 0);
            if (!s.warnings().isEmpty() && s.origin() == SimulationRunner.Origin.LOADED) warning(String.join("; ", s.warnings()));
        }
        dynamics.update(s);
        sim.runner().drainEvents(dynamics::event);
        kinematics.follow(s);
        time.setText(timeText(s));
        runState.setText(runState(s));
        runState.setForeground(s.error() != null ? Widgets.ERROR : Color.DARK_GRAY);
        if (!Objects.equals(s.error(), shownError)) {
            shownError = s.error();
            if (s.error() != null) error(s.error(), "Simulation stopped");
        }
        if (!Objects.equals(s.note(), shownNote)) {
            shownNote = s.note();
            if (s.note() != null) status(s.note(), true);
        }
    }

    /**
     * The time label: the model's time and the time its run ends, both step × dt in decimal and
     * written as {@code handsim run} writes them ({@code t = 2.500 s / 8.947 s}).
     */
    static String timeText(SimulationRunner.State s) {
        double end = s.scenario() == null ? 0 : org.handsim.model.HandModel.endTime(s.scenario());
        return String.format(Locale.ROOT, "t = %.3f s / %.3f s", s.time(), end);
    }

    /** The run state in words (the status bar's right end). */
    static String runState(SimulationRunner.State s) {
        if (s.error() != null) return "stopped by an error";
        if (s.snapshot() == null) return "no model";
        if (s.playing()) return "running";
        if (s.finished()) return "finished";
        if (s.time() == 0) return s.origin() == SimulationRunner.Origin.RESET ? "reset" : "ready";
        return "paused";
    }

    /** Every tick: trace rows into the charts, a redraw now and then while playing. */
    private void tickCharts() {
        ticks++;
        if (sim.runner().drainTrace(charts::add) > 0) chartsDirty = true;
        // the charts are drawn on their own thread: ask for a redraw every CHART_TICKS ticks while playing
        if (chartsDirty && (!sim.state().playing() || ticks % CHART_TICKS == 0)) {
            charts.flush();
            chartsDirty = false;
        }
    }

    /** Every tick: a newer grasp evaluation into the Dynamics panel. */
    private void tickGrasp() {
        LiveGrasp.Result g = sim.runner().grasp().latest();
        if (g != null && g.serial() != shownGraspSerial && dynamics.grasp(g)) shownGraspSerial = g.serial();
    }

    /**
     * Whether every readout shows the newest state of the model: the view, panels, labels and
     * table were given the newest published state, and the Dynamics panel's Grasp box the
     * newest evaluation — which, for a model at rest, must be of the state shown (its
     * generation and time; {@link LiveGrasp} evaluates a resting model's grasp at its time);
     * and the scenario's object is in the 3D view (its mesh read). Scripts wait for it before a screenshot or a log ({@link ScriptRunner#settle()}).
     */
    boolean settled() {
        SimulationRunner.State s = sim.state();
        if (sim.shownPublication() != s.publication()) return false;
        if (!sim.objectReady().isDone()) return false;   // the object's mesh still loading: not in the view yet
        LiveGrasp.Result g = sim.runner().grasp().latest();
        if (g != null && g.serial() != shownGraspSerial) return false;
        if (s.playing() || s.snapshot() == null) return true;
        return g != null && g.generation() == s.generation() && (g.assessment() == null || g.assessment().timeS() == s.time());
    }

    /** Runs the view update now and draws the charts (scripts call it before a screenshot). */
    public void refreshNow() {
        sim.tick();
        charts.flush();
    }
}
