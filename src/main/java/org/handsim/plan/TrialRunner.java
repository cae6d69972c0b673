package org.handsim.plan;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.IntConsumer;
import org.handsim.dynamics.HandDynamics;
import org.handsim.hand.HandDescription;
import org.handsim.clutch.ClutchState;
import org.handsim.body.MassProperties;
import org.handsim.grasp.GraspAssessment;
import org.handsim.hold.DirectionResult;
import org.handsim.hold.HoldTest;
import org.handsim.hold.LockedGrasp;
import org.handsim.hold.ObjectMass;
import org.handsim.model.HandClearance;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.SceneGeometry;
import org.handsim.model.TorqueModel;
import org.handsim.text.JsonWriter;

/**
 * Runs trial i of a plan from its {@link PlanSpec} alone: sample its parameters
 * ({@link TrialSampler}), approach ({@link Autograsp}), make the trial's scenario, run that
 * scenario until every finger has stalled or its profile ends, and evaluate the grasp
 * ({@link GraspAssessment}: force closure, ε, volume, minimum hold). The scenario run here is
 * exactly the one {@link #scenarioJson} writes for {@code best/NN.json} (made directly, not
 * through its text: {@link #trialScenario}) but for its outputs: no
 * trace, no charts, no joint torques (the contacts and the evaluation do not use them: the
 * contacts carry the torque the clutch transmits, DESIGN.md; the clutch's breakaway needs the
 * inner joint's τ_dyn, which the model computes while a finger is BLOCKED whether or not torques
 * are asked for, so the breakaway is the one {@code handsim run} finds), and it stops as soon
 * as all three fingers are STALLED — after that nothing in the model changes, so
 * {@code handsim run} on the written scenario ends in the same grasp.
 *
 * <p>A trial that throws becomes a failed row with its one-line error; the runner goes on.
 * Not thread-safe (collision scratch): one runner per thread; the trees are shared.
 */
public final class TrialRunner {
    private final PlanSpec spec;
    private final TrialSampler sampler;
    private final Map<String, Object> template;
    /** The template as parsed once: each trial is a copy with the trial's pose and spread ({@link #trialScenario}). */
    private final Scenario base;
    /**
     * The dynamics the models are given, one per runner (a model asks it only for a BLOCKED
     * finger's inner-joint torque; it keeps nothing from one call to the next but scratch).
     */
    private final TorqueModel dynamics = HandDynamics.barrettHand()::inverseDynamics;
    private final HandClearance clearance;
    private final StandoffRule standoffs;
    private final ObjectFrame shape;
    private final double[] startCounts = new double[3];
    private final IntConsumer fault;
    /** The object's mass properties for the hold test (null without it). */
    private final MassProperties holdMass;
    /** The last trial's collision: the next trial's takes over its query scratch (no allocation). */
    private SceneGeometry geometry;

    /**
     * @throws org.handsim.scenario.ScenarioException if the template's object cannot be loaded
     */
    public TrialRunner(PlanSpec spec) {
        this(spec, null);
    }

    /**
     * As {@link #TrialRunner(PlanSpec)}, with {@code fault} called before each trial (tests: a
     * trial that throws).
     */
    public TrialRunner(PlanSpec spec, IntConsumer fault) {
        this.spec = spec;
        this.template = spec.template();
        Scenario t = Scenario.parse(Path.of(spec.templateFile()), spec.templateJson());
        this.base = t;
        this.clearance = new HandClearance(t.object());
        SceneGeometry scene = new SceneGeometry(t.object(), SceneGeometry.DEFAULT_K);
        this.shape = new ObjectFrame(scene.objectMesh(), scene.worldFromObject(), clearance.objectCentroid());
        this.sampler = new TrialSampler(spec.trials(), spec.seed(), shape);
        this.standoffs = new StandoffRule(shape, new FingertipPath(HandDescription.barrettHand()));
        PlanHold h = spec.hold();
        // the hold test's mass: the option's, else a free object's from the template's fields, else the mesh's
        this.holdMass = h == null ? null : Double.isNaN(h.massKg()) && Double.isNaN(h.densityKgM3()) && t.freeObject() != null
            ? org.handsim.model.FreeObjectMass.of(t, scene.objectMesh()) : ObjectMass.of(scene.objectMesh(), h.massKg(), h.densityKgM3());
        for (int k = 0; k < 3; k++) startCounts[k] = t.startCounts(k);
        this.fault = fault;
    }

