package org.handsim.model;

import org.handsim.clutch.ClutchState;
import org.handsim.clutch.FingerClutch;
import org.handsim.contact.ContactForces;
import org.handsim.grasp.FrictionCone;
import org.handsim.grasp.GraspAssessment;
import org.handsim.hand.HandDescription;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;
import org.handsim.body.MassProperties;
import org.handsim.math.RigidTransform;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.scenario.SceneMeshes;
import org.handsim.scenario.UnitRule;
import org.handsim.trace.Recorder;
import org.handsim.trajectory.Trajectory;
import org.handsim.process.StepClock;

/**
 * The HandSim model, Easy-Java-Simulations style: read it top to bottom.
 * <ol>
 *   <li><b>Parameters</b> — fixed for a run: the scenario, the hand, the collision and dynamics
 *       back ends.</li>
 *   <li><b>State variables</b> — time, per finger the clutch state, joint angles, velocities,
 *       accelerations, torques and contacts.</li>
 *   <li>{@link #initialise()} — puts the state at t = 0.</li>
 *   <li>{@link #step()} — advances one time step dt. One step (DESIGN.md, "Data flow"):
 *       motor set-points q_Mk(t) → clutch state machine → joint angles, velocities and
 *       accelerations → forward kinematics → link meshes placed → collision with the object →
 *       patches → point contacts → joint torques (Lagrange–Euler plus the clutch spring) →
 *       contact forces (eq 11: the driven joints' torques carried, held joints reacting, loads
 *       locked in at a breakaway kept, the residual where no forces do) → every joint's carried
 *       torque → breakaway test (the torque through the clutch against τ_break) → next state;
 *       the spread moves first, and stops at a contact its motion pushes into.</li>
 *   <li><b>Fixed relations</b> — the private methods {@link #placeFinger}, {@link #collide},
 *       {@link #torquesAndForces} that the step calls.</li>
 * </ol>
 *
 * <p><b>Events inside a step.</b> The first touch of a closing finger and the breakaway are
 * located inside the step (bisection on the motor count for the touch, linear interpolation of
 * the linearly rising torque for the breakaway), so their times do not depend on dt.
 *
 * <p><b>Work saved.</b> A finger whose joints and placement did not change since its last
 * collision query reuses its contacts (held fingers in BLOCKED or STALLED, fingers at rest);
 * its dynamics likewise. {@link #counters()} counts both.
 *
 * <p>Not thread-safe: one thread steps a model; views read {@link #snapshot()} copies.
 */
public final class HandModel {
    /** Bound on how far a link's surface reaches beyond its DH segment (link half-thickness, rounded ends), m. */
    static final double LINK_MARGIN_M = 0.02;
    /**
     * How closely the first touch is located, in motor counts (1e-9 counts = 1.4e-14 rad of θk2):
     * a few more bisection steps at the event only, and the contact and breakaway times agree to
     * about 1e-15 s across dt (chart 1-dt; with 1e-6 counts they agreed to 1e-10 s).
     */
    static final double LOCATE_COUNTS = 1e-9;
    /**
     * A contact blocks a link's motion when the motion has a component into the object of more
     * than this fraction of its speed (an angle below 89.99994° from the push direction): a motion
     * within rounding of the surface's tangent slides along it (DESIGN.md decision 1).
     */
    static final double PUSH_COS = 1e-6;

    // ------------------------------------------------------------------ parameters
    private final Scenario scenario;
    private final HandDescription hand;   // the scenario's (hand.parameters applied)
    private final Transmission tr;
    private final LinkContacts objectContacts;      // null: no object in the scene
    private final TorqueModel dynamics;
    private final FingerKinematics[] fk = new FingerKinematics[3];
    private final double[][] gravityK0 = new double[3][3];
    private final double[][] worldFromK0 = new double[3][12];
    private final double dt;
    private final StepClock clock;                  // t = step × dt in decimal (8.947, not 8.947000000000001)
    private final long totalSteps;
    private final double reach2, reach3;           // metres: how far links 2-3 reach beyond joints k2, k3
    private final Recorder recorder;                // null: not recording

    // ------------------------------------------------------------------ state variables
    private long step;
    private double t;
    private final FingerClutch[] clutch = new FingerClutch[3];
    private final double[][] q = new double[3][3], qd = new double[3][3], qdd = new double[3][3];
    private final double[][] tau = new double[3][3], tauDyn = new double[3][3];
    private final double[] motorPrev = new double[3];
    private final double[] motorVel = new double[3], motorAcc = new double[3];
    private double spread, spreadVel, spreadAcc;    // where the spread is (counts), and how it moves
    private boolean spreadStopped;                  // a contact stopped the spread, which stays until its set-point turns back
    private double spreadStopDir, spreadStopCounts, spreadStopTime;   // the direction it was stopped in; where and when it first stopped
    private final ContactSet[] contacts = {new ContactSet(), new ContactSet(), new ContactSet()};
    private final double[][] framesWorld = new double[3][48];
    private final double[] framedTheta1 = {Double.NaN, Double.NaN, Double.NaN};   // θk1 that framesWorld's {k0}, {k1} are for
    private final ContactSet[][] linkContacts = new ContactSet[3][3];   // per finger and link
    // work saving (lazy): the inputs each result was last computed from; NaN (equal to nothing) until then
    private final double[][][] linkCollidedAt = new double[3][3][3];    // joints of each link's last query
    private final double[][] dynAt = new double[3][9];        // q, qd, qdd of the last dynamics call
    private final double[][] lastInput = new double[3][7];    // what drives each finger at its last update (idle)
    // breakaway bookkeeping: the last (t, q) sample of a BLOCKED finger
    private final double[] lastT = new double[3], lastQ = new double[3];
    // results
    private final double[] breakTime = new double[3], breakTorque = new double[3], breakForce = new double[3], breakQ = new double[3], contactQ = new double[3];
    private final double[] maxForce = new double[3];
    // how far the contact forces are from carrying the joint torques (ContactForces.residual), per finger:
    // now, the largest of the run, and the stretches of steps above RESIDUAL_WARN_NM
    private final double[] residual = new double[3], maxResidual = new double[3];
    /** Stretches warned about one by one, per finger (and per link or joint for the rating); the rest are counted in one line. */
    static final int MAX_EPISODE_WARNINGS = 20;
    private final Stretches residualStretches = new Stretches(3, RESIDUAL_WARN_NM, MAX_EPISODE_WARNINGS, new Stretches.Wording() {
        @Override
        public String stretch(int i, double start, double end, double max, double maxAt) {
            return String.format(java.util.Locale.ROOT, "finger %d: the contact forces cannot carry its joint torques from t = %s s"
                + " to %s s (largest residual %.3g N*m): no static equilibrium in that state", i + 1,
                org.handsim.text.Decimal.format(start), org.handsim.text.Decimal.format(end), max);
        }

        @Override
        public String more(int i, int more, double max) {
            return String.format(java.util.Locale.ROOT, "finger %d: %d more stretches without a static equilibrium (largest residual %.3g N*m)",
                i + 1, more, max);
        }
    });
    // the torque each joint carries, τ_dyn + Jᵀf (N·m), per finger and joint; the largest reaction of a worm-held inner joint (NaN: none)
    private final double[][] carried = new double[3][3];
    private final double[] maxWormReaction = new double[3];
    private final RatingWatch ratings;
    // loads locked into the contacts when an inner joint's worm locked (the breakaway), per finger and link:
    // the forces (3 per contact of the link then), and the joints the link had then (its contacts are a function of them)
    private final double[][][] lockedForces = new double[3][3][0];
    private final int[][] lockedCount = new int[3][3];
    private final double[][][] lockedJoints = new double[3][3][3];
    private final boolean[] locked = new boolean[3];
    private final int[] lockGeneration = new int[3];
    private double[][] lockedScratch = {new double[0], new double[0], new double[0]};
    private final double[] clutchTorque = new double[3];
    private final long[] counters = new long[Counter.values().length];
    private final int[] contactsAtStart = new int[3];

    // the free object (DESIGN.md decision 7): null / empty when the object is fixed
    private final FreeObjectScene free;
    private final SceneGeometry geometry;
    private final HandPath path;                    // the hand base's motion, null when it stays
    private final double[] gravity;                 // the scenario's, m/s² (world); Scenario.gravity() copies it
    private final boolean sceneMoves;               // the object or the base moves: no result is reused from an earlier step
    private final double releaseS;
    private final double[] objectStart;
    private final double[] palmStart = new double[12], palmPose = new double[12], palmTwist = new double[6];
    private final double[][] baseInPalm = new double[3][12];
    private final double[][] startFrames = new double[3][48];
    private final double[] startPalm = new double[12], stepTwist = new double[6];
    private final double[][] startQ = new double[3][3];
    private boolean released;
    private final FreeObjectState objectState = new FreeObjectState();
    private final double[] linkInertia = new double[6];           // D22, D33 per finger (kg·m²) at release
    private final int[][] followerOf = new int[3][2];
    private final double[] twistScratch = new double[6], pScratch = new double[3], nScratch = new double[3], fScratch = new double[3];

