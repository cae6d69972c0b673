package org.handsim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JSlider;
import javax.swing.SwingUtilities;
import javax.swing.text.JTextComponent;
import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Home;

/**
 * Runs a {@link Script} against a {@link HandSimWindow}, one action after the other, on the
 * calling thread (never the event dispatch thread): each action that touches Swing is done
 * on the EDT with {@code invokeAndWait}; waits ({@code play}, {@code import}) poll the
 * simulation's published state, so the window keeps updating meanwhile.
 *
 * <p>Screenshots are taken with {@link Robot#createScreenCapture} over the window's bounds:
 * the Java3D canvas is a heavyweight OpenGL surface that {@code paint} into an image would
 * leave blank, while the screen (Xvfb's framebuffer under a virtual display) holds what was
 * actually rendered. Before capturing, the view is updated, Java3D is asked for a new frame
 * and the runner waits until it was swapped.
 */
public final class ScriptRunner {
    /** How long {@code play} may take in wall time before the script fails. */
    static final long PLAY_TIMEOUT_MS = 20 * 60_000L;

    /** A failed action (exit code 1, or 4 for a simulation stopped by its guard). */
    public static final class ScriptFailure extends Exception {
        private static final long serialVersionUID = 1L;
        final int exitCode;

        ScriptFailure(String message, int exitCode) {
            super(org.handsim.text.SafeText.line(message));   // one line, no raw control bytes
            this.exitCode = exitCode;
        }

        public int exitCode() { return exitCode; }
    }

    private final HandSimWindow window;
    private final PrintWriter out;
    private final Path baseDir;

    /**
     * @param window  the window to drive
     * @param out     where {@code gui: } lines go
     * @param baseDir folder that relative file names are resolved against first (the script's)
     */
    public ScriptRunner(HandSimWindow window, PrintWriter out, Path baseDir) {
        this.window = window;
        this.out = out;
        this.baseDir = baseDir;
    }

    /**
     * Runs every action; throws on the first that fails — unless {@code expect-error TEXT} came
     * just before it and its message contains TEXT (then it says so and goes on; an action
     * expected to fail that succeeds fails the script).
     */
    public void run(Script script) throws ScriptFailure, InterruptedException {
        String expected = null;
        for (Script.Action a : script.actions()) {
            if (a.verb() == Script.Verb.EXPECT_ERROR) {
                expected = a.arg(0);
                continue;
            }
            String failure = null;
            int code = 1;
            try {
                perform(a);
            } catch (ScriptFailure f) {
                failure = f.getMessage();
                code = f.exitCode;
            } catch (InterruptedException e) {
                throw e;
            } catch (Exception e) {
                failure = message(e);
                // a message quoting what was typed is one line of bounded length, whatever was typed
                if (failure.length() > 2 * SHOWN_WHOLE) failure = failure.substring(0, SHOWN_WHOLE) + "..." + failure.substring(failure.length() - 100);
            }
            String where = script.source() + ":" + a.line() + ": " + shown(a.text()) + ": ";
            if (expected != null) {
                if (failure == null) throw new ScriptFailure(where + "expected an error containing '" + expected + "', but the action succeeded", 1);
                if (!failure.contains(expected)) throw new ScriptFailure(where + "expected an error containing '" + expected + "', got: " + failure, 1);
                say("expected error: " + failure);
                expected = null;
                continue;
            }
            if (failure != null) throw new ScriptFailure(where + failure, code);
        }
    }

    /** Script lines up to this long are shown whole in a failure's message; longer ones shortened. */
    static final int SHOWN_WHOLE = 500;

    /** A script line for a message: control characters escaped, shortened beyond {@link #SHOWN_WHOLE} characters. */
    static String shown(String line) {
        return line.length() <= SHOWN_WHOLE ? org.handsim.text.SafeText.escape(line) : org.handsim.text.SafeText.quote(line);
    }

    static String message(Throwable e) {
        Throwable c = e instanceof ExecutionException || e instanceof InvocationTargetException ? e.getCause() : e;
        return c.getMessage() != null ? c.getMessage() : c.toString();
    }

