package org.handsim.gui;

import java.awt.BorderLayout;
import java.awt.GridBagLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.handsim.hand.HandDescription;
import org.handsim.kinematics.CoupledReach;
import org.handsim.kinematics.IkResult;
import org.handsim.kinematics.InverseKinematics;
import org.handsim.kinematics.Transmission;
import org.handsim.math.RigidTransform;
import org.handsim.model.ContactSet;
import org.handsim.scenario.Scenario;
import org.handsim.model.SceneGeometry;
import org.handsim.trajectory.Hold;

/**
 * The <b>Kinematics</b> panel: move the hand by joint values (forward) or by a fingertip
 * position (inverse), paper Section II.
 *
 * <h2>Forward: counts and angles kept in sync</h2>
 * Per finger a slider and a field in motor encoder counts q_Mk ∈ [0, 17 500], and fields for
 * the two joint angles of the coupled (FREE) finger in degrees, θk2 = q_Mk / 125 and
 * θk3 = q_Mk / 375 (eqs 3, 4, {@link Transmission}); the spread q_M4 ∈ [0, 3 150] with
 * θ11 = −θ21 = −(2/35)·q_M4 degrees (eqs 1, 2). Editing any one of them (Enter or leaving the
 * field) recomputes the others, so a joint angle typed in is rounded to what the one motor can
 * do. The view shows the pose at once ({@link HandSimWindow#preview}, which pauses the
 * simulation); <i>Use as start pose</i> makes every motor hold these counts in the working
 * scenario.
 *
 * <h2>Following the model</h2>
 * Whenever the view shows a state of the model (while it plays, and after a pause, a step, a
 * reset, a load or the end of the run) the panel shows that same state, finger by finger:
 * the motor counts and spread of the published {@link org.handsim.model.Snapshot}, and the joint
 * angles the model has — not the coupled angles of the counts, which a finger whose clutch has
 * broken away or stalled no longer has (after a breakaway θk2 stays where the link met the
 * object while the motor winds θk3 on). Editing a value shows the FREE finger's pose of it
 * again, as above, until the model is shown once more (Play, Step, Reset).
 *
 * <h2>Inverse: fingertip target → joints</h2>
 * A target in the palm frame {P} (metres) is solved in closed form with the joint limits
 * ({@link InverseKinematics#solveInPalm}, eqs 5–7). Reachable: the joints, shown on the hand.
 * Unreachable: said plainly in red, with the closest reachable point, its distance and its
 * joints; the view marks the target (magenta) and the closest point (cyan). Because one motor
 * drives both joints of a finger, the exact joints are usually not a pose of the real hand;
 * the panel also gives the motor counts whose coupled fingertip comes closest
 * ({@link CoupledReach}) and <i>Move finger there</i> sets them in the forward part.
 *
 * <p>Script names: {@code fk1.counts}, {@code fk1.theta2}, {@code fk1.theta3},
 * {@code fk1.slider} (and 2, 3), {@code fk.spread.counts}, {@code fk.spread.theta11},
 * {@code fk.spread.slider}, buttons {@code fk.apply}; {@code ik.finger}, {@code ik.x},
 * {@code ik.y}, {@code ik.z}, buttons {@code ik.solve}, {@code ik.apply}; the script's
 * {@code log kinematics} prints the values shown ({@link #lines()}). Event dispatch thread only.
 *
 * <p>Every pose shown (forward or inverse) is collided with the object as the simulation would
 * collide it: its contacts are drawn and a pose that touches the object is warned about.
 */
public final class KinematicsPanel {
    private final HandSimWindow window;
    private final Transmission tr = Transmission.barrettHand();
    private final HandDescription hand = tr.hand();
    private final JPanel panel = Widgets.column();
    private final JSlider[] slider = new JSlider[4];
    private final JTextField[] counts = new JTextField[4];
    private final JTextField[] theta2 = new JTextField[3], theta3 = new JTextField[3];
    private JTextField theta11;
    /** Motor counts shown, M1..M4. */
    private final double[] q = new double[4];
    /** Joint angles shown per finger, θk1..θk3 in radians (the model's, or the FREE finger's of q). */
    private final double[][] angles = new double[3][];
    private boolean syncing;
    private final JComboBox<String> ikFinger = new JComboBox<>(new String[] {"1", "2", "3"});
    private final JTextField ikX, ikY, ikZ;
    private final JTextArea ikResult = new JTextArea(6, 28);
    private CoupledReach.Result lastReach;
    private SceneGeometry geometry;
    private Scenario.ObjectPlacement geometryFor;
    private int lastPreviewContacts;
    private int lastReachFinger;