    // scratch (no allocation in the step)
    private final ContactForces[] solvers = {new ContactForces(), new ContactForces(), new ContactForces()};   // per finger (warm starts)
    private final double[] sample = new double[3], rates = new double[2], transmitted = new double[2];
    private final double[] eventJoints = new double[3];
    private final ContactSet eventContacts = new ContactSet();
    private boolean lazy = true;
    private final double[] tauContact = new double[3], frameScratch = new double[48], linkScratch = new double[12];
    private final ContactForces.Problem[] problems = {new ContactForces.Problem(), new ContactForces.Problem(), new ContactForces.Problem()};
    private final double mu;                         // Coulomb coefficient of the contacts (0: the frictionless solve)
    private final int coneEdges;
    private final double[][] cones = {new double[0], new double[0], new double[0]};      // per finger: cone edges, 3·m per contact
    private final double[][] conesFor = {new double[0], new double[0], new double[0]};   // per finger: the push directions they were made for
    private final int[] conesCount = new int[3];
    private final double[][] forceKey = {new double[0], new double[0], new double[0]};   // per finger: the last force solve's inputs
    private final int[] forceKeyLength = new int[3];

    /**
     * A finger whose contact forces miss its joint torques by more than this (N·m, {@link
     * #torqueResidual}) has no static equilibrium in its state: {@link #warnings()} says so, once
     * per stretch of such steps.
     */
    public static final double RESIDUAL_WARN_NM = 1e-6;

    /** Work counters, for the savings table. */
    public enum Counter {
        STEPS, FINGER_UPDATES, FINGERS_IDLE, COLLISION_QUERIES, COLLISIONS_SKIPPED, DYNAMICS_CALLS, DYNAMICS_SKIPPED,
        EVENT_QUERIES, SWEPT_SUBSTEPS, TUNNELLING_CAUGHT
    }

    /**
     * @param scenario       what to simulate
     * @param objectContacts the collision back end, or null when the scene has no object
     * @param dynamics       the inverse dynamics ({@link TorqueModel#NONE} for kinematics only)
     * @param record         whether to keep a trace (one row per step)
     */
    public HandModel(Scenario scenario, LinkContacts objectContacts, TorqueModel dynamics, boolean record) {
        this(scenario, objectContacts, dynamics, record ? new Recorder() : null);
    }

    /**
     * @param recorder where the trace goes (e.g. {@link Recorder#bounded}), or null for none
     */
    public HandModel(Scenario scenario, LinkContacts objectContacts, TorqueModel dynamics, Recorder recorder) {
        if (scenario.freeObject() != null) {
            if (!(objectContacts instanceof SceneGeometry sg)) {
                throw new ScenarioException(scenario.file() + ": field object.free: a free object needs the object's mesh (its collision"
                    + " back end), which this run has not");
            }
            MassProperties props = FreeObjectMass.of(scenario, sg.objectMesh());
            FreeObjectStart.check(scenario, sg.objectMesh(), sg.worldFromObject());
            this.geometry = sg;
            this.free = new FreeObjectScene(scenario, sg, props);
            this.objectStart = sg.worldFromObject();
            this.releaseS = scenario.freeObject().releaseS();
            if (recorder != null) recorder.withObject();
        } else {
            this.geometry = null;
            this.free = null;
            this.objectStart = null;
            this.releaseS = Double.POSITIVE_INFINITY;
        }
        this.path = scenario.moves().isEmpty() ? null : new HandPath(scenario.worldFromPalm(), scenario.moves());
        this.sceneMoves = free != null || path != null;
        scenario.worldFromPalm().copyTo(palmStart, 0);
        System.arraycopy(palmStart, 0, palmPose, 0, 12);
        this.scenario = scenario;
        this.hand = scenario.hand();
        this.tr = new Transmission(hand);
        this.ratings = new RatingWatch(hand);
        this.objectContacts = objectContacts;
        this.dynamics = dynamics;
        this.dt = scenario.dt();
        this.clock = new StepClock(dt);
        this.mu = scenario.friction();
        this.coneEdges = scenario.coneEdges();
        this.totalSteps = totalSteps(scenario);
        this.recorder = recorder;
        this.reach2 = hand.a2() + hand.a3() + LINK_MARGIN_M;
        this.reach3 = hand.a3() + LINK_MARGIN_M;
        this.gravity = scenario.gravity();
        double[] g = gravity;
        for (int k = 1; k <= 3; k++) {
            fk[k - 1] = new FingerKinematics(hand.finger(k));
            clutch[k - 1] = new FingerClutch(tr, hand.kClutch(), hand.tauBreak(), hand.theta3Limits()[1]);
            // gravity in {k0}: (R_world<-palm · R_palm<-k0)ᵀ g
            RigidTransform base = scenario.worldFromPalm().compose(hand.finger(k).baseInPalm());
            base.copyTo(worldFromK0[k - 1], 0);
            hand.finger(k).baseInPalm().copyTo(baseInPalm[k - 1], 0);
            base.inverse().rotate(g, gravityK0[k - 1]);
        }
        initialise();
    }

    /** Steps a scenario runs: its duration over its time step, rounded up. */
    public static long totalSteps(Scenario scenario) {
        return Math.round(Math.ceil(scenario.duration() / scenario.dt() - 1e-9));
    }

    /**
     * The time a scenario's run ends: that of its last step, {@link #totalSteps} × dt in decimal
     * ({@link StepClock}; 8.947 s for the paper's scenario, whose trajectories last 8.9464 s) —
     * what {@code handsim run} reports as simulated.
     */
    public static double endTime(Scenario scenario) {
        return new StepClock(scenario.dt()).at(totalSteps(scenario));
    }

    // ------------------------------------------------------------------ initialisation
    /** Puts the model at t = 0: motors at their start counts, fingers FREE, nothing recorded. */
    public void initialise() {
        step = 0;
        t = 0;
        if (path != null) placeBase(0);
        if (free != null) {
            released = false;
            free.body().setPose(objectStart);
            free.body().setVelocity(new double[3], new double[3]);
            geometry.placeObject(objectStart);
            objectState.reset(palmPose, free);
        }
        residualStretches.clear();
        ratings.clear();
        if (recorder != null) recorder.clear();
        java.util.Arrays.fill(counters, 0);
        sampleSpread(0);
        for (int k = 1; k <= 3; k++) {
            int i = k - 1;
            Trajectory m = scenario.motor(i);
            m.sample(0, sample);
            clutch[i].reset(sample[0]);
            motorPrev[i] = sample[0];
            motorVel[i] = sample[1];
            motorAcc[i] = sample[2];
            for (int j = 0; j < 3; j++) {
                java.util.Arrays.fill(linkCollidedAt[i][j], Double.NaN);
                if (linkContacts[i][j] == null) linkContacts[i][j] = new ContactSet();
                linkContacts[i][j].clear();
            }
            contacts[i].clear();
            java.util.Arrays.fill(dynAt[i], Double.NaN);
            java.util.Arrays.fill(lastInput[i], Double.NaN);
            forceKeyLength[i] = 0;
            breakTime[i] = Double.NaN;
            breakTorque[i] = Double.NaN;
            breakForce[i] = Double.NaN;
            breakQ[i] = Double.NaN;
            contactQ[i] = Double.NaN;
            maxForce[i] = 0;
            residual[i] = 0;
            maxResidual[i] = 0;
            java.util.Arrays.fill(carried[i], 0);
            maxWormReaction[i] = Double.NaN;
            unlock(i);
            clutchTorque[i] = 0;
            updateFinger(k, false);
            contactsAtStart[i] = contacts[i].size();
        }
        if (free != null) objectState.held(t, palmPose, free);
        record();
    }

    // ------------------------------------------------------------------ evolution
    /** Advances one step of dt seconds. */
    public void step() {
        step++;
        t = clock.at(step);
        counters[Counter.STEPS.ordinal()]++;
        if (free != null) {
            // the object's step starts from the poses of the step's start: the hand's bodies as the last step left them
            for (int i = 0; i < 3; i++) {
                System.arraycopy(framesWorld[i], 0, startFrames[i], 0, 48);
                System.arraycopy(q[i], 0, startQ[i], 0, 3);
            }
            System.arraycopy(palmPose, 0, startPalm, 0, 12);
        }
        // released at the start of the step whose start is release_s or later: the fingers' update then takes its forces from the object's step
        if (free != null && !released && t - dt >= releaseS - 1e-12) released = true;
        if (path != null) placeBase(t);
        moveSpread(t);
        for (int k = 1; k <= 3; k++) {
            int i = k - 1;
            scenario.motor(i).sample(t, sample);
            motorPrev[i] = clutch[i].motor();
            motorVel[i] = sample[1];
            motorAcc[i] = sample[2];
            clutch[i].follow(sample[0]);
            if (clutch[i].state() == ClutchState.FREE) unlock(i);
            updateFinger(k, true);
        }
        if (free != null) stepObject();
        record();
    }

    /** @return true while the scenario's duration has not been reached */
    public boolean running() {
        return step < totalSteps;
    }

    /** Runs to the end; {@code progress} (may be null) is told the fraction done now and then. */
    public void run(java.util.function.DoubleConsumer progress) {
        long every = Math.max(1, totalSteps / 200);
        while (running()) {
            step();
            if (progress != null && step % every == 0) progress.accept(step / (double) totalSteps);
        }
        if (progress != null) progress.accept(1.0);
    }

    /**
     * The hand's base at {@code time} ({@link HandPath}): the palm's pose and twist, each
     * finger's base frame {k0} in the world and gravity in it.
     */
    private void placeBase(double time) {
        path.sample(time, palmPose, palmTwist);
        double[] g = gravity;
        for (int i = 0; i < 3; i++) {
            RigidTransform.multiply(palmPose, 0, baseInPalm[i], 0, worldFromK0[i], 0);
            double[] w = worldFromK0[i];
            for (int a = 0; a < 3; a++) gravityK0[i][a] = w[a] * g[0] + w[4 + a] * g[1] + w[8 + a] * g[2];
            framedTheta1[i] = Double.NaN;
        }
    }

