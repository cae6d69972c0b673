package org.handsim.gui;

import java.awt.GridBagLayout;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.text.Decimal;
import org.handsim.trajectory.Hold;
import org.handsim.trajectory.Sequence;
import org.handsim.trajectory.Trajectory;

/**
 * The <b>Path Planning</b> panel: every segment of every motor as the working scenario holds
 * it — the scenario file's {@code start_counts} and {@code motors} lists, with the same types
 * and fields and every number as the file writes it — and the run's duration; edited here,
 * <i>Run</i> or <i>Apply</i> puts them into the working scenario, which is what Play runs and
 * what Save scenario writes.
 *
 * <ul>
 *   <li><b>trapezoid</b> to a count with v max (counts/s) and a max (counts/s²): the paper's
 *       three-phase velocity profile ({@link org.handsim.trajectory.Trapezoid});</li>
 *   <li><b>quintic</b> to a count in T seconds: zero velocity and acceleration at both ends
 *       ({@link org.handsim.trajectory.Quintic});</li>
 *   <li><b>hold</b> where the previous segment ended, for T seconds;</li>
 *   <li><b>line</b> (M1–M3): the fingertip follows a straight line to a target {@code x,y,z}
 *       in the finger's base frame {k0}, metres, in T seconds
 *       ({@link org.handsim.trajectory.CartesianLine}).</li>
 * </ul>
 * Each segment starts where the one before it ends; a motor's first starts at its start count.
 * A segment shows only the fields its type uses. The duration left empty is the longest
 * motor's (as a scenario file without {@code duration_s}).
 *
 * <p>The fields become the working scenario the way a file does: the scenario's JSON with
 * these lists, read again ({@link Scenario#withJson}), so a value is checked with the range and
 * the words a file's would be (a refused one is reported in the status bar naming the motor,
 * the segment and the field, and nothing changes), and what runs is exactly what the panel
 * shows. The panel shows the working scenario again whenever its trajectories change (a
 * scenario opened, Use as start pose); a change of the object or gravity keeps edits not yet
 * applied.
 *
 * <p>Script names per motor m = 1..4 and segment i = 1, 2, ...: {@code path.M<m>.start},
 * {@code path.M<m>.<i>.type}, {@code path.M<m>.<i>.to}, {@code path.M<m>.<i>.target},
 * {@code path.M<m>.<i>.vmax}, {@code path.M<m>.<i>.amax}, {@code path.M<m>.<i>.duration};
 * buttons {@code path.M<m>.add} (a segment at the end), {@code path.M<m>.<i>.remove};
 * {@code path.duration}; buttons {@code path.run} ("Run": apply and play from t = 0),
 * {@code path.apply} ("Apply"), {@code path.here} ("Start here": the start counts become the
 * hand's counts now), {@code path.paper} ("Opened scenario": the trajectories of the scenario
 * the window opened); the script's {@code log path} prints {@link #lines()}. Event dispatch
 * thread only.
 */
public final class PathPlanningPanel {
    private static final String[] FINGER_TYPES = {"trapezoid", "quintic", "hold", "line"};
    private static final String[] SPREAD_TYPES = {"trapezoid", "quintic", "hold"};
    /** A new segment's speed and acceleration: fingers, then the spread (counts/s, counts/s²). */
    private static final double[][] NEW_LIMITS = {{5000, 25000}, {1000, 5000}};
    /** A new line's target in {k0}, metres: in front of the finger, within its reach. */
    private static final String NEW_TARGET = "0.12,0,0.08";

    private final HandSimWindow window;
    private final JPanel panel = Widgets.column();
    private final Motor[] motors = new Motor[4];
    private final JTextField duration = Widgets.field("path.duration", "", 8, null);
    private final JTextArea result = new JTextArea(4, 28);
    private Scenario shown;

