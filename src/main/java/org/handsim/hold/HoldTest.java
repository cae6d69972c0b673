package org.handsim.hold;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.handsim.body.BodyContacts;
import org.handsim.body.BodyScene;
import org.handsim.body.ContactSolver;
import org.handsim.body.FreeBody;
import org.handsim.body.MeshTopology;
import org.handsim.body.ProximityContacts;
import org.handsim.collision.KdopTree;
import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.SceneGeometry;

/**
 * The six-direction hold test on a locked grasp (the protocol of DexGraspBench, DexGraspNet,
 * MultiGripperGrasp and GraspGen): release the object and let it settle, then, from that same
 * settled state each time, push its centre of mass with a force F along −x, +x, −y, +y, −z, +z
 * of the world in turn for T seconds, and call the direction held if the object moved less than
 * the displacement threshold and turned less than the rotation threshold (from the settled
 * state) at every step. The object is the free body of {@code org.handsim.body}
 * ({@link BodyScene}: one convex contact problem per step, exact Coulomb cones, contact points
 * by proximity) among the hand's ten bodies where the closing left them ({@link LockedGrasp}).
 *
 * <p><b>The locked hand</b> (DESIGN.md decision 8). Every finger joint is held by its worm: no
 * load opens it. The closing leaves the contacts squeezed — the forces the simulation gave
 * them, which a rigid link held by a worm keeps as an elastic preload — so each flexion joint
 * k2, k3 presses on the object with the torque those forces make about it (a
 * {@link BodyScene#addJoint} follower, at rest each step, closing only), and the preload is let
 * go as the joint turns closing: linearly over the angle τ/(k·r²) (k =
 * {@link #CONTACT_STIFFNESS_N_M}, r its farthest contact's distance from the axis), the travel
 * over which contacts of that stiffness unload. The links it carries turn with it (by
 * micro-radians to milliradians), so a link that closed into a gap stays there. Without the
 * press a rigid grasp has no squeeze: friction needs normal force, and a pinch whose fingers
 * only touch holds nothing across. Without the letting go, a press that never ends would push a
 * released object on for ever.
 *
 * <p><b>Settling.</b> The forces a closing on a fixed object leaves need not balance (the fixed
 * object took the rest), so the freed object first moves: it is stepped with no push until it
 * is at rest ({@link #REST_SPEED_M_S}, {@link #REST_SPIN_RAD_S} over {@link #REST_WINDOW_S}),
 * at most {@link #SETTLE_MAX_S}; if it crossed a threshold or flew off meanwhile, it was
 * dropped on release and every direction fails.
 *
 * <p><b>Work saved, results unchanged or bounded.</b>
 * <ul>
 *   <li><i>Free flight</i>: once the object touches nothing and, for every body of the hand,
 *       its centre of mass is moving away from that body's bounding sphere and accelerating
 *       away from it (Δ·v ≥ 0, Δ·a ≥ 0, v·a ≥ 0 with Δ from the sphere's centre, a constant),
 *       the distance can only grow, so no contact can come back: the rest of the push is
 *       stepped without proximity queries — the same steps to the bit
 *       ({@link FreeBody#step} is the contact-free step).</li>
 *   <li><i>Settled</i>: once the object's step velocity has stayed below {@link #REST_SPEED_M_S}
 *       and its spin below {@link #REST_SPIN_RAD_S} for {@link #REST_WINDOW_S} with the same
 *       number of contacts, what it can still do in the time t left is bounded: its speed was
 *       below v over the window, so its acceleration (taken constant) is below 2v/W, and it moves
 *       less than v·t + (v/W)·t² (0.74 mm over 1.9 s) and turns less than ω·t + (ω/W)·t² (4.2°);
 *       when that cannot carry it past a threshold the push stops there, passed, and says so
 *       ({@link DirectionResult#settledS}, the bounds). A held object creeps at a few µm/s and
 *       hundredths of a mrad/s here (the contact solver's regularised friction), so this is
 *       where most held pushes end, some 0.1 s in.</li>
 *   <li><i>Creeping</i>: a held push whose object never gets that still — it creeps at
 *       1–2 × 10⁻⁵ m/s for the whole 2 s, a link's contact sliding under its press — is judged
 *       from {@link #CREEP_AFTER_S} on, window by window, with the same bound taken at the
 *       window's own largest speed and spin, but only while nothing says the creep will grow:
 *       neither is above the last window's, no clutch slipped in the window, and every engaged
 *       clutch's torque, its rise over the window carried on to the push's end, stays within
 *       τ_break. A clutch that lets go is how a creeping grasp fails after all: two of the
 *       LP-consistency pushes creep by micrometres for a second while a clutch slips, then
 *       turn 15°, and without the slip guard the test would call them held (the other two
 *       guards bound no push measured; they cover a creep that speeds up, or a clutch on its
 *       way to τ_break, before either shows).</li>
 *   <li><i>Verdict only</i> ({@link #push(int, boolean)} with {@code verdictOnly}): a failed
 *       direction stops at the step that crosses a threshold (the planner's rows need only the
 *       verdict and the margin, which do not depend on what comes after).</li>
 * </ul>
 *
 * <p>One instance per grasp and thread (its scene's scratch); allocation per step: none once
 * the contact buffers have grown (samples are kept in arrays made per push).
 */