    /**
     * The free object's part of the step (DESIGN.md decision 7). Until {@code release_s} the
     * object is held where it is and the fingers close on it as on a fixed object. From then on,
     * each step: the palm and the nine links are placed as the clutch state machines and motor
     * profiles put them at t, each with its velocity (the base's twist and the joints' rates of
     * FREE and BROKEN motion: kinematic bodies); a held inner joint (BLOCKED, BROKEN, STALLED)
     * and a held outer joint (BLOCKED, STALLED) press as followers with the torque their clutch
     * or stalled motor transmits ({@link FingerClutch#transmittedTorque}: the springs' wind-up,
     * the load kept at the breakaway, the stall torque), held against opening by the worm; the
     * object takes one {@link FreeObjectScene#step}; the joints that followed the object give
     * way by what they turned ({@link FingerClutch#giveWay}); the contact impulses over h are
     * the contact forces, whose torques about each joint (eq 9: Σ (z × (p − o))·f) are what the
     * joints carry beyond τ_dyn. The residual of a finger is then the torque that moved its
     * pressing joints, D·|θ̇|/h (0 while the object holds them).
     */
    private void stepObject() {
        double h = dt;
        if (!released) {
            objectState.held(t, palmPose, free);
            return;
        }
        if (Double.isNaN(objectState.releasedAt)) {
            objectState.releasedAt = clock.at(step - 1);
            free.release(objectState.releasedAt);
            org.handsim.dynamics.HandDynamics hd = org.handsim.dynamics.HandDynamics.barrettHand();
            for (int k = 1; k <= 3; k++) {
                org.handsim.dynamics.ChainDynamics chain = hd.finger(k);
                double[] qa = chain.dof() == 3 ? q[k - 1] : new double[] {q[k - 1][1], q[k - 1][2]};
                double[] d = chain.massMatrix(qa, null);
                int n = chain.dof();
                linkInertia[2 * (k - 1)] = d[(n - 2) * n + n - 2];
                linkInertia[2 * (k - 1) + 1] = d[(n - 1) * n + n - 1];
            }
        }
        free.begin();
        baseStepTwist(h);
        free.hand(FreeObjectScene.PALM, startPalm, 0, stepTwist, -1, -1);
        for (int k = 1; k <= 3; k++) {
            int i = k - 1;
            FingerClutch c = clutch[i];
            ClutchState st = c.state();
            double[] f = startFrames[i];
            c.transmittedTorque(transmitted);
            int f2 = -1, f3 = -1;
            if (st != ClutchState.FREE) f2 = follower(f, 1, linkInertia[2 * i], transmitted[0]);
            if (st == ClutchState.BLOCKED || st == ClutchState.STALLED) {
                f3 = follower(f, 2, linkInertia[2 * i + 1], c.stalledAtOuterLimit() ? 0 : transmitted[1]);
            }
            followerOf[i][0] = f2;
            followerOf[i][1] = f3;
            for (int j = 1; j <= 3; j++) {
                linkTwist(i, j, twistScratch);
                free.hand(FreeObjectScene.linkBody(k, j), f, 12 * j, twistScratch, j >= 2 ? f2 : -1, j == 3 ? f3 : -1);
            }
        }
        org.handsim.body.ContactSolver.Outcome outcome = free.step(t - h, h);
        if (outcome == org.handsim.body.ContactSolver.Outcome.NOT_POSITIVE_DEFINITE) {
            // its impulses are not a solution: an answer from them would be made up
            throw new SimulationException("the free object's contact problem at t = " + t + " s is not positive definite");
        }
        // each of Coulomb's solves is exact; only their fixed point may not settle: counted, said in the outputs
        if (outcome == org.handsim.body.ContactSolver.Outcome.MAX_ITERATIONS) objectState.unconverged++;
        org.handsim.body.BodyStepper stepper = free.stepper();
        for (int i = 0; i < 3; i++) {
            double w2 = followerOf[i][0] >= 0 ? stepper.followerVelocity(followerOf[i][0]) : 0;
            double w3 = followerOf[i][1] >= 0 ? stepper.followerVelocity(followerOf[i][1]) : 0;
            residual[i] = Math.max(linkInertia[2 * i] * Math.abs(w2), linkInertia[2 * i + 1] * Math.abs(w3)) / h;
            if (w2 > 0 || w3 > 0) {
                clutch[i].giveWay(h * Math.max(0, w2), h * Math.max(0, w3), hand.kClutch());
                placeFinger(i + 1);                    // where the links followed to: the next step starts there
            }
        }
        objectForces(h);
        geometry.placeObject(free.pose(poseScratch));
        objectState.stepped(t, palmPose, free);
        for (int i = 0; i < 3; i++) watch(i);
    }

    private final double[] poseScratch = new double[12], axisScratch = new double[3], originScratch = new double[3];

    /** A follower about joint m + 1's axis (z of frame {km} in {@code f}) with inertia D and torque τ. */
    private int follower(double[] f, int m, double inertia, double torque) {
        int a = 12 * m;
        axisScratch[0] = f[a + 2]; axisScratch[1] = f[a + 6]; axisScratch[2] = f[a + 10];
        originScratch[0] = f[a + 3]; originScratch[1] = f[a + 7]; originScratch[2] = f[a + 11];
        return free.follower(axisScratch, originScratch, inertia, Math.max(0, torque), true);
    }

    /**
     * The base's motion over the step, as the mean twist that takes the palm from its pose at the
     * step's start to its pose now (the velocity of its origin, (o − o₀)/h; the angular velocity
     * from R R₀ᵀ's skew part over h): the kinematic bodies move over the object's step exactly as
     * their poses change, so no offset builds up step by step.
     */
    private void baseStepTwist(double h) {
        double[] a = palmPose, b = startPalm;
        stepTwist[0] = (a[3] - b[3]) / h;
        stepTwist[1] = (a[7] - b[7]) / h;
        stepTwist[2] = (a[11] - b[11]) / h;
        // M = R R0ᵀ: M_rc = Σ_k R[r][k] R0[c][k]
        double m01 = a[0] * b[4] + a[1] * b[5] + a[2] * b[6], m10 = a[4] * b[0] + a[5] * b[1] + a[6] * b[2];
        double m02 = a[0] * b[8] + a[1] * b[9] + a[2] * b[10], m20 = a[8] * b[0] + a[9] * b[1] + a[10] * b[2];
        double m12 = a[4] * b[8] + a[5] * b[9] + a[6] * b[10], m21 = a[8] * b[4] + a[9] * b[5] + a[10] * b[6];
        stepTwist[3] = 0.5 * (m21 - m12) / h;
        stepTwist[4] = 0.5 * (m02 - m20) / h;
        stepTwist[5] = 0.5 * (m10 - m01) / h;
    }

    /**
     * Finger i's link j's twist over the step (world): the velocity of its frame's origin and its
     * angular velocity, from the base's ({@link #baseStepTwist}) and the joints 1..j's mean rates
     * over the step (their change over h: the kinematic motion of FREE and BROKEN links).
     */
    private void linkTwist(int i, int j, double[] out) {
        double[] f = startFrames[i];
        int b = 12 * j;
        double ox = f[b + 3], oy = f[b + 7], oz = f[b + 11];
        double wx = stepTwist[3], wy = stepTwist[4], wz = stepTwist[5];
        double rx = ox - startPalm[3], ry = oy - startPalm[7], rz = oz - startPalm[11];
        double vx = stepTwist[0] + wy * rz - wz * ry, vy = stepTwist[1] + wz * rx - wx * rz, vz = stepTwist[2] + wx * ry - wy * rx;
        for (int m = 1; m <= j; m++) {
            double r = (q[i][m - 1] - startQ[i][m - 1]) / dt;
            if (r == 0) continue;
            int a = 12 * (m - 1);
            double zx = f[a + 2], zy = f[a + 6], zz = f[a + 10];
            double dx = ox - f[a + 3], dy = oy - f[a + 7], dz = oz - f[a + 11];
            wx += r * zx; wy += r * zy; wz += r * zz;
            vx += r * (zy * dz - zz * dy); vy += r * (zz * dx - zx * dz); vz += r * (zx * dy - zy * dx);
        }
        out[0] = vx; out[1] = vy; out[2] = vz; out[3] = wx; out[4] = wy; out[5] = wz;
    }

    /**
     * The contact forces of the object's step (impulse / h) as each finger's contacts, with the
     * torques they put on its joints (carried = τ_dyn + Σ (z × (p − o))·f over the links each
     * joint carries, eq 9) and the largest sum of the run.
     */
    private void objectForces(double h) {
        org.handsim.body.BodyContacts bc = free.contacts();
        for (int i = 0; i < 3; i++) {
            contacts[i].clear();
            objectState.innerForce[i] = 0;
        }
        for (int c = 0, n = bc.size(); c < n; c++) {
            int b = bc.body(c);
            if (b < 1 || b >= FreeObjectScene.HAND_BODIES) continue;
            int i = (b - 1) / 3, j = (b - 1) % 3 + 1;
            bc.point(c, pScratch);
            bc.normal(c, nScratch);
            bc.impulse(c, fScratch);
            ContactSet cs = contacts[i];
            int x = cs.add(j, pScratch[0], pScratch[1], pScratch[2], -nScratch[0], -nScratch[1], -nScratch[2], 0);
            double fx = fScratch[0] / h, fy = fScratch[1] / h, fz = fScratch[2] / h, mag = Math.sqrt(fx * fx + fy * fy + fz * fz);
            cs.forceVectors[3 * x] = fx; cs.forceVectors[3 * x + 1] = fy; cs.forceVectors[3 * x + 2] = fz;
            cs.forces[x] = mag;
            if (j == 2) objectState.innerForce[i] += mag;
        }
        for (int i = 0; i < 3; i++) {
            ContactSet cs = contacts[i];
            double[] f = startFrames[i];
            for (int j = 1; j <= 3; j++) {
                int a = 12 * (j - 1);
                double zx = f[a + 2], zy = f[a + 6], zz = f[a + 10], ox = f[a + 3], oy = f[a + 7], oz = f[a + 11];
                double sum = 0;
                for (int c = 0; c < cs.size(); c++) {
                    if (cs.links[c] < j) continue;
                    double rx = cs.points[3 * c] - ox, ry = cs.points[3 * c + 1] - oy, rz = cs.points[3 * c + 2] - oz;
                    sum += (zy * rz - zz * ry) * cs.forceVectors[3 * c] + (zz * rx - zx * rz) * cs.forceVectors[3 * c + 1]
                        + (zx * ry - zy * rx) * cs.forceVectors[3 * c + 2];
                }
                carried[i][j - 1] = tauDyn[i][j - 1] + sum;
            }
            maxForce[i] = Math.max(maxForce[i], cs.forceSum());
        }
    }

