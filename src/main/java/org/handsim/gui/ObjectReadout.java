package org.handsim.gui;

import java.awt.GridBagLayout;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.handsim.model.Snapshot;
import org.handsim.trace.Recorder;

/**
 * The Dynamics panel's <b>Free object</b> box: the state of a free object (DESIGN.md decision 7)
 * at the time shown, under the names {@code handsim run} writes it with — trace.csv's object
 * columns ({@link Recorder#OBJECT_COLUMNS}: the centre of mass in the world, the orientation, the
 * displacement and rotation relative to the palm since the start, the speeds, the contact points
 * and the largest penetration) and summary.json's object keys ({@code max_displacement_m},
 * {@code max_rotation_deg}, {@code released_at_s}, {@code slipped_at_s}, {@code dropped_at_s}) —
 * and a status in words: held in place (before {@code release_s}), free, slipped or dropped.
 * The values are the model's own ({@link Snapshot.ObjectSnapshot}), not computed again here.
 * Hidden while the object is fixed, so a fixed-object run looks as it always did.
 *
 * <p>Script: {@code log object} prints {@link #lines()}, one {@code KEY=VALUE} per line. Event
 * dispatch thread only.
 */
final class ObjectReadout {
    /**
     * The rows of the box under the status line: each a label and the keys of {@link #values} it
     * shows, side by side (narrow enough for the panel at the window's smallest size).
     */
    private static final String[][] ROWS = {
        {"obj_x/y/z_m", "obj_x_m", "obj_y_m", "obj_z_m"},
        {"obj_qw/qx", "obj_qw", "obj_qx"},
        {"obj_qy/qz", "obj_qy", "obj_qz"},
        {"obj_disp_m", "obj_disp_m"},
        {"obj_rot_deg", "obj_rot_deg"},
        {"obj_speed_m_s", "obj_speed_m_s"},
        {"obj_spin_rad_s", "obj_spin_rad_s"},
        {"obj_contacts", "obj_contacts"},
        {"obj_penetration_m", "obj_penetration_m"},
        {"max_displacement_m", "max_displacement_m"},
        {"max_rotation_deg", "max_rotation_deg"},
        {"released_at_s", "released_at_s"},
        {"slipped_at_s", "slipped_at_s"},
        {"dropped_at_s", "dropped_at_s"},
    };

    private final JPanel box = Widgets.titled(new JPanel(new GridBagLayout()), "Free object (live): trace.csv / summary.json");
    private final JLabel[] values = new JLabel[ROWS.length];
    private final JLabel status = new JLabel("–");
    private Map<String, String> shown = Map.of();

    ObjectReadout() {
        box.setName("dyn.object");
        status.setName("dyn.object.status");
        status.setFont(Widgets.small().deriveFont(java.awt.Font.BOLD));
        box.add(status, Widgets.at(0, 0, 2));
        for (int r = 0; r < ROWS.length; r++) {
            JLabel l = new JLabel(ROWS[r][0]);
            l.setFont(Widgets.small());
            java.awt.GridBagConstraints at = Widgets.at(0, r + 1);
            at.weightx = 0;   // the labels as wide as the widest, the figures the rest
            box.add(l, at);
            values[r] = new JLabel("–");
            values[r].setName("dyn.object." + ROWS[r][1]);
            // several figures in one row: plain, to fit; one: bold, as the Grasp box's
            values[r].setFont(ROWS[r].length > 2 ? Widgets.small() : Widgets.small().deriveFont(java.awt.Font.BOLD));
            box.add(values[r], Widgets.at(1, r + 1));
        }
        box.setVisible(false);
    }

    /** The box (hidden until a free object is shown). */
    JPanel component() { return box; }

    /** Shows the free object of a state, or hides the box (null: the object is fixed, or there is none). */
    void show(Snapshot.ObjectSnapshot o) {
        box.setVisible(o != null);
        if (o == null) {
            shown = Map.of();
            return;
        }
        shown = values(o);
        status.setText(shown.get("status"));
        for (int r = 0; r < ROWS.length; r++) {
            StringBuilder sb = new StringBuilder();
            for (int i = 1; i < ROWS[r].length; i++) sb.append(i > 1 ? " " : "").append(shown.get(ROWS[r][i]));
            values[r].setText(sb.toString());
            values[r].setToolTipText(sb.toString());
        }
    }

    /** What the box shows, one {@code KEY=VALUE} per line (empty while it is hidden). */
    List<String> lines() {
        return shown.entrySet().stream().map(e -> e.getKey() + "=" + e.getValue()).toList();
    }

    /**
     * The texts the box shows for a free object, by trace.csv column or summary.json key (and
     * {@code status}): positions and the quaternion with five decimals, the other figures with four
     * significant digits ({@link Widgets#significant}), times with four decimals as the Dynamics
     * table writes the breakaway, "–" for a time that has not come.
     */
    static Map<String, String> values(Snapshot.ObjectSnapshot o) {
        Map<String, String> v = new LinkedHashMap<>();
        v.put("status", status(o));
        for (int c = Recorder.OBJ_X; c <= Recorder.OBJ_ROT; c++) {
            double x = o.column(c);
            String text;
            if (c <= Recorder.OBJ_QZ) text = Widgets.fmt(x, 5);
            else if (c == Recorder.OBJ_CONTACTS) text = Long.toString(Math.round(x));
            else text = Widgets.significant(x, 4);
            v.put(Recorder.OBJECT_COLUMNS[c], text);
        }
        v.put("max_displacement_m", Widgets.significant(o.maxDisplacementM(), 4));
        v.put("max_rotation_deg", Widgets.significant(o.maxRotationDeg(), 4));
        v.put("released_at_s", time(o.releasedAtS()));
        v.put("slipped_at_s", time(o.slippedAtS()));
        v.put("dropped_at_s", time(o.droppedAtS()));
        return v;
    }

    /** Held in place, free, slipped or dropped, with the time it happened. */
    static String status(Snapshot.ObjectSnapshot o) {
        if (!o.released()) return "held in place (not released yet)";
        if (!Double.isNaN(o.droppedAtS())) return String.format(Locale.ROOT, "DROPPED at t = %.4f s", o.droppedAtS());
        if (!Double.isNaN(o.slippedAtS())) return String.format(Locale.ROOT, "SLIPPED at t = %.4f s", o.slippedAtS());
        return String.format(Locale.ROOT, "free since t = %.4f s, not slipped", o.releasedAtS());
    }

    private static String time(double t) {
        return Double.isNaN(t) ? "–" : Widgets.fmt(t, 4);
    }
}