    private void perform(Script.Action a) throws Exception {
        switch (a.verb()) {
            case PRESS: edt(() -> { press(a.arg(0)); return null; }); break;
            case SET: edt(() -> { set(a.arg(0), a.arg(1)); return null; }); break;
            case IMPORT:
                importObject(resolve(a.arg(0)));
                break;
            case PLAY: play(a.arg(0)); break;
            case SPEED: {
                double f = a.arg(0).equals("max") ? 0 : Double.parseDouble(a.arg(0));
                edt(() -> { window.setSpeed(f); return null; });
                break;
            }
            case WAIT: {
                boolean held = window.runner().held();
                window.runner().hold(false);   // a playing model goes on meanwhile
                try {
                    Thread.sleep(Long.parseLong(a.arg(0)));
                } finally {
                    window.runner().hold(held);
                }
                break;
            }
            case SCREENSHOT: screenshot(resolveOut(a.arg(0))); break;
            case SHOW: {
                SceneView.Part p = SceneView.Part.valueOf(a.arg(0).toUpperCase(Locale.ROOT));
                boolean on = a.arg(1).equals("on");
                edt(() -> {
                    window.view().setVisible(p, on);
                    // the View menu's check box says what is shown
                    AbstractButton item = window.menuItems().get("view." + a.arg(0));
                    if (item != null) item.setSelected(on);
                    return null;
                });
                say("show " + a.arg(0) + " " + a.arg(1));
                break;
            }
            case ASSERT_STATE: {
                int k = Integer.parseInt(a.arg(0));
                window.runner().sync();
                SimulationRunner.State s = window.runner().latest();
                if (s.snapshot() == null) throw new ScriptFailure("no model", 1);
                ClutchState c = s.clutch(k);
                List<String> want = List.of(a.arg(1).split("\\|"));
                if (!want.contains(c.name())) throw new ScriptFailure("finger " + k + " is " + c + ", expected " + a.arg(1), 1);
                say(String.format(Locale.ROOT, "finger %d is %s at t = %.4f s (breakaway %s)", k, c, s.time(),
                    Double.isNaN(s.breakaway()[k - 1]) ? "none" : Widgets.fmt(s.breakaway()[k - 1], 4) + " s"));
                break;
            }
            case ASSERT_STATUS: {
                String st = edt(window::statusText);
                if (!st.contains(a.arg(0))) throw new ScriptFailure("the status bar says '" + st + "'", 1);
                say("status: " + st);
                break;
            }
            case LOG: log(a.arg(0)); break;
            case MEASURE_FPS: measureFps(Double.parseDouble(a.arg(0))); break;
            case OPEN: {
                Path f = resolve(a.arg(0));
                if (!edt(() -> window.openScenario(f))) throw new ScriptFailure(edt(window::statusText), 1);
                window.runner().sync();
                say("opened " + f);
                break;
            }
            case SAVE_SCENARIO: {
                Path f = resolveOut(a.arg(0));
                if (!edt(() -> window.saveScenario(f))) throw new ScriptFailure(edt(window::statusText), 1);
                say("saved scenario " + f);
                break;
            }
            case EXPORT_TRACES: {
                Path f = resolveOut(a.arg(0));
                window.runner().sync();
                int rows = edt(() -> window.exportTraces(f)).get(5, TimeUnit.MINUTES);
                say("exported " + rows + " trace rows to " + f);
                break;
            }
            case SAVE_CHARTS: {
                Path f = resolveOut(a.arg(0));
                edt(() -> { window.refreshNow(); return null; });
                edt(() -> window.saveCharts(f)).get(2, TimeUnit.MINUTES);
                say("saved charts " + f);
                break;
            }
            case MENU: {
                String name = a.arg(0);
                edt(() -> {
                    AbstractButton item = window.menuItems().get(name);
                    if (item == null) throw new ScriptFailure("no menu item '" + name + "' (menu items: " + String.join(", ", window.menuItems().keySet()) + ")", 1);
                    if (!item.isEnabled()) throw new ScriptFailure("the menu item '" + name + "' is disabled", 1);
                    item.doClick(0);
                    return null;
                });
                window.runner().sync();
                say("menu " + name);
                break;
            }
            case KEY: key(a.arg(0)); break;
            case RESIZE: {
                int w = Integer.parseInt(a.arg(0)), h = Integer.parseInt(a.arg(1));
                edt(() -> {
                    window.frame().setSize(w, h);
                    window.frame().validate();
                    return null;
                });
                Thread.sleep(300);
                edt(() -> { window.frame().validate(); window.refreshNow(); return null; });
                window.charts().awaitDrawn();
                java.awt.Dimension d = edt(() -> window.frame().getSize());
                say("window " + d.width + "x" + d.height);
                break;
            }
            case CAMERA: {
                SceneView.Camera c = SceneView.Camera.of(a.arg(0));
                edt(() -> { window.camera(c); return null; });
                double[] eye = edt(() -> window.view().eyeWorld());
                say(String.format(Locale.ROOT, "camera %s: eye at (%.3f, %.3f, %.3f) m", c.id(), eye[0], eye[1], eye[2]));
                break;
            }
            case ASSERT_RUNSTATE: {
                window.runner().sync();
                edt(() -> { window.refreshNow(); return null; });
                String st = edt(window::runStateText);
                if (!st.contains(a.arg(0))) throw new ScriptFailure("the run state is '" + st + "', expected '" + a.arg(0) + "'", 1);
                say("run state: " + st);
                break;
            }
            case ASSERT_TIME: {
                window.runner().sync();
                SimulationRunner.State s = window.runner().latest();
                double want = Double.parseDouble(a.arg(0));
                double dt = s.scenario() != null ? s.scenario().dt() : 1e-3;
                if (!(Math.abs(s.time() - want) <= dt / 2)) throw new ScriptFailure("the model is at t = " + s.time() + " s, expected " + want, 1);
                say(String.format(Locale.ROOT, "time: t = %.4f s", s.time()));
                break;
            }
            case ASSERT_CONTACTS: {
                window.runner().sync();
                int want = Integer.parseInt(a.arg(0));
                int have = edt(this::contactsNow);
                if (have != want) throw new ScriptFailure("the hand has " + have + " contacts, expected " + want, 1);
                say("contacts: " + have);
                break;
            }
            default:
                throw new AssertionError(a.verb());
        }
    }