public final class HoldTest {
    /** The directions in the protocol's order. */
    public static final List<String> DIRECTIONS = List.of("-x", "+x", "-y", "+y", "-z", "+z");
    private static final double[][] UNITS = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    /** The rest test's speed of the centre of mass, m/s. */
    public static final double REST_SPEED_M_S = 1e-5;
    /** The rest test's angular speed, rad/s. */
    public static final double REST_SPIN_RAD_S = 1e-3;
    /** How long the rest test waits, s. */
    public static final double REST_WINDOW_S = 0.05;
    /** When the creep test starts to judge a push that has not come to rest, s into it. */
    public static final double CREEP_AFTER_S = 0.5;
    /** Interval of the samples kept for the chart and the CSV, s. */
    public static final double SAMPLE_S = 0.01;

    /**
     * The contacts' stiffness that holds a locked joint's preload, N/m: the softest of DESIGN.md
     * decision 5's range (1e5–1e6 N/m), so the preload lasts over the longest travel.
     */
    public static final double CONTACT_STIFFNESS_N_M = 1e5;
    private final LockedGrasp grasp;
    private final HoldSettings settings;
    private final BodyScene scene;
    private final double[] release;
    private double[] settledPose, settledTurns;
    private final Run settle;
    private final boolean dropped;
    /** The longest the object is left to settle after its release, s. */
    public static final double SETTLE_MAX_S = 1;
    private final double[][] spheres = new double[LockedGrasp.BODIES][];
    /** Per joint of the scene: its press, N·m, its release angle, rad, and whether an engaged clutch holds it (it may slip). */
    private final double[] jointPress = new double[6], jointRelease = new double[6];
    private final boolean[] jointSlips = new boolean[6];
    private final double[] jointArm = new double[6], pressNow = new double[6];
    private final boolean[] slipping = new boolean[6];
    private final double objectRadius;
    private final double[] x = new double[3], q = new double[4], v = new double[3], w = new double[3];
    private final double[] zero = new double[3], force = new double[3], torque = new double[3], accel = new double[3], flight = new double[3];

