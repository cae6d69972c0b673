package org.handsim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridBagLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.table.AbstractTableModel;
import org.handsim.clutch.ClutchState;
import org.handsim.scenario.Scenario;
import org.handsim.model.Snapshot;

/**
 * The <b>Dynamics</b> panel: run the simulation with dynamics (Lagrange–Euler joint torques,
 * eq 8, plus the clutch's transmitted torque) and watch, live, per finger: the clutch state
 * (FREE / BLOCKED / BROKEN / STALLED, DESIGN.md decision 1), the joint torques τk1..τk3, the
 * number of contacts, the total contact force, and the breakaway time once τk2 passed
 * τ_break (eq 9). Below the table, the events of the run shown: one line per change of a
 * finger's clutch state, in time order, each with its time as {@code t = 1.8000 s} (the
 * breakaway at the time located inside its step, the others at the end of the step they were
 * seen in); a new run (loaded or reset) starts a new list.
 * Gravity is a world-frame vector (m/s²), chosen from a list of directions or typed in;
 * applying it rebuilds the model (the simulation restarts at t = 0).
 *
 * <h2>The grasp, live</h2>
 * The <b>Grasp</b> box shows the grasp of the state on screen as {@code handsim grasp} reports
 * it ({@link org.handsim.grasp.GraspAssessment}, DESIGN.md decisions 5 and 6): force
 * closure (yes / no), the Ferrari–Canny ε and the volume of the L1 grasp wrench space, and the
 * minimum hold over the six world directions ±x, ±y, ±z in newtons — with the friction μ and
 * cone edges m of the scenario (the Objects panel's friction field), the simulated time it was
 * evaluated at and the number of contacts. Numbers have four significant digits. It is
 * evaluated off the simulation and Swing threads when the contacts change, at most 10 times a
 * second ({@link LiveGrasp}), so during a run it may trail the view by up to ~0.1 s; paused or
 * finished, it is the grasp of the state shown.
 *
 * <h2>A free object</h2>
 * When the scenario's object is free (DESIGN.md decision 7) a <b>Free object</b> box under the
 * table shows its state as {@code handsim run} writes it ({@link ObjectReadout}): position,
 * orientation, displacement and rotation relative to the palm, speeds, contact points, largest
 * penetration, the largest displacement and rotation so far, and whether it is held in place,
 * free, slipped or dropped, with the times. With a fixed object the box is hidden.
 *
 * <p>Script names: button {@code dyn.run} ("Run with dynamics"), {@code dyn.gravity} (the
 * list), {@code dyn.gx}, {@code dyn.gy}, {@code dyn.gz}, button {@code dyn.applyGravity}
 * ("Apply gravity"); labels {@code dyn.grasp.closure}, {@code dyn.grasp.epsilon},
 * {@code dyn.grasp.volume}, {@code dyn.grasp.hold}, {@code dyn.grasp.at}; the script's
 * {@code log grasp} prints them ({@link #graspLine()}). Event dispatch thread only.
 */
public final class DynamicsPanel {
    private static final String[] GRAVITY = {"-z (palm up)", "-x (hand on its side)", "+z (palm down)", "-y", "+y", "+x", "none", "custom"};
    private static final double[][] GRAVITY_VECTORS = {{0, 0, -9.81}, {-9.81, 0, 0}, {0, 0, 9.81}, {0, -9.81, 0}, {0, 9.81, 0}, {9.81, 0, 0}, {0, 0, 0}};
    private static final String[] COLUMNS = {"k", "clutch", "τk1", "τk2", "τk3", "cont.", "force", "break"};
    /** The widest texts each column shows (space-separated), for its width. */
    private static final String[] WIDEST = {"3", "STALLED BLOCKED BROKEN", "-9.999", "-9.999", "-9.999", "99", "999.99", "10.0000"};
    /** Column names in {@link #tableLines()} (the script's log). */
    private static final String[] KEYS = {"finger", "clutch", "tau1_Nm", "tau2_Nm", "tau3_Nm", "contacts", "force_N", "breakaway_s"};
    /**
     * Where each column's value is in {@code handsim run}'s output, {@code %d} the finger: a
     * {@code trace.csv} column, or for the breakaway (a time, not a per-step value)
     * {@code summary.json}'s {@code fingers[k].breakaway_time_s}; null for the finger number.
     */
    static final String[] OUTPUT = {null, "state%d", "tau%d1_Nm", "tau%d2_Nm", "tau%d3_Nm", "contacts%d", "force%d_N",
        "summary.json fingers[%d].breakaway_time_s"};