    /** Imports an object as the Objects panel's file chooser does, and waits until it is in the view and the model. */
    public void importObject(Path f) throws Exception {
        Future<?> done = edt(() -> window.objectsPanel().importFile(f));
        done.get(5, TimeUnit.MINUTES);
        window.runner().sync();
        edt(() -> { window.refreshNow(); return null; });
        say("imported " + f);
    }

    /**
     * Renders continuously for {@code seconds} and prints {@code gui: fps F (view WxH, N triangles,
     * S s of continuous rendering)}.
     */
    public void measureFps(double seconds) throws Exception {
        double fps = window.view().measureFps(seconds);
        int[] info = edt(() -> new int[] {window.view().canvas().getWidth(), window.view().canvas().getHeight(), window.triangleCount()});
        say(String.format(Locale.ROOT, "fps %.1f (view %dx%d, %d triangles, %.1f s of continuous rendering)",
            fps, info[0], info[1], info[2], seconds));
    }

    /** Contacts shown now: the Kinematics preview's if one is shown, else the model's (EDT). */
    private int contactsNow() {
        if (window.simulator().previewing()) return window.kinematics().previewContacts();
        SimulationRunner.State s = window.runner().latest();
        int n = 0;
        if (s.snapshot() != null) for (org.handsim.model.Snapshot.FingerSnapshot f : s.snapshot().fingers()) n += f.contactCount();
        return n;
    }

    /**
     * The contacts of the state shown, one line each: {@code finger 3 at (x, y, z) m, pixel
     * (px, py)} — the pixel where the 3D view draws the point, in window coordinates (as the
     * screenshot's regions). EDT.
     */
    private List<String> contactLines() {
        List<String> out = new ArrayList<>();
        SimulationRunner.State s = window.runner().latest();
        if (s.snapshot() == null) return out;
        java.awt.Point at = SwingUtilities.convertPoint(window.view().canvas().getParent(), window.view().canvas().getLocation(), window.frame());
        for (int k = 1; k <= 3; k++) {
            org.handsim.model.Snapshot.FingerSnapshot f = s.snapshot().fingers()[k - 1];
            double[] p = f.contactPoints();
            for (int i = 0; i < f.contactCount(); i++) {
                double[] w = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
                double[] px = window.view().pixelOf(w);
                out.add(String.format(Locale.ROOT, "finger %d at (%.5f, %.5f, %.5f) m, pixel (%.1f, %.1f)", k, w[0], w[1], w[2],
                    at.x + px[0], at.y + px[1]));
            }
        }
        return out;
    }