    KinematicsPanel(HandSimWindow window) {
        this.window = window;

        JPanel fk = Widgets.titled(new JPanel(new GridBagLayout()), "Forward kinematics (FREE finger)");
        int row = 0;
        for (int k = 1; k <= 3; k++) {
            int m = k - 1;
            fk.add(new JLabel("Finger " + k + "  (motor M" + k + ")"), Widgets.at(0, row++, 4));
            slider[m] = slider("fk" + k + ".slider", hand.fingerCountsMax(), m);
            fk.add(slider[m], Widgets.at(0, row++, 4));
            counts[m] = Widgets.field("fk" + k + ".counts", "0", 6, () -> commitCounts(m));
            theta2[m] = Widgets.field("fk" + k + ".theta2", "0.00", 5, () -> commitAngle(m, 2));
            theta3[m] = Widgets.field("fk" + k + ".theta3", "0.00", 5, () -> commitAngle(m, 3));
            fk.add(labelled("counts", counts[m]), Widgets.at(0, row));
            fk.add(labelled("θ" + k + "2 °", theta2[m]), Widgets.at(1, row));
            fk.add(labelled("θ" + k + "3 °", theta3[m]), Widgets.at(2, row++));
        }
        fk.add(new JLabel("Spread (motor M4): θ11 = −θ21"), Widgets.at(0, row++, 4));
        slider[3] = slider("fk.spread.slider", hand.spreadCountsMax(), 3);
        fk.add(slider[3], Widgets.at(0, row++, 4));
        counts[3] = Widgets.field("fk.spread.counts", "0", 6, () -> commitCounts(3));
        theta11 = Widgets.field("fk.spread.theta11", "0.00", 5, this::commitSpreadAngle);
        fk.add(labelled("counts", counts[3]), Widgets.at(0, row));
        fk.add(labelled("θ11 °", theta11), Widgets.at(1, row++));
        fk.add(Widgets.button("fk.apply", "Use as start pose", this::useAsStartPose), Widgets.at(0, row, 3));
        panel.add(fk);

        JPanel ik = Widgets.titled(new JPanel(new GridBagLayout()), "Inverse kinematics (fingertip, palm frame, m)");
        ikFinger.setName("ik.finger");
        ikFinger.setSelectedIndex(2);
        ik.add(labelled("finger", ikFinger), Widgets.at(0, 0));
        ikX = Widgets.field("ik.x", "0.000", 6, null);
        ikY = Widgets.field("ik.y", "0.100", 6, null);
        ikZ = Widgets.field("ik.z", "0.180", 6, null);
        ik.add(labelled("x", ikX), Widgets.at(0, 1));
        ik.add(labelled("y", ikY), Widgets.at(1, 1));
        ik.add(labelled("z", ikZ), Widgets.at(2, 1));
        JButton solve = Widgets.button("ik.solve", "Solve", this::solve);
        ikX.addActionListener(e -> solve());
        ikY.addActionListener(e -> solve());
        ikZ.addActionListener(e -> solve());
        ik.add(solve, Widgets.at(0, 2));
        ik.add(Widgets.button("ik.apply", "Move finger there", this::applyReach), Widgets.at(1, 2, 2));
        ikResult.setName("ik.result");
        ikResult.setEditable(false);
        ikResult.setLineWrap(true);
        ikResult.setWrapStyleWord(true);
        ikResult.setFont(Widgets.small());
        ikResult.setOpaque(false);
        ik.add(ikResult, Widgets.at(0, 3, 3));
        panel.add(ik);
        setAll(window.scenario());
    }

