package org.handsim.gui;

import java.awt.GridBagLayout;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.handsim.grasp.FrictionCone;
import org.handsim.scenario.Home;
import org.handsim.scenario.MeshFiles;
import org.handsim.model.ObjectPlacer;
import org.handsim.scenario.Scenario;

/**
 * The <b>Objects</b> panel: import a 3D model from a VRML97, Wavefront OBJ or STL file, choose
 * its units, place it by position and rotation, remove it (paper Section III, "Object model").
 *
 * <h2>Import</h2>
 * A new import is placed where it cannot start inside the hand ({@link ObjectPlacer}): its axes
 * along the palm's, its centre on the palm axis in front of the palm, moved out along that axis
 * until the simulator's own collision finds no link touching it at the start. Its units come
 * from the list: <i>auto</i> (metres for a model at most 2 units across, else millimetres,
 * GraspIt!'s unit), mm, cm or m — saved in the scenario as {@code object.units}. The list is the
 * choice for the next import; the line under the file's name says the unit the object is read
 * in now (what runs and what Save scenario writes), and whether the file's size chose it. Then the camera
 * frames the scene. Should the hand still start in contact (a placement typed by hand, or no
 * clear place found), the window says so in the status bar with the command line's warning.
 *
 * <h2>Placement</h2>
 * {@code world ← object}: the position in metres and the rotation as an axis-angle vector in
 * degrees (direction = axis, length = angle; the scenario files' {@code rotation_rad} in
 * degrees), then the units and a uniform scale applied in the object's own frame. Every change
 * rebuilds the model with the object ({@code Scenario.withObject}); a file that fails to load is
 * reported in the window (status bar; a dialog when interactive) and changes nothing.
 *
 * <h2>Friction</h2>
 * The object's Coulomb coefficient μ (scenario field {@code object.friction}, default 0.5; 0 is
 * frictionless): the contact forces of the simulation, the friction cones the view draws and the
 * grasp the Dynamics panel evaluates all use it. Enter (or Place) rebuilds the model with it;
 * a saved scenario keeps it.
 *
 * <p>Script names: buttons {@code obj.import} ("Import…"), {@code obj.place} ("Place"),
 * {@code obj.remove} ("Remove"); fields {@code obj.x}, {@code obj.y}, {@code obj.z},
 * {@code obj.rx}, {@code obj.ry}, {@code obj.rz}, {@code obj.scale}, {@code obj.friction};
 * list {@code obj.units}.
 * The script action {@code import FILE} does what the file chooser does. Event dispatch thread only.
 */
public final class ObjectsPanel {
    /** The units list: auto, then {@link Scenario.Units} by name. */
    static final String[] UNITS = {"auto", "mm", "cm", "m"};

    private final HandSimWindow window;
    private final JPanel panel = Widgets.column();
    private final JLabel file = new JLabel("no object");
    private final JLabel placed = new JLabel(" ");
    private final JLabel unitsUsed = new JLabel(" ");
    /** The placement this panel's last import with units "auto" made: its unit was judged by the file's size. */
    private Scenario.ObjectPlacement judged;
    private final JTextField x, y, z, rx, ry, rz, scale, friction;
    private final JComboBox<String> units = new JComboBox<>(UNITS);
    private boolean syncing;

