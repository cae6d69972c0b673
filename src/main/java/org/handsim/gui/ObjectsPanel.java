package org.handsim.gui;

import java.awt.GridBagLayout;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.handsim.math.RigidTransform;
import org.handsim.sim.Home;
import org.handsim.sim.Scenario;

/**
 * The <b>Objects</b> panel: import a 3D model from a VRML97 file (a file chooser), place it by
 * position and rotation, remove it (paper Section III, "Object model").
 *
 * <p>The placement is {@code world ← object}: the position in metres and the rotation as an
 * axis-angle vector in degrees (direction = axis, length = angle; the scenario files'
 * {@code rotation_rad} in degrees), then a uniform scale applied in the object's own frame.
 * A new import keeps the current placement when there is one, else it uses the placement of the
 * opened scenario's object, else {@link #DEFAULT_POSITION} in the palm frame. Every change
 * rebuilds the model with the object ({@code Scenario.withObject}); a file that fails to load
 * is reported in the window (status bar; a dialog when interactive) and changes nothing.
 *
 * <p>Script names: buttons {@code obj.import} ("Import VRML…"), {@code obj.place} ("Place"),
 * {@code obj.remove} ("Remove"); fields {@code obj.x}, {@code obj.y}, {@code obj.z},
 * {@code obj.rx}, {@code obj.ry}, {@code obj.rz}, {@code obj.scale}. The script action
 * {@code import FILE} does what the file chooser does. Event dispatch thread only.
 */
public final class ObjectsPanel {
    /** Where a first object goes when nothing says otherwise: above the palm, palm frame, m. */
    static final double[] DEFAULT_POSITION = {0, 0, 0.16};

    private final HandSimWindow window;
    private final JPanel panel = Widgets.column();
    private final JLabel file = new JLabel("no object");
    private final JTextField x, y, z, rx, ry, rz, scale;

    ObjectsPanel(HandSimWindow window) {
        this.window = window;
        JPanel io = Widgets.titled(new JPanel(new GridBagLayout()), "Object from a VRML97 file");
        io.add(Widgets.button("obj.import", "Import VRML…", this::choose), Widgets.at(0, 0));
        io.add(Widgets.button("obj.remove", "Remove", this::remove), Widgets.at(1, 0));
        file.setName("obj.file");
        io.add(file, Widgets.at(0, 1, 2));
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
        place.add(Widgets.note("Rotation: axis-angle vector (axis × angle in degrees)."), Widgets.at(0, 3, 4));
        panel.add(place);
    }

    JComponent component() {
        return Widgets.top(panel);
    }

    private void choose() {
        Path start = Home.dir().resolve("vrml").resolve("objects");
        JFileChooser fc = new JFileChooser(Files.isDirectory(start) ? start.toFile() : null);
        fc.setFileFilter(new FileNameExtensionFilter("VRML97 files (*.wrl)", "wrl", "WRL"));
        if (fc.showOpenDialog(window.frame()) == JFileChooser.APPROVE_OPTION) importFile(fc.getSelectedFile().toPath());
    }

    /**
     * Imports a VRML file (what the file chooser's OK does): reads it off the event dispatch
     * thread, then places it and rebuilds the model. The future completes when the object is in
     * the view and the model, or exceptionally with the error that the window shows.
     */
    public CompletableFuture<?> importFile(Path f) {
        Path abs = f.toAbsolutePath().normalize();
        if (!Files.isRegularFile(abs)) {
            window.error("cannot import " + abs + ": no such file", "Object not loaded");
            return CompletableFuture.failedFuture(new java.io.IOException("no such file: " + abs));
        }
        Scenario s = window.scenario();
        Scenario.ObjectPlacement p = s.object();
        if (p == null) p = window.originalScenario().object();
        RigidTransform pose = p != null ? p.worldFromObject()
            : s.worldFromPalm().compose(RigidTransform.translation(DEFAULT_POSITION[0], DEFAULT_POSITION[1], DEFAULT_POSITION[2]));
        Scenario.ObjectPlacement np = new Scenario.ObjectPlacement(abs, pose, p != null ? p.scale() : 1.0, p != null ? p.divisions() : 24);
        CompletableFuture<MeshSource.Model> loaded = window.loadObjectMesh(abs, np.divisions());
        return loaded.thenAccept(m -> {
            window.load(window.scenario().withObject(np));
            window.status("imported " + abs.getFileName() + " (" + m.mesh().triangleCount() + " triangles)", false);
        });
    }

    private void remove() {
        if (window.scenario().object() == null) {
            window.status("no object to remove", false);
            return;
        }
        window.load(window.scenario().withObject(null));
        file.setText("no object");
        window.status("object removed", false);
    }

    private void place() {
        Scenario.ObjectPlacement p = window.scenario().object();
        if (p == null) {
            window.status("import an object first", true);
            return;
        }
        try {
            double d = Math.PI / 180;
            RigidTransform pose = RigidTransform.fromPose(Widgets.number(x, "x"), Widgets.number(y, "y"), Widgets.number(z, "z"),
                d * Widgets.number(rx, "rotation x"), d * Widgets.number(ry, "rotation y"), d * Widgets.number(rz, "rotation z"));
            double sc = Widgets.number(scale, "scale");
            if (!(sc > 0)) throw new IllegalArgumentException("scale must be > 0, got " + sc);
            window.load(window.scenario().withObject(new Scenario.ObjectPlacement(p.file(), pose, sc, p.divisions())));
            window.status(String.format(Locale.ROOT, "object placed at (%.3f, %.3f, %.3f) m", pose.origin()[0], pose.origin()[1], pose.origin()[2]), false);
        } catch (IllegalArgumentException e) {
            window.status("object not placed: " + e.getMessage(), true);
        }
    }

    /** Shows a placement in the fields (called when the working scenario changes). */
    void showPlacement(Scenario.ObjectPlacement p) {
        if (p == null) return;
        double[] o = p.worldFromObject().origin();
        double[] r = rotationVector(p.worldFromObject());
        x.setText(Widgets.fmt(o[0], 4));
        y.setText(Widgets.fmt(o[1], 4));
        z.setText(Widgets.fmt(o[2], 4));
        rx.setText(Widgets.fmt(Math.toDegrees(r[0]), 2));
        ry.setText(Widgets.fmt(Math.toDegrees(r[1]), 2));
        rz.setText(Widgets.fmt(Math.toDegrees(r[2]), 2));
        scale.setText(Widgets.fmt(p.scale(), 4));
    }

    /** Shows the loaded mesh's name and size. */
    void showMesh(Path f, MeshSource.Model m) {
        file.setText(f.getFileName() + " — " + m.mesh().triangleCount() + " triangles");
    }

    /** The axis-angle vector of a placement's rotation, rad ({@link RigidTransform#rotationVector()}). */
    static double[] rotationVector(RigidTransform t) {
        return t.rotationVector();
    }
}
