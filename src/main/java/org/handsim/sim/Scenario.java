package org.handsim.sim;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.grasp.FrictionCone;
import org.handsim.hand.HandDescription;
import org.handsim.math.RigidTransform;
import org.handsim.sim.trajectory.CartesianLine;
import org.handsim.sim.trajectory.Hold;
import org.handsim.sim.trajectory.Quintic;
import org.handsim.sim.trajectory.Sequence;
import org.handsim.sim.trajectory.Trajectory;
import org.handsim.sim.trajectory.Trapezoid;
import org.handsim.util.Json;
import org.handsim.util.JsonObject;

/**
 * A simulation scenario read from JSON: where the hand and the object are, what the four
 * motors do, the step and the duration, and what to write. A bad file is a
 * {@link ScenarioException} naming the file and the field path, e.g.
 * {@code paper.json: field motors.M3[0].v_max: must be > 0, got -1.0}.
 *
 * <h2>File format</h2>
 * <pre>{@code
 * {
 *   "name": "paper-breakaway",
 *   "description": "...",                     // optional, free text
 *   "notes": { "any": "text" },               // optional: choices and their reasons
 *   "hand": { "position_m": [0,0,0], "rotation_rad": [0,0,0] },   // world <- palm (axis-angle)
 *   "gravity_m_s2": [-9.81, 0, 0],            // world frame
 *   "object": {                                // optional
 *     "file": "../vrml/objects/cube.wrl",      // relative to the scenario file
 *     "position_m": [..], "rotation_rad": [..], "scale": 1.0, "divisions": 24,
 *     "friction": 0.5 },                       // Coulomb μ of the contacts, ≥ 0 (default 0.5)
 *   "start_counts": { "M1": 0, "M2": 0, "M3": 0, "M4": 0 },        // optional, default 0
 *   "motors": {                                // each motor: a list of segments played in order
 *     "M3": [ {"type": "trapezoid", "to": 17500, "v_max": 5000, "a_max": 25000},
 *             {"type": "hold", "duration_s": 0.5},
 *             {"type": "quintic", "to": 0, "duration_s": 2.0},
 *             {"type": "line", "target_m": [x,y,z], "duration_s": 1.0} ] },   // fingertip line, {k0}
 *   "dt_s": 0.001, "duration_s": 9.0,          // duration optional: default the longest motor
 *   "outputs": { "trace": true, "charts": true, "torques": true }
 * }
 * }</pre>
 * Motors M1–M3 drive fingers 1–3 (counts in [0, 17 500]); M4 is the spread (counts in [0, 3 150]).
 *
 * <p><b>Friction.</b> {@code object.friction} is the Coulomb coefficient μ of every contact
 * with the object (default {@link FrictionCone#DEFAULT_MU} = 0.5; 0 is frictionless, as in the
 * paper's model). The contact forces of the simulation and the grasp analysis use it with the
 * friction cone linearised with {@link #coneEdges()} edges ({@link FrictionCone}, DESIGN.md
 * decision 5); commands override both ({@code --friction}, {@code --edges}).
 */
public final class Scenario implements Cloneable {
    /** The object's {@code divisions} when the file does not give it. */
    public static final int DEFAULT_DIVISIONS = 24;

    // effectively immutable: only the with...() copies below assign after construction
    private String name, description;
    private Path file;
    private RigidTransform worldFromPalm;
    private double[] gravity;
    private ObjectPlacement object;
    private double[] startCounts = new double[4];
    private Trajectory[] motors = new Trajectory[4];
    private double dt, duration;
    private boolean writeTrace, writeCharts, computeTorques;
    private int coneEdges = FrictionCone.DEFAULT_EDGES;
    private double defaultFriction = FrictionCone.DEFAULT_MU;   // μ when there is no object
    private JsonObject root;

    /**
     * Where the object is, how it is tessellated and its Coulomb friction coefficient μ with the
     * fingers (≥ 0).
     */
    public record ObjectPlacement(Path file, RigidTransform worldFromObject, double scale, int divisions, double friction) {
        public ObjectPlacement {
            FrictionCone.checkMu(friction);
        }

        /** A placement with the default friction, {@link FrictionCone#DEFAULT_MU}. */
        public ObjectPlacement(Path file, RigidTransform worldFromObject, double scale, int divisions) {
            this(file, worldFromObject, scale, divisions, FrictionCone.DEFAULT_MU);
        }

        /** A copy with another friction coefficient μ ≥ 0. */
        public ObjectPlacement withFriction(double mu) {
            return new ObjectPlacement(file, worldFromObject, scale, divisions, mu);
        }
    }

