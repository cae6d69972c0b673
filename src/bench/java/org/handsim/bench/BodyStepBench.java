package org.handsim.bench;

import java.util.Arrays;
import java.util.Locale;
import org.handsim.body.BodyScene;
import org.handsim.body.ContactSolver;
import org.handsim.body.MassProperties;
import org.handsim.hold.HoldReport;
import org.handsim.hold.HoldTest;
import org.handsim.hold.LockedGrasp;
import org.handsim.hold.ObjectMass;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.HandModel;
import org.handsim.model.SceneGeometry;
import org.handsim.model.Simulation;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;

/**
 * Suite "body-step": the free object's whole step (proximity contacts against every body of the
 * hand, the convex problem with the pressing joints, the exact Coulomb solve, the integration) on
 * the mug grasp with the mug free — {@code scenarios/mug-grasp.json} closed until every finger
 * stalls, the hand locked as the hold test locks it ({@link LockedGrasp}: each flexion joint
 * pressing with what the closing left in it and held by its worm), the mug released with 0.1 kg
 * (the MuJoCo anchor's mass) under gravity, dt = 1 ms — the scene {@code tools/mujoco-step}
 * times in MuJoCo. After 1 s of settling, every step of the next 5 s is timed on its own
 * (wall, {@code System.nanoTime}): the median over the run, its quartiles and the contacts per
 * step; and the thread's CPU time per step as the median of 11 batches.
 *
 * <p>Then the same on {@code scenarios/mug-lift.json} as {@code handsim run} steps it: every
 * {@code HandModel.step()} from the mug's release to the end of the scenario timed on its own
 * (the hand's motors and moves, the link poses, the free object's contacts with the palm and
 * the nine links, its convex problem with the pressing joints, the clutches), the median over
 * the run, after two untimed runs of the whole scenario (the JIT), with the thread's CPU time and
 * the bytes it allocated per step over those steps. Suite "mug-lift-step" runs that part alone.
 */
final class BodyStepBench implements BenchMain.Suite {
    static final double DT = 0.001, SETTLE_S = 1, RUN_S = 5, MASS_KG = 0.1;

    @Override
    public void run() throws Exception {
        BodyScene scene = mugGrasp();
        for (int i = 0; i < Math.round(SETTLE_S / DT); i++) scene.step(DT);
        double[] x0 = scene.body().position(new double[3]);
        int n = (int) Math.round(RUN_S / DT);
        long[] ns = new long[n];
        int[] contacts = new int[n];
        int unconverged = 0;
        com.sun.management.ThreadMXBean tb = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long b0 = tb.getCurrentThreadAllocatedBytes();
        for (int i = 0; i < n; i++) {
            long a = System.nanoTime();
            ContactSolver.Outcome o = scene.step(DT);
            ns[i] = System.nanoTime() - a;
            contacts[i] = scene.contacts().size();
            if (o != ContactSolver.Outcome.CONVERGED) unconverged++;
        }
        long bytes = tb.getCurrentThreadAllocatedBytes() - b0;
        double[] x1 = scene.body().position(new double[3]);
        Arrays.sort(ns);
        Arrays.sort(contacts);
        double cpu = BodyBench.cpuMedianUs(() -> { scene.step(DT); return scene.contacts().size(); }, 300, 11, 50);
        double moved = Math.sqrt(sq(x1[0] - x0[0]) + sq(x1[1] - x0[1]) + sq(x1[2] - x0[2]));
        System.out.printf(Locale.ROOT, "mug grasp, mug free (0.1 kg, gravity), dt 1 ms, %d steps after %.0f s of settling:%n", n, SETTLE_S);
        System.out.printf(Locale.ROOT, "  wall per step: median %s (quartiles %s, %s; 95th %s)%n", Bench.human(ns[n / 2]), Bench.human(ns[n / 4]),
            Bench.human(ns[3 * n / 4]), Bench.human(ns[(int) (0.95 * n)]));
        System.out.printf(Locale.ROOT, "  thread CPU per step: median of 11 batches %s%n", Bench.human(1e3 * cpu));
        System.out.printf(Locale.ROOT, "  contacts per step: median %d (%d-%d); solves not converged: %d; the mug moved %.3g mm over the run%n",
            contacts[n / 2], contacts[0], contacts[n - 1], unconverged, 1e3 * moved);
        System.out.printf(Locale.ROOT, "  allocated over the run: %.1f bytes/step%n", bytes / (double) n);
        mugLift();
    }