    private final HandSimWindow window;
    private final JPanel panel = Widgets.column();
    private final Table table = new Table();
    private final ObjectReadout object = new ObjectReadout();
    private final JTextArea events = new JTextArea(8, 28);
    private final JComboBox<String> gravity = new JComboBox<>(GRAVITY);
    private final JTextField gx, gy, gz;
    private long lastGeneration = -1;
    private String header = "";
    private final List<SimulationRunner.Event> shown = new ArrayList<>();
    private final JLabel closure = graspLabel("dyn.grasp.closure"), epsilon = graspLabel("dyn.grasp.epsilon"),
        volume = graspLabel("dyn.grasp.volume"), hold = graspLabel("dyn.grasp.hold"), graspAt = new JLabel();
    private LiveGrasp.Result grasp;
    private String graspNote = "";

    DynamicsPanel(HandSimWindow window) {
        this.window = window;
        JPanel run = Widgets.titled(new JPanel(new GridBagLayout()), "Dynamics");
        run.add(Widgets.button("dyn.run", "Run with dynamics", this::runWithDynamics), Widgets.at(0, 0, 3));
        JLabel note = Widgets.note("Restarts the scenario with joint torques on and plays it.");
        run.add(note, Widgets.at(0, 1, 3));
        panel.add(run);

        JPanel g = Widgets.titled(new JPanel(new GridBagLayout()), "Gravity (world frame, m/s²)");
        gravity.setName("dyn.gravity");
        double[] now = window.scenario().gravity();
        gx = Widgets.field("dyn.gx", Widgets.fmt(now[0], 2), 5, null);
        gy = Widgets.field("dyn.gy", Widgets.fmt(now[1], 2), 5, null);
        gz = Widgets.field("dyn.gz", Widgets.fmt(now[2], 2), 5, null);
        gravity.setSelectedIndex(presetOf(now));
        gravity.addActionListener(e -> {
            int i = gravity.getSelectedIndex();
            if (i < GRAVITY_VECTORS.length) {
                gx.setText(Widgets.fmt(GRAVITY_VECTORS[i][0], 2));
                gy.setText(Widgets.fmt(GRAVITY_VECTORS[i][1], 2));
                gz.setText(Widgets.fmt(GRAVITY_VECTORS[i][2], 2));
            }
        });
        g.add(gravity, Widgets.at(0, 0, 3));
        g.add(gx, Widgets.at(0, 1));
        g.add(gy, Widgets.at(1, 1));
        g.add(gz, Widgets.at(2, 1));
        g.add(Widgets.button("dyn.applyGravity", "Apply gravity", this::applyGravity), Widgets.at(0, 2, 3));
        panel.add(g);

        JTable t = new JTable(table) {
            private static final long serialVersionUID = 1L;

            // fill the width when the columns fit, else keep their widths and scroll sideways
            @Override
            public boolean getScrollableTracksViewportWidth() {
                return getParent() == null || getPreferredSize().width <= getParent().getWidth();
            }
        };
        t.setName("dyn.table");
        t.setFont(Widgets.small());
        t.getTableHeader().setFont(Widgets.small());
        t.setRowHeight(18);
        sizeColumns(t);
        JScrollPane sp = new JScrollPane(t);
        sp.setPreferredSize(new Dimension(340, 80));
        JPanel tp = Widgets.titled(new JPanel(new BorderLayout()), "Per finger (live): τ N·m, force N, breakaway s");
        tp.add(sp, BorderLayout.CENTER);
        panel.add(tp);
        panel.add(object.component());

        JPanel gp = Widgets.titled(new JPanel(new GridBagLayout()), "Grasp (live): as handsim grasp reports it");
        String[] names = {"force closure", "ε (epsilon)", "volume", "min. hold"};
        JLabel[] values = {closure, epsilon, volume, hold};
        for (int r = 0; r < names.length; r++) {
            JLabel l = new JLabel(names[r]);
            l.setFont(Widgets.small());
            gp.add(l, Widgets.at(0, r));
            gp.add(values[r], Widgets.at(1, r));
        }
        graspAt.setName("dyn.grasp.at");
        gp.add(graspAt, Widgets.at(0, names.length, 2));
        showGrasp();
        panel.add(gp);

        events.setName("dyn.events");
        events.setEditable(false);
        events.setLineWrap(true);
        events.setWrapStyleWord(true);
        events.setFont(Widgets.small());
        JPanel ep = Widgets.titled(new JPanel(new BorderLayout()), "Events");
        ep.add(new JScrollPane(events), BorderLayout.CENTER);
        panel.add(ep);
    }