    ObjectsPanel(HandSimWindow window) {
        this.window = window;
        JPanel io = Widgets.titled(new JPanel(new GridBagLayout()), "Object from a VRML97, OBJ or STL file");
        io.add(Widgets.button("obj.import", "Import…", this::choose), Widgets.at(0, 0));
        io.add(Widgets.button("obj.remove", "Remove", this::remove), Widgets.at(1, 0));
        JPanel u = new JPanel(new java.awt.BorderLayout(4, 0));
        u.add(new JLabel("units"), java.awt.BorderLayout.WEST);
        units.setName("obj.units");
        units.setToolTipText("auto: metres for a model at most 2 units across, else millimetres (GraspIt!'s unit)");
        units.addActionListener(e -> { if (!syncing) unitsChanged(); });
        u.add(units, java.awt.BorderLayout.CENTER);
        io.add(u, Widgets.at(2, 0));
        file.setName("obj.file");
        io.add(file, Widgets.at(0, 1, 3));
        unitsUsed.setName("obj.unitsused");
        io.add(unitsUsed, Widgets.at(0, 2, 3));
        placed.setName("obj.placed");
        placed.setFont(Widgets.small());
        io.add(placed, Widgets.at(0, 3, 3));
        panel.add(io);

        JPanel place = Widgets.titled(new JPanel(new GridBagLayout()), "Placement (world frame)");
        Runnable apply = this::place;
        x = Widgets.field("obj.x", "0.000", 6, null);
        y = Widgets.field("obj.y", "0.000", 6, null);
        z = Widgets.field("obj.z", "0.000", 6, null);
        rx = Widgets.field("obj.rx", "0.0", 6, null);
        ry = Widgets.field("obj.ry", "0.0", 6, null);
        rz = Widgets.field("obj.rz", "0.0", 6, null);
        scale = Widgets.field("obj.scale", "1.0", 6, null);
        for (JTextField f : new JTextField[] {x, y, z, rx, ry, rz, scale}) f.addActionListener(e -> apply.run());
        place.add(new JLabel("position m"), Widgets.at(0, 0));
        place.add(x, Widgets.at(1, 0));
        place.add(y, Widgets.at(2, 0));
        place.add(z, Widgets.at(3, 0));
        place.add(new JLabel("rotation °"), Widgets.at(0, 1));
        place.add(rx, Widgets.at(1, 1));
        place.add(ry, Widgets.at(2, 1));
        place.add(rz, Widgets.at(3, 1));
        place.add(new JLabel("scale"), Widgets.at(0, 2));
        place.add(scale, Widgets.at(1, 2));
        place.add(Widgets.button("obj.place", "Place", apply), Widgets.at(2, 2, 2));
        place.add(Widgets.note("Rotation: axis-angle vector (axis × angle in degrees). The scale multiplies the file's "
            + "coordinates after the units."), Widgets.at(0, 3, 4));
        panel.add(place);

        JPanel fr = Widgets.titled(new JPanel(new GridBagLayout()), "Friction of the contacts");
        friction = Widgets.field("obj.friction", org.handsim.text.Decimal.format(FrictionCone.DEFAULT_MU), 6, null);
        friction.addActionListener(e -> applyFriction());
        fr.add(new JLabel("Coulomb μ"), Widgets.at(0, 0));
        fr.add(friction, Widgets.at(1, 0));
        fr.add(Widgets.note("μ ≥ 0 (0: frictionless). The simulation's contact forces, the friction cones (View menu) and "
            + "the grasp (Dynamics panel) use it; Enter restarts the model at t = 0."), Widgets.at(0, 1, 4));
        panel.add(fr);
    }

    JComponent component() {
        return Widgets.top(panel);
    }

    /** The file chooser (File ▸ Import object, the Import button). */
    void choose() {
        Path start = Home.dir().resolve("vrml").resolve("objects");
        JFileChooser fc = new JFileChooser(Files.isDirectory(start) ? start.toFile() : null);
        fc.setFileFilter(new FileNameExtensionFilter("3D models: VRML97, OBJ, STL (*.wrl, *.wrz, *.obj, *.stl)",
            MeshFiles.EXTENSIONS.toArray(new String[0])));
        if (fc.showOpenDialog(window.frame()) == JFileChooser.APPROVE_OPTION) importFile(fc.getSelectedFile().toPath());
    }

    /** The units chosen in the list, or null for auto. */
    private Scenario.Units chosenUnits() {
        return Scenario.Units.of((String) units.getSelectedItem());
    }

    /**
     * Imports an object file (what the file chooser's OK does): reads it and finds a clear
     * placement off the event dispatch thread, then rebuilds the model with it and frames the
     * camera. The future completes when the object is in the view and the model, or
     * exceptionally with the error that the window shows.
     */
    public CompletableFuture<?> importFile(Path f) {
        Path abs = f.toAbsolutePath().normalize();
        String why = org.handsim.files.InputFile.problem(abs);   // a FIFO or a device is refused before it is opened
        if (why != null) {
            window.error("cannot import " + abs + ": " + why, "Object not loaded");
            return CompletableFuture.failedFuture(new java.io.IOException(abs + ": " + why));
        }
        Scenario s = window.scenario();
        int divisions = s.object() != null ? s.object().divisions() : Scenario.DEFAULT_DIVISIONS;
        return placeAndLoad(abs, divisions, chosenUnits(), 1.0, "imported");
    }