    /** A test of {@code grasp} with {@code settings}; builds its scene (trees and topologies of shared meshes are cached). */
    public HoldTest(LockedGrasp grasp, HoldSettings settings) {
        this.grasp = grasp;
        this.settings = settings;
        TriangleMesh om = grasp.objectMesh();
        this.release = grasp.worldFromObject();
        this.scene = new BodyScene(Shapes.tree(om), Shapes.topology(om), grasp.mass(), RigidTransform.of(release));
        for (int b = 0; b < LockedGrasp.BODIES; b++) {
            TriangleMesh m = grasp.mesh(b);
            double[] p = grasp.pose(b);
            scene.addSupport(Shapes.tree(m), Shapes.topology(m), RigidTransform.of(p));
            double[] s = SceneGeometry.boundingSphere(m);
            spheres[b] = new double[] {p[0] * s[0] + p[1] * s[1] + p[2] * s[2] + p[3], p[4] * s[0] + p[5] * s[1] + p[6] * s[2] + p[7],
                p[8] * s[0] + p[9] * s[1] + p[10] * s[2] + p[11], s[3]};
        }
        // every flexion joint presses as the closing left it and its worm holds it (the spread, back-drivable in
        // Barrett's hand but held here with the rest, and finger 3's fixed first link stay where they are)
        for (int k = 1; k <= 3; k++) {
            for (int j = 2; j <= 3; j++) {
                double[] jt = grasp.joint(k, j);
                // an engaged clutch carries at most τ_break: it presses with no more than that
                boolean slips = j == 2 && grasp.clutchEngaged(k);
                double press = slips ? Math.min(jt[7], grasp.tauBreak()) : jt[7];
                double releaseRad = press > 0 && jt[8] > 0 ? press / (CONTACT_STIFFNESS_N_M * jt[8] * jt[8]) : Double.POSITIVE_INFINITY;
                int id = scene.addJoint(new double[] {jt[0], jt[1], jt[2]}, new double[] {jt[3], jt[4], jt[5]}, jt[6], press, true,
                    releaseRad);
                jointPress[id] = press;
                jointRelease[id] = releaseRad;
                jointSlips[id] = slips;
                jointArm[id] = jt[8];
                for (int link = j; link <= 3; link++) scene.moves(id, LockedGrasp.body(k, link));
            }
        }
        double[] com = grasp.mass().centreOfMass(), vs = om.vertices();
        double r = 0;
        for (int i = 0; i < vs.length; i += 3) {
            double dx = vs[i] - com[0], dy = vs[i + 1] - com[1], dz = vs[i + 2] - com[2];
            r = Math.max(r, dx * dx + dy * dy + dz * dz);
        }
        this.objectRadius = Math.sqrt(r);
        scene.friction(grasp.friction());
        double[] g = settings.gravity() ? grasp.gravity() : new double[3];
        scene.gravity(g[0], g[1], g[2]);
        settledPose = release.clone();
        settledTurns = scene.jointTurns();
        settle = new Run(zero, 0, Double.NaN, settings.maxDisplacementM(), Math.toRadians(settings.maxRotationDeg()), true);
        settle.settling = true;
        settle.go(Math.round(SETTLE_MAX_S / settings.dtS()));
        // dropped: it crossed a threshold, or it left the hand moving (at rest and touching nothing, nothing moved it)
        dropped = !settle.passed() || settle.free && !settle.slow;
        scene.body().worldFromMesh(settledPose, 0);
        settledTurns = scene.jointTurns();
    }

    /**
     * How the object settled after its release, before any push: the displacement and rotation
     * (m, degrees) of the settling from the pose at release, how long it took (s), and whether it
     * dropped instead (it crossed a threshold or flew off: then no push can hold it), and how
     * many of its steps did not settle Coulomb's fixed point ({@link DirectionResult#unconvergedSteps}).
     */
    public double[] settling() {
        return new double[] {settle.maxD, Math.toDegrees(settle.maxR), settle.simulated, dropped ? 1 : 0, settle.unconverged};
    }

    /** The object left the hand while it settled: every direction fails. */
    public boolean droppedOnRelease() { return dropped; }

    /** The grasp tested. */
    public LockedGrasp grasp() { return grasp; }

    /** The settings. */
    public HoldSettings settings() { return settings; }

    /** F of this test, N. */
    public double forceN() { return settings.force(grasp.mass().mass()); }

