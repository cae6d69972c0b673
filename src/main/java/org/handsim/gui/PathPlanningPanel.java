package org.handsim.gui;

import java.awt.GridBagLayout;
import java.util.Locale;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.handsim.hand.HandDescription;
import org.handsim.scenario.Scenario;
import org.handsim.trajectory.CartesianLine;
import org.handsim.trajectory.Hold;
import org.handsim.trajectory.Quintic;
import org.handsim.trajectory.Trajectory;
import org.handsim.trajectory.Trapezoid;

/**
 * The <b>Path Planning</b> panel: per motor a trajectory type and an end point, from where the
 * hand is now; <i>Run</i> puts them into the working scenario and plays it.
 *
 * <ul>
 *   <li><b>hold</b>: the motor stays where it is;</li>
 *   <li><b>trapezoid</b> to an end count with v max (counts/s) and a max (counts/s²): the
 *       paper's three-phase velocity profile ({@link Trapezoid});</li>
 *   <li><b>quintic</b> to an end count in a duration: zero velocity and acceleration at both
 *       ends ({@link Quintic});</li>
 *   <li><b>line</b> (M1–M3): the fingertip follows a straight line to an end point
 *       {@code x,y,z} in the <b>palm frame</b> {P}, metres (the frame of the Kinematics panel's
 *       targets), in a duration ({@link CartesianLine}, which works in the finger's base frame
 *       {k0}: the point is converted; solved by coupled inverse kinematics at 101 points; the
 *       panel reports how far the coupled finger strays from the line).</li>
 * </ul>
 * Only the fields the chosen type uses are enabled (hold: none; trapezoid: end, v max, a max;
 * quintic: end, T; line: end point, T).
 * The start of every trajectory is the motor's count now ({@link HandSimWindow#currentCounts});
 * the scenario's duration becomes the longest trajectory plus {@value #SETTLE_S} s. A bad
 * value is reported in the status bar with the motor and field, and nothing runs.
 *
 * <p>Script names per motor m = 1..4: {@code path.M<m>.type}, {@code path.M<m>.end},
 * {@code path.M<m>.vmax}, {@code path.M<m>.amax}, {@code path.M<m>.duration}; button
 * {@code path.run} ("Run"), {@code path.paper} ("Paper experiment"). Event dispatch thread only.
 */
public final class PathPlanningPanel {
    static final double SETTLE_S = 0.5;
    private static final String[] FINGER_TYPES = {"hold", "trapezoid", "quintic", "line"};
    private static final String[] SPREAD_TYPES = {"hold", "trapezoid", "quintic"};

    private final HandSimWindow window;
    private final JPanel panel = Widgets.column();
    @SuppressWarnings("unchecked")
    private final JComboBox<String>[] type = new JComboBox[4];
    private final JTextField[] end = new JTextField[4], vmax = new JTextField[4], amax = new JTextField[4], duration = new JTextField[4];
    private final JTextArea result = new JTextArea(4, 28);

    PathPlanningPanel(HandSimWindow window) {
        this.window = window;
        JPanel grid = Widgets.titled(new JPanel(new GridBagLayout()), "Trajectory per motor, from the current counts");
        int row = 0;
        for (int m = 0; m < 4; m++) {
            String motor = "M" + (m + 1);
            JLabel title = new JLabel(m < 3 ? motor + " (finger " + (m + 1) + ")" : motor + " (spread)");
            type[m] = new JComboBox<>(m < 3 ? FINGER_TYPES : SPREAD_TYPES);
            type[m].setName("path." + motor + ".type");
            grid.add(title, Widgets.at(0, row));
            grid.add(type[m], Widgets.at(1, row, 2));
            row++;
            end[m] = Widgets.field("path." + motor + ".end", m < 3 ? "17500" : "0", 10, null);
            vmax[m] = Widgets.field("path." + motor + ".vmax", m < 3 ? "5000" : "1000", 5, null);
            amax[m] = Widgets.field("path." + motor + ".amax", m < 3 ? "25000" : "5000", 5, null);
            duration[m] = Widgets.field("path." + motor + ".duration", "2.0", 4, null);
            grid.add(small("end"), Widgets.at(0, row));
            grid.add(end[m], Widgets.at(1, row, 2));
            row++;
            JPanel p = new JPanel(new GridBagLayout());
            p.add(small("v max"), Widgets.at(0, 0));
            p.add(vmax[m], Widgets.at(1, 0));
            p.add(small("a max"), Widgets.at(2, 0));
            p.add(amax[m], Widgets.at(3, 0));
            p.add(small("T s"), Widgets.at(4, 0));
            p.add(duration[m], Widgets.at(5, 0));
            grid.add(p, Widgets.at(0, row++, 3));
        }
        for (int m = 0; m < 4; m++) {
            int motor = m;
            type[m].addActionListener(e -> enableFields(motor));
            enableFields(m);
        }
        type[2].setSelectedItem("trapezoid");
        grid.add(Widgets.button("path.run", "Run", this::run), Widgets.at(0, row));
        grid.add(Widgets.button("path.paper", "Paper experiment", this::paper), Widgets.at(1, row, 2));
        panel.add(grid);
        JLabel help = Widgets.note("Units: counts, counts/s, counts/s². Fingers: 0–17 500 counts "
            + "(θk2 = q/125°); spread: 0–3 150 counts. <i>line</i>: the fingertip's end point in the "
            + "palm frame {P}, metres (as the Kinematics panel's targets), e.g. <tt>0.02,0.05,0.20</tt>.");
        panel.add(help);
        result.setName("path.result");
        result.setEditable(false);
        result.setLineWrap(true);
        result.setWrapStyleWord(true);
        result.setOpaque(false);
        result.setFont(Widgets.small());
        panel.add(result);
    }