    JComponent component() {
        return Widgets.top(panel);
    }

    private static JPanel labelled(String label, JComponent c) {
        JPanel p = new JPanel(new BorderLayout(3, 0));
        p.add(new JLabel(label), BorderLayout.WEST);
        p.add(c, BorderLayout.CENTER);
        return p;
    }

    private JSlider slider(String name, int max, int m) {
        JSlider s = new JSlider(0, max, 0);
        s.setName(name);
        s.addChangeListener(e -> {
            if (syncing) return;
            q[m] = s.getValue();
            coupled();
            showValues();
            showPose();
        });
        return s;
    }

    private void setAll(Scenario s) {
        for (int m = 0; m < 4; m++) q[m] = s.startCounts(m);
        coupled();
        showValues();
    }

    /** The angles of FREE fingers at the counts q (eqs 1–4): what an edited value moves the hand to. */
    private void coupled() {
        for (int k = 1; k <= 3; k++) {
            angles[k - 1] = tr.joints(k, q[k - 1], q[3], null);
        }
    }

    /** Writes q and the angles into every slider and field without triggering their listeners. */
    private void showValues() {
        syncing = true;
        try {
            for (int m = 0; m < 4; m++) {
                slider[m].setValue((int) Math.round(q[m]));
                counts[m].setText(Widgets.fmt(q[m], 0));
            }
            for (int m = 0; m < 3; m++) {
                theta2[m].setText(degrees(angles[m][1]));
                theta3[m].setText(degrees(angles[m][2]));
            }
            theta11.setText(degrees(angles[0][0]));
        } finally {
            syncing = false;
        }
    }

    /**
     * What the panel shows, one line per finger (the script's {@code log kinematics}):
     * {@code finger 3: M3 9479 counts, θ31 0.00°, θ32 47.72°, θ33 30.06°} — the counts and
     * θk2, θk3 as their fields show them; θk1 from the spread field (θ11 as shown, θ21 = −θ11,
     * θ31 = 0).
     */
    public List<String> lines() {
        List<String> out = new ArrayList<>();
        for (int k = 1; k <= 3; k++) {
            String spread = k == 1 ? theta11.getText() : degrees(angles[k - 1][0]);
            out.add(String.format(Locale.ROOT, "finger %d: M%d %s counts, θ%d1 %s°, θ%d2 %s°, θ%d3 %s°", k, k, counts[k - 1].getText(),
                k, spread, k, theta2[k - 1].getText(), k, theta3[k - 1].getText()));
        }
        return out;
    }

    private void commitCounts(int m) {
        if (syncing) return;
        double max = m == 3 ? hand.spreadCountsMax() : hand.fingerCountsMax();
        try {
            double v = Widgets.number(counts[m], m == 3 ? "spread counts" : "finger " + (m + 1) + " counts");
            if (v < 0 || v > max) throw new IllegalArgumentException((m == 3 ? "spread" : "finger " + (m + 1)) + " counts must be in [0, " + (int) max + "], got " + v);
            if (counts[m].getText().trim().equals(Widgets.fmt(q[m], 0))) return;   // nothing edited
            q[m] = Math.round(v);
            coupled();
            showValues();
            showPose();
        } catch (IllegalArgumentException e) {
            window.refused(e.getMessage());
            showValues();
        }
    }

    private void commitAngle(int m, int joint) {
        if (syncing) return;
        JTextField f = joint == 2 ? theta2[m] : theta3[m];
        try {
            double deg = Widgets.number(f, "θ" + (m + 1) + joint);
            double c = joint == 2 ? tr.countsForInner(Math.toRadians(deg)) : tr.countsForOuter(Math.toRadians(deg));
            if (c < -1e-9 || c > hand.fingerCountsMax() + 1e-9) {
                throw new IllegalArgumentException("θ" + (m + 1) + joint + " = " + deg + "° needs " + Math.round(c)
                    + " counts, outside [0, " + hand.fingerCountsMax() + "]");
            }
            if (f.getText().trim().equals(degrees(angles[m][joint - 1]))) return;   // nothing edited
            q[m] = Math.round(c);
            coupled();
            showValues();
            showPose();
        } catch (IllegalArgumentException e) {
            window.refused(e.getMessage());
            showValues();
        }
    }

