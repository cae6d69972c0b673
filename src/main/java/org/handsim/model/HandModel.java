package org.handsim.model;

import org.handsim.clutch.ClutchState;
import org.handsim.clutch.FingerClutch;
import org.handsim.contact.ContactForces;
import org.handsim.grasp.FrictionCone;
import org.handsim.grasp.GraspAssessment;
import org.handsim.hand.HandDescription;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;
import org.handsim.math.RigidTransform;
import org.handsim.scenario.Scenario;
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
 *       contact forces (eq 11: the driven joints' torques carried, a held joint's reaction
 *       within its bounds, the residual where no forces do) → breakaway test (the torque
 *       through the clutch against τ_break) → next state.</li>
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

    // ------------------------------------------------------------------ parameters
    private final Scenario scenario;
    private final HandDescription hand = HandDescription.barrettHand();
    private final Transmission tr = new Transmission(hand);
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
    private double spread, spreadVel, spreadAcc;
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
    // now, the largest of the run, and the stretch of steps above RESIDUAL_WARN_NM now going on
    private final double[] residual = new double[3], maxResidual = new double[3];
    private final double[] episodeStart = new double[3], episodeEnd = new double[3], episodeMax = new double[3];
    private final java.util.List<String> residualWarnings = new java.util.ArrayList<>();
    private final int[] episodes = new int[3];
    private final double[] moreEpisodesMax = new double[3];
    /** Stretches without equilibrium warned about one by one, per finger; the rest are counted in one line. */
    static final int MAX_EPISODE_WARNINGS = 20;
    private final double[] clutchTorque = new double[3];
    private final long[] counters = new long[Counter.values().length];
    private final int[] contactsAtStart = new int[3];

    // scratch (no allocation in the step)
    private final ContactForces[] solvers = {new ContactForces(), new ContactForces(), new ContactForces()};   // per finger (warm starts)
    private final double[] sample = new double[3], rates = new double[2], transmitted = new double[2];
    private final double[] eventJoints = new double[3];
    private boolean lazy = true;
    private final double[] tauContact = new double[3], frameScratch = new double[48], linkScratch = new double[12];
    private final double[] bounds = new double[2], boundScratch = new double[2];
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
        this.scenario = scenario;
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
        double[] g = scenario.gravity();
        for (int k = 1; k <= 3; k++) {
            fk[k - 1] = new FingerKinematics(hand.finger(k));
            clutch[k - 1] = new FingerClutch(tr, hand.kClutch(), hand.tauBreak(), hand.theta3Limits()[1]);
            // gravity in {k0}: (R_world<-palm · R_palm<-k0)ᵀ g
            RigidTransform base = scenario.worldFromPalm().compose(hand.finger(k).baseInPalm());
            base.copyTo(worldFromK0[k - 1], 0);
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
        residualWarnings.clear();
        java.util.Arrays.fill(episodes, 0);
        java.util.Arrays.fill(moreEpisodesMax, 0);
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
            episodeStart[i] = Double.NaN;
            clutchTorque[i] = 0;
            updateFinger(k, false);
            contactsAtStart[i] = contacts[i].size();
        }
        record();
    }

    // ------------------------------------------------------------------ evolution
    /** Advances one step of dt seconds. */
    public void step() {
        step++;
        t = clock.at(step);
        counters[Counter.STEPS.ordinal()]++;
        sampleSpread(t);
        for (int k = 1; k <= 3; k++) {
            int i = k - 1;
            scenario.motor(i).sample(t, sample);
            motorPrev[i] = clutch[i].motor();
            motorVel[i] = sample[1];
            motorAcc[i] = sample[2];
            clutch[i].follow(sample[0]);
            updateFinger(k, true);
        }
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

    private void sampleSpread(double time) {
        scenario.motor(3).sample(time, sample);
        spread = sample[0];
        spreadVel = sample[1];
        spreadAcc = sample[2];
    }

    /** One finger through the whole chain of the step. */
    private void updateFinger(int k, boolean events) {
        int i = k - 1;
        if (events && lazy && idle(k)) {
            counters[Counter.FINGERS_IDLE.ordinal()]++;
            watchResidual(i);                  // an idle finger keeps its residual (and its stretch goes on)
            return;
        }
        counters[Counter.FINGER_UPDATES.ordinal()]++;
        placeFinger(k);
        collide(k);
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
        watchResidual(i);
    }

    /**
     * Keeps the largest residual of the run, and turns each stretch of steps in which finger i's
     * forces miss its torques by more than {@link #RESIDUAL_WARN_NM} into one warning (its
     * start, end and largest residual), so a long run in such a state warns once, not per step.
     */
    private void watchResidual(int i) {
        double r = residual[i];
        maxResidual[i] = Math.max(maxResidual[i], r);
        if (r > RESIDUAL_WARN_NM) {
            if (Double.isNaN(episodeStart[i])) { episodeStart[i] = t; episodeMax[i] = 0; }
            episodeEnd[i] = t;
            episodeMax[i] = Math.max(episodeMax[i], r);
        } else if (!Double.isNaN(episodeStart[i])) {
            endEpisode(i);
        }
    }

    private void endEpisode(int i) {
        // a long run that keeps cycling through such a state says so a bounded number of times
        if (++episodes[i] <= MAX_EPISODE_WARNINGS) residualWarnings.add(episodeWarning(i));
        else moreEpisodesMax[i] = Math.max(moreEpisodesMax[i], episodeMax[i]);
        episodeStart[i] = Double.NaN;
    }

    private String episodeWarning(int i) {
        return String.format(java.util.Locale.ROOT, "finger %d: the contact forces cannot carry its joint torques from t = %s s"
            + " to %s s (largest residual %.3g N*m): no static equilibrium in that state", i + 1,
            org.handsim.text.Decimal.format(episodeStart[i]), org.handsim.text.Decimal.format(episodeEnd[i]), episodeMax[i]);
    }

    /**
     * True when nothing that drives finger k changed since its last update (motor position,
     * velocity and acceleration, spread, clutch state): its joints, contacts and torques are
     * what they were, so the step leaves it alone (no kinematics, collision or dynamics).
     */
    private boolean idle(int k) {
        int i = k - 1;
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
            boolean same = lazy;
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
     * A closing FREE finger (or a BROKEN one's outer link) that touches the object: locate the
     * first-touch motor count by bisection between the previous and the current count, then
     * change state (inner link → BLOCKED, outer link → STALLED). Returns true if the state changed.
     */
    private boolean locateFirstTouch(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        ContactSet cs = contacts[i];
        double qNow = c.motor(), qBefore = motorPrev[i];
        if (objectContacts == null || qNow <= qBefore) return false;
        boolean inner = c.state() == ClutchState.FREE && cs.touches(2);
        boolean outer = (c.state() == ClutchState.FREE || c.state() == ClutchState.BROKEN) && cs.touches(3);
        if (!inner && !outer) return false;
        locate(k, qBefore, qNow, inner);
        return true;
    }

    /**
     * Tunnelling guard: a closing link may pass through a thin object between two steps. If the
     * motion since the last step moves some point of links 2–3 by more than half the object's
     * thinnest width (a bound: |Δθk2|·R2 + |Δθk3|·R3, R the reach of the links beyond each
     * joint), the step is re-checked at intermediate motor counts spaced to move at most that
     * much; a contact found there is located and handled as usual, and counted
     * ({@link Counter#TUNNELLING_CAUGHT}). So a large dt costs substeps, never a silent miss.
     * Returns true if the state changed.
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
            if (touchesAt(k, qs, innerCounts) != 0) {
                counters[Counter.TUNNELLING_CAUGHT.ordinal()]++;
                locate(k, qBefore + (qNow - qBefore) * (s - 1) / n, qs, innerCounts);
                return true;
            }
        }
        return false;
    }

    /**
     * Bisection for the first-touch motor count in (lo, hi] (a contact exists at hi), then the
     * state change: inner link → BLOCKED, outer link → STALLED.
     */
    private void locate(int k, double lo, double hi, boolean innerCounts) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        double qNow = c.motor(), qBefore = motorPrev[i];
        for (int it = 0; it < 60 && hi - lo > LOCATE_COUNTS; it++) {
            double mid = 0.5 * (lo + hi);
            if (touchesAt(k, mid, innerCounts) != 0) hi = mid; else lo = mid;
        }
        int which = touchesAt(k, hi, innerCounts);
        if (which == 0) which = innerCounts ? 2 : 3;
        double tTouch = t - dt + dt * (hi - qBefore) / (qNow - qBefore);
        if (which == 2) {
            c.innerContact(hi);
            if (Double.isNaN(contactQ[i])) contactQ[i] = hi;
            lastT[i] = tTouch;
            lastQ[i] = hi;
        } else {
            c.outerContact(hi);
        }
    }

    /**
     * 2 if the inner link (when {@code innerCounts}), 3 if the outer link has a contact at motor
     * count q (state unchanged), else 0. Asks {@link LinkContacts#touches}, which is exactly
     * "the full contact query finds a contact", so the held pose the bisection ends on is one
     * where the contact exists (the back end may stop at the first touching triangle pair).
     */
    private int touchesAt(int k, double qm, boolean innerCounts) {
        int i = k - 1;
        eventJoints[0] = q[i][0];
        eventJoints[1] = clutch[i].theta2For(qm);
        eventJoints[2] = clutch[i].theta3For(qm);
        framesInWorld(k, eventJoints, frameScratch);
        counters[Counter.EVENT_QUERIES.ordinal()] += 2;
        if (innerCounts) {
            System.arraycopy(frameScratch, 24, linkScratch, 0, 12);
            if (objectContacts.touches(k, 2, linkScratch)) return 2;
        }
        System.arraycopy(frameScratch, 36, linkScratch, 0, 12);
        if (objectContacts.touches(k, 3, linkScratch)) return 3;
        return 0;
    }

    /**
     * Joint torques τ = τ_dyn (eq 8) + the torque the clutch transmits to the held links, and
     * the contact forces that carry the transmitted part (DESIGN.md, "Which torques the contacts
     * carry"): the torques the drive sets are carried exactly — k2 and k3 while the clutch drives
     * the inner link (FREE, BLOCKED), k3 alone when the inner joint is held by its worm
     * ({@link FingerClutch#innerHeld}: after a breakaway, or stalled before one) — and the held
     * inner joint's reaction stays within what its holder resists ({@link #innerBounds}); eq (11)
     * as non-negative least squares without friction, the least-norm forces in the friction cones
     * with it ({@link ContactForces#solveHeld}). Where no forces do that, {@link #torqueResidual}
     * says by how much. τ_dyn is computed when the scenario asks for torques, and always while the
     * finger is BLOCKED: the torque through the clutch, which decides the breakaway, includes it.
     */
    private void torquesAndForces(int k) {
        int i = k - 1;
        FingerClutch c = clutch[i];
        if (scenario.computeTorques() || c.state() == ClutchState.BLOCKED) {
            double[] a = dynAt[i];
            boolean same = lazy;
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
        ContactSet cs = contacts[i];
        int n = cs.size();
        ContactForces solver = solvers[i];
        if (n > 0) {
            boolean held = c.innerHeld();
            if (held) innerBounds(k, bounds);
            else { bounds[0] = Double.NaN; bounds[1] = Double.NaN; }
            // the same inputs as finger k's last solve (a held link, the same transmitted torque):
            // its solver still holds the answer
            if (!(lazy && sameForceInputs(i, cs, held ? 1 : 0))) {
                double[] coneEdges = mu == 0 ? null : conesOf(i, cs);
                if (held) {
                    solver.solveHeld(framesWorld[i], 1, tauContact, bounds[0], bounds[1], n, cs.points, cs.pushDirs, cs.links,
                        coneEdges, this.coneEdges);
                } else if (coneEdges == null) {
                    solver.solve(framesWorld[i], 1, tauContact, n, cs.points, cs.pushDirs, cs.links);
                } else {
                    solver.solveWithFriction(framesWorld[i], 1, tauContact, n, cs.points, cs.pushDirs, cs.links, coneEdges, this.coneEdges);
                }
            }
            for (int j = 0; j < n; j++) {
                cs.forces[j] = solver.force(j);
                solver.forceVector(j, cs.forceVectors, 3 * j);
                cs.undetermined[j] = solver.undetermined(j);
            }
            residual[i] = solver.residual();
        } else {
            // nothing touches: a held link's torque goes into the drive train (or the outer stop), and a
            // driven torque with no contact to carry it would be a contact the collision missed
            residual[i] = c.innerHeld() ? tauContact[2] : Math.max(Math.abs(tauContact[1]), Math.abs(tauContact[2]));
        }
    }

    /**
     * What finger k's held inner joint resists, [lo, hi] N·m on the torque the contacts put on
     * it, into out[0..1] (DESIGN.md, "Which torques the contacts carry"). It is held by its
     * self-locking worm, which no load on the link back-drives and whose load never reaches the
     * clutch: hi is the worm's limit of the hold LP ({@link GraspAssessment#jointLimit} of a joint
     * its worm holds: the finger rating's torque, decision 6). After a breakaway the joint keeps
     * at least the load the clutch had put on it (the worm does not let the link back off, so the
     * preload stays, and τk2 stays at τ_break as in the paper's Fig. 7): lo = that load. Stalled
     * before any breakaway nothing preloads it: lo = −hi.
     */
    private void innerBounds(int k, double[] out) {
        FingerClutch c = clutch[k - 1];
        double worm = GraspAssessment.jointLimit(hand, k, 2, false);
        out[1] = worm;
        if (c.innerHeldByWorm()) {
            out[0] = -worm;
        } else {
            c.transmittedTorque(boundScratch);
            out[0] = Math.min(boundScratch[0], worm);
        }
    }

    /**
     * True when the contact-force solve of finger i would get what its last one got — whether
     * k2 is held ({@code held}) and its bounds, the torques on k2, k3, the frames of joints
     * 1–3 and every contact's link, point and push direction — and records them otherwise (for
     * the next call). No allocation once the key array has grown to the contact count.
     */
    private boolean sameForceInputs(int i, ContactSet cs, int held) {
        int n = cs.size(), len = 6 + 36 + 7 * n;
        double[] key = forceKey[i];
        if (key.length < len) key = forceKey[i] = java.util.Arrays.copyOf(key, Math.max(len, 2 * key.length));
        boolean same = forceKeyLength[i] == len;
        int o = 0;
        same &= key[o] == held; key[o++] = held;
        for (int j = 0; j < 2; j++, o++) {
            double b = bounds[j];
            same &= key[o] == b || (Double.isNaN(key[o]) && Double.isNaN(b));
            key[o] = b;
        }
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
            // the contact forces carry the spring's share, which grows linearly with the count:
            // at the crossing they are (τ_break − τ_dyn2)/(now − τ_dyn2) of now's
            double share = hand.tauBreak() - tauDyn2, shareNow = now - tauDyn2;
            double scale = shareNow > 0 ? Math.max(0, share) / shareNow : 0;
            ContactSet cs = contacts[i];
            double forceInner = 0;
            for (int j = 0; j < cs.size(); j++) if (cs.links[j] == 2) forceInner += cs.forces[j];
            breakForce[i] = forceInner * scale;
            maxForce[i] = Math.max(maxForce[i], cs.forceSum() * scale);
            breakQ[i] = qb;
            c.breakAway(qb, Math.max(0, share));
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
        }
        recorder.setSpread(spread);
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
        for (int k = 1; k <= 3; k++) {
            residual[k - 1] = torqueResidual(k);
            ContactSet cs = contacts(k);
            for (int i = 0; i < cs.size(); i++) {
                double[] n = cs.normal(i);
                // into the object: 0 − n, which turns a zero component into +0, not −0
                list.add(new GraspAssessment.Contact(k, cs.link(i), cs.point(i), new double[] {0.0 - n[0], 0.0 - n[1], 0.0 - n[2]}, cs.forceVector(i)));
            }
            frames[k - 1] = framesWorld(k);
            engaged[k - 1] = clutchEngaged(k);
        }
        return new GraspAssessment.Input(time(), java.util.List.copyOf(list), frames, engaged, hand(), objectCentroidAndRadius(), residual);
    }
    /** Joint torques of finger k (a new array, N·m). */
    public double[] torques(int k) { return tau[k - 1].clone(); }
    /** Motor counts of finger k now. */
    public double motorCounts(int k) { return clutch[k - 1].motor(); }
    public double spreadCounts() { return spread; }
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
     * Everything the user should know before trusting the run so far, one sentence each: the
     * {@link #startWarnings()}, then each stretch of steps whose contact forces missed the joint
     * torques by more than {@link #RESIDUAL_WARN_NM}, in the order they ended (one warning per
     * stretch, naming the finger, its start and end time and its largest residual; a stretch
     * still going on ends now, last).
     */
    public java.util.List<String> warnings() {
        java.util.List<String> w = startWarnings();
        w.addAll(residualWarnings);
        for (int k = 1; k <= 3; k++) {
            int i = k - 1;
            if (episodes[i] > MAX_EPISODE_WARNINGS) {
                w.add(String.format(java.util.Locale.ROOT, "finger %d: %d more stretches without a static equilibrium (largest residual %.3g N*m)",
                    k, episodes[i] - MAX_EPISODE_WARNINGS, moreEpisodesMax[i]));
            }
            if (!Double.isNaN(episodeStart[i])) w.add(episodeWarning(i));
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

    /** Work counters since {@link #initialise()}. */
    public long counter(Counter c) { return counters[c.ordinal()]; }
    public long[] counters() { return counters.clone(); }
}