    /**
     * Types a shortcut key into the window: the frame is brought to the front and focused, the key
     * pressed and released with {@link Robot} (real input events, through the window's key
     * handling), and the script waits until the event queue has handled it.
     */
    private void key(String name) throws Exception {
        int code;
        switch (name) {
            case "SPACE": code = java.awt.event.KeyEvent.VK_SPACE; break;
            case "RIGHT": code = java.awt.event.KeyEvent.VK_RIGHT; break;
            default: code = java.awt.event.KeyEvent.getExtendedKeyCodeForChar(name.charAt(0));
        }
        edt(() -> {
            window.frame().toFront();
            window.frame().requestFocus();
            window.view().canvas().requestFocusInWindow();
            return null;
        });
        long until = System.currentTimeMillis() + 3000;
        while (!edt(() -> window.frame().isFocused()) && System.currentTimeMillis() < until) Thread.sleep(20);
        if (!edt(() -> window.frame().isFocused())) throw new ScriptFailure("the window did not get the keyboard focus", 1);
        Robot robot = new Robot();
        robot.keyPress(code);
        robot.keyRelease(code);
        robot.waitForIdle();
        edt(() -> null);
        window.runner().sync();
        say("key " + name);
    }

    private void say(String line) {
        out.println("gui: " + org.handsim.text.SafeText.line(line));
        out.flush();
    }

    private Path resolve(String name) {
        Path p = Path.of(name);
        if (p.isAbsolute()) return p;
        if (baseDir != null && Files.exists(baseDir.resolve(p))) return baseDir.resolve(p);
        if (Files.exists(p)) return p.toAbsolutePath();
        return Home.dir().resolve(p);
    }

    private Path resolveOut(String name) {
        Path p = Path.of(name);
        return p.isAbsolute() ? p : p.toAbsolutePath();
    }

    // ------------------------------------------------------------------ actions on the EDT
    private void press(String label) throws ScriptFailure {
        List<AbstractButton> all = new ArrayList<>();
        collect(window.frame().getRootPane(), AbstractButton.class, all);
        AbstractButton hidden = null;
        for (AbstractButton b : all) {
            boolean match = label.equalsIgnoreCase(b.getName()) || label.equalsIgnoreCase(b.getText())
                || label.equalsIgnoreCase("tool." + b.getText());
            if (!match) continue;
            if (b.isShowing() && b.isEnabled()) {
                int before = window.statusSerial();
                b.doClick(0);
                // as for 'set': a panel that refuses its fields' values says so in red, and the press failed
                if (window.statusSerial() != before && window.statusRefused()) {
                    throw new ScriptFailure("press " + label + ": the window refused it: " + window.statusText(), 1);
                }
                say("pressed " + label);
                return;
            }
            hidden = b;
        }
        throw new ScriptFailure(hidden != null ? "the button '" + label + "' is not on screen (open its panel first)"
            : "no button '" + label + "' (buttons on screen: " + String.join(", ", buttonNames(all)) + ")", 1);
    }

    /** The buttons on screen as {@code press} knows them: the label, and the name when it differs ("Solve (ik.solve)"). */
    private static List<String> buttonNames(List<AbstractButton> all) {
        List<String> names = new ArrayList<>();
        for (AbstractButton b : all) {
            if (!b.isShowing() || b instanceof javax.swing.JMenu) continue;
            String text = b.getText() == null ? "" : b.getText().trim(), name = b.getName();
            String shown = text.isEmpty() ? name : name == null || name.equalsIgnoreCase(text) || name.equalsIgnoreCase("tool." + text) ? text
                : text + " (" + name + ")";
            if (shown != null && !names.contains(shown)) names.add(shown);
        }
        return names;
    }