    private void commitSpreadAngle() {
        if (syncing) return;
        try {
            double deg = Widgets.number(theta11, "θ11");
            double c = tr.countsForSpread(1, Math.toRadians(deg));
            if (c < -1e-9 || c > hand.spreadCountsMax() + 1e-9) {
                throw new IllegalArgumentException("θ11 = " + deg + "° needs " + Math.round(c) + " spread counts, outside [0, " + hand.spreadCountsMax() + "]");
            }
            if (theta11.getText().trim().equals(degrees(angles[0][0]))) return;   // nothing edited
            q[3] = Math.round(c);
            coupled();
            showValues();
            showPose();
        } catch (IllegalArgumentException e) {
            window.refused(e.getMessage());
            showValues();
        }
    }

    /** The joint angles shown, radians (the FREE fingers' of q after an edit, the model's when following it). */
    private double[][] joints() {
        double[][] j = new double[3][];
        for (int k = 0; k < 3; k++) j[k] = angles[k].clone();
        return j;
    }

    /** An angle in radians as its field shows it: degrees, two decimals. */
    private static String degrees(double rad) {
        return Widgets.fmt(Math.toDegrees(rad), 2);
    }

    private void showPose() {
        String fk = String.format(Locale.ROOT, "forward kinematics: M1 %.0f, M2 %.0f, M3 %.0f, M4 %.0f counts (simulation paused)",
            q[0], q[1], q[2], q[3]);
        String touch = preview(Pose.ofJoints(joints(), window.scenario().worldFromPalm()));
        if (touch == null) window.status(fk, false);
        else window.warning(fk + " — " + touch);
    }

    /**
     * Shows a pose with the contacts it would have: the links are collided with the object by
     * the simulator's own collision ({@link SceneGeometry}, as {@code HandModel} does at every
     * step) and the contacts drawn. Returns the warning for the status bar when the pose touches
     * the object, else null.
     */
    private String preview(Pose p) {
        SceneGeometry g = geometry();
        int[] perFinger = new int[3];
        if (g != null) {
            ContactSet all = new ContactSet(), one = new ContactSet();
            double[] link = new double[12];
            for (int k = 1; k <= 3; k++) {
                for (int j = 1; j <= 3; j++) {
                    System.arraycopy(p.framesWorld()[k - 1], 12 * j, link, 0, 12);
                    one.clear();
                    perFinger[k - 1] += g.collide(k, j, link, one);
                    all.append(one);
                }
            }
            p = p.withContacts(all, perFinger);
        }
        window.preview(p);
        StringBuilder touching = new StringBuilder();
        for (int k = 1; k <= 3; k++) {
            if (perFinger[k - 1] > 0) {
                touching.append(touching.length() == 0 ? "" : "; ").append(String.format(Locale.ROOT, "finger %d touches the object (%d contact%s)",
                    k, perFinger[k - 1], perFinger[k - 1] == 1 ? "" : "s"));
            }
        }
        lastPreviewContacts = perFinger[0] + perFinger[1] + perFinger[2];
        return touching.length() == 0 ? null : "this pose: " + touching + ": a run started from it would begin in contact";
    }

    /** The collision of the working scenario's object, built when first needed (null: no object, or it does not load). */
    private SceneGeometry geometry() {
        Scenario.ObjectPlacement o = window.scenario().object();
        if (o == null) return null;
        if (geometry == null || geometryFor != o) {
            geometryFor = o;
            try {
                geometry = new SceneGeometry(o, SceneGeometry.DEFAULT_K);
            } catch (RuntimeException e) {
                geometry = null;
            }
        }
        return geometry;
    }

    /** The working scenario's object changed: the next preview collides with the new one. */
    void previewChanged() {
        geometry = null;
        geometryFor = null;
    }

    /** Contacts in the last preview (for scripts and tests). */
    public int previewContacts() { return lastPreviewContacts; }

