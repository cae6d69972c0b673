package org.handsim.tradeoff;

import java.util.List;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import org.handsim.body.BoxMesh;
import org.handsim.body.FreeBody;
import org.handsim.body.MassProperties;
import org.handsim.chart.StudyTable;
import org.handsim.dynamics.TorqueFreeRotation;
import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;

/**
 * Chart 6, the free object's step without contact: the time step against the error of a
 * torque-free tumble. An asymmetric box (100 × 60 × 30 mm, 800 kg/m³: principal moments
 * 1 : 2.4 : 3.0) spun at ω = (0.3, 4, −0.5) rad/s (body axes), near its unstable middle axis, so
 * it turns over, for 2 s ({@link FreeBody}: a fourth-order Lie–Poisson integrator). Three
 * errors at the end, against:
 * <ul>
 *   <li>the conservation laws: the kinetic energy and the angular momentum (relative; the
 *       integrator keeps both by construction, so these are its rounding);</li>
 *   <li>an independent integration: Euler's equations I ω̇ = −ω × Iω in the body frame with
 *       q̇ = ½ q ⊗ (0, ω), by Dormand–Prince 5(4) at tolerance 1e-13 (a different method on a
 *       different formulation): the angle between the two orientations (rad).</li>
 * </ul>
 * x: dt (s, log); y: the error (log). The CSV also has the worst energy error over the run and
 * the wall time of the 2 s. Default: dt = 1 ms, the simulator's.
 */
public final class BodyTumbleStudy implements Study {
    static final double[] DTS = {0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1};
    static final double[] QUICK_DTS = {0.001, 0.01, 0.1};
    static final double DEFAULT_DT = 0.001, DURATION = 2;
    static final MassProperties BOX = MassProperties.ofSolid(BoxMesh.of("box", 0.1, 0.06, 0.03), 800);
    static final double[] W0_BODY = {0.3, 4.0, -0.5}, TURN0 = {0.4, -0.3, 0.8};
    static final String ENERGY = "energy (relative)", MOMENTUM = "angular momentum (relative)", ORIENTATION = "orientation vs Euler's equations (rad)";
    static final List<String> COLUMNS = List.of("dt_s", "error", "worst_energy", "wall_s");

    @Override
    public String id() {
        return "6-body-tumble";
    }

    /** What one run measured: relative energy and momentum errors at the end, the worst energy error, the orientation error (rad), wall s. */
    record Measure(double energy, double momentum, double worstEnergy, double orientation, double wall) {}

    static FreeBody tumbler() {
        FreeBody b = new FreeBody(BOX, RigidTransform.fromPose(0, 0, 0, TURN0[0], TURN0[1], TURN0[2]));
        double[] r = new double[9], q = b.orientation(new double[4]), w = new double[3];
        Quaternion.toMatrix(q, 0, r, 0);
        for (int i = 0; i < 3; i++) w[i] = r[3 * i] * W0_BODY[0] + r[3 * i + 1] * W0_BODY[1] + r[3 * i + 2] * W0_BODY[2];
        b.setVelocity(new double[3], w);
        return b;
    }

    static Measure run(double dt, double[] reference) {
        FreeBody b = tumbler();
        double e0 = b.kineticEnergy();
        double[] l0 = b.angularMomentum(new double[3]), l = new double[3], zero = new double[3];
        double worst = 0;
        long n = Math.round(DURATION / dt);
        long t0 = System.nanoTime();
        for (long i = 0; i < n; i++) {
            b.step(dt, zero, zero);
            worst = Math.max(worst, Math.abs(b.kineticEnergy() - e0) / e0);
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        b.angularMomentum(l);
        double dl = Math.sqrt(sq(l[0] - l0[0]) + sq(l[1] - l0[1]) + sq(l[2] - l0[2])) / Math.sqrt(sq(l0[0]) + sq(l0[1]) + sq(l0[2]));
        double err = Quaternion.angleBetween(reference, 0, b.orientation(new double[4]), 0);
        return new Measure(Math.abs(b.kineticEnergy() - e0) / e0, dl, worst, err, wall);
    }

    /** The orientation after {@code t} by Euler's equations, integrated apart from the free body's own step. */
    static double[] reference(double t) {
        double[] q0 = new double[4];
        Quaternion.fromRotationVector(TURN0[0], TURN0[1], TURN0[2], q0, 0);
        return TorqueFreeRotation.orientationAfter(BOX.inertia(), BOX.inverseInertia(), W0_BODY, q0, t);
    }

    private static double sq(double a) { return a * a; }

    @Override
    public StudyTable run(boolean quick, DoubleConsumer progress) {
        double[] dts = quick ? QUICK_DTS : DTS;
        StudyTable t = new StudyTable(id(), "Free object, no contact: time step against the error of a torque-free tumble (2 s)", COLUMNS,
            "dt_s", "error", "time step dt (s, log)", "error after 2 s (relative; rad, log)").paretoFront(false);
        double[] p = BOX.principalMoments();
        t.note("setup", String.format(Locale.ROOT,
            "box 100 x 60 x 30 mm, 800 kg/m3, principal moments %.3g, %.3g, %.3g kg m2; w0 = (0.3, 4, -0.5) rad/s (body), near the unstable"
                + " middle axis; torque-free for 2 s", p[0], p[1], p[2]));
        t.note("reference", "orientation against Euler's equations with quaternion rates by Dormand-Prince 5(4) at 1e-13; energy and angular"
            + " momentum against their starting values (kept by the integrator: what is left is rounding)");
        t.note("default", "default: dt = 1 ms (the simulator's)");
        double[] ref = reference(DURATION);
        for (int i = 0; i < (quick ? 1 : 5); i++) run(0.01, ref);   // warm the JIT before timing
        int done = 0;
        StringBuilder failed = new StringBuilder();
        for (double dt : dts) {
            boolean def = dt == DEFAULT_DT;
            try {
                Measure m = run(dt, ref);
                t.add(ENERGY, DtStudy.ms(dt), def, dt, m.energy(), m.worstEnergy(), m.wall());
                t.add(MOMENTUM, DtStudy.ms(dt), def, dt, m.momentum(), m.worstEnergy(), m.wall());
                t.add(ORIENTATION, DtStudy.ms(dt), def, dt, m.orientation(), m.worstEnergy(), m.wall());
            } catch (IllegalStateException e) {
                failed.append(failed.length() == 0 ? "" : "; ").append(DtStudy.ms(dt)).append(": ").append(e.getMessage());
            }
            if (progress != null) progress.accept((double) ++done / dts.length);
        }
        if (failed.length() > 0) t.note("failed", "not plotted, the step refused: " + failed);
        return t;
    }
}