    PathPlanningPanel(HandSimWindow window) {
        this.window = window;
        for (int m = 0; m < 4; m++) {
            motors[m] = new Motor(m);
            panel.add(motors[m].box);
        }
        JPanel run = Widgets.titled(new JPanel(new GridBagLayout()), "Run");
        run.add(small("duration s"), Widgets.at(0, 0));
        run.add(duration, Widgets.at(1, 0));
        run.add(small("(empty: the longest motor's)"), Widgets.at(2, 0));
        run.add(Widgets.button("path.run", "Run", this::run), Widgets.at(0, 1));
        run.add(Widgets.button("path.apply", "Apply", this::apply), Widgets.at(1, 1));
        run.add(Widgets.button("path.here", "Start here", this::startHere), Widgets.at(2, 1));
        run.add(Widgets.button("path.paper", "Opened scenario", this::paper), Widgets.at(0, 2, 3));
        panel.add(run);
        panel.add(Widgets.note("Each motor's segments in order, as the scenario file holds them; each starts where "
            + "the one before ends. Counts, counts/s, counts/s², seconds. Fingers: 0–17 500 counts (θk2 = q/125°); "
            + "spread: 0–3 150 counts. <i>line</i>: the fingertip's target in the finger's base frame {k0}, metres, "
            + "e.g. <tt>0.12,0,0.08</tt>. Run and Apply start the scenario at t = 0; Save scenario writes these segments."));
        result.setName("path.result");
        result.setEditable(false);
        result.setLineWrap(true);
        result.setWrapStyleWord(true);
        result.setOpaque(false);
        result.setFont(Widgets.small());
        panel.add(result);
        show(window.scenario());
    }

    private static JLabel small(String s) {
        JLabel l = new JLabel(s);
        l.setFont(Widgets.small());
        return l;
    }

    JComponent component() {
        return Widgets.top(panel);
    }

    /**
     * Shows the segments of {@code s} (called by the window with every scenario it loads); keeps
     * the fields as they are when its trajectories, start counts and duration are the ones shown.
     */
    void show(Scenario s) {
        if (shown != null && sameTrajectories(shown, s)) {
            shown = s;
            return;
        }
        shown = s;
        for (Motor m : motors) m.set(s);
        duration.setText(s.duration() == longest(s) ? "" : Decimal.format(s.duration()));
    }

    private static boolean sameTrajectories(Scenario a, Scenario b) {
        for (int m = 0; m < 4; m++) {
            if (a.motor(m) != b.motor(m) || a.startCounts(m) != b.startCounts(m)) return false;
        }
        return a.duration() == b.duration();
    }

    private static double longest(Scenario s) {
        double d = 0;
        for (int m = 0; m < 4; m++) d = Math.max(d, s.motor(m).duration());
        return d;
    }

    /** The segments of a trajectory as a scenario file lists them (none for the default hold at the start count). */
    static List<Map<String, Object>> segments(Trajectory t, double start) {
        List<Map<String, Object>> out = new ArrayList<>();
        if (t instanceof Hold && t.duration() == 0 && t.start() == start) return out;
        if (t instanceof Sequence) {
            for (Trajectory p : ((Sequence) t).segments()) out.addAll(segments(p, Double.NaN));
        } else {
            out.add(t.segment());
        }
        return out;
    }

    /** Puts the fields into the working scenario and plays it from t = 0. */
    void run() {
        if (apply()) {
            window.play();
            window.status("path planning: the segments run from t = 0", false);
        }
    }

    /** Puts the fields into the working scenario (at t = 0); false, with the reason in the status bar, if refused. */
    boolean apply() {
        Scenario s;
        try {
            Map<String, Object> start = new LinkedHashMap<>(), lists = new LinkedHashMap<>();
            for (Motor m : motors) {
                start.put(m.name, number(m.start, m.name + " start"));
                List<Object> segs = m.json();
                if (!segs.isEmpty()) lists.put(m.name, segs);
            }
            String d = duration.getText().trim();
            Double seconds = d.isEmpty() ? null : number(duration, "duration");
            s = window.scenario().withJson(j -> {
                j.put("start_counts", start);
                j.put("motors", lists);
                if (seconds == null) j.remove("duration_s");
                else j.put("duration_s", seconds);
            });
        } catch (IllegalArgumentException | ScenarioException e) {
            String why = e instanceof ScenarioException ? fieldWords(e.getMessage()) : e.getMessage();
            window.refused("path planning: " + why);
            result.setText("Not applied: " + why);
            return false;
        }
        shown = null;   // show what the scenario made of the fields: every number as it runs
        window.load(s);
        result.setText(String.format(Locale.ROOT, "%s s from t = 0, from M1..M4 = %s, %s, %s, %s counts. Save scenario writes these segments.",
            Decimal.format(s.duration()), Decimal.format(s.startCounts(0)), Decimal.format(s.startCounts(1)),
            Decimal.format(s.startCounts(2)), Decimal.format(s.startCounts(3))));
        window.status("path planning: the segments are the working scenario (t = 0)", false);
        return true;
    }