    /** Enables the fields motor m's type uses. */
    private void enableFields(int m) {
        String kind = (String) type[m].getSelectedItem();
        end[m].setEnabled(!"hold".equals(kind));
        vmax[m].setEnabled("trapezoid".equals(kind));
        amax[m].setEnabled("trapezoid".equals(kind));
        duration[m].setEnabled("quintic".equals(kind) || "line".equals(kind));
        if ("line".equals(kind) && !end[m].getText().contains(",")) {
            // a palm-frame point in front of the finger as a start
            double[] tip = org.handsim.kinematics.FingerKinematics.of(m + 1).baseInPalm().apply(new double[] {0.12, 0, 0.08});
            end[m].setText(String.format(Locale.ROOT, "%.3f,%.3f,%.3f", tip[0], tip[1], tip[2]));
        } else if (!"line".equals(kind) && end[m].getText().contains(",")) {
            end[m].setText(m < 3 ? "17500" : "0");
        }
    }

    private static JLabel small(String s) {
        JLabel l = new JLabel(s);
        l.setFont(Widgets.small());
        return l;
    }

    JComponent component() {
        return Widgets.top(panel);
    }

    /** Builds the trajectories, loads the scenario and plays it. */
    void run() {
        double[] from = window.currentCounts();
        Scenario s = window.scenario();
        StringBuilder report = new StringBuilder();
        double longest = 0;
        try {
            Trajectory[] t = new Trajectory[4];
            for (int m = 0; m < 4; m++) {
                t[m] = trajectory(m, from);
                longest = Math.max(longest, t[m].duration());
                if (t[m] instanceof CartesianLine) {
                    report.append(String.format(Locale.ROOT, "M%d line: the coupled fingertip strays up to %.1f mm from the straight line.%n",
                        m + 1, 1000 * ((CartesianLine) t[m]).maxDeviationM()));
                }
            }
            if (longest == 0) throw new IllegalArgumentException("every motor holds: choose a trajectory type");
            for (int m = 0; m < 4; m++) s = s.withMotor(m, t[m]);
            s = s.withDuration(longest + SETTLE_S);
        } catch (IllegalArgumentException e) {
            window.refused("path planning: " + e.getMessage());
            result.setText("Not run: " + e.getMessage());
            return;
        }
        report.append(String.format(Locale.ROOT, "Running %.2f s from M1..M4 = %.0f, %.0f, %.0f, %.0f counts.", longest + SETTLE_S,
            from[0], from[1], from[2], from[3]));
        result.setText(report.toString());
        window.load(s);
        window.play();
        window.status("path planning: trajectories planned from the current counts; the run starts from t = 0", false);
    }

    private Trajectory trajectory(int m, double[] from) {
        String motor = "M" + (m + 1);
        String kind = (String) type[m].getSelectedItem();
        double q0 = from[m];
        double max = m == 3 ? HandDescription.barrettHand().spreadCountsMax() : HandDescription.barrettHand().fingerCountsMax();
        switch (kind) {
            case "hold":
                return new Hold(q0, 0);
            case "trapezoid": {
                double to = counts(m, max);
                double v = positive(vmax[m], motor + " v max"), a = positive(amax[m], motor + " a max");
                return new Trapezoid(q0, to, v, a);
            }
            case "quintic":
                return new Quintic(q0, counts(m, max), positive(duration[m], motor + " T"));
            case "line": {
                String[] parts = end[m].getText().trim().split("\\s*,\\s*");
                if (parts.length != 3) throw new IllegalArgumentException(motor + " end: a line needs x,y,z in metres, got '" + end[m].getText() + "'");
                double[] p = new double[3];
                for (int i = 0; i < 3; i++) {
                    try {
                        p[i] = org.handsim.text.Decimal.parse(parts[i]);
                    } catch (NumberFormatException e) {
                        throw new IllegalArgumentException(motor + " end: '" + org.handsim.text.SafeText.quote(parts[i]) + "' is not a number");
                    }
                }
                // palm frame (the panel's) → the finger's base frame {k0} (the trajectory's)
                double[] inK0 = org.handsim.kinematics.FingerKinematics.of(m + 1).baseInPalm().inverse().apply(p);
                return new CartesianLine(m + 1, q0, from[3], inK0, positive(duration[m], motor + " T"));
            }
            default:
                throw new IllegalArgumentException(motor + ": unknown trajectory type " + kind);
        }
    }

    private double counts(int m, double max) {
        double v = Widgets.number(end[m], "M" + (m + 1) + " end");
        if (v < 0 || v > max) throw new IllegalArgumentException("M" + (m + 1) + " end must be in [0, " + (long) max + "] counts, got " + v);
        return v;
    }

    private static double positive(JTextField f, String what) {
        double v = Widgets.number(f, what);
        if (!(v > 0)) throw new IllegalArgumentException(what + " must be > 0, got " + v);
        return v;
    }

    /** Back to the scenario the window was opened with (the paper's experiment by default). */
    private void paper() {
        window.load(window.originalScenario().withObject(window.scenario().object()));
        result.setText("The opened scenario's trajectories restored (the object stays as placed).");
        window.status("scenario " + window.originalScenario().name() + " restored", false);
    }
}