    private Scenario(Path file, JsonObject r, HandDescription hand) {
        this.file = file;
        this.root = r;
        r.allowOnly("name", "description", "notes", "hand", "gravity_m_s2", "object", "start_counts", "motors", "dt_s", "duration_s", "outputs");
        name = r.string("name");
        if (!name.matches("[A-Za-z0-9._-]+")) throw r.error("name", "must be letters, digits, '.', '_' or '-' (it names the output folder), got \"" + name + "\"");
        description = r.string("description", "");
        if (r.has("hand")) {
            JsonObject h = r.object("hand");
            h.allowOnly("position_m", "rotation_rad");
            worldFromPalm = pose(h);
        } else {
            worldFromPalm = RigidTransform.IDENTITY;
        }
        gravity = r.has("gravity_m_s2") ? r.numbers("gravity_m_s2", 3) : new double[] {0, 0, -9.81};
        if (r.has("object")) {
            JsonObject o = r.object("object");
            o.allowOnly("file", "position_m", "rotation_rad", "scale", "divisions", "friction");
            Path dir = file.toAbsolutePath().getParent();
            Path f = dir.resolve(o.string("file")).normalize();
            if (!Files.isRegularFile(f)) throw o.error("file", "no such file: " + f);
            double scale = o.has("scale") ? o.positive("scale") : 1.0;
            int div = o.has("divisions") ? o.integer("divisions") : DEFAULT_DIVISIONS;
            if (div < 3 || div > 1024) throw o.error("divisions", "must be in [3, 1024], got " + div);
            double mu = o.has("friction") ? o.nonNegative("friction") : FrictionCone.DEFAULT_MU;
            object = new ObjectPlacement(f, pose(o), scale, div, mu);
        } else {
            object = null;
        }
        dt = r.positive("dt_s");
        if (dt > 0.1) throw r.error("dt_s", "must be at most 0.1 s, got " + dt);

        JsonObject start = r.has("start_counts") ? r.object("start_counts") : null;
        if (start != null) start.allowOnly("M1", "M2", "M3", "M4");
        for (int m = 0; m < 4; m++) {
            String key = "M" + (m + 1);
            double max = m == 3 ? hand.spreadCountsMax() : hand.fingerCountsMax();
            startCounts[m] = start != null && start.has(key) ? counts(start, key, max) : 0;
        }
        JsonObject mot = r.has("motors") ? r.object("motors") : null;
        if (mot != null) mot.allowOnly("M1", "M2", "M3", "M4");
        double longest = 0;
        for (int m = 0; m < 4; m++) {
            String key = "M" + (m + 1);
            if (mot != null && mot.has(key)) motors[m] = segments(mot, key, m, hand);
            else motors[m] = new Hold(startCounts[m], 0);
            longest = Math.max(longest, motors[m].duration());
        }
        duration = r.has("duration_s") ? r.positive("duration_s") : longest;
        if (duration / dt > 5e8) throw r.error("duration_s", "needs " + (long) (duration / dt) + " steps at dt_s = " + dt + ": too many");
        if (r.has("outputs")) {
            JsonObject out = r.object("outputs");
            out.allowOnly("trace", "charts", "torques");
            writeTrace = out.bool("trace", true);
            writeCharts = out.bool("charts", true);
            computeTorques = out.bool("torques", true);
        } else {
            writeTrace = writeCharts = computeTorques = true;
        }
    }

    private static RigidTransform pose(JsonObject o) {
        double[] p = o.has("position_m") ? o.numbers("position_m", 3) : new double[3];
        double[] r = o.has("rotation_rad") ? o.numbers("rotation_rad", 3) : new double[3];
        return RigidTransform.fromPose(p[0], p[1], p[2], r[0], r[1], r[2]);
    }

    private static double counts(JsonObject o, String field, double max) {
        double q = o.number(field);
        if (q < 0 || q > max) throw o.error(field, "must be in [0, " + (long) max + "] counts, got " + q);
        return q;
    }

    private Trajectory segments(JsonObject mot, String key, int m, HandDescription hand) {
        int n = mot.list(key).size();
        if (n == 0) return new Hold(startCounts[m], 0);
        double max = m == 3 ? hand.spreadCountsMax() : hand.fingerCountsMax();
        List<Trajectory> parts = new ArrayList<>();
        double at = startCounts[m];
        for (int i = 0; i < n; i++) {
            JsonObject s = mot.objectAt(key, i);
            String type = s.string("type");
            Trajectory t;
            try {
                switch (type) {
                    case "trapezoid":
                        s.allowOnly("type", "to", "v_max", "a_max");
                        t = new Trapezoid(at, counts(s, "to", max), s.positive("v_max"), s.positive("a_max"));
                        break;
                    case "quintic":
                        s.allowOnly("type", "to", "duration_s");
                        t = new Quintic(at, counts(s, "to", max), s.positive("duration_s"));
                        break;
                    case "hold":
                        s.allowOnly("type", "duration_s");
                        t = new Hold(at, s.nonNegative("duration_s"));
                        break;
                    case "line":
                        s.allowOnly("type", "target_m", "duration_s");
                        if (m == 3) throw s.error("type", "a fingertip line needs a finger motor (M1-M3), not the spread M4");
                        t = new CartesianLine(m + 1, at, startCounts[3], s.numbers("target_m", 3), s.positive("duration_s"));
                        break;
                    default:
                        throw s.error("type", "must be trapezoid, quintic, hold or line, got \"" + type + "\"");
                }
            } catch (IllegalArgumentException e) {
                throw s.error("type", e.getMessage());
            }
            parts.add(t);
            at = t.end();
        }
        return parts.size() == 1 ? parts.get(0) : new Sequence(parts);
    }

