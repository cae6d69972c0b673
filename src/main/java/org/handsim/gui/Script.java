package org.handsim.gui;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.handsim.clutch.ClutchState;
import org.handsim.text.SafeText;

/**
 * The action language of {@code handsim gui --script FILE}: one action per line, run in
 * order against the window as a user would (pressing its buttons, typing into its fields),
 * for tests, documentation screenshots and measurements. Parsing is pure (no window), so a
 * bad script fails before anything opens.
 *
 * <h2>Syntax</h2>
 * Blank lines and lines starting with {@code #} are ignored; otherwise a line is
 * {@code VERB ARGUMENTS}, words separated by spaces. File names are relative to the script
 * file's folder, then to the HandSim home folder.
 * <pre>
 * press LABEL               click the button whose label or name is LABEL (case-insensitive),
 *                           e.g. press Kinematics, press Path Planning, press Run with dynamics,
 *                           press ik.solve; only buttons on screen count (open the panel first);
 *                           fails when the panel refuses its fields' values (the status bar in red)
 * set NAME VALUE            type VALUE into the field NAME and press Enter (fk3.counts, ik.x,
 *                           path.M3.1.to, obj.z, dyn.gx, ...); a list: the item with that text,
 *                           or starting with it; a slider: the number
 * import FILE               import an object, VRML97, OBJ or STL (what the Objects panel's file
 *                           chooser does: placed clear of the hand, camera framed) and wait
 *                           until it is in the view and the model
 * open FILE                 open a scenario file (File ▸ Open scenario)
 * save-scenario FILE        save the window's state as a scenario (File ▸ Save scenario)
 * export-traces FILE        write the run's trace so far as trace.csv (File ▸ Export traces)
 * save-charts FILE          save the charts, .png or .svg (File ▸ Save charts)
 * menu NAME                 click a menu item by name (file.save, view.camera.fit,
 *                           view.series.finger1, run.toggle, ...; see HandSimWindow)
 * key KEY                   type a key into the window as a user would: SPACE, RIGHT, R, H, F,
 *                           1, 2, 3 (the window's shortcuts)
 * camera home|fit|front|top|side       move the camera
 * resize WIDTH HEIGHT       make the window that size (pixels; at least 1024 × 700)
 * expect-error TEXT         the next action must fail with TEXT in its message; the script
 *                           goes on (to screenshot error states)
 * play SECONDS | end        play until the simulated time reaches SECONDS (or the scenario's
 *                           end) and wait; if it is there already, pause there
 * speed FACTOR | max        simulation speed: 1 = real time, max = as fast as possible
 * wait MS                   wait MS milliseconds of wall time
 * screenshot FILE           save the whole window as PNG, after waiting until every live readout
 *                           shows the model's state (the Grasp box evaluated at the time shown)
 * show hand|object|contacts|normals|cones on|off   show or hide a part of the 3D scene (cones:
 *                           the friction cones at the contacts, as View ▸ Friction cones)
 * assert-state FINGER S1[|S2...]       fail unless finger 1..3's clutch is in one of the
 *                                      states (FREE, BLOCKED, BROKEN, STALLED)
 * assert-status TEXT        fail unless the status bar contains TEXT
 * assert-runstate TEXT      fail unless the status bar's run state (running, paused,
 *                           finished, reset, ready) contains TEXT
 * assert-time SECONDS       fail unless the model is at that simulated time (within dt/2)
 * assert-contacts N         fail unless the hand has N contacts now (the preview's, if one is shown)
 * log dynamics|state|events|ik|charts|grasp   print the Dynamics table, the time and clutch
 *                                      states, the Dynamics events, the Kinematics answer, the
 *                                      charts' time axis, points and series shown, or the
 *                                      Dynamics panel's Grasp box (after waiting for the
 *                                      evaluation of the state shown)
 * log contacts              print each contact of the state shown: finger, point (world, m)
 *                           and where the 3D view draws it (pixels in the window)
 * log kinematics            print what the Kinematics panel shows, one line per finger:
 *                           {@code kinematics: finger 3: M3 9479 counts, θ31 0.00°, θ32 47.72°, θ33 30.06°}
 *                           (the model's state at the time shown; every log first waits, as a
 *                           screenshot does, until the readouts show the model's state)
 * log path                  print what the Path Planning panel shows, one line per motor, then
 *                           the duration: {@code path: M3: start 0; trapezoid to=17500
 *                           v_max=4244.294 a_max=21221.471; hold duration_s=0.3; ...}
 * log objects               print what the Objects panel shows: the file, the units used
 *                           ({@code objects: units used: mm (judged by the file's size)}) and
 *                           the placement's note
 * log object                print the Dynamics panel's Free object box, one KEY=VALUE per line
 *                           (trace.csv's and summary.json's names: {@code object: obj_disp_m=0.0000006734}),
 *                           then where the 3D view draws the object and where the model has it
 *                           ({@code object: view_world_from_object=...}, {@code object: model_world_from_object=...
 *                           scale=...}: 12 row-major values each, the view's with the mesh's scale in its rotation),
 *                           and the palm's alike ({@code view_world_from_palm}, {@code model_world_from_palm});
 *                           {@code object: fixed} when the object is not free
 * measure-fps SECONDS       render continuously (the scene turning) and print frames/second
 * </pre>
 * While a script runs, the model moves only during {@code play} and {@code wait}: a button that
 * starts a run (Path Planning's Run, Run with dynamics, the Space key) leaves it where it is
 * until then ({@link SimulationRunner#hold}), so that a script gives one state on any machine.
 * Output lines start with {@code gui: }. An unknown verb or a bad argument is an error naming
 * the file and line ({@link ScriptException}; the command exits with code 2); a failing
 * {@code assert-*} or an action that cannot be done exits with code 1.
 *
 * <p><b>Limits.</b> A script file is UTF-8 (a leading byte-order mark is dropped) of at most
 * {@link #MAX_BYTES} bytes. Numbers are decimals ({@code text.Decimal.parse}: {@code 0d},
 * {@code NaN}, {@code 1e400} are refused): {@code wait} takes whole milliseconds up to
 * {@link #MAX_WAIT_MS} (one hour), {@code measure-fps} seconds in (0, {@link #MAX_FPS_SECONDS}]
 * as {@code --measure-fps} does, {@code assert-contacts} a count up to {@link #MAX_CONTACTS}.
 * Text quoted from the script in a message has its control characters escaped and is shortened
 * ({@code text.SafeText.quote}), so a message is one short line whatever the script holds.
 *
 * <h2>Example</h2>
 * <pre>
 * press Objects
 * import vrml/objects/cube.wrl
 * press Dynamics
 * speed max
 * play 2.5
 * assert-state 3 BROKEN|STALLED
 * screenshot out/gui.png
 * play end
 * log dynamics
 * </pre>
 */