    private void set(String name, String value) throws ScriptFailure {
        List<Component> all = new ArrayList<>();
        collect(window.frame().getRootPane(), Component.class, all);
        Component found = null;
        for (Component c : all) {
            if (name.equals(c.getName())) {
                found = c;
                if (c.isShowing()) break;
            }
        }
        if (found == null) throw new ScriptFailure("no field '" + name + "' (fields on screen: " + String.join(", ", fieldNames(all)) + ")", 1);
        if (!found.isShowing()) throw new ScriptFailure("the field '" + name + "' is not on screen (open its panel first)", 1);
        if (found instanceof javax.swing.JTextField) {
            javax.swing.JTextField f = (javax.swing.JTextField) found;
            f.requestFocusInWindow();
            int before = window.statusSerial();
            f.setText(value);
            f.postActionEvent();
            // the panel refuses a value in the status bar (in red): the action failed then
            if (window.statusSerial() != before && window.statusRefused()) {
                throw new ScriptFailure("set " + name + " " + org.handsim.text.SafeText.quote(value) + ": the window refused it: " + window.statusText(), 1);
            }
        } else if (found instanceof JTextComponent) {
            ((JTextComponent) found).setText(value);
        } else if (found instanceof JComboBox) {
            JComboBox<?> box = (JComboBox<?>) found;
            int pick = -1;
            for (int i = 0; i < box.getItemCount() && pick < 0; i++) if (String.valueOf(box.getItemAt(i)).equalsIgnoreCase(value)) pick = i;
            for (int i = 0; i < box.getItemCount() && pick < 0; i++) {
                if (String.valueOf(box.getItemAt(i)).toLowerCase(Locale.ROOT).startsWith(value.toLowerCase(Locale.ROOT))) pick = i;
            }
            if (pick < 0) throw new ScriptFailure("the list '" + name + "' has no item '" + value + "'", 1);
            box.setSelectedIndex(pick);
        } else if (found instanceof JSlider) {
            try {
                ((JSlider) found).setValue((int) Math.round(org.handsim.text.Decimal.parse(value)));
            } catch (NumberFormatException e) {
                throw new ScriptFailure("the slider '" + name + "' needs a number, got '" + value + "'", 1);
            }
        } else {
            throw new ScriptFailure("'" + name + "' is a " + found.getClass().getSimpleName() + ", not a field", 1);
        }
        say("set " + name + " = " + value);
    }

    /** Names of the fields, lists and sliders on screen. */
    private static List<String> fieldNames(List<Component> all) {
        List<String> names = new ArrayList<>();
        for (Component c : all) {
            if (c.getName() != null && c.isShowing() && (c instanceof JTextComponent || c instanceof JComboBox || c instanceof JSlider)
                && !names.contains(c.getName())) {
                names.add(c.getName());
            }
        }
        return names;
    }

    private static <T> void collect(Container c, Class<T> type, List<T> out) {
        for (Component child : c.getComponents()) {
            if (type.isInstance(child)) out.add(type.cast(child));
            if (child instanceof Container) collect((Container) child, type, out);
        }
    }

    // ------------------------------------------------------------------ play, log, screenshot
    private void play(String arg) throws Exception {
        SimulationRunner r = window.runner();
        r.sync();
        double target = arg.equals("end") ? Double.POSITIVE_INFINITY : Double.parseDouble(arg);
        long frames0 = window.view().framesRendered(), wall0 = System.nanoTime();
        edt(() -> { window.playUntil(target); return null; });
        r.sync();
        boolean held = r.held();
        r.hold(false);
        try {
            playing(r, wall0, frames0);
        } finally {
            r.hold(held);
        }
    }