    /** Where the spread starts: its set-point at t = 0, moving freely. */
    private void sampleSpread(double time) {
        scenario.motor(3).sample(time, sample);
        spread = sample[0];
        spreadVel = sample[1];
        spreadAcc = sample[2];
        spreadStopped = false;
        spreadStopCounts = Double.NaN;
        spreadStopTime = Double.NaN;
    }

    /**
     * The spread follows its set-point at time {@code time} unless a contact blocks it (DESIGN.md
     * decision 1, "The spread"): fingers 1 and 2 turn about their k1 axes with it, and a contact
     * that this motion pushes into the object ({@link #spreadBlockedAt}) stops it where the first
     * such contact begins (bisection on the spread count, to {@link #LOCATE_COUNTS}), the fingers'
     * flexion joints as they were at the last step. Barrett's spread has no clutch and is
     * back-drivable: it stays there, held by its motor and pushing with nothing of its own, while
     * the set-point goes on the same way, and follows again once the set-point turns back past it.
     */
    private void moveSpread(double time) {
        scenario.motor(3).sample(time, sample);
        double target = sample[0];
        if (spreadStopped && (target - spread) * spreadStopDir < 0) spreadStopped = false;
        if (spreadStopped) {
            spreadVel = 0;
            spreadAcc = 0;
            return;
        }
        if (objectContacts != null && target != spread) {
            double from = spread, dir = Math.signum(target - from);
            if (spreadBlockedAt(target, dir)) {
                double lo = from, hi = target;
                for (int it = 0; it < 80 && Math.abs(hi - lo) > LOCATE_COUNTS; it++) {
                    double mid = 0.5 * (lo + hi);
                    if (spreadBlockedAt(mid, dir)) hi = mid; else lo = mid;
                }
                spread = hi;
                spreadVel = 0;
                spreadAcc = 0;
                spreadStopped = true;
                spreadStopDir = dir;
                if (Double.isNaN(spreadStopCounts)) {
                    spreadStopCounts = hi;
                    spreadStopTime = t - dt + dt * (hi - from) / (target - from);
                }
                return;
            }
        }
        spread = target;
        spreadVel = sample[1];
        spreadAcc = sample[2];
    }