public final class Script {
    /**
     * The language in brief, for {@code handsim gui --help} (a compile-time constant for
     * picocli's annotations; {@code %n} is a line break there).
     */
    public static final String HELP = "Script actions (one per line, '#' starts a comment; output: 'gui: ' lines):%n"
        + "  press LABEL          click a button by label or name (press Kinematics)%n"
        + "  set NAME VALUE       type into a field, then Enter (fk3.counts, ik.x, obj.z)%n"
        + "  import FILE          import an object (.wrl .obj .stl) as the chooser does%n"
        + "  open FILE            open a scenario;  save-scenario FILE%n"
        + "  export-traces FILE   trace.csv so far; save-charts FILE (.png or .svg)%n"
        + "  menu NAME            click a menu item (file.save, view.camera.fit)%n"
        + "  key KEY              a shortcut key: SPACE, RIGHT, R, H, F, 1, 2, 3%n"
        + "  camera home|fit|front|top|side   resize WIDTH HEIGHT%n"
        + "  expect-error TEXT    the next action must fail with TEXT in its message%n"
        + "  play T|end           play until simulated time T s (or the end), and wait%n"
        + "  speed FACTOR|max     1 = real time, max = as fast as possible%n"
        + "  wait MS              wait MS milliseconds%n"
        + "  screenshot FILE      save the whole window as PNG, once every readout shows%n"
        + "                       the model's state (the Grasp box evaluated at its time)%n"
        + "  show hand|object|contacts|normals|cones on|off%n"
        + "  assert-state FINGER STATE[|STATE]   e.g. assert-state 3 BROKEN|STALLED%n"
        + "  assert-status TEXT   fail unless the status bar contains TEXT%n"
        + "  assert-runstate TEXT | assert-time SECONDS | assert-contacts N%n"
        + "  log dynamics|state|events|ik|charts|grasp|contacts|kinematics|path|objects|object%n"
        + "                       print what a panel shows, once it shows the model's%n"
        + "                       state (kinematics, per finger: 'M3 9479 counts,%n"
        + "                       θ31 0.00°, θ32 47.72°, θ33 30.06°'; path: per motor%n"
        + "                       its start and segments, as the scenario file writes them;%n"
        + "                       objects: the file, the units used, the placement;%n"
        + "                       object: a free object's state, trace.csv's names)%n"
        + "  measure-fps SECONDS  render continuously and print frames per second%n"
        + "The model moves only while play or wait runs (a button that starts a run, e.g.%n"
        + "press path.run, leaves it at t = 0 until then): one script, one state.%n"
        + "Exit codes: 0 done; 2 bad script (FILE:LINE named); 1 an action failed or an%n"
        + "exception reached the event dispatch thread; 4 the simulation stopped on its%n"
        + "numerical guard. Field and button names: the Javadoc of each panel class.";