    /** The six directions, in {@link #DIRECTIONS}' order, each pushed to the end. */
    public List<DirectionResult> run() {
        List<DirectionResult> out = new ArrayList<>(6);
        for (int d = 0; d < 6; d++) out.add(push(d, false));
        return out;
    }

    /** The six directions' ramps, in {@link #DIRECTIONS}' order. */
    public List<RampResult> ramps() {
        List<RampResult> out = new ArrayList<>(6);
        for (int d = 0; d < 6; d++) out.add(ramp(DIRECTIONS.get(d), UNITS[d]));
        return out;
    }

    /** The unit vector of direction d (index into {@link #DIRECTIONS}), world; a copy. */
    public static double[] unit(int d) { return UNITS[d].clone(); }

    /**
     * Pushes along direction d (index into {@link #DIRECTIONS}) from the released state.
     *
     * @param verdictOnly stop as soon as the verdict is known (a threshold crossed)
     */
    public DirectionResult push(int d, boolean verdictOnly) {
        return push(DIRECTIONS.get(d), UNITS[d], forceN(), verdictOnly);
    }

    /** Pushes along any unit direction u (world) with a constant force f, N, from the released state. */
    public DirectionResult push(String name, double[] u, double f, boolean verdictOnly) {
        if (dropped) {
            return new DirectionResult(name, u.clone(), f, false, settle.maxD, Math.toDegrees(settle.maxR), settle.disp,
                Math.toDegrees(settle.rot), 1 - settle.ratio, 0, settle.lostAt, Double.NaN, 0, 0, List.of(), 0, 0,
                settle.times(), settle.displacements(), settle.rotations());
        }
        Run r = new Run(u, f, Double.NaN, settings.maxDisplacementM(), Math.toRadians(settings.maxRotationDeg()), verdictOnly);
        r.go(Math.round(settings.durationS() / settings.dtS()));
        return new DirectionResult(name, u.clone(), f, r.passed(), r.maxD, Math.toDegrees(r.maxR), r.disp, Math.toDegrees(r.rot),
            1 - r.ratio, r.crossedAt, r.lostAt, r.settledAt, r.boundD, Math.toDegrees(r.boundR), r.endContacts(), r.simulated,
            r.unconverged, r.times(), r.displacements(), r.rotations());
    }

    /**
     * The ramp along u (world): the force rises from 0 at the settings' rate until the object
     * has moved the ramp's displacement or turned its rotation, or the force reaches the ramp's
     * largest (then it held at least that).
     */
    public RampResult ramp(String name, double[] u) {
        if (dropped) {
            return new RampResult(name, u.clone(), 0, false, 0, 0, Math.toDegrees(settle.rot), settle.disp, settle.times(),
                settle.displacements(), settle.rotations());
        }
        double max = settings.rampMaxN(), rate = settings.rampRateNPerS();
        Run r = new Run(u, Double.NaN, rate, settings.rampDisplacementM(), Math.toRadians(settings.rampRotationDeg()), true);
        r.go((long) Math.ceil(max / rate / settings.dtS()));
        boolean held = r.passed();
        return new RampResult(name, u.clone(), held ? max : r.forceAtCrossing, held, r.forceAtRest, r.crossedAt, Math.toDegrees(r.rot),
            r.disp, r.times(), r.displacements(), r.rotations());
    }

    /**
     * One push simulated step by step: a constant force f, or a force rising at {@code rate}
     * (f NaN), capped at the ramp's largest.
     */
    private final class Run {
        final double[] u;
        final double f, rate, dispThr, rotThr;
        final boolean stopAtCrossing;
        final double h = settings.dtS();
        final int every = Math.max(1, (int) Math.round(SAMPLE_S / h));
        final long windowSteps = Math.max(1, Math.round(REST_WINDOW_S / h));
        double[] ts, ds, rs;
        int ns;
        double maxD, maxR, disp, rot, ratio, crossedAt = Double.NaN, lostAt = Double.NaN, settledAt = Double.NaN;
        double boundD, boundR, forceAtCrossing = Double.NaN, forceAtRest, simulated;
        long unconverged;
        boolean free, settling, slow;
        final double[] x0 = new double[3], q0 = new double[4];
        // the creep test's current window: largest speed, spin and clutch torques, the clutch torques at its start
        double winV, winW, lastWinV = -1, lastWinW = -1;
        boolean winSlip;
        final double[] winTau = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        final double[] winStartTau = {Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN}, lastTau = new double[6];