    /**
     * Whether, with the spread at {@code counts} and fingers 1 and 2's flexion joints as they are,
     * a contact of theirs is pushed into the object by the spread turning in direction
     * {@code dir} (+1 or −1 counts): its velocity dθk1 · z0 × (p − o0) has a component along the
     * direction the finger pushes there ({@link #pushesInto}). Cheap test first ({@link
     * LinkContacts#touches}), the full contact query only for a link that touches.
     */
    private boolean spreadBlockedAt(double counts, double dir) {
        for (int k = 1; k <= 2; k++) {
            int i = k - 1;
            double rate = hand.finger(k).spreadRadPerCount() * dir;
            if (rate == 0) continue;
            eventJoints[0] = hand.finger(k).spreadRadPerCount() * counts;
            eventJoints[1] = q[i][1];
            eventJoints[2] = q[i][2];
            framesInWorld(k, eventJoints, frameScratch);
            double zx = frameScratch[2], zy = frameScratch[6], zz = frameScratch[10];
            double ox = frameScratch[3], oy = frameScratch[7], oz = frameScratch[11];
            for (int j = 1; j <= 3; j++) {
                System.arraycopy(frameScratch, 12 * j, linkScratch, 0, 12);
                counters[Counter.EVENT_QUERIES.ordinal()]++;
                if (!objectContacts.touches(k, j, linkScratch)) continue;
                eventContacts.clear();
                objectContacts.collide(k, j, linkScratch, eventContacts);
                for (int c = 0; c < eventContacts.size(); c++) {
                    double rx = eventContacts.points[3 * c] - ox, ry = eventContacts.points[3 * c + 1] - oy, rz = eventContacts.points[3 * c + 2] - oz;
                    if (pushesInto(rate * (zy * rz - zz * ry), rate * (zz * rx - zx * rz), rate * (zx * ry - zy * rx), eventContacts.pushDirs, 3 * c)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** One finger through the whole chain of the step. */
    private void updateFinger(int k, boolean events) {
        int i = k - 1;
        if (events && lazy && idle(k)) {
            counters[Counter.FINGERS_IDLE.ordinal()]++;
            watch(i);                          // an idle finger keeps its forces (and its stretches go on)
            return;
        }
        counters[Counter.FINGER_UPDATES.ordinal()]++;
        placeFinger(k);
        if (released && !contactsConsulted(i)) {
            counters[Counter.COLLISIONS_SKIPPED.ordinal()] += 3;
        } else {
            collide(k);
        }
        if (events && (locateFirstTouch(k) || sweptTouch(k))) {
            placeFinger(k);
            collide(k);
        }
        torquesAndForces(k);
        if (events && breakawayTest(k)) {
            placeFinger(k);
            collide(k);
            torquesAndForces(k);
        }
        maxForce[i] = Math.max(maxForce[i], contacts[i].forceSum());
        clutchTorque[i] = clutch[i].clutchTorque(tauDyn[i][1]);
        guard(k);
        if (!released) watch(i);                      // released: after the object's step gives the forces
    }

    /**
     * Whether finger i's update after the release reads its contacts with the object: a closing
     * FREE or BROKEN finger looks for a first touch, a BLOCKED one may break away and lock its
     * contacts' forces. Otherwise (held, stalled, or a motor that does not advance) the object's
     * step replaces the contacts before anything reads them ({@link #objectForces}), so the
     * intersection query would be work thrown away.
     */
    private boolean contactsConsulted(int i) {
        ClutchState st = clutch[i].state();
        if (st == ClutchState.BLOCKED) return true;
        return (st == ClutchState.FREE || st == ClutchState.BROKEN) && clutch[i].motor() > motorPrev[i];
    }

    /**
     * Keeps the largest residual and worm reaction of the run, and turns each stretch of steps in
     * which finger i's forces miss its torques by more than {@link #RESIDUAL_WARN_NM}, or exceed
     * Barrett's rating, into one warning ({@link Stretches}).
     */
    private void watch(int i) {
        double r = residual[i];
        maxResidual[i] = Math.max(maxResidual[i], r);
        // a released object's residual is the torque that moved a pressing joint (dynamics), not a missing static equilibrium
        residualStretches.watch(i, released ? 0 : r, t);
        if (clutch[i].innerHeld()) {
            double w = Math.abs(carried[i][1]);
            if (!(w <= maxWormReaction[i])) maxWormReaction[i] = w;
        }
        ratings.watch(i + 1, contacts[i], carried[i], t);
    }

    /**
     * True when nothing that drives finger k changed since its last update (motor position,
     * velocity and acceleration, spread, clutch state): its joints, contacts and torques are
     * what they were, so the step leaves it alone (no kinematics, collision or dynamics).
     */
    private boolean idle(int k) {
        int i = k - 1;
        if (sceneMoves) return false;
        double[] in = lastInput[i];
        double sr = hand.finger(k).spreadRadPerCount();
        double s0 = clutch[i].motor(), s1 = motorVel[i], s2 = motorAcc[i];
        double s3 = sr * spread, s4 = sr * spreadVel, s5 = sr * spreadAcc, s6 = clutch[i].state().ordinal();
        boolean same = in[0] == s0 && in[1] == s1 && in[2] == s2 && in[3] == s3 && in[4] == s4 && in[5] == s5 && in[6] == s6;
        in[0] = s0; in[1] = s1; in[2] = s2; in[3] = s3; in[4] = s4; in[5] = s5; in[6] = s6;
        return same;
    }

    // ------------------------------------------------------------------ fixed relations
    /** Joint angles, velocities and accelerations from the clutch; frames by forward kinematics. */
    private void placeFinger(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        double spreadRate = hand.finger(k).spreadRadPerCount();
        q[i][0] = spreadRate * spread;
        q[i][1] = c.theta2();
        q[i][2] = c.theta3();
        c.jointRates(rates);
        qd[i][0] = spreadRate * spreadVel;
        qdd[i][0] = spreadRate * spreadAcc;
        boolean moving = c.state() == ClutchState.FREE || c.state() == ClutchState.BROKEN;
        qd[i][1] = moving ? rates[0] * motorVel[i] : 0;
        qd[i][2] = moving ? rates[1] * motorVel[i] : 0;
        qdd[i][1] = moving ? rates[0] * motorAcc[i] : 0;
        qdd[i][2] = moving ? rates[1] * motorAcc[i] : 0;
        if (q[i][0] == framedTheta1[i]) {
            fk[i].framesFromKeepingLink1(q[i], framesWorld[i]);   // {k0}, {k1} as last time
        } else {
            framesInWorld(k, q[i], framesWorld[i]);
            framedTheta1[i] = q[i][0];
        }
    }

    private void framesInWorld(int k, double[] joints, double[] out) {
        fk[k - 1].framesFrom(worldFromK0[k - 1], joints, out);
    }

    /**
     * Point contacts of the finger's three links with the object. Link j's pose depends on joints
     * 1..j only, so a link whose joints did not change keeps its contacts (in BROKEN the held
     * inner link is not collided again while the outer link closes).
     */
    private void collide(int k) {
        int i = k - 1;
        if (objectContacts == null) return;
        ContactSet cs = contacts[i];
        boolean changed = false;
        for (int j = 1; j <= 3; j++) {
            double[] at = linkCollidedAt[i][j - 1];
            boolean same = lazy && !sceneMoves;
            for (int m = 0; m < j && same; m++) same = at[m] == q[i][m];
            if (same) {
                counters[Counter.COLLISIONS_SKIPPED.ordinal()]++;
                continue;
            }
            ContactSet lc = linkContacts[i][j - 1];
            lc.clear();
            System.arraycopy(framesWorld[i], 12 * j, linkScratch, 0, 12);
            objectContacts.collide(k, j, linkScratch, lc);
            counters[Counter.COLLISION_QUERIES.ordinal()]++;
            System.arraycopy(q[i], 0, at, 0, 3);
            changed = true;
        }
        if (changed) {
            cs.clear();
            for (int j = 0; j < 3; j++) cs.append(linkContacts[i][j]);
        }
    }

    /**
     * A closing FREE finger (or a BROKEN one's outer link) with a contact that blocks its closing
     * ({@link #blocksClosing}): locate the motor count where it began by bisection between the
     * previous and the current count, then change state (inner link → BLOCKED, outer link →
     * STALLED). Contacts that do not block (the back of a link the closing pulls away) change
     * nothing. Returns true if the state changed.
     */
    private boolean locateFirstTouch(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        ContactSet cs = contacts[i];
        double qNow = c.motor(), qBefore = motorPrev[i];
        if (objectContacts == null || qNow <= qBefore) return false;
        boolean free = c.state() == ClutchState.FREE;
        boolean inner = free && blocksClosing(i, framesWorld[i], cs, 2);
        boolean outer = (free || c.state() == ClutchState.BROKEN) && blocksClosing(i, framesWorld[i], cs, 3);
        if (!inner && !outer) return false;
        return locate(k, qBefore, qNow, inner, outer);
    }

    /**
     * Tunnelling guard: a closing link may pass through a thin object between two steps. If the
     * motion since the last step moves some point of links 2–3 by more than half the object's
     * thinnest width (a bound: |Δθk2|·R2 + |Δθk3|·R3, R the reach of the links beyond each
     * joint), the step is re-checked at intermediate motor counts spaced to move at most that
     * much; a contact found there that blocks the closing is located and handled as usual, and
     * counted ({@link Counter#TUNNELLING_CAUGHT}). So a large dt costs substeps, never a silent
     * miss. Returns true if the state changed.
     */
    private boolean sweptTouch(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        if (objectContacts == null) return false;
        ClutchState st = c.state();
        double qNow = c.motor(), qBefore = motorPrev[i];
        if (qNow <= qBefore || (st != ClutchState.FREE && st != ClutchState.BROKEN)) return false;
        double half = 0.5 * Math.max(objectContacts.minThickness(), objectContacts.minLinkThickness());
        double disp = Math.abs(c.theta2For(qNow) - c.theta2For(qBefore)) * reach2
            + Math.abs(c.theta3For(qNow) - c.theta3For(qBefore)) * reach3;
        if (!(disp > half)) return false;
        int n = (int) Math.min(100_000, Math.ceil(disp / half));
        boolean innerCounts = st == ClutchState.FREE;
        for (int s = 1; s < n; s++) {
            double qs = qBefore + (qNow - qBefore) * s / n;
            counters[Counter.SWEPT_SUBSTEPS.ordinal()]++;
            if (touchesAt(k, qs, innerCounts, true) != 0 && blockingAt(k, qs, innerCounts, true) != 0) {
                counters[Counter.TUNNELLING_CAUGHT.ordinal()]++;
                return locate(k, qBefore + (qNow - qBefore) * (s - 1) / n, qs, innerCounts, true);
            }
        }
        return false;
    }

    /**
     * The first motor count in (lo, hi] at which a contact blocks the closing (one exists at hi
     * on the links counted: the inner link when {@code innerCounts}, the outer when
     * {@code outerCounts}), then the state change: inner link → BLOCKED, outer link → STALLED.
     * First the first touch of any kind, by bisection on {@link #touchesAt} (which may stop at
     * the first intersecting triangle pair); if the contacts there do not block the closing (the
     * back of a link, a slide along the surface), the first that do lie beyond it: bisection on
     * {@link #blockingAt}. Returns true (the state changed).
     */
    private boolean locate(int k, double lo, double hi, boolean innerCounts, boolean outerCounts) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        double qNow = c.motor(), qBefore = motorPrev[i], top = hi;
        for (int it = 0; it < 60 && hi - lo > LOCATE_COUNTS; it++) {
            double mid = 0.5 * (lo + hi);
            if (touchesAt(k, mid, innerCounts, outerCounts) != 0) hi = mid; else lo = mid;
        }
        int which = blockingAt(k, hi, innerCounts, outerCounts);
        if (which == 0) {
            lo = hi;
            hi = top;
            for (int it = 0; it < 60 && hi - lo > LOCATE_COUNTS; it++) {
                double mid = 0.5 * (lo + hi);
                if (blockingAt(k, mid, innerCounts, outerCounts) != 0) hi = mid; else lo = mid;
            }
            which = blockingAt(k, hi, innerCounts, outerCounts);
            if (which == 0) which = innerCounts ? 2 : 3;
        }
        double tTouch = t - dt + dt * (hi - qBefore) / (qNow - qBefore);
        if (which == 2) {
            c.innerContact(hi);
            if (Double.isNaN(contactQ[i])) contactQ[i] = hi;
            lastT[i] = tTouch;
            lastQ[i] = hi;
        } else {
            c.outerContact(hi);
        }
        return true;
    }

    /**
     * 2 if the inner link (when {@code innerCounts}), 3 if the outer link (when
     * {@code outerCounts}) has a contact at motor count q (state unchanged), else 0. Asks
     * {@link LinkContacts#touches}, which is exactly "the full contact query finds a contact", so
     * the held pose the bisection ends on is one where the contact exists (the back end may stop at
     * the first touching triangle pair).
     */
    private int touchesAt(int k, double qm, boolean innerCounts, boolean outerCounts) {
        eventFrames(k, qm);
        if (innerCounts) {
            counters[Counter.EVENT_QUERIES.ordinal()]++;
            System.arraycopy(frameScratch, 24, linkScratch, 0, 12);
            if (objectContacts.touches(k, 2, linkScratch)) return 2;
        }
        if (outerCounts) {
            counters[Counter.EVENT_QUERIES.ordinal()]++;
            System.arraycopy(frameScratch, 36, linkScratch, 0, 12);
            if (objectContacts.touches(k, 3, linkScratch)) return 3;
        }
        return 0;
    }

    /**
     * As {@link #touchesAt}, but only for contacts that block the closing ({@link #blocksClosing}):
     * the full contact query at motor count q, with the contacts' normals.
     */
    private int blockingAt(int k, double qm, boolean innerCounts, boolean outerCounts) {
        int i = k - 1;
        eventFrames(k, qm);
        for (int j = innerCounts ? 2 : 3; j <= (outerCounts ? 3 : 2); j++) {
            counters[Counter.EVENT_QUERIES.ordinal()]++;
            eventContacts.clear();
            System.arraycopy(frameScratch, 12 * j, linkScratch, 0, 12);
            objectContacts.collide(k, j, linkScratch, eventContacts);
            if (blocksClosing(i, frameScratch, eventContacts, j)) return j;
        }
        return 0;
    }

    /** Frames of finger k in the world at motor count q (state unchanged) into {@code frameScratch}. */
    private void eventFrames(int k, double qm) {
        int i = k - 1;
        eventJoints[0] = q[i][0];
        eventJoints[1] = clutch[i].theta2For(qm);
        eventJoints[2] = clutch[i].theta3For(qm);
        framesInWorld(k, eventJoints, frameScratch);
    }

    /**
     * Whether a contact of {@code cs} on link {@code link} blocks finger i's closing in its
     * current state (DESIGN.md decision 1, "Blocking means pushing back"): the link's velocity at
     * the contact point, per motor count — Σ_m (dθ_m/dq) z_{m−1} × (p − o_{m−1}) over the flexion
     * joints that move it ({@link FingerClutch#jointRates}) — has a component along the direction
     * the finger pushes there, into the object ({@link #pushesInto}). A contact on the back of a
     * moving link, which the closing pulls away from the object, does not block it.
     *
     * @param frames the finger's frames (48 values) the contacts were found at
     */
    private boolean blocksClosing(int i, double[] frames, ContactSet cs, int link) {
        clutch[i].jointRates(rates);
        for (int c = 0; c < cs.size(); c++) {
            if (cs.links[c] != link) continue;
            double ux = 0, uy = 0, uz = 0;
            for (int m = 1; m < link; m++) {
                double r = rates[m - 1];
                if (r == 0) continue;
                int o = 12 * m;
                double zx = frames[o + 2], zy = frames[o + 6], zz = frames[o + 10];
                double rx = cs.points[3 * c] - frames[o + 3], ry = cs.points[3 * c + 1] - frames[o + 7], rz = cs.points[3 * c + 2] - frames[o + 11];
                ux += r * (zy * rz - zz * ry); uy += r * (zz * rx - zx * rz); uz += r * (zx * ry - zy * rx);
            }
            if (pushesInto(ux, uy, uz, cs.pushDirs, 3 * c)) return true;
        }
        return false;
    }

    /**
     * Whether a motion (ux, uy, uz) of a contact point pushes into the object, whose push
     * direction (unit, into the object) is at {@code d[o..]}: its component along it exceeds
     * {@link #PUSH_COS} of its length — a motion closer to the surface's tangent slides along it.
     */
    static boolean pushesInto(double ux, double uy, double uz, double[] d, int o) {
        double along = ux * d[o] + uy * d[o + 1] + uz * d[o + 2];
        return along > PUSH_COS * Math.sqrt(ux * ux + uy * uy + uz * uz);
    }

    /**
     * Joint torques τ = τ_dyn (eq 8) + the torque the clutch transmits to the held links, and
     * the contact forces the hand's compliance gives (DESIGN.md, "Which contact forces";
     * {@link ContactForces}): the torques the drive sets are carried exactly — k2 and k3 while
     * the clutch drives the inner link (FREE, BLOCKED), k3 alone when the inner joint is held by
     * its worm ({@link FingerClutch#innerHeld}: after a breakaway, or stalled before one) — the
     * held joints (the spread, a worm-held inner joint) react with whatever the contacts put on
     * them, and a held link's contacts keep the loads locked into them at the breakaway
     * ({@link #lockedFor}). Where no forces carry the driven torques, {@link #torqueResidual} says
     * by how much. Every joint's carried torque is τ_dyn + Jᵀf ({@link #carriedTorque}). τ_dyn is
     * computed when the scenario asks for torques, and always while the finger is BLOCKED: the
     * torque through the clutch, which decides the breakaway, includes it.
     */
    private void torquesAndForces(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        if (scenario.computeTorques() || c.state() == ClutchState.BLOCKED) {
            double[] a = dynAt[i];
            boolean same = lazy && !sceneMoves;
            for (int j = 0; j < 3 && same; j++) {
                same = a[j] == q[i][j] && a[3 + j] == qd[i][j] && a[6 + j] == qdd[i][j];
            }
            if (same) {
                counters[Counter.DYNAMICS_SKIPPED.ordinal()]++;
            } else {
                dynamics.inverseDynamics(k, q[i], qd[i], qdd[i], gravityK0[i], tauDyn[i]);
                counters[Counter.DYNAMICS_CALLS.ordinal()]++;
                for (int j = 0; j < 3; j++) { a[j] = q[i][j]; a[3 + j] = qd[i][j]; a[6 + j] = qdd[i][j]; }
            }
        } else if (tauDyn[i][0] != 0 || tauDyn[i][1] != 0 || tauDyn[i][2] != 0) {
            // no torques asked for: the clutch's τ_dyn of a BLOCKED phase is not carried over
            java.util.Arrays.fill(tauDyn[i], 0);
            java.util.Arrays.fill(dynAt[i], Double.NaN);
        }
        c.transmittedTorque(transmitted);
        tauContact[0] = 0;
        tauContact[1] = transmitted[0];
        // stalled at the outer joint's limit: its stop, not the contacts, holds the stalled motor's torque
        tauContact[2] = c.stalledAtOuterLimit() ? 0 : transmitted[1];
        tau[i][0] = tauDyn[i][0];
        tau[i][1] = tauDyn[i][1] + transmitted[0];
        tau[i][2] = tauDyn[i][2] + transmitted[1];
        if (released) return;                          // the object's step gives the forces (stepObject)
        solveForces(k, c.innerHeld());
    }

    /**
     * The contact forces of finger k for the driven torques in {@code tauContact} (k2 held when
     * {@code innerHeld}), into its contact set, with the residual and the carried torques. No
     * contacts: a held link's torque goes into the drive train (or the outer stop), and a driven
     * torque with no contact to carry it is the residual (a contact the collision missed).
     */
    private void solveForces(int k, boolean innerHeld) {
        int i = k - 1;
        ContactSet cs = contacts[i];
        int n = cs.size();
        ContactForces solver = solvers[i];
        if (n > 0) {
            // the same inputs as finger k's last solve (a held link, the same transmitted torque):
            // its solver still holds the answer
            if (!(lazy && sameForceInputs(i, cs, innerHeld ? 1 : 0))) {
                ContactForces.Problem pr = problems[i].frames(framesWorld[i]).held(0).driven(2, tauContact[2])
                    .contacts(n, cs.points, cs.pushDirs, cs.links)
                    .friction(mu == 0 ? null : conesOf(i, cs), coneEdges)
                    .locked(lockedFor(i, cs));
                if (innerHeld) pr.held(1); else pr.driven(1, tauContact[1]);
                solver.solve(pr);
            }
            for (int j = 0; j < n; j++) {
                cs.forces[j] = solver.force(j);
                solver.forceVector(j, cs.forceVectors, 3 * j);
                cs.undetermined[j] = solver.undetermined(j);
            }
            residual[i] = solver.residual();
            for (int j = 0; j < 3; j++) carried[i][j] = tauDyn[i][j] + solver.torqueOn(j);
        } else {
            residual[i] = innerHeld ? Math.abs(tauContact[2]) : Math.max(Math.abs(tauContact[1]), Math.abs(tauContact[2]));
            for (int j = 0; j < 3; j++) carried[i][j] = tauDyn[i][j];
        }
    }

    /**
     * The forces locked into finger i's contacts, aligned with {@code cs} (3 per contact), or
     * null when none are: at its last breakaway ({@link #lock}) each link's contacts and forces
     * were kept with the joints the link had; a link whose joints are the same now has the same
     * contacts (they are a function of its pose, the object being fixed) and keeps those forces —
     * the inner link, held by its worm — while a link that moved since (the outer link closing
     * on eq 10) has new contacts, locked to nothing.
     */
    private double[] lockedFor(int i, ContactSet cs) {
        if (!locked[i]) return null;
        int n = cs.size();
        if (lockedScratch[i].length < 3 * n) lockedScratch[i] = new double[Math.max(3 * n, 2 * lockedScratch[i].length)];
        double[] out = lockedScratch[i];
        int o = 0;
        boolean any = false;
        for (int j = 0; j < 3; j++) {
            int m = linkContacts[i][j].size();
            boolean same = lockedCount[i][j] == m;
            for (int a = 0; a < j + 1 && same; a++) same = lockedJoints[i][j][a] == q[i][a];
            for (int c = 0; c < 3 * m; c++) {
                double f = same ? lockedForces[i][j][c] : 0;
                out[o++] = f;
                any |= f != 0;
            }
        }
        return any ? out : null;
    }

    /**
     * Locks finger i's current contact forces into its contacts: the inner joint's worm takes over
     * from the clutch (the breakaway), so the inner link cannot move, and what its contacts carry
     * stays unless the geometry unloads them (DESIGN.md, "Which contact forces").
     */
    private void lock(int i) {
        ContactSet cs = contacts[i];
        int o = 0;
        for (int j = 0; j < 3; j++) {
            int m = linkContacts[i][j].size();
            if (lockedForces[i][j].length < 3 * m) lockedForces[i][j] = new double[3 * m];
            System.arraycopy(cs.forceVectors, o, lockedForces[i][j], 0, 3 * m);
            o += 3 * m;
            lockedCount[i][j] = m;
            System.arraycopy(q[i], 0, lockedJoints[i][j], 0, 3);
        }
        locked[i] = true;
        lockGeneration[i]++;
    }

    /** No loads locked into finger i's contacts (at the start, and whenever the finger is FREE again: its links leave the object). */
    private void unlock(int i) {
        if (locked[i]) lockGeneration[i]++;
        locked[i] = false;
    }

    /**
     * True when the contact-force solve of finger i would get what its last one got — whether
     * k2 is held ({@code held}), the loads locked in (their generation, {@link #lock}; each link's
     * share follows from its joints, in the frames), the torques on k2, k3, the frames of joints
     * 1–3 and every contact's link, point and push direction — and records them otherwise (for
     * the next call). No allocation once the key array has grown to the contact count.
     */
    private boolean sameForceInputs(int i, ContactSet cs, int held) {
        int n = cs.size(), len = 5 + 36 + 7 * n;
        double[] key = forceKey[i];
        if (key.length < len) key = forceKey[i] = java.util.Arrays.copyOf(key, Math.max(len, 2 * key.length));
        boolean same = forceKeyLength[i] == len;
        int o = 0;
        same &= key[o] == held; key[o++] = held;
        double generation = locked[i] ? lockGeneration[i] : -1;
        same &= key[o] == generation; key[o++] = generation;
        for (int j = 0; j < 3; j++, o++) { same &= key[o] == tauContact[j]; key[o] = tauContact[j]; }
        double[] f = framesWorld[i];
        for (int j = 0; j < 36; j++, o++) { same &= key[o] == f[j]; key[o] = f[j]; }
        for (int c = 0; c < n; c++) {
            same &= key[o] == cs.links[c]; key[o++] = cs.links[c];
            for (int a = 0; a < 3; a++, o++) { same &= key[o] == cs.points[3 * c + a]; key[o] = cs.points[3 * c + a]; }
            for (int a = 0; a < 3; a++, o++) { same &= key[o] == cs.pushDirs[3 * c + a]; key[o] = cs.pushDirs[3 * c + a]; }
        }
        forceKeyLength[i] = len;
        return same;
    }

    /**
     * The friction-cone edges of finger i's contacts ({@link FrictionCone}), made again only
     * when the contacts' push directions changed (held links keep theirs for many steps).
     */
    private double[] conesOf(int i, ContactSet cs) {
        int n = cs.size(), m = coneEdges;
        boolean same = conesCount[i] == n;
        for (int c = 0; c < 3 * n && same; c++) same = conesFor[i][c] == cs.pushDirs[c];
        if (same) return cones[i];
        if (cones[i].length < 3 * m * n) {
            int cap = Math.max(n, 2 * cones[i].length / (3 * m));
            cones[i] = new double[3 * m * cap];
            conesFor[i] = new double[3 * cap];
        }
        for (int c = 0; c < n; c++) {
            FrictionCone.edges(cs.pushDirs[3 * c], cs.pushDirs[3 * c + 1], cs.pushDirs[3 * c + 2], mu, m, cones[i], 3 * m * c);
        }
        System.arraycopy(cs.pushDirs, 0, conesFor[i], 0, 3 * n);
        conesCount[i] = n;
        return cones[i];
    }

    /**
     * The one clutch criterion (DESIGN.md decision 1): a BLOCKED finger breaks away when the
     * torque through its clutch ({@link FingerClutch#clutchTorque}: τ_dyn2 + the spring's,
     * eq (9)'s torque when the contacts carry it) exceeds τ_break, whatever share gravity and
     * inertia take. The springs wind linearly with the motor count and the held link's τ_dyn is
     * that of a still pose, so the crossing count is exact ({@link
     * FingerClutch#countsWhereClutchTorqueIs}); its time is interpolated linearly between the
     * step's samples. Returns true if the state changed.
     */
    private boolean breakawayTest(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        if (c.state() != ClutchState.BLOCKED) return false;
        double tauDyn2 = tauDyn[i][1];
        double now = c.clutchTorque(tauDyn2);
        double qm = c.motor();
        if (now > hand.tauBreak()) {
            double qb = c.countsWhereClutchTorqueIs(hand.tauBreak(), tauDyn2);
            qb = Math.max(lastQ[i], Math.min(qm, qb));
            double frac = qm > lastQ[i] ? (qb - lastQ[i]) / (qm - lastQ[i]) : 1;
            breakTime[i] = lastT[i] + frac * (t - lastT[i]);
            breakTorque[i] = hand.tauBreak();
            // the contacts at the crossing carry the spring's share, τ_break − τ_dyn2 (the held
            // pose is the step's): solved there, then locked in, since the worm now holds the link
            double share = Math.max(0, hand.tauBreak() - tauDyn2);
            tauContact[0] = 0;
            tauContact[1] = share;
            tauContact[2] = 0;                         // BLOCKED drives the outer joint at 0
            ContactSet cs = contacts[i];
            double forceInner = 0;
            if (released) {
                forceInner = objectState.innerForce[i];   // the last object step's, on the inner link
            } else {
                solveForces(k, false);
                for (int j = 0; j < cs.size(); j++) if (cs.links[j] == 2) forceInner += cs.forces[j];
            }
            breakForce[i] = forceInner;
            maxForce[i] = Math.max(maxForce[i], cs.forceSum());
            breakQ[i] = qb;
            lock(i);
            c.breakAway(qb, share);
            return true;
        }
        lastT[i] = t;
        lastQ[i] = qm;
        return false;
    }

    /** Stops the run with a message naming the step, the time and the value if anything is not finite. */
    private void guard(int k) {
        int i = k - 1;
        for (int j = 0; j < 3; j++) {
            if (!Double.isFinite(q[i][j]) || !Double.isFinite(qd[i][j]) || !Double.isFinite(tau[i][j])) {
                throw new SimulationException("step " + step + " (t = " + t + " s): finger " + k + " joint " + (j + 1)
                    + " is not finite (angle " + q[i][j] + ", velocity " + qd[i][j] + ", torque " + tau[i][j] + ")");
            }
        }
    }

    private void record() {
        if (recorder == null) return;
        recorder.beginRow(t);
        for (int k = 1; k <= 3; k++) {
            int i = k - 1;
            recorder.set(k, Recorder.Q, clutch[i].motor());
            recorder.set(k, Recorder.TH1, q[i][0]);
            recorder.set(k, Recorder.TH2, q[i][1]);
            recorder.set(k, Recorder.TH3, q[i][2]);
            recorder.set(k, Recorder.DTH2, qd[i][1]);
            recorder.set(k, Recorder.DTH3, qd[i][2]);
            recorder.set(k, Recorder.DDTH2, qdd[i][1]);
            recorder.set(k, Recorder.DDTH3, qdd[i][2]);
            recorder.set(k, Recorder.TAU2, tau[i][1]);
            recorder.set(k, Recorder.TAU3, tau[i][2]);
            recorder.setState(k, clutch[i].state());
            recorder.setContacts(k, contacts[i].size(), contacts[i].forceSum());
            recorder.setClutchAndResidual(k, clutchTorque[i], residual[i]);
            for (int j = k == 3 ? 2 : 1; j <= 3; j++) recorder.setCarried(k, j, carried[i][j - 1]);
            recorder.setSpreadTorque(k, tau[i][0]);
        }
        recorder.setSpread(spread);
        if (free != null) {
            FreeObjectState o = objectState;
            recorder.setObject(Recorder.OBJ_X, o.x[0]);
            recorder.setObject(Recorder.OBJ_Y, o.x[1]);
            recorder.setObject(Recorder.OBJ_Z, o.x[2]);
            recorder.setObject(Recorder.OBJ_QW, o.q[0]);
            recorder.setObject(Recorder.OBJ_QX, o.q[1]);
            recorder.setObject(Recorder.OBJ_QY, o.q[2]);
            recorder.setObject(Recorder.OBJ_QZ, o.q[3]);
            recorder.setObject(Recorder.OBJ_SPEED, o.speed);
            recorder.setObject(Recorder.OBJ_SPIN, o.spin);
            recorder.setObject(Recorder.OBJ_CONTACTS, o.contacts);
            recorder.setObject(Recorder.OBJ_PENETRATION, o.penetration);
            recorder.setObject(Recorder.OBJ_DISP, o.disp);
            recorder.setObject(Recorder.OBJ_ROT, o.rot);
        }
    }

    /**
     * Whether the model saves work it does not need (default true): idle fingers are not
     * updated, unchanged poses are not collided again, unchanged states not re-run through the
     * dynamics. Off, every finger is fully computed every step (for the savings table).
     */
    public HandModel lazy(boolean on) {
        lazy = on;
        return this;
    }

    /** Whether work saving is on ({@link #lazy(boolean)}). */
    public boolean isLazy() { return lazy; }

    /**
     * What the user should know before trusting the run, one sentence each (shown by
     * {@code handsim run} on standard error and in summary.json, and by the window): an object
     * far larger than the hand's workspace ({@link UnitRule#sizeWarning}: a unit mistake, most
     * likely); a finger whose links are already in the object at t = 0 (a misplaced object) gets
     * contact forces from the first step on, as if it had closed onto it there.
     */
    public java.util.List<String> startWarnings() {
        java.util.List<String> w = new java.util.ArrayList<>();
        Scenario.ObjectPlacement o = scenario.object();
        if (o != null) {
            // the mesh the run collides with (shared, already loaded): an object far larger than
            // the hand is almost always a unit mistake, and would run without a contact
            String size = UnitRule.sizeWarning(o.file(), SceneMeshes.mesh(o.file(), o.divisions(), o.meshScale()), o.units());
            if (size != null) w.add(size);
        }
        for (int k = 1; k <= 3; k++) {
            int n = contactsAtStart[k - 1];
            if (n > 0) {
                w.add(String.format(java.util.Locale.ROOT, "finger %d starts in contact with the object (%d contact%s at t = 0): its links begin inside it;"
                    + " check the object's pose", k, n, n == 1 ? "" : "s"));
            }
        }
        return w;
    }

    /** Whether any finger's links touch the object at t = 0 (the start-in-contact warnings of {@link #startWarnings}). */
    public boolean startsInContact() {
        for (int n : contactsAtStart) if (n > 0) return true;
        return false;
    }

    // ------------------------------------------------------------------ read-out
    public Scenario scenario() { return scenario; }
    public double time() { return t; }
    public long stepIndex() { return step; }
    public long totalSteps() { return totalSteps; }
    public Recorder recorder() { return recorder; }
    public ClutchState state(int k) { return clutch[k - 1].state(); }
    /** Whether finger k's clutch still couples its inner link to the motor ({@link FingerClutch#engaged()}). */
    public boolean clutchEngaged(int k) { return clutch[k - 1].engaged(); }
    /** The hand's description (the BarrettHand). */
    public HandDescription hand() { return hand; }
    /** Joint angles of finger k (a new array, radians). */
    public double[] joints(int k) { return q[k - 1].clone(); }
    /** Joint velocities of finger k (a new array, rad/s). */
    public double[] velocities(int k) { return qd[k - 1].clone(); }
    /** Joint accelerations of finger k (a new array, rad/s²). */
    public double[] accelerations(int k) { return qdd[k - 1].clone(); }
    /** An immutable copy of the state now, for other threads. */
    public Snapshot snapshot() { return Snapshot.of(this); }
    /**
     * What a grasp evaluation reads of this model as it is now, copied ({@link
     * GraspAssessment#of(GraspAssessment.Input, double, int)} evaluates it on any thread); this
     * model's thread only.
     */
    public GraspAssessment.Input graspInput() {
        java.util.List<GraspAssessment.Contact> list = new java.util.ArrayList<>();
        double[][] frames = new double[3][];
        boolean[] engaged = new boolean[3];
        double[] residual = new double[3];
        double[][] carriedNow = new double[3][3];
        for (int k = 1; k <= 3; k++) {
            residual[k - 1] = torqueResidual(k);
            for (int j = 1; j <= 3; j++) carriedNow[k - 1][j - 1] = carriedTorque(k, j);
            ContactSet cs = contacts(k);
            for (int i = 0; i < cs.size(); i++) {
                double[] n = cs.normal(i);
                // into the object: 0 − n, which turns a zero component into +0, not −0
                list.add(new GraspAssessment.Contact(k, cs.link(i), cs.point(i), new double[] {0.0 - n[0], 0.0 - n[1], 0.0 - n[2]}, cs.forceVector(i)));
            }
            frames[k - 1] = framesWorld(k);
            engaged[k - 1] = clutchEngaged(k);
        }
        return new GraspAssessment.Input(time(), java.util.List.copyOf(list), frames, engaged, hand(), objectCentroidAndRadius(), residual, carriedNow);
    }
    /** Joint torques of finger k (a new array, N·m). */
    public double[] torques(int k) { return tau[k - 1].clone(); }
    /** Motor counts of finger k now. */
    public double motorCounts(int k) { return clutch[k - 1].motor(); }
    /** Where the spread is now, counts: its set-point, unless a contact stopped it ({@link #spreadStopped}). */
    public double spreadCounts() { return spread; }
    /** Whether a contact that the spread's motion pushes into the object holds it now. */
    public boolean spreadStopped() { return spreadStopped; }
    /** The spread count where a contact first stopped the spread, NaN if none did. */
    public double spreadStopCounts() { return spreadStopCounts; }
    /** The time a contact first stopped the spread, s (interpolated inside the step), NaN if none did. */
    public double spreadStopTime() { return spreadStopTime; }
    /** The contacts of finger k (live: copy before handing to another thread). */
    public ContactSet contacts(int k) { return contacts[k - 1]; }
    /** Frames {k0}..{k3} of finger k in the world (a new 48-array). */
    public double[] framesWorld(int k) { return framesWorld[k - 1].clone(); }
    /** Breakaway time of finger k in seconds, NaN if none. */
    public double breakawayTime(int k) { return breakTime[k - 1]; }
    public double breakawayTorque(int k) { return breakTorque[k - 1]; }
    public double breakawayForce(int k) { return breakForce[k - 1]; }
    public double maxContactForce(int k) { return maxForce[k - 1]; }
    /**
     * How far finger k's contact forces are from carrying its joint torques now, N·m
     * ({@link ContactForces#residual}: the largest |τ − τ_dyn − Jᵀf| over the joints the drive
     * sets, and how far a held joint's reaction lies outside what holds it); 0 up to rounding
     * when the state has a static equilibrium.
     */
    public double torqueResidual(int k) { return residual[k - 1]; }
    /** The largest {@link #torqueResidual} of finger k since {@link #initialise()}, N·m. */
    public double maxTorqueResidual(int k) { return maxResidual[k - 1]; }
    /** The torque through finger k's clutch now ({@link FingerClutch#clutchTorque}), N·m. */
    public double clutchTorque(int k) { return clutchTorque[k - 1]; }
    /**
     * The torque joint j (1 spread, 2 inner, 3 outer) of finger k carries now, N·m: τ_dyn (eq 8)
     * plus the contacts' Jᵀf (eq 9) — the drive's torque where the drive sets it (the motor
     * through the clutch, a stalled motor), the reaction of what holds it where it is held (the
     * inner joint's worm after a breakaway or in a stall, the spread's motor). Finger 3 has no
     * joint 1 (0).
     */
    public double carriedTorque(int k, int j) { return k == 3 && j == 1 ? 0 : carried[k - 1][j - 1]; }
    /**
     * The largest |reaction| of finger k's inner joint while its worm held it (after a breakaway,
     * or stalled before one) since {@link #initialise()}, N·m; NaN if the worm never held it.
     * Not capped: Barrett documents no strength of the worm drive, only the 2 kg finger rating,
     * which {@link #warnings()} compares with it.
     */
    public double maxWormReaction(int k) { return maxWormReaction[k - 1]; }

    /**
     * Everything the user should know before trusting the run so far, one sentence each: the
     * {@link #startWarnings()}, then each stretch of steps whose contact forces missed the joint
     * torques by more than {@link #RESIDUAL_WARN_NM} (one warning per stretch, naming the finger,
     * its start and end time and its largest residual), then each stretch in which a contact force
     * or a joint's fingertip-equivalent force exceeded Barrett's rating ({@link RatingWatch}); each
     * kind in the order the stretches ended, those still going on ending now, last; then, for a
     * free object, the steps in which it moved more than the contact margin (tunnelling: the
     * first and the fastest, with their times and speeds) and those whose Coulomb fixed point did
     * not settle.
     */
    public java.util.List<String> warnings() {
        java.util.List<String> w = startWarnings();
        w.addAll(residualStretches.warnings());
        w.addAll(ratings.warnings());
        String tunnel = free == null || free.tunnelling() == null ? null : free.tunnelling().warning();
        if (tunnel != null) w.add(tunnel.replaceFirst("^warning: ", ""));
        if (objectUnconvergedSteps() > 0) {
            w.add(org.handsim.body.ContactSolver.unsettledSteps(objectUnconvergedSteps() + " of the free object's") + " (unconverged_steps)");
        }
        return w;
    }
    /** Motor count of finger k's (first) breakaway, NaN if none. */
    public double breakawayCounts(int k) { return breakQ[k - 1]; }
    /** Motor count where finger k's inner link (first) met the object, NaN if never. */
    public double contactCounts(int k) { return contactQ[k - 1]; }
    /**
     * The collision back end's counters by name ({@link LinkContacts#counters()}; for
     * {@link SceneGeometry}: sphere tests that sufficed, tree walks, queries answered from near
     * pairs, triangle tests), counted since the back end was made; empty without an object.
     */
    public java.util.Map<String, Long> collisionCounters() {
        return objectContacts == null ? java.util.Map.of() : objectContacts.counters();
    }

    /**
     * The object's centroid in the world and its characteristic length R, {cx, cy, cz, R} in
     * metres (a new array; {@link LinkContacts#centroidAndRadius()}), or null when the scene has
     * no object geometry.
     */
    public double[] objectCentroidAndRadius() {
        return objectContacts == null ? null : objectContacts.centroidAndRadius();
    }

    /** Whether the scenario's object is free (DESIGN.md decision 7). */
    public boolean objectFree() { return free != null; }

    /** Whether the free object has been released (false while it is held, and for a fixed object). */
    public boolean objectReleased() { return released; }

    /**
     * The free object's figures now, or null for a fixed object: {x, y, z (centre of mass,
     * world, m), qw, qx, qy, qz (mesh frame to world), speed (m/s), spin (rad/s), contact points,
     * largest penetration (m), displacement (m) and rotation (degrees) relative to the palm since
     * the start} (a new array).
     */
    public double[] objectNow() {
        if (free == null) return null;
        FreeObjectState o = objectState;
        return new double[] {o.x[0], o.x[1], o.x[2], o.q[0], o.q[1], o.q[2], o.q[3], o.speed, o.spin, o.contacts, o.penetration, o.disp, o.rot};
    }

    /**
     * Where the free object's mesh is now: world ← object, 12 row-major values (the pose its
     * collision geometry is placed at; the scenario's placement until the release), a new array;
     * null for a fixed object.
     */
    public double[] objectPose() { return free == null ? null : geometry.worldFromObject(); }

    /** The palm's pose now, world ← palm, 12 row-major values (it follows {@code hand.moves}; a new array). */
    public double[] worldFromPalm() { return palmPose.clone(); }

    /** The free object's largest displacement relative to the palm so far, m (NaN for a fixed object). */
    public double objectMaxDisplacement() { return free == null ? Double.NaN : objectState.maxDisp; }

    /** The free object's largest rotation relative to the palm so far, degrees (NaN for a fixed object). */
    public double objectMaxRotation() { return free == null ? Double.NaN : objectState.maxRot; }

    /** When the free object dropped ({@link FreeObjectState#droppedAt}), s; NaN if it did not, or for a fixed object. */
    public double objectDroppedAt() { return free == null ? Double.NaN : objectState.droppedAt(); }

    /** When the free object first moved more than 5 mm relative to the palm, s; NaN if never. */
    public double objectSlippedAt() { return free == null ? Double.NaN : objectState.slippedAt; }

    /**
     * What the free object's tunnelling watch saw since its release ({@link
     * org.handsim.body.Tunnelling}: steps in which a point of it moved more than the contact
     * margin), or null for a fixed object or before the release.
     */
    public org.handsim.body.Tunnelling objectTunnelling() { return free == null ? null : free.tunnelling(); }

    /**
     * The free object's steps whose Coulomb fixed point did not settle within
     * {@link org.handsim.body.ContactSolver#MAX_FIXED_POINT} solves (each step then used the last
     * exact solve); 0 for a fixed object.
     */
    public long objectUnconvergedSteps() { return free == null ? 0 : objectState.unconverged; }

    /** When the free object was released (the start of its first free step), s; NaN before. */
    public double objectReleasedAt() { return free == null ? Double.NaN : objectState.releasedAt; }

    /** Work counters since {@link #initialise()}. */
    public long counter(Counter c) { return counters[c.ordinal()]; }
    public long[] counters() { return counters.clone(); }
}
