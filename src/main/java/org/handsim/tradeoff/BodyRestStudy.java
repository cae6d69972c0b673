package org.handsim.tradeoff;

import java.util.Locale;
import java.util.function.DoubleConsumer;
import org.handsim.body.BodyScene;
import org.handsim.body.BoxMesh;
import org.handsim.body.ContactSolver;
import org.handsim.body.MassProperties;
import org.handsim.body.ProximityContacts;
import org.handsim.chart.StudyTable;
import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;

/**
 * Chart 5, where the free object's step fails in contact: the time step against the drift and
 * the penetration of a box on a table ({@link BodyScene}: proximity contacts within the margin
 * δ = 1 mm, exact Coulomb cones, μ = 0.5, gravity 9.80665 m/s²). Two cases per dt:
 * <ul>
 *   <li><b>resting</b>: the box (60 × 40 × 20 mm, 1000 kg/m³) placed touching the table and left
 *       for 10 s: y = the drift of its centre of mass (m); the CSV has its rotation (rad) and the
 *       deepest penetration over the run;</li>
 *   <li><b>dropped</b> from 10 mm above the table (lands at √(2g·0.01) = 0.443 m/s), and from
 *       7 more heights up to 11.75 mm (steps of 0.25 mm, so that where the last step before the
 *       table starts varies over more than a step's travel), each left until 0.5 s: y = the
 *       deepest penetration over the runs (m), the depth of the box's lowest corner below the
 *       table's top at a step's end, found from the pose (exact for a box on a flat table, and
 *       independent of what the proximity query reports); the other columns are the 10 mm
 *       drop's. A step that carries the box further than δ tunnels ({@code tunnelling_steps});
 *       one that carries it past the deepest penetration the query reports (5δ) lets it through
 *       the table: {@code fell_through} (any of the drops).</li>
 * </ul>
 * x: dt (s, log). The wall time of each run (one run, no repeats: a run is 10⁴–10⁵ steps) is in
 * the CSV as {@code wall_s_per_sim_s} (wall time per simulated second). Default: dt = 1 ms, the
 * simulator's.
 */
public final class BodyRestStudy implements Study {
    static final double[] DTS = {0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02};
    static final double[] QUICK_DTS = {0.001, 0.005, 0.02};
    static final double DEFAULT_DT = 0.001, REST_S = 10, QUICK_REST_S = 1, DROP_S = 0.5, DROP_M = 0.01, DROP_STEP_M = 0.00025, DROPS = 8, MU = 0.5;
    static final double HX = 0.03, HY = 0.02, HZ = 0.01;
    static final TriangleMesh BOX = BoxMesh.of("box", 2 * HX, 2 * HY, 2 * HZ), TABLE = BoxMesh.of("table", 0.8, 0.6, 0.02);
    static final String RESTING = "resting 10 s: drift", DROPPED = "dropped 10-11.75 mm: deepest penetration";
    static final java.util.List<String> COLUMNS = java.util.List.of("dt_s", "error_m", "drift_m", "rotation_rad", "penetration_m",
        "tunnelling_steps", "fell_through", "wall_s_per_sim_s");

    @Override
    public String id() {
        return "5-body-rest";
    }

    /** What one run measured. */
    record Measure(double drift, double rotation, double penetration, long tunnelling, boolean fellThrough, double wallPerSecond) {}