    public PlanSpec spec() { return spec; }

    /** The object's largest extent along its principal axes, metres (for the plan's advice). */
    public double objectExtent() { return shape.extent(0); }

    /** Trial {@code index}: never throws for a failing trial (a failed row instead). */
    public TrialResult run(int index) {
        TrialParameters p = sampler.sample(index);
        long t0 = System.nanoTime();
        double[] standoff = {Double.NaN};
        try {
            return attempt(p, t0, standoff);
        } catch (RuntimeException e) {
            String msg = e.getMessage() != null ? e.getMessage() : e.toString();
            return TrialResult.failed(p, standoff[0], (System.nanoTime() - t0) / 1e9, msg);
        }
    }

    private TrialResult attempt(TrialParameters p, long t0, double[] standoffOut) {
        Autograsp.Touch touch = Autograsp.touch(clearance, p.approach(), p.roll(), p.spreadCounts(), startCounts);
        double standoff = standoffs.standoff(p, touch);
        standoffOut[0] = standoff;
        if (fault != null) fault.accept(p.index());
        Autograsp.Approach ap = Autograsp.backOff(touch, standoff);
        Scenario s = trialScenario(p, ap.position(), ap.rotation());
        SceneGeometry sg = s.object() == null ? null : new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K, geometry);
        if (sg != null) geometry = sg;
        HandModel m = new HandModel(s, sg, dynamics, false);
        while (m.running() && !allStalled(m)) m.step();
        GraspAssessment g = GraspAssessment.of(m.graspInput(), spec.mu(), spec.edges());
        int contacts = 0;
        String[] states = new String[3];
        for (int k = 1; k <= 3; k++) {
            contacts += m.contacts(k).size();
            states[k - 1] = m.state(k).name();
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        double[][] frames = {m.framesWorld(1), m.framesWorld(2), m.framesWorld(3)};
        if (clearance.fingersCross(frames)) {
            // fingers that closed through each other: no pose of the hand, so no grasp (force closure false, ε, volume, hold 0)
            TrialResult r = new TrialResult(p.index(), true, p.approach(), p.roll(), p.spreadCounts(), standoff, contacts,
                false, 0, 0, 0, states, m.time(), wall, "", ap.position(), ap.rotation(), TrialOutcome.FINGERS_CROSS);
            // no pose of the hand: nothing holds it
            return spec.hold() == null ? r : r.withHold(new boolean[6], Double.NEGATIVE_INFINITY);
        }
        TrialResult r = new TrialResult(p.index(), true, p.approach(), p.roll(), p.spreadCounts(), standoff, contacts,
            g.quality().forceClosure(), g.quality().epsilon(), g.quality().volume(), g.holdMinN(), states, m.time(), wall, "",
            ap.position(), ap.rotation(), TrialOutcome.of(g, touch.approach()));
        return spec.hold() == null ? r : holdTest(r, m, sg, t0);
    }

