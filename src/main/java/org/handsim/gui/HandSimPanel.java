package org.handsim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BiConsumer;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import org.handsim.math.RigidTransform;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;

/**
 * The simulator as one Swing component, to put in any frame (an Easy-Java-Simulations-style
 * "view + model" you can embed): the Java3D view of the hand and the object, and the model
 * stepping on its own thread. {@link HandSimWindow} is built around it; another program can use
 * it alone.
 *
 * <h2>API</h2>
 * <pre>{@code
 * HandSimPanel sim = HandSimPanel.create(Scenario.load(Path.of("scenarios/paper-breakaway.json")));  // not on the EDT
 * SwingUtilities.invokeLater(() -> {
 *     JFrame f = new JFrame("My experiment");
 *     f.add(sim);                                    // a JPanel: any layout
 *     sim.addStepListener(s -> label.setText(String.format("t = %.3f s", s.time())));
 *     f.pack();
 *     f.setVisible(true);
 *     sim.play();                                    // also pause(), step(), reset(), load(scenario)
 * });
 * }</pre>
 * {@link #create} reads the hand's meshes and must not run on the event dispatch thread; every
 * other method runs on the event dispatch thread. Step listeners are called there too, each time
 * the view shows a newer state of the model (at most every {@value #TICK_MS} ms: the model may
 * have taken many steps in between; {@link SimulationRunner.State} says where it is). The first
 * state a listener sees may have no model yet ({@code s.snapshot() == null}, before the model
 * thread has built it); {@code s.time()} is 0 then.
 * {@link #dispose()} stops the model's thread and Java3D's. The grasp of the model (force
 * closure, ε, volume, hold), evaluated live off both threads: {@code runner().grasp().latest()}
 * ({@link LiveGrasp}); the friction cones: {@code view().setVisible(SceneView.Part.CONES, true)}.
 */
public class HandSimPanel extends JPanel {
    private static final long serialVersionUID = 1L;

    /** Milliseconds between view updates (~40 Hz). */
    public static final int TICK_MS = 25;

    /** Told about each newer state the view shows (event dispatch thread). */
    @FunctionalInterface
    public interface StepListener {
        void stepped(SimulationRunner.State state);
    }

    private final transient SceneView view;
    private final transient SimulationRunner runner = new SimulationRunner();
    private final Timer timer;
    private final List<StepListener> listeners = new CopyOnWriteArrayList<>();
    private final List<Runnable> tickHooks = new CopyOnWriteArrayList<>();
    private transient Scenario scenario;
    private transient Pose preview;
    private transient MeshSource.Model objectModel;
    private transient Path objectFile;
    private transient CompletableFuture<MeshSource.Model> objectLoad = CompletableFuture.completedFuture(null);
    private long shownPublication = -1;
    private transient BiConsumer<String, Boolean> messages = (m, error) -> {
        if (error) System.err.println("handsim: " + m);
    };
    private boolean disposed;