    private static final Pattern SEGMENT_FIELD = Pattern.compile("motors\\.M(\\d)\\[(\\d+)\\]\\.(\\w+)");

    /**
     * A scenario's error in the panel's words: the field {@code motors.M3[1].v_max} is "M3
     * segment 2 v_max", {@code start_counts.M3} "M3 start", {@code duration_s} "duration";
     * the file's name is left out (the panel has none).
     */
    static String fieldWords(String message) {
        int at = message.indexOf(": field ");
        String m = at < 0 ? message : message.substring(at + ": field ".length());
        Matcher seg = SEGMENT_FIELD.matcher(m);
        StringBuilder sb = new StringBuilder();
        while (seg.find()) {
            seg.appendReplacement(sb, "M" + seg.group(1) + " segment " + (Integer.parseInt(seg.group(2)) + 1) + " " + seg.group(3));
        }
        seg.appendTail(sb);
        return sb.toString().replaceAll("start_counts\\.M(\\d)", "M$1 start").replace("duration_s:", "duration:");
    }

    private static double number(JTextField f, String what) {
        return Widgets.number(f, what);
    }

    /** The start counts become the counts the hand is at now (the segments stay). */
    private void startHere() {
        double[] q = window.currentCounts();
        for (int m = 0; m < 4; m++) motors[m].start.setText(Decimal.format(q[m]));
        result.setText("Start counts set to the hand's counts now: Run or Apply to use them.");
    }

    /** Back to the trajectories of the scenario the window opened (the object stays as placed). */
    private void paper() {
        window.load(window.originalScenario().withObject(window.scenario().object()));
        result.setText("The opened scenario's trajectories restored (the object stays as placed).");
        window.status("scenario " + window.originalScenario().name() + " restored", false);
    }

    /**
     * What the panel shows, one line per motor and one for the duration (the script's
     * {@code log path}): {@code M3: start 0; trapezoid to=17500 v_max=4244.294
     * a_max=21221.471; hold duration_s=0.3; ...}, each field as its text and named as the
     * scenario file names it; {@code duration_s=} the field, or {@code longest} when empty.
     */
    public List<String> lines() {
        List<String> out = new ArrayList<>();
        for (Motor m : motors) out.add(m.line());
        String d = duration.getText().trim();
        out.add("duration_s=" + (d.isEmpty() ? "longest" : d));
        return out;
    }

    /**
     * The {@link #lines()} line of a motor with these segments (as {@link Trajectory#segment()}
     * gives them), its numbers as a scenario file writes them.
     */
    static String line(String motor, double start, List<Map<String, Object>> segments) {
        StringBuilder sb = new StringBuilder(motor).append(": start ").append(Decimal.format(start));
        for (Map<String, Object> seg : segments) {
            sb.append("; ").append(seg.get("type"));
            for (Map.Entry<String, Object> e : seg.entrySet()) {
                if (e.getKey().equals("type")) continue;
                sb.append(' ').append(e.getKey()).append('=').append(text(e.getValue()));
            }
        }
        return sb.toString();
    }

    private static String text(Object v) {
        if (v instanceof double[]) {
            StringBuilder sb = new StringBuilder();
            for (double d : (double[]) v) sb.append(sb.length() == 0 ? "" : ",").append(Decimal.format(d));
            return sb.toString();
        }
        return v instanceof Number ? Decimal.format(((Number) v).doubleValue()) : String.valueOf(v);
    }

    /** One motor's box: its start count and its segments. */
    private final class Motor {
        final int m;
        final String name;
        final JPanel box;
        final JTextField start;
        final JButton add;
        final List<Segment> rows = new ArrayList<>();