    /** Waits while the model plays, then says where it stopped. */
    private void playing(SimulationRunner r, long wall0, long frames0) throws Exception {
        r.sync();   // after hold(false)'s re-anchoring
        long deadline = System.currentTimeMillis() + PLAY_TIMEOUT_MS;
        SimulationRunner.State s = r.latest();
        // probe the event dispatch thread: how late does a posted event run while the model plays?
        java.util.concurrent.atomic.AtomicLong worstLatency = new java.util.concurrent.atomic.AtomicLong();
        int probes = 0;
        while (s.playing()) {
            if (System.currentTimeMillis() > deadline) throw new ScriptFailure("still playing after " + PLAY_TIMEOUT_MS / 1000 + " s", 1);
            long posted = System.nanoTime();
            SwingUtilities.invokeLater(() -> worstLatency.accumulateAndGet(System.nanoTime() - posted, Math::max));
            probes++;
            Thread.sleep(20);
            s = r.latest();
        }
        edt(() -> { window.refreshNow(); return null; });
        if (s.error() != null) throw new ScriptFailure(s.error(), 4);
        double wall = (System.nanoTime() - wall0) / 1e9;
        long frames = window.view().framesRendered() - frames0;
        say(String.format(Locale.ROOT, "played to t = %.4f s%s in %.2f s wall; the 3D view showed %d frames (%.1f per second); "
            + "event dispatch thread latency at most %.1f ms (%d probes)",
            s.time(), s.finished() ? " (end of the scenario)" : "", wall, frames, frames / wall, worstLatency.get() / 1e6, probes));
    }

    /** How long {@link #settle()} waits for the readouts before the action fails. */
    static final long SETTLE_TIMEOUT_MS = 60_000;

    /**
     * Waits until every live readout shows the model's newest state ({@link HandSimWindow#settled()}):
     * the model's queued commands done, every grasp offered evaluated ({@link LiveGrasp}, at
     * most 10 a second on its own thread), the view, panels, time label, Dynamics table and
     * Grasp box updated with them, the charts drawn. Screenshots and logs of one script then
     * show one state whatever the machine's speed.
     */
    void settle() throws Exception {
        SimulationRunner r = window.runner();
        long deadline = System.currentTimeMillis() + SETTLE_TIMEOUT_MS;
        while (true) {
            r.sync();
            r.grasp().awaitIdle();
            if (edt(() -> { window.refreshNow(); return window.settled(); })) break;
            if (System.currentTimeMillis() > deadline) {
                throw new ScriptFailure("the window's readouts did not catch up with the model within " + SETTLE_TIMEOUT_MS / 1000 + " s", 1);
            }
            Thread.sleep(10);
        }
        window.charts().awaitDrawn();
    }