        Run(double[] u, double f, double rate, double dispThr, double rotThr, boolean stopAtCrossing) {
            this.u = u;
            this.f = f;
            this.rate = rate;
            this.dispThr = dispThr;
            this.rotThr = rotThr;
            this.stopAtCrossing = stopAtCrossing;
        }

        void go(long n) {
            FreeBody body = scene.body();
            for (int j = 0; j < 6; j++) {
                if (jointSlips[j] && pressNow[j] != jointPress[j] || slipping[j]) scene.setJoint(j, jointPress[j], true, jointRelease[j]);
                pressNow[j] = jointPress[j];
                slipping[j] = false;
            }
            scene.setJointTurns(settledTurns);
            body.setPose(settledPose);
            body.setVelocity(zero, zero);
            body.position(x0);
            body.orientation(q0);
            int samples = (int) (n / every) + 2;
            ts = new double[samples];
            ds = new double[samples];
            rs = new double[samples];
            ns = 1;
            double[] g = settings.gravity() ? grasp.gravity() : zero;
            double m = grasp.mass().mass();
            double restV = REST_SPEED_M_S, restW = REST_SPIN_RAD_S;
            long still = 0;
            int lastContacts = -1;
            long i = 0;
            while (i < n) {
                i++;
                double t = time(i);
                // the force of this step: constant, or the ramp's at the step's middle
                double fi = Double.isNaN(f) ? Math.min(settings.rampMaxN(), rate * (t - 0.5 * h)) : f;
                for (int k = 0; k < 3; k++) force[k] = fi * u[k];
                int contacts;
                if (free) {
                    for (int k = 0; k < 3; k++) {
                        torque[k] = 0;
                        flight[k] = m * g[k] + force[k];
                    }
                    body.step(h, flight, torque);
                    contacts = 0;
                } else {
                    scene.disturbance(force, zero);
                    ContactSolver.Outcome outcome = scene.step(h);
                    if (outcome == ContactSolver.Outcome.NOT_POSITIVE_DEFINITE) {
                        // its impulses are not a solution: an answer from them would be made up
                        throw new IllegalStateException("hold test: the contact problem at t = " + t + " s is not positive definite");
                    }
                    // each of Coulomb's solves is exact; only their fixed point may not settle: counted, said in the outputs
                    if (outcome == ContactSolver.Outcome.MAX_ITERATIONS) unconverged++;
                    contacts = scene.contacts().size();
                    // an engaged clutch slips once the torque it carries (its press and what held it
                    // against opening) passes τ_break, transmits τ_break while it slips, and grips
                    // again where the link stops opening, loaded then with τ_break
                    for (int j = 0; j < 6; j++) {
                        if (!jointSlips[j]) continue;
                        if (!slipping[j] && pressNow[j] + scene.jointWormTorque(j, h) > grasp.tauBreak()) {
                            scene.setJoint(j, grasp.tauBreak(), false, Double.POSITIVE_INFINITY);
                            slipping[j] = true;
                        } else if (slipping[j] && scene.jointVelocity(j) >= 0) {
                            scene.setJoint(j, grasp.tauBreak(), true, grasp.tauBreak() / (CONTACT_STIFFNESS_N_M * jointArm[j] * jointArm[j]));
                            pressNow[j] = grasp.tauBreak();
                            slipping[j] = false;
                        }
                    }
                }
                body.position(x);
                body.orientation(q);
                disp = Math.sqrt(sq(x[0] - x0[0]) + sq(x[1] - x0[1]) + sq(x[2] - x0[2]));
                rot = Quaternion.angleBetween(q0, 0, q, 0);
                maxD = Math.max(maxD, disp);
                maxR = Math.max(maxR, rot);
                if (Double.isNaN(crossedAt)) ratio = Math.max(ratio, Math.max(disp / dispThr, rot / rotThr));
                if (contacts == 0) {
                    if (Double.isNaN(lostAt)) lostAt = t;
                } else {
                    lostAt = Double.NaN;
                }
                if (i % every == 0 || i == n) sample(t);
                body.stepVelocity(v);
                body.stepAngularVelocity(w);
                boolean slow = norm(v) < restV && norm(w) < restW;
                if (slow && Double.isNaN(crossedAt)) forceAtRest = fi;
                if (Double.isNaN(crossedAt) && !(disp < dispThr && rot < rotThr)) {
                    crossedAt = t;
                    forceAtCrossing = fi;
                    if (stopAtCrossing) break;
                }
                if (!free && contacts == 0) {
                    for (int k = 0; k < 3; k++) accel[k] = force[k] / m + g[k];
                    free = Double.isNaN(f) ? false : flyingAway(body);
                }
                this.slow = slow;
                if (settling && free) break;   // touching nothing and leaving (or at rest): no contact comes back
                if (!free && !Double.isNaN(f)) {
                    // settled: slow for a whole window with the same contacts, and what is left cannot cross
                    still = slow && contacts == lastContacts ? still + 1 : 0;
                    lastContacts = contacts;
                    if (settling && still >= windowSteps) break;
                    if (still >= windowSteps && i < n && Double.isNaN(crossedAt)) {
                        double left = (n - i) * h, bd = bound(restV, left), br = bound(restW, left);
                        if (maxD + bd < dispThr && maxR + br < rotThr) {
                            settle(i, n, t, bd, br);
                            break;
                        }
                    }
                    if (!settling && creeping(i, n, t)) break;
                }
            }
            simulated = time(i);
        }