        Motor(int m) {
            this.m = m;
            this.name = "M" + (m + 1);
            box = Widgets.titled(new JPanel(new GridBagLayout()), m < 3 ? name + " (finger " + (m + 1) + ")" : name + " (spread)");
            start = Widgets.field("path." + name + ".start", "0", 8, null);
            add = Widgets.button("path." + name + ".add", "Add segment", this::add);
        }

        double max() {
            return m == 3 ? window.scenario().hand().spreadCountsMax() : window.scenario().hand().fingerCountsMax();
        }

        void set(Scenario s) {
            rows.clear();
            start.setText(Decimal.format(s.startCounts(m)));
            for (Map<String, Object> seg : segments(s.motor(m), s.startCounts(m))) rows.add(new Segment(this, seg));
            layout();
        }

        void layout() {
            box.removeAll();
            box.add(small("start counts"), Widgets.at(0, 0));
            box.add(start, Widgets.at(1, 0));
            box.add(add, Widgets.at(2, 0));
            for (int i = 0; i < rows.size(); i++) {
                rows.get(i).name(i + 1);
                box.add(rows.get(i).panel, Widgets.at(0, i + 1, 3));
            }
            box.revalidate();
            box.repaint();
        }

        /** A trapezoid at the end, towards the far end of the range from where the motor then is. */
        void add() {
            double at;
            try {
                at = rows.isEmpty() ? number(start, name + " start") : rows.get(rows.size() - 1).endCounts();
            } catch (IllegalArgumentException e) {
                at = 0;
            }
            Map<String, Object> seg = new LinkedHashMap<>();
            seg.put("type", "trapezoid");
            seg.put("to", at < max() / 2 ? max() : 0.0);
            seg.put("v_max", NEW_LIMITS[m == 3 ? 1 : 0][0]);
            seg.put("a_max", NEW_LIMITS[m == 3 ? 1 : 0][1]);
            rows.add(new Segment(this, seg));
            layout();
        }

        void remove(Segment s) {
            rows.remove(s);
            layout();
        }

        List<Object> json() {
            List<Object> out = new ArrayList<>();
            for (int i = 0; i < rows.size(); i++) out.add(rows.get(i).json(name + " segment " + (i + 1)));
            return out;
        }

        String line() {
            StringBuilder sb = new StringBuilder(name).append(": start ").append(start.getText().trim());
            for (Segment s : rows) sb.append("; ").append(s.line());
            return sb.toString();
        }
    }

    /** One segment: its type and the fields that type uses. */
    private final class Segment {
        final Motor owner;
        final JPanel panel = new JPanel(new GridBagLayout());
        final JLabel number = small("");
        final JComboBox<String> type;
        final JTextField to, target, vmax, amax, seconds;
        final JLabel toLabel = small("to"), targetLabel = small("target m"), vLabel = small("v max"), aLabel = small("a max"),
            tLabel = small("T s");
        final JButton remove;

        Segment(Motor owner, Map<String, Object> seg) {
            this.owner = owner;
            type = new JComboBox<>(owner.m < 3 ? FINGER_TYPES : SPREAD_TYPES);
            type.setSelectedItem(seg.get("type"));
            double[] limits = NEW_LIMITS[owner.m == 3 ? 1 : 0];
            to = Widgets.field(null, seg.containsKey("to") ? text(seg.get("to")) : text(owner.max()), 8, null);
            target = Widgets.field(null, seg.containsKey("target_m") ? text(seg.get("target_m")) : NEW_TARGET, 12, null);
            vmax = Widgets.field(null, seg.containsKey("v_max") ? text(seg.get("v_max")) : text(limits[0]), 7, null);
            amax = Widgets.field(null, seg.containsKey("a_max") ? text(seg.get("a_max")) : text(limits[1]), 7, null);
            seconds = Widgets.field(null, seg.containsKey("duration_s") ? text(seg.get("duration_s")) : "1", 5, null);
            remove = Widgets.button(null, "Remove", () -> owner.remove(this));
            panel.add(number, Widgets.at(0, 0));
            panel.add(type, Widgets.at(1, 0, 2));
            panel.add(remove, Widgets.at(3, 0));
            panel.add(toLabel, Widgets.at(0, 1));
            panel.add(to, Widgets.at(1, 1, 3));
            panel.add(targetLabel, Widgets.at(0, 2));
            panel.add(target, Widgets.at(1, 2, 3));
            panel.add(vLabel, Widgets.at(0, 3));
            panel.add(vmax, Widgets.at(1, 3));
            panel.add(aLabel, Widgets.at(2, 3));
            panel.add(amax, Widgets.at(3, 3));
            panel.add(tLabel, Widgets.at(0, 4));
            panel.add(seconds, Widgets.at(1, 4));
            type.addActionListener(e -> fields());
            fields();
        }