    /** Loads a scenario file (the hand is the BarrettHand). */
    public static Scenario load(Path file) {
        String text;
        try {
            text = Files.readString(file);
        } catch (IOException e) {
            throw new ScenarioException(file + ": cannot read: " + e.getMessage(), e);
        }
        return parse(file, text);
    }

    /** Parses scenario text; {@code file} names it and anchors relative paths. */
    public static Scenario parse(Path file, String text) {
        try {
            return new Scenario(file, JsonObject.parse(file.toString(), text), HandDescription.barrettHand());
        } catch (Json.JsonException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
    }

    public String name() { return name; }
    public String description() { return description; }
    public Path file() { return file; }
    /** {@code world ← palm}. */
    public RigidTransform worldFromPalm() { return worldFromPalm; }
    /** Gravity in the world frame, m/s² (a new array). */
    public double[] gravity() { return gravity.clone(); }
    /** The object, or null when the scene has none. */
    public ObjectPlacement object() { return object; }
    /** Motor m (0..3 = M1..M4) set-point trajectory. */
    public Trajectory motor(int m) { return motors[m]; }
    /** Initial counts of motor m (0..3). */
    public double startCounts(int m) { return startCounts[m]; }
    public double dt() { return dt; }
    public double duration() { return duration; }
    public boolean writeTrace() { return writeTrace; }
    public boolean writeCharts() { return writeCharts; }
    public boolean computeTorques() { return computeTorques; }
    /**
     * Coulomb coefficient μ of the contacts: the object's {@code friction}, or
     * {@link FrictionCone#DEFAULT_MU} when the scene has no object (analytic test shapes).
     */
    public double friction() { return object != null ? object.friction() : defaultFriction; }
    /** Edges m of the linearised friction cones (default {@link FrictionCone#DEFAULT_EDGES}). */
    public int coneEdges() { return coneEdges; }
    /** The parsed file (for fields other tools add). */
    public JsonObject json() { return root; }

    private Scenario copy() {
        try {
            Scenario c = (Scenario) super.clone();
            c.gravity = gravity.clone();
            c.startCounts = startCounts.clone();
            c.motors = motors.clone();
            return c;
        } catch (CloneNotSupportedException e) {
            throw new AssertionError(e);
        }
    }

    /** A copy with another time step (seconds, in (0, 0.1]). */
    public Scenario withDt(double newDt) {
        if (!(newDt > 0) || newDt > 0.1) throw new IllegalArgumentException("dt must be in (0, 0.1] s, got " + newDt);
        Scenario c = copy();
        c.dt = newDt;
        return c;
    }

    /** A copy with another duration (seconds). */
    public Scenario withDuration(double seconds) {
        if (!(seconds > 0)) throw new IllegalArgumentException("duration must be > 0, got " + seconds);
        Scenario c = copy();
        c.duration = seconds;
        return c;
    }

    /** A copy with another name (the output folder). */
    public Scenario withName(String newName) {
        Scenario c = copy();
        c.name = newName;
        return c;
    }

    /** A copy with another object (null: none). */
    public Scenario withObject(ObjectPlacement placement) {
        Scenario c = copy();
        c.object = placement;
        return c;
    }

    /** A copy with another gravity vector (world frame, m/s²). */
    public Scenario withGravity(double[] g) {
        Scenario c = copy();
        c.gravity = g.clone();
        return c;
    }

    /** A copy where motor m (0..3) follows {@code t} from t = 0 (its start counts become t's start). */
    public Scenario withMotor(int m, Trajectory t) {
        Scenario c = copy();
        c.motors[m] = t;
        c.startCounts[m] = t.start();
        c.duration = Math.max(c.duration, t.duration());
        return c;
    }

    /**
     * A copy with another Coulomb coefficient μ ≥ 0 (the object's; without an object, the one
     * analytic contact back ends get).
     */
    public Scenario withFriction(double mu) {
        FrictionCone.checkMu(mu);
        Scenario c = copy();
        if (c.object != null) c.object = c.object.withFriction(mu);
        c.defaultFriction = mu;
        return c;
    }

    /** A copy whose friction cones have m edges (1..1024). */
    public Scenario withConeEdges(int m) {
        FrictionCone.checkEdges(m);
        Scenario c = copy();
        c.coneEdges = m;
        return c;
    }

    /** A copy with torques computed or not (the clutch does not need them). */
    public Scenario withTorques(boolean on) {
        Scenario c = copy();
        c.computeTorques = on;
        return c;
    }
}