    /** Finds the units (if null: guessed) and a clear placement off the EDT, then loads the scenario with it. */
    private CompletableFuture<?> placeAndLoad(Path abs, int divisions, Scenario.Units wanted, double sc, String verb) {
        window.status("loading " + abs.getFileName() + " ...", false);
        Scenario s = window.scenario();
        CompletableFuture<ObjectPlacer.Placed> found = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                Scenario.Units u = org.handsim.scenario.UnitRule.resolve(abs, divisions, wanted).units();
                found.complete(ObjectPlacer.place(s, abs, divisions, sc, u));
            } catch (RuntimeException e) {
                found.completeExceptionally(e);
            }
        }, "handsim-object-placer");
        t.setDaemon(true);
        t.start();
        CompletableFuture<Object> done = new CompletableFuture<>();
        found.whenComplete((p, e) -> SwingUtilities.invokeLater(() -> {
            if (e != null) {
                Throwable c = e.getCause() != null && e instanceof java.util.concurrent.CompletionException ? e.getCause() : e;
                window.error("cannot load " + abs + ": " + c.getMessage(), "Object not loaded");
                done.completeExceptionally(c);
                return;
            }
            judged = wanted == null ? p.placement() : null;
            window.load(window.scenario().withObject(p.placement()));
            window.simulator().objectReady().whenComplete((m, e2) -> SwingUtilities.invokeLater(() -> {
                if (e2 != null) {
                    done.completeExceptionally(e2);
                    return;
                }
                window.camera(org.handsim.gui.SceneView.Camera.FIT);
                Scenario.ObjectPlacement pl = p.placement();
                String where = String.format(Locale.ROOT, "%s %s (%d triangles, units %s%s), placed on the palm axis%s", verb, abs.getFileName(),
                    m != null ? m.mesh().triangleCount() : 0, pl.units().id(), wanted == null ? " by its size" : "",
                    p.steps() == 0 ? "" : String.format(Locale.ROOT, ", moved out %d steps to clear the hand", p.steps()));
                placed.setText(p.clear() ? "placed clear of the hand" : "no clear place found: the hand starts in contact");
                if (p.clear()) window.status(where, false);
                else window.warning(where + ": no place clear of the hand found within " + p.steps() + " steps");
                done.complete(m);
            }));
        }));
        return done;
    }

    private void unitsChanged() {
        Scenario.ObjectPlacement p = window.scenario().object();
        if (p == null) return;
        placeAndLoad(p.file(), p.divisions(), chosenUnits(), p.scale(), "re-placed");
    }

    private void remove() {
        if (window.scenario().object() == null) {
            window.status("no object to remove", false);
            return;
        }
        window.load(window.scenario().withObject(null));
        file.setText("no object");
        unitsUsed.setText(" ");
        placed.setText(" ");
        window.status("object removed", false);
    }

    /** Friction field's Enter: the working scenario with the object's μ, the model rebuilt. */
    private void applyFriction() {
        Scenario.ObjectPlacement p = window.scenario().object();
        if (p == null) {
            window.status("import an object first: the friction is the object's", true);
            return;
        }
        try {
            double mu = frictionValue();
            window.load(window.scenario().withFriction(mu));
            window.status(String.format(Locale.ROOT, "friction μ = %s applied%s: the model restarts at t = 0", Widgets.significant(mu, 4),
                mu == 0 ? " (frictionless contacts)" : ""), false);
        } catch (IllegalArgumentException e) {
            window.refused("friction not applied: " + e.getMessage());
        }
    }

    private double frictionValue() {
        double mu = Widgets.number(friction, "friction");
        if (!(mu >= 0)) throw new IllegalArgumentException("friction must be >= 0, got " + friction.getText().trim());
        return mu;
    }

    private void place() {
        Scenario.ObjectPlacement p = window.scenario().object();
        if (p == null) {
            window.status("import an object first", true);
            return;
        }
        try {
            double d = Math.PI / 180;
            double[] position = {Widgets.number(x, "x"), Widgets.number(y, "y"), Widgets.number(z, "z")};
            double[] rotation = {d * Widgets.number(rx, "rotation x"), d * Widgets.number(ry, "rotation y"), d * Widgets.number(rz, "rotation z")};
            double sc = Widgets.number(scale, "scale");
            String scaleWhy = org.handsim.mesh.MeshLimits.scaleProblem(sc);   // the ranges scenario files have
            if (scaleWhy != null) throw new IllegalArgumentException("scale " + scaleWhy);
            String poseWhy = org.handsim.math.RigidTransform.poseProblem("position", position, "rotation (rad)", rotation);
            if (poseWhy != null) throw new IllegalArgumentException(poseWhy);
            Scenario.Units u = chosenUnits() != null ? chosenUnits() : p.units();
            double mu = frictionValue();
            window.load(window.scenario().withObject(Scenario.ObjectPlacement.of(p.file(), position, rotation, sc, p.divisions(), u).withFriction(mu)));
            placed.setText("placed by hand");
            window.status(String.format(Locale.ROOT, "object placed at (%.3f, %.3f, %.3f) m", position[0], position[1], position[2]), false);
        } catch (IllegalArgumentException e) {
            window.refused("object not placed: " + e.getMessage());
        }
    }

    /** Shows the scenario's object in the fields (called when the working scenario changes). */
    void showPlacement(Scenario s) {
        showUnits(s);
        Scenario.ObjectPlacement p = s.object();
        if (p == null) {
            file.setText("no object");
            placed.setText(" ");
            return;
        }
        double[] o = p.position();
        double[] r = p.rotation();
        x.setText(Widgets.fmt(o[0], 4));
        y.setText(Widgets.fmt(o[1], 4));
        z.setText(Widgets.fmt(o[2], 4));
        rx.setText(Widgets.fmt(Math.toDegrees(r[0]), 2));
        ry.setText(Widgets.fmt(Math.toDegrees(r[1]), 2));
        rz.setText(Widgets.fmt(Math.toDegrees(r[2]), 2));
        scale.setText(Widgets.fmt(p.scale(), 4));
        friction.setText(org.handsim.text.Decimal.format(p.friction()));   // the number the scenario holds, shortest
        syncing = true;
        try {
            if (chosenUnits() != null) units.setSelectedItem(p.units().id());
        } finally {
            syncing = false;
        }
        file.setText(p.file().getFileName() + " (" + MeshFiles.Format.of(p.file()).label() + ")");
    }

    /**
     * Shows the unit the scenario's object is read in — what runs and what Save scenario writes
     * as {@code object.units} — apart from the units list, which stays the choice for the next
     * import (auto keeps judging each new file by its size).
     */
    private void showUnits(Scenario s) {
        unitsUsed.setText(unitsText(s, judged));
    }

    /**
     * The units line for a scenario's object: {@code units used: mm}, with {@code (judged by
     * the file's size)} when nobody chose it (the scenario's {@code object.units} absent or
     * auto, or this panel's import with auto made {@code judged}); blank without an object.
     */
    static String unitsText(Scenario s, Scenario.ObjectPlacement judged) {
        Scenario.ObjectPlacement p = s.object();
        if (p == null) return " ";
        boolean bySize = s.unitsBySize() || judged != null && judged.file().equals(p.file()) && judged.units() == p.units();
        return "units used: " + p.units().id() + (bySize ? " (judged by the file's size)" : "");
    }

    /** What the panel shows of the object, for the script's {@code log objects}: the file, the units used, the placement's note (blank lines left out). */
    public java.util.List<String> lines() {
        java.util.List<String> out = new java.util.ArrayList<>();
        for (JLabel l : new JLabel[] {file, unitsUsed, placed}) if (!l.getText().isBlank()) out.add(l.getText().trim());
        return out;
    }

}