    /**
     * Sizes each column of the table for the widest text it shows — its header, or a sample of
     * its widest value ("BLOCKED", "-9.999" N·m, "999.99" N, "10.0000" s) as the table's own
     * renderers draw them — so that no value is cut to "-0.0…"; the eight columns need about
     * 320 px, which the panel has.
     */
    static void sizeColumns(JTable t) {
        for (int c = 0; c < COLUMNS.length; c++) {
            javax.swing.table.TableCellRenderer head = t.getTableHeader().getDefaultRenderer();
            int w = head.getTableCellRendererComponent(t, COLUMNS[c], false, false, -1, c).getPreferredSize().width;
            for (String sample : WIDEST[c].split(" ")) {
                w = Math.max(w, t.getDefaultRenderer(Object.class).getTableCellRendererComponent(t, sample, false, false, 0, c).getPreferredSize().width);
            }
            w += t.getIntercellSpacing().width + 1;   // the grid line, and a pixel of air
            javax.swing.table.TableColumn col = t.getColumnModel().getColumn(c);
            col.setMinWidth(w);
            col.setPreferredWidth(w);
        }
    }

    private static JLabel graspLabel(String name) {
        JLabel l = new JLabel("–");
        l.setName(name);
        l.setFont(l.getFont().deriveFont(java.awt.Font.BOLD));
        return l;
    }

    private static int presetOf(double[] g) {
        for (int i = 0; i < GRAVITY_VECTORS.length; i++) {
            if (java.util.Arrays.equals(g, GRAVITY_VECTORS[i])) return i;
        }
        return GRAVITY.length - 1;
    }

    JComponent component() {
        return Widgets.top(panel);
    }

    private void runWithDynamics() {
        Scenario s = window.scenario();
        if (!s.computeTorques()) {
            window.load(s.withTorques(true));
        } else {
            window.reset();
        }
        window.play();
        window.status("running with dynamics", false);
    }

    private void applyGravity() {
        try {
            double[] g = {Widgets.number(gx, "gravity x"), Widgets.number(gy, "gravity y"), Widgets.number(gz, "gravity z")};
            String range = org.handsim.hand.InputRanges.GRAVITY.problem("gravity", g);   // the range scenario files have
            if (range != null) throw new IllegalArgumentException(range);
            window.load(window.scenario().withGravity(g));
            window.status(String.format(Locale.ROOT, "gravity (%.2f, %.2f, %.2f) m/s² applied: the model restarts at t = 0", g[0], g[1], g[2]), false);
        } catch (IllegalArgumentException e) {
            window.refused(e.getMessage());
        }
    }

    /**
     * The Events box's first line: the run and its length as {@code handsim run} prints it, the
     * time of the last step ({@link org.handsim.model.HandModel#endTime}: 8.947 s for the paper's
     * scenario, whose trajectories end at 8.9464 s).
     */
    static String eventsHeader(SimulationRunner.State s) {
        Scenario sc = s.scenario();
        return String.format(Locale.ROOT, "%s %s%s, %s s:%n", s.origin() == SimulationRunner.Origin.RESET ? "Reset:" : "Run of",
            sc.name(), sc.object() != null ? " with " + sc.object().file().getFileName() : "",
            org.handsim.text.Decimal.format(org.handsim.model.HandModel.endTime(sc)));
    }

    /** Shows a published state (called by the window's view update). */
    void update(SimulationRunner.State s) {
        if (s.snapshot() == null) return;
        if (s.generation() != lastGeneration) {
            lastGeneration = s.generation();
            shown.clear();
            header = eventsHeader(s);
            for (String w : s.warnings()) header += "warning: " + w + System.lineSeparator();
            render();
            grasp = null;       // the new model's grasp comes from its first evaluation
            showGrasp();
        }
        table.set(s);
        object.show(s.snapshot().object());
    }

    /**
     * Shows a grasp evaluation (called by the window's timer with each new one). Returns false if
     * it belongs to a model generation the panel has not shown yet (the window offers it again);
     * one of an earlier generation is dropped.
     */
    boolean grasp(LiveGrasp.Result g) {
        if (g.generation() > lastGeneration) return false;
        if (g.generation() == lastGeneration) {
            grasp = g;
            showGrasp();
        }
        return true;
    }

    private void showGrasp() {
        LiveGrasp.Result g = grasp;
        if (g == null) {
            for (JLabel l : new JLabel[] {closure, epsilon, volume, hold}) {
                l.setText("–");
                l.setForeground(java.awt.Color.DARK_GRAY);
            }
            note("not evaluated yet");
            return;
        }
        if (g.assessment() == null) {
            for (JLabel l : new JLabel[] {closure, epsilon, volume, hold}) l.setText("–");
            note("cannot evaluate: " + g.error());
            return;
        }
        org.handsim.grasp.GraspAssessment a = g.assessment();
        boolean fc = a.quality().forceClosure();
        closure.setText(fc ? "yes" : "no");
        closure.setForeground(fc ? Widgets.OK : Widgets.ERROR);
        epsilon.setText(Widgets.significant(a.quality().epsilon(), 4));
        volume.setText(Widgets.significant(a.quality().volume(), 4));
        hold.setText(Widgets.significant(a.holdMinN(), 4) + " N");
        note(String.format(Locale.ROOT, "%d contact%s as at t = %.4f s (evaluated when they change), μ %s, %d cone edges",
            a.contacts().size(), a.contacts().size() == 1 ? "" : "s", a.timeS(), org.handsim.text.Decimal.format(g.mu()), g.edges()));
    }