        /** Ends the push at step i of n (time t) as held, what is left bounded by bd (m) and br (rad). */
        private void settle(long i, long n, double t, double bd, double br) {
            settledAt = t;
            boundD = bd;
            boundR = br;
            for (long j = i + 1; j <= n; j++) if (j % every == 0 || j == n) sample(time(j));
        }

        /**
         * The creep test, from {@link #CREEP_AFTER_S} into a push that the rest test has not
         * ended, window by window ({@link #REST_WINDOW_S}, back to back): the window's own largest
         * speed v and spin ω bound what is left as the rest test's bound does ({@link #bound}),
         * provided the object is not speeding up (neither is above the last window's), no clutch is slipping, and every engaged clutch's torque, its largest in
         * the window raised by its rise over the window for every window left, stays below
         * τ_break: a clutch that lets go later is what makes a creeping grasp fail after all. True
         * when the push ends here, held.
         */
        private boolean creeping(long i, long n, double t) {
            double speed = norm(v), spin = norm(w);
            winV = Math.max(winV, speed);
            winW = Math.max(winW, spin);
            for (int j = 0; j < 6; j++) {
                if (!jointSlips[j]) continue;
                if (slipping[j]) winSlip = true;
                double carried = pressNow[j] + scene.jointWormTorque(j, h);
                if (Double.isNaN(winStartTau[j])) winStartTau[j] = carried;
                winTau[j] = Math.max(winTau[j], carried);
                lastTau[j] = carried;
            }
            if (i % windowSteps != 0) return false;
            boolean ended = false;
            if (t >= CREEP_AFTER_S - 1e-12 && i < n && Double.isNaN(crossedAt) && !winSlip && lastWinV >= 0
                && winV <= lastWinV && winW <= lastWinW) {
                double left = (n - i) * h, windows = left / REST_WINDOW_S;
                boolean torqueOk = true;
                for (int j = 0; j < 6; j++) {
                    if (!jointSlips[j] || Double.isNaN(winStartTau[j])) continue;
                    double rise = Math.max(0, lastTau[j] - winStartTau[j]);
                    if (!(winTau[j] + rise * windows <= grasp.tauBreak())) torqueOk = false;
                }
                double bd = bound(winV, left), br = bound(winW, left);
                if (torqueOk && maxD + bd < dispThr && maxR + br < rotThr) {
                    settle(i, n, t, bd, br);
                    ended = true;
                }
            }
            lastWinV = winV;
            lastWinW = winW;
            winV = winW = 0;
            winSlip = false;
            Arrays.fill(winTau, Double.NEGATIVE_INFINITY);
            Arrays.fill(winStartTau, Double.NaN);
            return ended;
        }