    /**
     * The trial's row with the hold test's six verdicts and smallest margin (verdicts only: a
     * failed push stops where it crossed a threshold); the trial's wall time includes it.
     */
    private TrialResult holdTest(TrialResult r, HandModel m, SceneGeometry sg, long t0) {
        HoldTest test = new HoldTest(LockedGrasp.of(m, sg, holdMass), spec.hold().settings());
        boolean[] passed = new boolean[6];
        double margin = Double.POSITIVE_INFINITY;
        for (int d = 0; d < 6; d++) {
            DirectionResult x = test.push(d, true);
            passed[d] = x.passed();
            margin = Math.min(margin, x.margin());
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        return new TrialResult(r.index(), r.ok(), r.approach(), r.roll(), r.spreadCounts(), r.standoff(), r.contacts(), r.forceClosure(),
            r.epsilon(), r.volume(), r.holdMinN(), r.finalStates(), r.simTimeS(), wall, r.error(), r.palmPosition(), r.palmRotation(),
            r.outcome(), passed, margin);
    }

    /**
     * The scenario trial {@code p.index()} runs: the one {@link #scenarioJson} writes for it
     * ({@code best} false), made directly from the template parsed once — the same pose
     * ({@link Scenario#withHandPose}, from the same position and rotation vector), the spread
     * held ({@link Scenario#withSpreadHeld}), no trace, charts or torques — instead of writing
     * and parsing that text for every trial. The same numbers (a test runs both).
     */
    Scenario trialScenario(TrialParameters p, double[] position, double[] rotation) {
        return base.withName(spec.name() + "-trial" + p.index()).withHandPose(position, rotation)
            .withSpreadHeld(p.spreadCounts()).withOutputs(false, false, false);
    }

    private static boolean allStalled(HandModel m) {
        return m.state(1) == ClutchState.STALLED && m.state(2) == ClutchState.STALLED && m.state(3) == ClutchState.STALLED;
    }

    /**
     * The trial as a scenario (JSON text): the template with the hand at the approach's pose,
     * the spread held at the trial's q_M4, and {@code name}. For a trial ({@code best} false)
     * the outputs are off; for {@code best/NN.json} they are the template's and
     * {@code objectFile} (may be null) replaces the object's file (relative to the new file).
     */
    @SuppressWarnings("unchecked")
    public String scenarioJson(TrialParameters p, double standoff, double[] position, double[] rotation, String name, boolean best, String objectFile) {
        Map<String, Object> t = new LinkedHashMap<>(template);
        t.put("name", name);
        if (best) {
            t.put("description", String.format(java.util.Locale.ROOT, "Grasp found by handsim plan %s (trial %d of %d, seed %d):"
                + " the hand approached along (%s, %s, %s) with roll %s rad, spread %d counts, standoff %s m, then closed every finger.",
                spec.target(), p.index(), spec.trials(), spec.seed(), JsonWriter.write(p.approach()[0]), JsonWriter.write(p.approach()[1]),
                JsonWriter.write(p.approach()[2]), JsonWriter.write(p.roll()), p.spreadCounts(), JsonWriter.write(standoff)));
        }
        Map<String, Object> hand = new LinkedHashMap<>();
        hand.put("position_m", position);
        hand.put("rotation_rad", rotation);
        if (t.get("hand") instanceof Map && ((Map<String, Object>) t.get("hand")).get("parameters") != null) {
            hand.put("parameters", ((Map<String, Object>) t.get("hand")).get("parameters"));   // the hand's own parameters stay
        }
        t.put("hand", hand);
        Map<String, Object> start = t.get("start_counts") instanceof Map
            ? new LinkedHashMap<>((Map<String, Object>) t.get("start_counts")) : new LinkedHashMap<>();
        start.put("M4", p.spreadCounts());
        t.put("start_counts", start);
        if (t.get("motors") instanceof Map) {
            Map<String, Object> motors = new LinkedHashMap<>((Map<String, Object>) t.get("motors"));
            motors.remove("M4");
            t.put("motors", motors);
        }
        if (objectFile != null) {
            Map<String, Object> o = new LinkedHashMap<>((Map<String, Object>) t.get("object"));
            o.put("file", objectFile);
            t.put("object", o);
        }
        if (!best) {
            Map<String, Object> out = new LinkedHashMap<>();
            out.put("trace", false);
            out.put("charts", false);
            out.put("torques", false);
            t.put("outputs", out);
        }
        return best ? JsonWriter.pretty(t) : JsonWriter.write(t);
    }

    /** The parameters of a trial (the sampler's). */
    public TrialParameters parameters(int index) {
        return sampler.sample(index);
    }

}
