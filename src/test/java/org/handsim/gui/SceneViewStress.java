package org.handsim.gui;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import org.handsim.math.RigidTransform;
import org.jogamp.java3d.GeometryArray;

/**
 * A child JVM's program for {@link SceneViewLinesTest}: opens a {@link SceneView} in a frame,
 * turns the friction cones on and shows {@code args[0]} poses with contacts, one per call on the
 * event dispatch thread, each after a random pause of up to {@code args[1]} ns (seeded), so that
 * Java3D's threads handle the scene graph's messages while the next pose is written. Prints
 * {@code stress: N poses shown, E exceptions on Java3D threads, W of G geometry arrays written
 * while live} (G: the view's geometry arrays, {@link #geometryArrays}; W: those a write reached
 * while live, {@link Java3dMessages}) and halts with exit code 0 when E and W are 0, 1 otherwise
 * (halts: a Java3D thread that died would keep {@code SimpleUniverse.cleanup()} waiting for ever).
 */
final class SceneViewStress {
    private SceneViewStress() {}

    /**
     * Every geometry array the view keeps in a field, directly or in a
     * {@link DoubleBufferedLines}: the ones it may rewrite after they went live.
     */
    static List<GeometryArray> geometryArrays(SceneView view) throws IllegalAccessException {
        List<GeometryArray> out = new ArrayList<>();
        for (Field f : SceneView.class.getDeclaredFields()) {
            if (Modifier.isStatic(f.getModifiers())) continue;
            f.setAccessible(true);
            Object o = f.get(view);
            if (o instanceof GeometryArray g) out.add(g);
            if (o instanceof DoubleBufferedLines d) {
                out.add(d.shown());
                out.add(d.spare());
            }
        }
        return out;
    }

    public static void main(String[] args) throws Exception {
        int poses = Integer.parseInt(args[0]);
        int pauseNanos = args.length > 1 ? Integer.parseInt(args[1]) : 500_000;
        List<String> errors = new ArrayList<>();
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
            synchronized (errors) {
                errors.add(t.getName() + ": " + e);
            }
            System.out.println("stress: uncaught exception on thread " + t.getName() + ": " + e);
            e.printStackTrace(System.out);
        });
        MeshSource.Model[] hand = HandSimPanel.loadHand();
        SceneView[] v = new SceneView[1];
        SwingUtilities.invokeAndWait(() -> {
            v[0] = new SceneView(hand[0], new MeshSource.Model[] {hand[1], hand[2], hand[3]});
            JFrame f = new JFrame("stress");
            f.add(v[0].canvas());
            f.setSize(640, 480);
            f.setVisible(true);
        });
        long deadline = System.currentTimeMillis() + 120_000;
        while (v[0].framesRendered() == 0 && System.currentTimeMillis() < deadline) Thread.sleep(10);
        SwingUtilities.invokeAndWait(() -> v[0].setVisible(SceneView.Part.CONES, true));
        Pose base = Pose.ofJoints(new double[][] {{0, 0.6, 0.4}, {0, 0.6, 0.4}, {0, 0.6, 0.4}}, RigidTransform.IDENTITY);
        Random r = new Random(20261128L);
        Pose[] set = new Pose[16];
        for (int s = 0; s < set.length; s++) {
            int n = 1 + r.nextInt(12);
            double[] p = new double[3 * n], nn = new double[3 * n], force = new double[n];
            int[] fingers = new int[n];
            for (int i = 0; i < n; i++) {
                for (int c = 0; c < 3; c++) {
                    p[3 * i + c] = 0.05 * r.nextGaussian() + (c == 2 ? 0.1 : 0);
                    nn[3 * i + c] = r.nextGaussian();
                }
                fingers[i] = 1 + i % 3;
            }
            set[s] = new Pose(base.worldFromPalm(), base.framesWorld(), p, nn, force, fingers, null, null, null);
        }
        int shown = 0;
        while (shown < poses) {
            synchronized (errors) {
                if (!errors.isEmpty()) break;
            }
            int from = shown;
            SwingUtilities.invokeAndWait(() -> v[0].show(set[from % set.length]));
            shown++;
            java.util.concurrent.locks.LockSupport.parkNanos(r.nextInt(pauseNanos + 1));
        }
        Thread.sleep(500);   // the last batch's messages reach Java3D's threads
        int e;
        synchronized (errors) {
            e = errors.size();
        }
        List<GeometryArray> arrays = geometryArrays(v[0]);
        int written = 0;
        for (GeometryArray g : arrays) if (Java3dMessages.sentDataChanged(g)) written++;
        System.out.println("stress: " + shown + " poses shown, " + e + " exceptions on Java3D threads, "
            + written + " of " + arrays.size() + " geometry arrays written while live");
        System.out.flush();
        Runtime.getRuntime().halt(e == 0 && written == 0 ? 0 : 1);
    }
}