        /** Step i's time, s, to the nanosecond (i·h without its rounding noise in the outputs). */
        private double time(long i) {
            return Math.round(i * h * 1e9) / 1e9;
        }

        private void sample(double t) {
            ts[ns] = t;
            ds[ns] = disp;
            rs[ns] = Math.toDegrees(rot);
            ns++;
        }

        boolean passed() { return Double.isNaN(crossedAt); }

        double[] times() { return Arrays.copyOf(ts, ns); }

        double[] displacements() { return Arrays.copyOf(ds, ns); }

        double[] rotations() { return Arrays.copyOf(rs, ns); }

        List<DirectionResult.Contact> endContacts() {
            List<DirectionResult.Contact> end = new ArrayList<>();
            if (free) return end;
            BodyContacts c = scene.contacts();
            for (int k = 0; k < c.size(); k++) {
                double[] imp = c.impulse(k, new double[3]);
                for (int a = 0; a < 3; a++) imp[a] /= h;
                end.add(new DirectionResult.Contact(LockedGrasp.name(c.body(k)), c.point(k, new double[3]), c.normal(k, new double[3]),
                    imp, c.gap(k)));
            }
            return end;
        }
    }

    /**
     * True when no contact can come back: for every body of the hand, the object's centre of mass
     * is beyond reach of its bounding sphere (object radius + sphere radius + the contact margin)
     * and both its velocity and its constant acceleration point away from the sphere's centre,
     * with v·a ≥ 0, so the distance only grows.
     */
    private boolean flyingAway(FreeBody body) {
        body.position(x);
        body.velocity(v);
        double va = v[0] * accel[0] + v[1] * accel[1] + v[2] * accel[2];
        if (va < 0) return false;
        for (double[] s : spheres) {
            double dx = x[0] - s[0], dy = x[1] - s[1], dz = x[2] - s[2];
            double reach = objectRadius + s[3] + ProximityContacts.DEFAULT_MARGIN;
            if (dx * dx + dy * dy + dz * dz <= reach * reach) return false;
            if (dx * v[0] + dy * v[1] + dz * v[2] < 0) return false;
            if (dx * accel[0] + dy * accel[1] + dz * accel[2] < 0) return false;
        }
        return true;
    }

    /**
     * How far a speed (or spin) below {@code rate} over a whole rest window can carry the object
     * in the {@code left} seconds that remain, its acceleration taken constant and so below
     * 2·rate/W: rate·t + (rate/W)·t².
     */
    private static double bound(double rate, double left) {
        return rate * left + rate / REST_WINDOW_S * left * left;
    }

    private static double sq(double a) { return a * a; }

    private static double norm(double[] a) { return Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

    /** Trees and topologies of the meshes the tests share (the hand's, an object's), made once per mesh. */
    static final class Shapes {
        private static final java.util.Map<TriangleMesh, KdopTree> TREES = java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());
        private static final java.util.Map<TriangleMesh, MeshTopology> TOPOLOGIES =
            java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());

        static KdopTree tree(TriangleMesh m) { return TREES.computeIfAbsent(m, x -> KdopTree.build(x, BodyScene.K)); }

        static MeshTopology topology(TriangleMesh m) { return TOPOLOGIES.computeIfAbsent(m, MeshTopology::new); }
    }
}