    /** The box with its bottom {@code heightM} above the table's top (z = 0), at rest, run for {@code seconds} at dt. */
    static Measure run(double dt, double heightM, double seconds) {
        BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), RigidTransform.fromPose(0, 0, HZ + heightM, 0, 0, 0)).friction(MU);
        s.addSupport(TABLE, RigidTransform.fromPose(0, 0, -0.01, 0, 0, 0));
        double[] x0 = s.body().position(new double[3]), q0 = s.body().orientation(new double[4]);
        double[] pose = new double[12];
        double deepest = 0;
        long n = Math.round(seconds / dt);
        long t0 = System.nanoTime();
        for (long i = 0; i < n; i++) {
            ContactSolver.Outcome o = s.step(dt);
            if (o != ContactSolver.Outcome.CONVERGED) {
                throw new IllegalStateException(String.format(Locale.ROOT, "dt %s: the contact solve ended %s at t = %.4f s", DtStudy.ms(dt), o, (i + 1) * dt));
            }
            deepest = Math.max(deepest, -lowestCorner(s.body().worldFromMesh(pose, 0)));
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        double[] x = s.body().position(new double[3]);
        double drift = Math.sqrt(sq(x[0] - x0[0]) + sq(x[1] - x0[1]) + sq(x[2] - x0[2] + heightM));
        double turned = Quaternion.angleBetween(q0, 0, s.body().orientation(new double[4]), 0);
        boolean through = x[2] < -HZ;
        return new Measure(drift, turned, deepest, s.tunnelling().steps(), through, wall / seconds);
    }

    /** z of the box's lowest corner, world (m), for the mesh pose {@code m} (12 values, row-major). */
    static double lowestCorner(double[] m) {
        double low = Double.POSITIVE_INFINITY;
        for (int c = 0; c < 8; c++) {
            double px = (c & 1) != 0 ? HX : -HX, py = (c & 2) != 0 ? HY : -HY, pz = (c & 4) != 0 ? HZ : -HZ;
            low = Math.min(low, m[8] * px + m[9] * py + m[10] * pz + m[11]);
        }
        return low;
    }

    private static double sq(double a) { return a * a; }

    @Override
    public StudyTable run(boolean quick, DoubleConsumer progress) {
        double[] dts = quick ? QUICK_DTS : DTS;
        double rest = quick ? QUICK_REST_S : REST_S;
        StudyTable t = new StudyTable(id(), "Free object in contact: time step against drift and penetration (box on a table)", COLUMNS,
            "dt_s", "error_m", "time step dt (s, log)", "drift, penetration (m, log)").paretoFront(false);
        t.note("setup", String.format(Locale.ROOT,
            "box 60 x 40 x 20 mm, 1000 kg/m3 (%.3f kg) on a table, mu %.1f, contact margin %.0f mm (deepest penetration reported %.0f mm),"
                + " g 9.80665 m/s2; resting: placed touching, %.0f s; dropped: from 10, 10.25, ..., 11.75 mm (0.443 m/s at the table), %.1f s each",
            MassProperties.ofSolid(BOX, 1000).mass(), MU, 1e3 * ProximityContacts.DEFAULT_MARGIN, 5e3 * ProximityContacts.DEFAULT_MARGIN, rest, DROP_S));
        t.note("measures", "drift = |x(end) - x(start)| of the centre of mass (dropped: from where it rests); penetration = deepest of"
            + " the box's lowest corner below the table's top at the steps' ends, from the pose (dropped: over the 8 heights); tunnelling_steps = steps in which a point moved more than the margin;"
            + " fell_through = 1 if the box ended below the table's top by more than its half height");
        t.note("default", "default: dt = 1 ms (the simulator's)");
        // warm the JIT on the step before the first timed run
        run(DEFAULT_DT, 0, quick ? 0.05 : 0.5);
        int done = 0;
        StringBuilder through = new StringBuilder();
        for (double dt : dts) {
            Measure r = run(dt, 0, rest), d = run(dt, DROP_M, DROP_S);
            double deepest = d.penetration();
            boolean fell = d.fellThrough();
            for (int k = 1; k < DROPS; k++) {
                Measure e = run(dt, DROP_M + k * DROP_STEP_M, DROP_S);
                deepest = Math.max(deepest, e.penetration());
                fell |= e.fellThrough();
            }
            boolean def = dt == DEFAULT_DT;
            t.add(RESTING, DtStudy.ms(dt), def, dt, r.drift(), r.drift(), r.rotation(), r.penetration(), r.tunnelling(), r.fellThrough() ? 1 : 0, r.wallPerSecond());
            // a box that fell through has no depth to plot: the CSV keeps it, the chart skips it
            t.add(DROPPED, DtStudy.ms(dt), def, dt, fell ? Double.NaN : deepest, d.drift(), d.rotation(), deepest,
                d.tunnelling(), fell ? 1 : 0, d.wallPerSecond());
            if (fell) through.append(through.length() == 0 ? "" : ", ").append(DtStudy.ms(dt));
            if (progress != null) progress.accept((double) ++done / dts.length);
        }
        if (through.length() > 0) t.note("fell", "dropped box fell through the table (not plotted): dt " + through);
        return t;
    }
}