    /** Largest script file, bytes (a script is a few hundred lines of short actions). */
    public static final long MAX_BYTES = 1 << 24;
    /** Longest {@code wait}, milliseconds: an hour. */
    public static final long MAX_WAIT_MS = 3_600_000;
    /** Longest {@code measure-fps}, seconds (as {@code handsim gui --measure-fps}). */
    public static final double MAX_FPS_SECONDS = 3600;
    /** Largest {@code assert-contacts} count. */
    public static final int MAX_CONTACTS = 1_000_000;

    /** The keys {@code key} can type (the window's shortcuts without a modifier). */
    public static final List<String> KEYS = List.of("SPACE", "RIGHT", "R", "H", "F", "1", "2", "3");

    /** The verbs. */
    public enum Verb {
        PRESS("press"), SET("set"), IMPORT("import"), PLAY("play"), SPEED("speed"), WAIT("wait"),
        SCREENSHOT("screenshot"), SHOW("show"), ASSERT_STATE("assert-state"), ASSERT_STATUS("assert-status"),
        LOG("log"), MEASURE_FPS("measure-fps"), OPEN("open"), SAVE_SCENARIO("save-scenario"), EXPORT_TRACES("export-traces"),
        SAVE_CHARTS("save-charts"), MENU("menu"), KEY("key"), CAMERA("camera"), EXPECT_ERROR("expect-error"),
        ASSERT_RUNSTATE("assert-runstate"), ASSERT_TIME("assert-time"), ASSERT_CONTACTS("assert-contacts"), RESIZE("resize");

        final String word;

        Verb(String word) { this.word = word; }

        static Verb of(String w) {
            for (Verb v : values()) if (v.word.equals(w)) return v;
            return null;
        }
    }

    /**
     * One action.
     *
     * @param line 1-based line number in the file
     * @param text the line as written (trimmed)
     * @param verb what to do
     * @param args the arguments (the last one may contain spaces: labels, values, file names)
     */
    public record Action(int line, String text, Verb verb, List<String> args) {
        public String arg(int i) { return args.get(i); }
    }

    /** A script that cannot be run as written. */
    public static final class ScriptException extends Exception {
        private static final long serialVersionUID = 1L;

        ScriptException(String message) { super(message); }
    }

    private final String source;
    private final List<Action> actions;

    private Script(String source, List<Action> actions) {
        this.source = source;
        this.actions = List.copyOf(actions);
    }

    /** The file name the script came from (for messages). */
    public String source() { return source; }

    public List<Action> actions() { return actions; }