    private void log(String what) throws Exception {
        settle();
        switch (what) {
            case "dynamics":
                for (String l : edt(() -> window.dynamics().tableLines())) say("dynamics: " + l);
                break;
            case "events":
                for (String l : edt(() -> window.dynamics().eventsText()).split("\\R")) if (!l.isBlank()) say("event: " + l);
                break;
            case "ik":
                for (String l : edt(() -> window.kinematics().ikText()).split("\n")) say("ik: " + l);
                break;
            case "grasp":
                say("grasp: " + edt(() -> window.dynamics().graspLine()));
                break;
            case "kinematics":
                for (String l : edt(() -> window.kinematics().lines())) say("kinematics: " + l);
                break;
            case "path":
                for (String l : edt(() -> window.pathPlanning().lines())) say("path: " + l);
                break;
            case "objects":
                for (String l : edt(() -> window.objectsPanel().lines())) say("objects: " + l);
                break;
            case "object":
                for (String l : edt(this::objectLines)) say("object: " + l);
                break;
            case "contacts": {
                List<String> lines = edt(this::contactLines);
                say("contacts: " + lines.size());
                for (String l : lines) say("contact: " + l);
                break;
            }
            case "charts": {
                double[] r = window.charts().timeRange();
                StringBuilder shown = new StringBuilder();
                for (int k = 1; k <= 3; k++) if (window.charts().fingerVisible(k)) shown.append(shown.length() == 0 ? "" : ",").append(k);
                say(String.format(Locale.ROOT, "charts: time axis %s..%s s, %d points, fingers shown %s", Widgets.fmt(r[0], 3),
                    Widgets.fmt(r[1], 3), window.charts().points(), shown.length() == 0 ? "none" : shown));
                break;
            }
            default: {
                SimulationRunner.State s = window.runner().latest();
                StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "state: t = %.4f s, %s", s.time(),
                    s.error() != null ? "stopped: " + s.error() : HandSimWindow.runState(s)));
                if (s.snapshot() != null) {
                    for (int k = 1; k <= 3; k++) sb.append(", finger ").append(k).append(' ').append(s.clutch(k));
                }
                say(sb.toString());
            }
        }
    }

    /**
     * The Free object box's lines, then the object's transform in the 3D view's scene graph and
     * the model's pose of it with the mesh's scale, and the palm's in both (each as 12 row-major
     * values, each number as Java writes a double: exactly); "fixed" when the state shown has no
     * free object.
     */
    private List<String> objectLines() {
        SimulationRunner.State s = window.runner().latest();
        if (s.snapshot() == null || s.snapshot().object() == null) return List.of("fixed");
        List<String> out = new ArrayList<>(window.dynamics().objectLines());
        double[] v = window.view().objectTransform();
        out.add("view_world_from_object=" + numbers(v, 12));
        double scale = s.scenario().object().meshScale();
        out.add("model_world_from_object=" + numbers(s.snapshot().object().worldFromMesh(), 12) + " scale=" + scale);
        out.add("view_world_from_palm=" + numbers(window.view().palmTransform(), 12));
        out.add("model_world_from_palm=" + numbers(s.snapshot().worldFromPalm(), 12));
        return out;
    }

    private static String numbers(double[] v, int n) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) sb.append(i > 0 ? "," : "").append(v[i]);
        return sb.toString();
    }

    /**
     * Saves the whole window as PNG (atomically), once every readout shows the model's state
     * ({@link #settle()}), and prints its size and the regions of the 3D view, the charts, the
     * status bar and the tool panel on the left in window coordinates: {@code gui: screenshot
     * FILE WxH view=x,y,w,h charts=x,y,w,h status=x,y,w,h panel=x,y,w,h}.
     */
    public void screenshot(Path file) throws Exception {
        settle();
        edt(() -> {
            window.frame().toFront();
            window.frame().getRootPane().paintImmediately(window.frame().getRootPane().getBounds());
            return null;
        });
        long f0 = window.view().framesRendered();
        window.view().canvas().getView().repaint();
        long until = System.currentTimeMillis() + 3000;
        while (window.view().framesRendered() < f0 + 2 && System.currentTimeMillis() < until) {
            window.view().canvas().getView().repaint();
            Thread.sleep(20);
        }
        Thread.sleep(150);
        List<Rectangle> regions = edt(window::regions);
        BufferedImage img = window.capture();
        HandSimWindow.writePng(img, file);
        say(String.format(Locale.ROOT, "screenshot %s %dx%d view=%s charts=%s status=%s panel=%s", file, img.getWidth(), img.getHeight(),
            rect(regions.get(0)), rect(regions.get(1)), rect(regions.get(2)), rect(regions.get(3))));
    }

    private static String rect(Rectangle r) {
        return r.x + "," + r.y + "," + r.width + "," + r.height;
    }

    /**
     * How long an action may wait for the event dispatch thread before the script fails: longer
     * than any action takes, so only a blocked thread reaches it (a Java3D thread that died leaves
     * the event dispatch thread waiting for it for ever in some of Java3D's calls).
     */
    static final long EDT_TIMEOUT_MS = 60_000;

    /** Runs {@code c} on the event dispatch thread and returns its value ({@link #EDT_TIMEOUT_MS} at most). */
    static <T> T edt(Callable<T> c) throws Exception {
        return edt(c, EDT_TIMEOUT_MS);
    }

    /**
     * Runs {@code c} on the event dispatch thread and returns its value, or fails the script when
     * the thread has not run it within {@code timeoutMs} ({@link GuiLauncher#onEdtWithin}: a
     * blocked event dispatch thread never holds the script, and with it the run, for ever).
     */
    static <T> T edt(Callable<T> c, long timeoutMs) throws Exception {
        if (SwingUtilities.isEventDispatchThread()) return c.call();
        AtomicReference<T> value = new AtomicReference<>();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        boolean ran = GuiLauncher.onEdtWithin(() -> {
            try {
                value.set(c.call());
            } catch (Throwable e) {
                failure.set(e);
            }
        }, timeoutMs);
        if (!ran) {
            throw new ScriptFailure("the event dispatch thread did not answer within " + GuiLauncher.seconds(timeoutMs)
                + " s (Java3D's threads no longer answer?)", 1);
        }
        Throwable f = failure.get();
        if (f instanceof Exception e) throw e;
        if (f instanceof Error e) throw e;
        return value.get();
    }
}