    /**
     * Each HandModel step of mug-lift.json after the release, timed on its own; the third run of
     * three. With it, over the same steps of that run, the thread's CPU time and the bytes it
     * allocated ({@code ThreadMXBean}), per step: the hot loop should allocate nothing.
     */
    static void mugLift() {
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-lift.json"));
        com.sun.management.ThreadMXBean tb = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long[] ns = null;
        int n = 0;
        long cpu = 0, bytes = 0;
        for (int round = 0; round < 3; round++) {
            HandModel m = Simulation.model(s, false);
            ns = new long[(int) Math.round(s.duration() / s.dt()) + 2];
            n = 0;
            while (m.running() && Double.isNaN(m.objectReleasedAt())) m.step();
            long c0 = tb.getCurrentThreadCpuTime(), b0 = tb.getCurrentThreadAllocatedBytes();
            while (m.running()) {
                long a = System.nanoTime();
                freeStep(m);
                long b = System.nanoTime() - a;
                if (n < ns.length) ns[n++] = b;
            }
            cpu = tb.getCurrentThreadCpuTime() - c0;
            bytes = tb.getCurrentThreadAllocatedBytes() - b0;
        }
        long[] t = Arrays.copyOf(ns, n);
        Arrays.sort(t);
        System.out.printf(Locale.ROOT, "mug-lift.json, HandModel.step() after the release, %d steps: median %s (quartiles %s, %s; 95th %s)%n", n,
            Bench.human(t[n / 2]), Bench.human(t[n / 4]), Bench.human(t[3 * n / 4]), Bench.human(t[(int) (0.95 * n)]));
        System.out.printf(Locale.ROOT, "  thread CPU per step (mean over the run) %s; allocated %.1f bytes/step%n", Bench.human(cpu / (double) n),
            bytes / (double) n);
    }

    /** A step after the release: its own frame, so a profile of the bench tells it from the closing's steps. */
    private static void freeStep(HandModel m) {
        m.step();
    }

    /** The mug grasp closed and locked, the mug free under gravity: the hold test's scene without a push. */
    static BodyScene mugGrasp() {
        Scenario s = Scenario.load(Home.scenarios().resolve("mug-grasp.json"));
        SceneGeometry g = new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K);
        HandModel m = Simulation.model(s, g);
        HoldReport.close(m);
        MassProperties props = ObjectMass.of(g.objectMesh(), MASS_KG, Double.NaN);
        LockedGrasp grasp = LockedGrasp.of(m, g, props);
        BodyScene scene = new BodyScene(grasp.objectMesh(), props, grasp.worldFromObjectTransform());
        for (int b = 0; b < LockedGrasp.BODIES; b++) {
            TriangleMesh mesh = grasp.mesh(b);
            scene.addSupport(mesh, RigidTransform.of(grasp.pose(b)));
        }
        // as HoldTest presses: an engaged clutch carries at most τ_break; the preload lets go over a contact's compliance
        for (int k = 1; k <= 3; k++) {
            for (int j = 2; j <= 3; j++) {
                double[] jt = grasp.joint(k, j);
                double press = j == 2 && grasp.clutchEngaged(k) ? Math.min(jt[7], grasp.tauBreak()) : jt[7];
                double release = press > 0 && jt[8] > 0 ? press / (HoldTest.CONTACT_STIFFNESS_N_M * jt[8] * jt[8]) : Double.POSITIVE_INFINITY;
                int id = scene.addJoint(new double[] {jt[0], jt[1], jt[2]}, new double[] {jt[3], jt[4], jt[5]}, jt[6], press, true, release);
                for (int link = j; link <= 3; link++) scene.moves(id, LockedGrasp.body(k, link));
            }
        }
        double[] gr = grasp.gravity();
        scene.friction(grasp.friction()).gravity(gr[0], gr[1], gr[2]);
        return scene;
    }

    private static double sq(double a) { return a * a; }
}