    /** All verbs, for messages and help. */
    public static String verbs() {
        StringBuilder sb = new StringBuilder();
        for (Verb v : Verb.values()) sb.append(sb.length() == 0 ? "" : ", ").append(v.word);
        return sb.toString();
    }

    /**
     * Parses a script.
     *
     * @param source a name for messages (the file name)
     * @throws ScriptException "{@code SOURCE:LINE: message}" for the first bad line
     */
    public static Script parse(String source, String text) throws ScriptException {
        List<Action> out = new ArrayList<>();
        if (text.startsWith("\uFEFF")) text = text.substring(1);   // a byte-order mark, as CSV inputs allow
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].trim();
            if (line.isEmpty() || line.startsWith("#")) continue;
            int n = i + 1;
            String[] head = line.split("\\s+", 2);
            Verb v = Verb.of(head[0].toLowerCase(Locale.ROOT));
            String rest = head.length > 1 ? head[1].trim() : "";
            if (v == null) throw error(source, n, "unknown action '" + q(head[0]) + "' (known: " + verbs() + ")");
            out.add(new Action(n, line, v, arguments(source, n, v, rest)));
        }
        for (int i = 0; i < out.size(); i++) {
            Action a = out.get(i);
            if (a.verb() == Verb.EXPECT_ERROR && (i + 1 == out.size() || out.get(i + 1).verb() == Verb.EXPECT_ERROR)) {
                throw error(source, a.line(), "expect-error needs an action after it (the one expected to fail)");
            }
        }
        return new Script(source, out);
    }

    private static List<String> arguments(String src, int n, Verb v, String rest) throws ScriptException {
        switch (v) {
            case PRESS:
            case IMPORT:
            case SCREENSHOT:
            case ASSERT_STATUS:
            case OPEN:
            case SAVE_SCENARIO:
            case EXPORT_TRACES:
            case MENU:
            case EXPECT_ERROR:
            case ASSERT_RUNSTATE:
                if (rest.isEmpty()) throw error(src, n, v.word + " needs an argument");
                return List.of(rest);
            case SET: {
                String[] p = rest.split("\\s+", 2);
                if (p.length < 2 || p[1].isEmpty()) throw error(src, n, "set needs a field name and a value, e.g. 'set fk3.counts 5000'");
                return List.of(p[0], p[1].trim());
            }
            case PLAY:
                if (!rest.equalsIgnoreCase("end")) positive(src, n, v, rest);
                return List.of(rest.toLowerCase(Locale.ROOT));
            case SPEED:
                if (!rest.equalsIgnoreCase("max")) {
                    double f = number(src, n, v, rest);
                    if (!(f > 0)) throw error(src, n, "speed must be > 0 or 'max', got '" + q(rest) + "'");
                }
                return List.of(rest.toLowerCase(Locale.ROOT));
            case WAIT: {
                double ms = number(src, n, v, rest);
                if (ms < 0 || ms != Math.rint(ms) || ms > MAX_WAIT_MS) {
                    throw error(src, n, "wait needs whole milliseconds in [0, " + MAX_WAIT_MS + "] (an hour), got '" + q(rest) + "'");
                }
                return List.of(Long.toString((long) ms));
            }
            case MEASURE_FPS: {
                double s = positive(src, n, v, rest);
                if (s > MAX_FPS_SECONDS) throw error(src, n, "measure-fps needs seconds in (0, " + (int) MAX_FPS_SECONDS + "], got '" + q(rest) + "'");
                return List.of(rest);
            }
            case ASSERT_TIME:
                if (number(src, n, v, rest) < 0) throw error(src, n, "assert-time needs a time >= 0, got '" + q(rest) + "'");
                return List.of(rest);
            case ASSERT_CONTACTS: {
                double c = number(src, n, v, rest);
                if (c < 0 || c != Math.rint(c) || c > MAX_CONTACTS) {
                    throw error(src, n, "assert-contacts needs a whole number in [0, " + MAX_CONTACTS + "], got '" + q(rest) + "'");
                }
                return List.of(Integer.toString((int) c));
            }
            case SAVE_CHARTS: {
                String low = rest.toLowerCase(Locale.ROOT);
                if (!low.endsWith(".png") && !low.endsWith(".svg")) throw error(src, n, "save-charts needs a .png or .svg file, got '" + q(rest) + "'");
                return List.of(rest);
            }
            case KEY: {
                String k = rest.toUpperCase(Locale.ROOT);
                if (!KEYS.contains(k)) throw error(src, n, "key needs one of " + String.join(", ", KEYS) + ", got '" + q(rest) + "'");
                return List.of(k);
            }
            case CAMERA:
                if (SceneView.Camera.of(rest) == null) throw error(src, n, "camera needs home, fit, front, top or side, got '" + q(rest) + "'");
                return List.of(rest.toLowerCase(Locale.ROOT));
            case SHOW: {
                String[] p = rest.toLowerCase(Locale.ROOT).split("\\s+");
                List<String> parts = new java.util.ArrayList<>();
                for (SceneView.Part part : SceneView.Part.values()) parts.add(part.name().toLowerCase(Locale.ROOT));
                if (p.length != 2 || !parts.contains(p[0]) || !Arrays.asList("on", "off").contains(p[1])) {
                    throw error(src, n, "show needs " + String.join("|", parts) + " and on|off, got '" + q(rest) + "'");
                }
                return List.of(p[0], p[1]);
            }
            case ASSERT_STATE: {
                String[] p = rest.split("\\s+");
                if (p.length != 2 || !p[0].matches("[123]")) throw error(src, n, "assert-state needs a finger 1..3 and states, e.g. 'assert-state 3 BROKEN|STALLED'");
                for (String s : p[1].split("\\|")) {
                    try {
                        ClutchState.valueOf(s.toUpperCase(Locale.ROOT));
                    } catch (IllegalArgumentException e) {
                        throw error(src, n, "unknown clutch state '" + q(s) + "' (FREE, BLOCKED, BROKEN, STALLED)");
                    }
                }
                return List.of(p[0], p[1].toUpperCase(Locale.ROOT));
            }
            case RESIZE: {
                String[] p = rest.split("\\s+");
                if (p.length != 2 || !p[0].matches("\\d{3,5}") || !p[1].matches("\\d{3,5}")
                    || Integer.parseInt(p[0]) < HandSimWindow.MINIMUM.width || Integer.parseInt(p[1]) < HandSimWindow.MINIMUM.height) {
                    throw error(src, n, "resize needs WIDTH HEIGHT in pixels, at least " + HandSimWindow.MINIMUM.width + " " + HandSimWindow.MINIMUM.height
                        + ", got '" + q(rest) + "'");
                }
                return List.of(p[0], p[1]);
            }
            case LOG:
                if (!Arrays.asList("dynamics", "state", "events", "ik", "charts", "grasp", "contacts", "kinematics", "path", "objects", "object")
                    .contains(rest.toLowerCase(Locale.ROOT))) {
                    throw error(src, n, "log needs dynamics, state, events, ik, charts, grasp, contacts, kinematics, path, objects or object, got '" + q(rest) + "'");
                }
                return List.of(rest.toLowerCase(Locale.ROOT));
            default:
                throw new AssertionError(v);
        }
    }

    private static double number(String src, int n, Verb v, String text) throws ScriptException {
        try {
            double d = org.handsim.text.Decimal.parse(text);
            if (!Double.isFinite(d)) throw new NumberFormatException();
            return d;
        } catch (NumberFormatException e) {
            throw error(src, n, v.word + " needs a number, got '" + q(text) + "'");
        }
    }

    private static double positive(String src, int n, Verb v, String text) throws ScriptException {
        double d = number(src, n, v, text);
        if (!(d > 0)) throw error(src, n, v.word + " needs a number > 0, got '" + q(text) + "'");
        return d;
    }

    private static ScriptException error(String src, int line, String message) {
        return new ScriptException(SafeText.line(src + ":" + line + ": " + message));
    }

    /** Script text for a message: control characters escaped, shortened ({@link SafeText#quote}). */
    static String q(String text) {
        return SafeText.quote(text);
    }
}