    /**
     * Reads the hand's meshes and builds a panel showing {@code scenario} at t = 0 (paused).
     * Call it from any thread but the event dispatch thread (the meshes are read here). On X11
     * it first initialises JOGL and replaces its fatal X I/O error handler
     * ({@link X11Exit#prepare()}).
     *
     * @throws IOException naming the file if a hand mesh cannot be read
     */
    public static HandSimPanel create(Scenario scenario) throws IOException, InterruptedException {
        X11Exit.prepare();   // before the first window: a lost X server must not abort the program
        MeshSource.Model[] hand = loadHand();
        try {
            return ScriptRunner.edt(() -> new HandSimPanel(scenario, hand));
        } catch (IOException | InterruptedException | RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * Reads the hand's meshes, {@code vrml/hand/palm.wrl} and {@code finger_link1..3.wrl}
     * (palm, links 1–3). Not on the event dispatch thread ({@link MeshSource}).
     */
    public static MeshSource.Model[] loadHand() throws IOException {
        MeshSource.Model[] m = new MeshSource.Model[4];
        m[0] = MeshSource.load(SceneMeshes.palmFile(), SceneMeshes.LINK_DIVISIONS);
        for (int j = 1; j <= 3; j++) m[j] = MeshSource.load(SceneMeshes.linkFile(j), SceneMeshes.LINK_DIVISIONS);
        return m;
    }

    /**
     * Builds the panel with hand meshes read beforehand ({@link #loadHand()}). Event dispatch thread.
     */
    public HandSimPanel(Scenario scenario, MeshSource.Model[] hand) {
        super(new BorderLayout());
        this.scenario = scenario;
        view = new SceneView(hand[0], new MeshSource.Model[] {hand[1], hand[2], hand[3]});
        view.lookAt(scenario.worldFromPalm());
        add(view.canvas(), BorderLayout.CENTER);
        view.canvas().setMinimumSize(new Dimension(100, 100));
        setMinimumSize(new Dimension(200, 200));
        setPreferredSize(new Dimension(640, 560));
        setName("simulator");
        timer = new Timer(TICK_MS, e -> tick());
        timer.setCoalesce(true);
        load(scenario);
        timer.start();
    }

    // ------------------------------------------------------------------ the API
    /** Builds a model for {@code s}, shows its t = 0 (paused) and makes it the working scenario. */
    public void load(Scenario s) {
        Scenario.ObjectPlacement before = scenario.object(), after = s.object();
        scenario = s;
        preview = null;
        view.setFriction(s.friction(), s.coneEdges());
        runner.load(s);
        if (after == null) {
            objectModel = null;
            objectFile = null;
            view.setObject(null, null, 1);
        } else if (objectModel == null || !after.file().equals(objectFile)) {
            objectLoad = loadObjectMesh(after.file(), after.divisions());
        } else if (before == null || !samePlacement(before, after)) {
            view.placeObject(after.worldFromObject(), after.meshScale());
        }
    }

    /** Plays from where the model is (drops a preview pose). */
    public void play() { preview = null; runner.play(); }

    /** Plays until the simulated time reaches {@code t} seconds (or the end), then pauses. */
    public void playUntil(double t) { preview = null; runner.playUntil(t); }

    public void pause() { runner.pause(); }

    /** One step of dt (pauses first). */
    public void step() { preview = null; runner.step(); }

    /** Back to t = 0 of the working scenario (paused). */
    public void reset() { preview = null; runner.reset(); }

    /** Speed: 1 = real time, 0 = as fast as possible. */
    public void setSpeed(double factor) { runner.setSpeed(factor); }

    /** The working scenario (what Play runs). */
    public Scenario scenario() { return scenario; }

    /** The newest published state of the model (never null). */
    public SimulationRunner.State state() { return runner.latest(); }

    public void addStepListener(StepListener l) { listeners.add(l); }

    public void removeStepListener(StepListener l) { listeners.remove(l); }

    /** The 3D view (camera, visibility of parts). */
    public SceneView view() { return view; }

    /** The model's thread (commands, trace rows, events, export). */
    public SimulationRunner runner() { return runner; }

    /** Stops the model's thread and Java3D's for this panel. */
    public void dispose() {
        if (disposed) return;
        disposed = true;
        timer.stop();
        runner.close();
        view.dispose();
    }

    // ------------------------------------------------------------------ for the window
    /** Where "loading ..." and load errors go (the window's status bar). */
    void setMessages(BiConsumer<String, Boolean> sink) { messages = sink; }

    /** Runs on every tick of the view update (the window's chart redraws). */
    void addTickHook(Runnable r) { tickHooks.add(r); }

    /** Shows a pose of the caller's own (paused) until the next play, step, reset or load. */
    void preview(Pose p) {
        runner.pause();
        preview = p;
        view.show(p);
    }

    boolean previewing() { return preview != null; }

    /** The publication of the state the view and the listeners were last given (-1: none yet). */
    long shownPublication() { return shownPublication; }

    /** Completes when the working scenario's object is in the view (at once if it already is). */
    public CompletableFuture<MeshSource.Model> objectReady() { return objectLoad; }

    /** The loaded object's mesh (file units), or null. */
    MeshSource.Model objectModel() { return objectModel; }

    private static boolean samePlacement(Scenario.ObjectPlacement a, Scenario.ObjectPlacement b) {
        return a.meshScale() == b.meshScale() && java.util.Arrays.equals(a.worldFromObject().toArray(), b.worldFromObject().toArray());
    }

    /**
     * Reads an object's mesh off the event dispatch thread and shows it at the working
     * scenario's placement when done. The future completes (on the EDT) after the view has it,
     * or exceptionally with the load error, which is also reported.
     */
    CompletableFuture<MeshSource.Model> loadObjectMesh(Path file, int divisions) {
        objectFile = file;
        messages.accept("loading " + file.getFileName() + " ...", false);
        CompletableFuture<MeshSource.Model> done = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                MeshSource.Model m = MeshSource.load(file, divisions);
                SwingUtilities.invokeLater(() -> {
                    if (!file.equals(objectFile)) { done.complete(m); return; }   // superseded
                    objectModel = m;
                    Scenario.ObjectPlacement p = scenario.object();
                    view.setObject(m, p != null ? p.worldFromObject() : RigidTransform.IDENTITY, p != null ? p.meshScale() : 1);
                    // a free object the model has moved already: where the model has it, not where it started
                    SimulationRunner.State now = runner.latest();
                    if (now.scenario() == scenario && now.snapshot() != null && now.snapshot().object() != null && preview == null) {
                        view.show(Pose.of(now.snapshot()));
                    }
                    messages.accept(file.getFileName() + ": " + m.mesh().triangleCount() + " triangles", false);
                    done.complete(m);
                });
            } catch (IOException | RuntimeException e) {
                SwingUtilities.invokeLater(() -> {
                    if (file.equals(objectFile)) objectFile = null;
                    messages.accept("cannot load " + file + ": " + e.getMessage(), true);
                    done.completeExceptionally(e);
                });
            }
        }, "handsim-mesh-loader");
        t.setDaemon(true);
        t.start();
        return done;
    }

    /**
     * One tick of the view: the newest state into the 3D view, then the listeners and hooks. An
     * exception from one of them is reported (the thread's uncaught-exception handler: the
     * window's error log) and the others still run: a coalescing {@code javax.swing.Timer}
     * whose action throws is never fired again, which would freeze the view for good.
     */
    void tick() {
        SimulationRunner.State s = runner.latest();
        if (s.publication() != shownPublication) {
            shownPublication = s.publication();
            if (s.snapshot() != null && preview == null && s.scenario() != null) view.show(Pose.of(s.snapshot()));
            for (StepListener l : listeners) {
                try {
                    l.stepped(s);
                } catch (RuntimeException e) {
                    report(e);
                }
            }
        }
        for (Runnable r : tickHooks) {
            try {
                r.run();
            } catch (RuntimeException e) {
                report(e);
            }
        }
    }

    private static void report(RuntimeException e) {
        Thread t = Thread.currentThread();
        t.getUncaughtExceptionHandler().uncaughtException(t, e);
    }
}