    /**
     * The Grasp box as one line (the script's {@code log grasp}): {@code force_closure=yes
     * epsilon=0.2091  volume=0.08985  hold_min=58.84 N  6 contacts as at t = 4.7000 s (evaluated when they change),
     * μ 0.5, 8 cone edges}.
     */
    public String graspLine() {
        return "force_closure=" + closure.getText() + "  epsilon=" + epsilon.getText() + "  volume=" + volume.getText()
            + "  hold_min=" + hold.getText() + "  " + graspNote;
    }

    /** The line under the grasp figures (wrapped at the panel's width). */
    private void note(String text) {
        graspNote = text;
        graspAt.setText("<html><body style='width: 240px'><small>" + text.replace("&", "&amp;").replace("<", "&lt;") + "</small></body></html>");
    }

    /** Lists a clutch state change (called by the window's view update) in time order. */
    void event(SimulationRunner.Event e) {
        if (e.generation() != lastGeneration) return;   // from a model no longer shown
        int at = shown.size();
        while (at > 0 && shown.get(at - 1).time() > e.time()) at--;
        shown.add(at, e);
        render();
    }

    private void render() {
        StringBuilder sb = new StringBuilder(header);
        for (SimulationRunner.Event e : shown) sb.append(line(e)).append(System.lineSeparator());
        events.setText(sb.toString());
    }

    /** One event as listed: {@code t = 1.8000 s  finger 3: BLOCKED → BROKEN, breakaway (τ32 reached τ_break)}. */
    static String line(SimulationRunner.Event e) {
        String why = "";
        if (e.from() == ClutchState.FREE && e.to() == ClutchState.BLOCKED) why = ", the inner link touches the object";
        else if (e.from() == ClutchState.BLOCKED && e.to() == ClutchState.BROKEN) why = ", BREAKAWAY (τ" + e.finger() + "2 reached τ_break)";
        else if (e.to() == ClutchState.STALLED) why = ", the outer link is blocked";
        else if (e.to() == ClutchState.FREE) why = ", the clutch re-engaged";
        return String.format(Locale.ROOT, "t = %.4f s  finger %d: %s → %s%s", e.time(), e.finger(), e.from(), e.to(), why);
    }

    /** The table as text, one line per finger (the script's {@code log dynamics}). */
    public List<String> tableLines() {
        List<String> out = new ArrayList<>();
        for (int r = 0; r < 3; r++) {
            StringBuilder sb = new StringBuilder();
            for (int c = 0; c < COLUMNS.length; c++) {
                if (c > 0) sb.append("  ");
                sb.append(KEYS[c]).append('=').append(table.getValueAt(r, c));
            }
            out.add(sb.toString());
        }
        return out;
    }

    /** The Free object box as text, one {@code KEY=VALUE} per line (the script's {@code log object}); empty for a fixed object. */
    public List<String> objectLines() { return object.lines(); }

    /** The events list as shown. */
    public String eventsText() { return events.getText(); }

    /**
     * Finger k's row as the table shows it, into {@code row} (one cell per column): the
     * snapshot's values and the breakaway time (NaN: none yet).
     */
    static void row(int k, Snapshot.FingerSnapshot f, double breakaway, Object[] row) {
        row[0] = k;
        row[1] = f.state();
        double[] tau = f.torques();
        row[2] = Widgets.fmt(tau[0], 3);
        row[3] = Widgets.fmt(tau[1], 3);
        row[4] = Widgets.fmt(tau[2], 3);
        row[5] = f.contactCount();
        row[6] = Widgets.fmt(f.forceSum(), 2);
        row[7] = Double.isNaN(breakaway) ? "–" : Widgets.fmt(breakaway, 4);
    }

    private static final class Table extends AbstractTableModel {
        private static final long serialVersionUID = 1L;
        private final Object[][] cells = new Object[3][COLUMNS.length];

        Table() {
            for (int r = 0; r < 3; r++) {
                cells[r][0] = r + 1;
                for (int c = 1; c < COLUMNS.length; c++) cells[r][c] = "–";
            }
        }

        void set(SimulationRunner.State s) {
            for (int k = 0; k < 3; k++) row(k + 1, s.snapshot().fingers()[k], s.breakaway()[k], cells[k]);
            fireTableRowsUpdated(0, 2);
        }

        @Override public int getRowCount() { return 3; }
        @Override public int getColumnCount() { return COLUMNS.length; }
        @Override public String getColumnName(int c) { return COLUMNS[c]; }
        @Override public Object getValueAt(int r, int c) { return cells[r][c]; }
    }
}