        /** Names the segment's fields and buttons for its place i (1, 2, ...) in its motor's list. */
        void name(int i) {
            String p = "path." + owner.name + "." + i + ".";
            number.setText("#" + i);
            type.setName(p + "type");
            to.setName(p + "to");
            target.setName(p + "target");
            vmax.setName(p + "vmax");
            amax.setName(p + "amax");
            seconds.setName(p + "duration");
            remove.setName(p + "remove");
        }

        String kind() { return (String) type.getSelectedItem(); }

        /** Shows the fields the type uses, only those. */
        private void fields() {
            String k = kind();
            boolean counts = k.equals("trapezoid") || k.equals("quintic");
            to.setVisible(counts);
            toLabel.setVisible(counts);
            target.setVisible(k.equals("line"));
            targetLabel.setVisible(k.equals("line"));
            vmax.setVisible(k.equals("trapezoid"));
            vLabel.setVisible(k.equals("trapezoid"));
            amax.setVisible(k.equals("trapezoid"));
            aLabel.setVisible(k.equals("trapezoid"));
            seconds.setVisible(!k.equals("trapezoid"));
            tLabel.setVisible(!k.equals("trapezoid"));
            panel.revalidate();
            panel.repaint();
        }

        /** Where the segment ends, counts, if its type says (a hold or line: where it starts, for a new segment's default). */
        double endCounts() {
            if (to.isVisible()) return number(to, "to");
            int i = owner.rows.indexOf(this);
            return i == 0 ? number(owner.start, "start") : owner.rows.get(i - 1).endCounts();
        }

        /** The segment as a scenario file's list entry, its numbers parsed from the fields. */
        Map<String, Object> json(String where) {
            Map<String, Object> m = new LinkedHashMap<>();
            String k = kind();
            m.put("type", k);
            switch (k) {
                case "trapezoid":
                    m.put("to", number(to, where + " to"));
                    m.put("v_max", number(vmax, where + " v max"));
                    m.put("a_max", number(amax, where + " a max"));
                    break;
                case "quintic":
                    m.put("to", number(to, where + " to"));
                    m.put("duration_s", number(seconds, where + " T"));
                    break;
                case "hold":
                    m.put("duration_s", number(seconds, where + " T"));
                    break;
                default: {
                    String[] parts = target.getText().trim().split("\\s*,\\s*");
                    if (parts.length != 3) {
                        throw new IllegalArgumentException(where + " target: a line needs x,y,z in metres, got '"
                            + org.handsim.text.SafeText.quote(target.getText()) + "'");
                    }
                    double[] p = new double[3];
                    for (int i = 0; i < 3; i++) {
                        try {
                            p[i] = Decimal.parse(parts[i]);
                            if (!Double.isFinite(p[i])) throw new NumberFormatException();
                        } catch (NumberFormatException e) {
                            throw new IllegalArgumentException(where + " target: '" + org.handsim.text.SafeText.quote(parts[i]) + "' is not a number");
                        }
                    }
                    m.put("target_m", p);
                    m.put("duration_s", number(seconds, where + " T"));
                }
            }
            return m;
        }

        /** The segment as {@link #lines()} shows it: its type and the texts of the fields it uses. */
        String line() {
            String k = kind();
            switch (k) {
                case "trapezoid":
                    return k + " to=" + to.getText().trim() + " v_max=" + vmax.getText().trim() + " a_max=" + amax.getText().trim();
                case "quintic":
                    return k + " to=" + to.getText().trim() + " duration_s=" + seconds.getText().trim();
                case "hold":
                    return k + " duration_s=" + seconds.getText().trim();
                default:
                    return k + " target_m=" + target.getText().trim().replaceAll("\\s*,\\s*", ",") + " duration_s=" + seconds.getText().trim();
            }
        }
    }
}