    private void useAsStartPose() {
        Scenario s = window.scenario();
        for (int m = 0; m < 4; m++) s = s.withMotor(m, new Hold(q[m], 0));
        window.load(s);
        window.status("start pose set: every motor holds these counts (Path Planning plans from here)", false);
    }

    /**
     * Shows the model's state (called by the window's view update with each state the view
     * shows, playing or not): each finger's motor counts and joint angles, the spread. Not while
     * the panel's own pose is previewed.
     */
    void follow(SimulationRunner.State s) {
        if (s.snapshot() == null || window.simulator().previewing()) return;
        for (int k = 0; k < 3; k++) {
            org.handsim.model.Snapshot.FingerSnapshot f = s.snapshot().fingers()[k];
            q[k] = f.motorCounts();
            angles[k] = f.joints().clone();
        }
        q[3] = s.snapshot().spreadCounts();
        showValues();
    }

    /** Solves the inverse kinematics for the target fields and shows the answer. */
    void solve() {
        int k = ikFinger.getSelectedIndex() + 1;
        double[] target;
        try {
            target = new double[] {Widgets.number(ikX, "target x"), Widgets.number(ikY, "target y"), Widgets.number(ikZ, "target z")};
        } catch (IllegalArgumentException e) {
            window.refused(e.getMessage());
            return;
        }
        IkResult r = InverseKinematics.of(k).solveInPalm(target);
        RigidTransform wp = window.scenario().worldFromPalm();
        double[] targetInK0 = org.handsim.kinematics.FingerKinematics.of(k).baseInPalm().inverse().apply(target);
        lastReach = CoupledReach.of(k).closest(targetInK0);
        lastReachFinger = k;
        double[] j = r.joints();
        StringBuilder sb = new StringBuilder();
        if (r.reachable()) {
            sb.append(String.format(Locale.ROOT, "REACHABLE by finger %d: θ%d1 = %.2f°, θ%d2 = %.2f°, θ%d3 = %.2f°.",
                k, k, Math.toDegrees(j[0]), k, Math.toDegrees(j[1]), k, Math.toDegrees(j[2])));
            ikResult.setForeground(Widgets.OK);
        } else {
            double[] c = r.fingertip();
            sb.append(String.format(Locale.ROOT, "UNREACHABLE by finger %d: the closest reachable point is (%.4f, %.4f, %.4f) m, "
                + "%.1f mm from the target, at θ%d1 = %.2f°, θ%d2 = %.2f°, θ%d3 = %.2f°.",
                k, c[0], c[1], c[2], 1000 * r.errorM(), k, Math.toDegrees(j[0]), k, Math.toDegrees(j[1]), k, Math.toDegrees(j[2])));
            ikResult.setForeground(Widgets.ERROR);
        }
        sb.append(String.format(Locale.ROOT, "%nCoupled finger (one motor): M%d = %d, M4 = %d counts put the fingertip %.1f mm from the target.",
            k, lastReach.qMk(), lastReach.qM4(), 1000 * lastReach.errorM()));
        ikResult.setText(sb.toString());
        String ik = r.reachable() ? "inverse kinematics: target reachable" : "inverse kinematics: target UNREACHABLE (closest point shown in cyan)";
        // show the exact IK joints on finger k, the forward pose on the others, and the markers
        double[][] joints = joints();
        joints[k - 1] = j;
        if (k == 3) joints[2][0] = 0;
        double[] targetWorld = wp.apply(target);
        double[] closestWorld = r.reachable() ? null : wp.apply(r.fingertip());
        String touch = preview(Pose.ofJoints(joints, wp).withMarkers(targetWorld, closestWorld));
        if (touch == null || !r.reachable()) window.status(touch == null ? ik : ik + " — " + touch, !r.reachable());
        else window.warning(ik + " — " + touch);
    }

    private void applyReach() {
        if (lastReach == null) {
            window.status("solve a target first", true);
            return;
        }
        q[lastReachFinger - 1] = lastReach.qMk();
        if (lastReachFinger != 3) q[3] = lastReach.qM4();
        coupled();
        showValues();
        showPose();
    }

    /** The inverse-kinematics answer as shown (for logs). */
    public String ikText() { return ikResult.getText(); }
}
