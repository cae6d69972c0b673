package org.handsim.scenario;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.grasp.FrictionCone;
import org.handsim.hand.HandDescription;
import org.handsim.hand.HandParameters;
import org.handsim.hand.InputRanges;
import org.handsim.math.RigidTransform;
import org.handsim.trajectory.CartesianLine;
import org.handsim.trajectory.Hold;
import org.handsim.trajectory.Quintic;
import org.handsim.trajectory.Sequence;
import org.handsim.trajectory.Trajectory;
import org.handsim.trajectory.Trapezoid;
import org.handsim.mesh.MeshLimits;
import org.handsim.files.InputFile;
import org.handsim.files.FileName;
import org.handsim.text.Json;
import org.handsim.text.JsonObject;

/**
 * A simulation scenario read from JSON: where the hand and the object are, what the four
 * motors do, the step and the duration, and what to write. A bad file is a
 * {@link ScenarioException} naming the file and the field path, e.g.
 * {@code paper.json: field motors.M3[0].v_max: must be > 0, got -1}.
 *
 * <h2>File format</h2>
 * <pre>{@code
 * {
 *   "name": "paper-breakaway",
 *   "description": "...",                     // optional, free text
 *   "notes": { "any": "text" },               // optional: choices and their reasons
 *   "hand": { "position_m": [0,0,0], "rotation_rad": [0,0,0],     // world <- palm (axis-angle)
 *             "moves": [ {"type": "hold", "duration_s": 4},          // optional, free object only: the base's segments
 *                        {"type": "line", "by_m": [0,0,0.1], "v_max": 0.1, "a_max": 1},
 *                        {"type": "rotate", "axis": [1,0,0], "angle_rad": 0.5, "v_max": 1, "a_max": 5} ] },
 *   "gravity_m_s2": [-9.81, 0, 0],            // world frame
 *   "object": {                                // optional
 *     "file": "../vrml/objects/cube.wrl",      // relative to the scenario file; .wrl, .obj or .stl
 *     "position_m": [..], "rotation_rad": [..], "scale": 1.0, "divisions": 24,
 *     "units": "m",                            // the file's unit: auto (default), mm, cm or m
 *     "friction": 0.5,                         // Coulomb μ of the contacts, ≥ 0 (default 0.5)
 *     "free": true, "mass_kg": 0.3,            // optional: a free object (FreeObject), mass_kg or density_kg_m3,
 *     "inertia_kg_m2": [[..],[..],[..]], "com_m": [..],        // optional (default from the closed mesh),
 *     "velocity_m_s": [..], "angular_velocity_rad_s": [..], "release_s": 0 },   // world, at release
 *   "supports": [ {"box_m": [x,y,z], "position_m": [..], "rotation_rad": [..]}, {"file": "table.stl", ...} ],   // free object only
 *   "disturbances": [ {"from_s": 1, "to_s": 1.2, "force_N": [x,y,z], "torque_N_m": [x,y,z]} ],   // free object only; world, at its centre of mass
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
    private double[] handPose = new double[6];   // position_m, rotation_rad as written
    private double[] gravity;
    private ObjectPlacement object;
    private FreeObject freeObject;
    private List<Disturbance> disturbances = List.of();
    private List<Support> supports = List.of();
    private List<HandMove> moves = List.of();
    private double[] startCounts = new double[4];
    private Trajectory[] motors = new Trajectory[4];
    private double dt, duration;
    private boolean writeTrace, writeCharts, computeTorques;
    private int coneEdges = FrictionCone.DEFAULT_EDGES;
    private double defaultFriction = FrictionCone.DEFAULT_MU;   // μ when there is no object
    private boolean unitsBySize;   // object.units was auto: UnitRule judged the file by its size
    private JsonObject root;
    private HandDescription hand;                       // the hand file's, with hand.parameters applied
    private HandParameters handParameters = HandParameters.NONE;   // hand.parameters as written

    /**
     * The unit of an object file's coordinates (scenario field {@code object.units}: {@code mm},
     * {@code cm} or {@code m}, default {@code m}). GraspIt!'s models, and most CAD exports, are in
     * millimetres.
     */
    public enum Units {
        MM(0.001), CM(0.01), M(1.0);

        private final double metres;

        Units(double metres) { this.metres = metres; }

        /** Metres per file unit. */
        public double metres() { return metres; }

        /** The name in scenario files: mm, cm, m. */
        public String id() { return name().toLowerCase(java.util.Locale.ROOT); }

        /** The unit named {@code mm}, {@code cm} or {@code m}; null for anything else. */
        public static Units of(String id) {
            for (Units u : values()) if (u.id().equals(id)) return u;
            return null;
        }
    }

    /**
     * Where the object is, how it is tessellated and its Coulomb friction coefficient μ with the
     * fingers (≥ 0).
     *
     * @param file            the object's file (VRML97, OBJ or STL: {@link MeshFiles})
     * @param worldFromObject world ← object
     * @param scale           uniform scale in the object's frame, after the units
     * @param divisions       segments round VRML primitives
     * @param units           the file's unit of length
     * @param pose            the pose as written ({@code position_m} then {@code rotation_rad}, 6
     *                        numbers; {@code worldFromObject} is built from them), or null when
     *                        the placement was made from a transform
     * @param friction        Coulomb μ ≥ 0 of the contacts ({@link FrictionCone#DEFAULT_MU} by default)
     */
    public record ObjectPlacement(Path file, RigidTransform worldFromObject, double scale, int divisions, Units units, double[] pose,
                                  double friction) {
        public ObjectPlacement {
            if (pose != null && pose.length != 6) throw new IllegalArgumentException("pose needs 6 numbers, got " + pose.length);
            if (units == null) units = Units.M;
            FrictionCone.checkMu(friction);
        }

        /** A placement in metres from a transform, with the default friction. */
        public ObjectPlacement(Path file, RigidTransform worldFromObject, double scale, int divisions) {
            this(file, worldFromObject, scale, divisions, Units.M, null, FrictionCone.DEFAULT_MU);
        }

        /** A placement in metres from a transform with friction μ. */
        public ObjectPlacement(Path file, RigidTransform worldFromObject, double scale, int divisions, double friction) {
            this(file, worldFromObject, scale, divisions, Units.M, null, friction);
        }

        /** A placement with the default friction. */
        public ObjectPlacement(Path file, RigidTransform worldFromObject, double scale, int divisions, Units units, double[] pose) {
            this(file, worldFromObject, scale, divisions, units, pose, FrictionCone.DEFAULT_MU);
        }

        /** A copy with another friction coefficient μ ≥ 0. */
        public ObjectPlacement withFriction(double mu) {
            return new ObjectPlacement(file, worldFromObject, scale, divisions, units, pose, mu);
        }

        /**
         * A placement from a position (m) and an axis-angle rotation vector (rad), as a scenario
         * file writes it ({@link RigidTransform#fromPose}); saved back as exactly these numbers.
         */
        public static ObjectPlacement of(Path file, double[] position, double[] rotationRad, double scale, int divisions, Units units) {
            RigidTransform t = RigidTransform.fromPose(position[0], position[1], position[2], rotationRad[0], rotationRad[1], rotationRad[2]);
            double[] p = {position[0], position[1], position[2], rotationRad[0], rotationRad[1], rotationRad[2]};
            return new ObjectPlacement(file, t, scale, divisions, units, p);
        }

        /** What the file's coordinates are multiplied by to place the mesh in metres: units × scale. */
        public double meshScale() { return units.metres() * scale; }

        /** Position, m (a new array). */
        public double[] position() { return pose != null ? java.util.Arrays.copyOfRange(pose, 0, 3) : worldFromObject.origin(); }

        /** Rotation as an axis-angle vector, rad (a new array). */
        public double[] rotation() { return pose != null ? java.util.Arrays.copyOfRange(pose, 3, 6) : worldFromObject.rotationVector(); }

        /** The same at another pose. */
        public ObjectPlacement withPose(double[] position, double[] rotationRad) {
            return of(file, position, rotationRad, scale, divisions, units).withFriction(friction);
        }

        /** The same with other divisions. */
        public ObjectPlacement withDivisions(int d) {
            return new ObjectPlacement(file, worldFromObject, scale, d, units, pose, friction);
        }

        /** The same with another scale and unit. */
        public ObjectPlacement withScale(double s, Units u) {
            return new ObjectPlacement(file, worldFromObject, s, divisions, u, pose, friction);
        }
    }

    private Scenario(Path file, JsonObject r, HandDescription hand) {
        this.file = file;
        this.hand = hand;
        this.root = r;
        r.allowOnly("name", "description", "notes", "hand", "gravity_m_s2", "object", "supports", "disturbances", "start_counts", "motors", "dt_s",
            "duration_s", "outputs");
        name = r.string("name");
        String bad = FileName.problem(name);
        if (bad != null) throw r.error("name", bad + ", got \"" + name + "\"");
        description = r.string("description", "");
        if (r.has("hand")) {
            JsonObject h = r.object("hand");
            h.allowOnly("position_m", "rotation_rad", "parameters", "moves");
            moves = List.copyOf(HandMove.parse(h));
            if (h.has("parameters")) {
                handParameters = HandParametersJson.parse(h.object("parameters"));
                this.hand = hand.with(handParameters);
            }
            handPose = pose(h);
            worldFromPalm = RigidTransform.fromPose(handPose[0], handPose[1], handPose[2], handPose[3], handPose[4], handPose[5]);
        } else {
            worldFromPalm = RigidTransform.IDENTITY;
        }
        gravity = r.has("gravity_m_s2") ? r.numbers("gravity_m_s2", 3) : new double[] {0, 0, -9.81};
        for (int i = 0; i < 3; i++) {
            String why = InputRanges.GRAVITY.problem(gravity[i]);
            if (why != null) throw r.error("gravity_m_s2[" + i + "]", why);
        }
        if (r.has("object")) {
            JsonObject o = r.object("object");
            String[] fields = {"file", "position_m", "rotation_rad", "scale", "divisions", "units", "friction"};
            String[] all = java.util.Arrays.copyOf(fields, fields.length + FreeObject.FIELDS.length);
            System.arraycopy(FreeObject.FIELDS, 0, all, fields.length, FreeObject.FIELDS.length);
            o.allowOnly(all);
            freeObject = FreeObject.parse(o);
            Path dir = file.toAbsolutePath().getParent();
            Path f = dir.resolve(o.string("file")).normalize();
            String why = InputFile.problem(f);
            if (why != null) throw o.error("file", why + ": " + f);
            double scale = o.has("scale") ? o.number("scale") : 1.0;
            String scaleWhy = MeshLimits.scaleProblem(scale);
            if (scaleWhy != null) throw o.error("scale", scaleWhy);
            int div = o.has("divisions") ? o.integer("divisions") : DEFAULT_DIVISIONS;
            if (div < 3 || div > 1024) throw o.error("divisions", "must be in [3, 1024], got " + div);
            // UnitRule: absent or "auto" is judged by the file's size, as every command does
            Units chosen = null;
            if (o.has("units") && !UnitRule.AUTO.equals(o.string("units"))) {
                chosen = Units.of(o.string("units"));
                if (chosen == null) throw o.error("units", "must be auto, mm, cm or m, got \"" + o.string("units") + "\"");
            }
            double[] op = pose(o);
            UnitRule.Choice uc = UnitRule.resolve(f, div, chosen);
            Units units = uc.units();
            unitsBySize = uc.bySize();
            object = ObjectPlacement.of(f, java.util.Arrays.copyOfRange(op, 0, 3), java.util.Arrays.copyOfRange(op, 3, 6), scale, div, units)
                .withFriction(o.has("friction") ? friction(o) : FrictionCone.DEFAULT_MU);
        } else {
            object = null;
        }
        if (handParameters.friction() != null) {
            // the fingers' friction on the object: one value, given once
            JsonObject o = r.has("object") ? r.object("object") : null;
            if (o != null && o.has("friction") && o.number("friction") != handParameters.friction()) {
                throw r.object("hand").object("parameters").error("friction", "differs from object.friction (" + o.number("friction")
                    + "): give the contacts' friction once");
            }
            if (object != null) object = object.withFriction(handParameters.friction());
            defaultFriction = handParameters.friction();
        }
        if (!moves.isEmpty() && freeObject == null) {
            throw r.object("hand").error("moves", "carry a free object: add \"free\": true to the object, or remove them");
        }
        if (r.has("supports")) {
            int n = r.list("supports").size();
            if (n > 0 && freeObject == null) throw r.error("supports", "hold up a free object: add \"free\": true to the object, or remove them");
            List<Support> sup = new ArrayList<>();
            for (int i = 0; i < n; i++) sup.add(Support.parse(r.objectAt("supports", i), file.toAbsolutePath().getParent(), Scenario::pose));
            supports = List.copyOf(sup);
        }
        disturbances = List.copyOf(Disturbance.parse(r, freeObject != null));
        hand = this.hand;
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
        String steps = stepsProblem(duration, dt);
        if (steps != null) {
            // blame the field that is out of the ordinary: a duration too long even at 1 ms, else the step
            boolean longRun = r.has("duration_s") && stepsProblem(duration, Math.max(dt, 0.001)) != null;
            throw r.error(longRun ? "duration_s" : "dt_s", steps);
        }
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

    /** {@code object.friction}, within {@link FrictionCone#muProblem}'s range. */
    private static double friction(JsonObject o) {
        double mu = o.number("friction");
        String why = FrictionCone.muProblem(mu);
        if (why != null) throw o.error("friction", why);
        return mu;
    }

    /** {@code position_m} then {@code rotation_rad} (default 0), each within {@link RigidTransform#poseProblem}'s range. */
    private static double[] pose(JsonObject o) {
        double[] p = o.has("position_m") ? o.numbers("position_m", 3) : new double[3];
        double[] r = o.has("rotation_rad") ? o.numbers("rotation_rad", 3) : new double[3];
        String why = RigidTransform.poseProblem("position_m", p, "rotation_rad", r);
        if (why != null) {
            String field = why.substring(0, why.indexOf('['));
            throw o.error(field + why.substring(field.length(), why.indexOf(']') + 1), why.substring(why.indexOf(']') + 2));
        }
        return new double[] {p[0], p[1], p[2], r[0], r[1], r[2]};
    }

    /** A positive number within {@code range}, else an error naming the field. */
    private static double inRange(JsonObject o, String field, InputRanges.Range range) {
        double v = o.positive(field);
        String why = range.problem(v);
        if (why != null) throw o.error(field, why);
        return v;
    }

    private static double counts(JsonObject o, String field, double max) {
        double q = o.number(field);
        if (q < 0 || q > max) throw o.error(field, "must be in [0, " + (long) max + "] counts, got " + q);
        return q;
    }

    /**
     * Refuses a segment whose set-point moves faster or accelerates harder than the hand's motors
     * ({@code hand.parameters.motor_v_max_counts_s}, {@code motor_a_max_counts_s2}): a trapezoid
     * by its {@code v_max} and {@code a_max}, any other by its velocity and acceleration sampled
     * at 1 000 points, the error naming the segment.
     */
    private static void motorLimits(JsonObject s, Trajectory t, HandDescription hand) {
        if (t instanceof Trapezoid) {
            if (s.number("v_max") > hand.motorVMax()) throw s.error("v_max", "is above the hand's motor speed limit "
                + org.handsim.text.Decimal.format(hand.motorVMax()) + " counts/s (hand.parameters.motor_v_max_counts_s), got " + s.number("v_max"));
            if (s.number("a_max") > hand.motorAMax()) throw s.error("a_max", "is above the hand's motor acceleration limit "
                + org.handsim.text.Decimal.format(hand.motorAMax()) + " counts/s^2 (hand.parameters.motor_a_max_counts_s2), got " + s.number("a_max"));
            return;
        }
        double[] o = new double[3];
        double v = 0, a = 0;
        for (int i = 0; i <= 1000; i++) {
            t.sample(t.duration() * i / 1000, o);
            v = Math.max(v, Math.abs(o[1]));
            a = Math.max(a, Math.abs(o[2]));
        }
        if (v > hand.motorVMax() * (1 + 1e-9)) throw s.error("type", "moves at up to " + org.handsim.text.Decimal.format(v)
            + " counts/s, above the hand's motor speed limit " + org.handsim.text.Decimal.format(hand.motorVMax()) + " counts/s (hand.parameters.motor_v_max_counts_s)");
        if (a > hand.motorAMax() * (1 + 1e-9)) throw s.error("type", "accelerates at up to " + org.handsim.text.Decimal.format(a)
            + " counts/s^2, above the hand's motor acceleration limit " + org.handsim.text.Decimal.format(hand.motorAMax()) + " counts/s^2 (hand.parameters.motor_a_max_counts_s2)");
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
                        t = new Trapezoid(at, counts(s, "to", max), inRange(s, "v_max", InputRanges.MOTOR_SPEED),
                            inRange(s, "a_max", InputRanges.MOTOR_ACCELERATION));
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
            motorLimits(s, t, hand);
            parts.add(t);
            at = t.end();
        }
        return parts.size() == 1 ? parts.get(0) : new Sequence(parts);
    }

    /** Largest scenario or sweep file, bytes (ours are a few kilobytes; a sweep of 10 000 runs about 2 MB). */
    public static final long MAX_FILE_BYTES = 16 << 20;

    /**
     * The text of a scenario or sweep file ({@link InputFile#readText}: a regular file of at most
     * {@link #MAX_FILE_BYTES}, UTF-8 with an optional byte-order mark).
     *
     * @throws ScenarioException naming the file: missing, not a regular file (a FIFO is refused
     *                           before it is opened), too large, not UTF-8 (line and byte)
     */
    public static String readText(Path file) {
        String why = NotFound.problem(file);   // says where a relative path was looked for
        if (why != null) throw new ScenarioException(file + ": " + why);
        try {
            return InputFile.readText(file, MAX_FILE_BYTES, "the limit of scenario and sweep files");
        } catch (InputFile.InputFileException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
    }

    /** Loads a scenario file (the hand is the BarrettHand). */
    public static Scenario load(Path file) {
        return parse(file, readText(file));
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
    /** The object's motion when it is free ({@code "object": {"free": true, ...}}), else null: fixed in place. */
    public FreeObject freeObject() { return freeObject; }
    /** The hand base's segments ({@code hand.moves}), played in order; empty when the base stays put. */
    public List<HandMove> moves() { return moves; }
    /** Static bodies under a free object ({@code "supports"}); empty without them. */
    public List<Support> supports() { return supports; }
    /** Wrenches on the free object ({@code "disturbances"}), in the order given; empty without them. */
    public List<Disturbance> disturbances() { return disturbances; }
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
    /**
     * Whether the object's unit was judged from its file's size ({@code object.units} absent or
     * {@code auto}: {@link UnitRule}); the commands then print {@link #unitNotice}.
     */
    public boolean unitsBySize() { return unitsBySize; }

    /**
     * The one-line notice that the object's size chose its unit ({@link UnitRule#notice}), or
     * null when the unit was written or there is no object.
     *
     * @param who the command, e.g. {@code handsim run}
     */
    public String unitNotice(String who) {
        return object != null && unitsBySize ? UnitRule.notice(who, object.file(), object.units(), "object.units") : null;
    }

    /** The hand this scenario runs: the hand file's, with {@code hand.parameters} applied. */
    public HandDescription hand() { return hand; }

    /** The scenario's {@code hand.parameters} as written ({@link HandParameters#NONE} when absent). */
    public HandParameters handParameters() { return handParameters; }

    /**
     * This scenario with more hand parameters on top of its own (the command line's:
     * {@code --tau-break}, {@code --clutch-windup}), read again from its JSON so every derived
     * value and every check follows.
     *
     * @throws ScenarioException naming the field if a value is out of range
     */
    public Scenario withHandParameters(HandParameters more) {
        if (more == null || more.isEmpty()) return this;
        HandParameters merged = handParameters.and(more);
        String why = merged.problem();
        if (why != null) throw new ScenarioException(file + ": hand.parameters." + why);
        @SuppressWarnings("unchecked")
        Scenario s = withJson(j -> ((java.util.Map<String, Object>) j.get("hand")).put("parameters", merged.toJson()));
        s.root = root;
        return s;
    }

    /**
     * This scenario as its file would be with {@code edit} made to its JSON ({@link #toJson},
     * relative to this scenario's folder), read again: every field checked and every derived
     * value made as a file with that text would have them, so what runs is what
     * {@link #toJson} of the result writes.
     *
     * @throws ScenarioException naming the field, as for a file, when an edited value is refused
     */
    public Scenario withJson(java.util.function.Consumer<java.util.Map<String, Object>> edit) {
        java.util.Map<String, Object> j = toJson(file.toAbsolutePath().getParent());
        edit.accept(j);
        return parse(file, org.handsim.text.JsonWriter.write(j));
    }

    /** The parsed file (for fields other tools add). */
    public JsonObject json() { return root; }

    /**
     * This scenario as a scenario file's JSON (the format above), to be written into the folder
     * {@code dir}: the object's file relative to it (absolute when it cannot be). Every number is
     * the one this scenario runs with — poses as their position and rotation vector, trajectories
     * as their segments, dt and the duration — so {@link #parse} of the written text (with
     * {@code JsonWriter}'s shortest round-trip numbers) builds a scenario that simulates the same
     * steps to the last digit. Description and notes are kept.
     */
    public java.util.Map<String, Object> toJson(Path dir) {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("name", name);
        if (!description.isEmpty()) m.put("description", description);
        if (root != null && root.raw("notes") != null) m.put("notes", root.raw("notes"));
        java.util.Map<String, Object> h = new java.util.LinkedHashMap<>();
        h.put("position_m", java.util.Arrays.copyOfRange(handPose, 0, 3));
        h.put("rotation_rad", java.util.Arrays.copyOfRange(handPose, 3, 6));
        if (!handParameters.isEmpty()) h.put("parameters", handParameters.toJson());
        if (!moves.isEmpty()) {
            List<Object> l = new ArrayList<>();
            for (HandMove x : moves) l.add(x.toJson());
            h.put("moves", l);
        }
        m.put("hand", h);
        m.put("gravity_m_s2", gravity.clone());
        if (object != null) {
            java.util.Map<String, Object> o = new java.util.LinkedHashMap<>();
            o.put("file", fileName(dir, object.file()));
            o.put("position_m", object.position());
            o.put("rotation_rad", object.rotation());
            o.put("scale", object.scale());
            o.put("units", object.units().id());
            o.put("divisions", object.divisions());
            o.put("friction", object.friction());
            if (freeObject != null) freeObject.toJson(o);
            m.put("object", o);
        }
        if (!supports.isEmpty()) {
            List<Object> l = new ArrayList<>();
            for (Support x : supports) l.add(x.toJson(dir));
            m.put("supports", l);
        }
        if (!disturbances.isEmpty()) {
            List<Object> d = new ArrayList<>();
            for (Disturbance x : disturbances) d.add(x.toJson());
            m.put("disturbances", d);
        }
        java.util.Map<String, Object> start = new java.util.LinkedHashMap<>();
        for (int i = 0; i < 4; i++) start.put("M" + (i + 1), startCounts[i]);
        m.put("start_counts", start);
        java.util.Map<String, Object> mot = new java.util.LinkedHashMap<>();
        for (int i = 0; i < 4; i++) {
            Trajectory t = motors[i];
            if (t instanceof Hold && t.duration() == 0 && t.start() == startCounts[i]) continue;   // the default
            List<Object> segs = new ArrayList<>();
            addSegments(t, segs);
            mot.put("M" + (i + 1), segs);
        }
        m.put("motors", mot);
        m.put("dt_s", dt);
        m.put("duration_s", duration);
        java.util.Map<String, Object> out = new java.util.LinkedHashMap<>();
        out.put("trace", writeTrace);
        out.put("charts", writeCharts);
        out.put("torques", computeTorques);
        m.put("outputs", out);
        return m;
    }

    /** {@code file} as a scenario in {@code dir} names it: relative to dir with '/', absolute when it cannot be. */
    static String fileName(Path dir, Path file) {
        Path f = file.toAbsolutePath().normalize();
        try {
            return dir.toAbsolutePath().normalize().relativize(f).toString().replace(java.io.File.separatorChar, '/');
        } catch (IllegalArgumentException e) {
            return f.toString();
        }
    }

    private static void addSegments(Trajectory t, List<Object> out) {
        if (t instanceof Sequence) {
            for (Trajectory s : ((Sequence) t).segments()) addSegments(s, out);
        } else {
            out.add(t.segment());
        }
    }

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

    /**
     * Most steps one run may take: ten million — at the 7 000 to 44 000 steps/s of a run, 4 to
     * 25 minutes, and with the trace (about 200 bytes a step) 2 GB of {@code trace.csv}. The
     * paper's experiment takes 8 947; a finer study of the time step is the tradeoff chart's.
     */
    public static final long MAX_STEPS = 10_000_000;

    /**
     * Why a run of {@code duration} seconds at {@code dt} would take too many steps
     * ({@link #MAX_STEPS}), the count written as people read it ({@code 8.9 billion steps}), or
     * null when it would not.
     */
    public static String stepsProblem(double duration, double dt) {
        double steps = Math.ceil(duration / dt - 1e-9);
        if (steps <= MAX_STEPS) return null;
        return "needs " + org.handsim.text.Decimal.count(steps) + " steps (" + org.handsim.text.Decimal.format(duration) + " s at "
            + org.handsim.text.Decimal.format(dt) + " s a step), more than the limit of " + org.handsim.text.Decimal.count(MAX_STEPS)
            + " (about 25 minutes and 2 GB of trace)";
    }

    /**
     * A copy with another time step (seconds, in (0, 0.1]).
     *
     * @throws IllegalArgumentException out of range, or too many steps ({@link #stepsProblem})
     */
    public Scenario withDt(double newDt) {
        if (!(newDt > 0) || newDt > 0.1) throw new IllegalArgumentException("dt must be in (0, 0.1] s, got " + newDt);
        String steps = stepsProblem(duration, newDt);
        if (steps != null) throw new IllegalArgumentException(steps);
        Scenario c = copy();
        c.dt = newDt;
        return c;
    }

    /** A copy with another duration (seconds). */
    public Scenario withDuration(double seconds) {
        if (!(seconds > 0)) throw new IllegalArgumentException("duration must be > 0, got " + seconds);
        String steps = stepsProblem(seconds, dt);
        if (steps != null) throw new IllegalArgumentException(steps);
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
        if (placement == null) {
            c.freeObject = null;
            c.disturbances = List.of();
            c.supports = List.of();
            c.moves = List.of();
        }
        c.unitsBySize = false;   // a placement made by the caller carries a chosen unit
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

    /**
     * A copy with the hand at another pose: the palm's position (m) and axis-angle rotation
     * (rad), built into {@code world ← palm} as the parser builds {@code hand}, so the copy runs
     * as the scenario file with these numbers as {@code hand.position_m} and
     * {@code hand.rotation_rad} would.
     */
    public Scenario withHandPose(double[] position, double[] rotationRad) {
        Scenario c = copy();
        c.worldFromPalm = RigidTransform.fromPose(position[0], position[1], position[2], rotationRad[0], rotationRad[1], rotationRad[2]);
        c.handPose = new double[] {position[0], position[1], position[2], rotationRad[0], rotationRad[1], rotationRad[2]};
        return c;
    }

    /**
     * A copy whose spread motor M4 holds {@code counts} from t = 0 — what the scenario file with
     * {@code start_counts.M4} = counts and no {@code motors.M4} would run: finger motors whose
     * segments depend on the spread (fingertip lines) are made again from this scenario's
     * {@code motors}, and a duration the file does not give is again the longest motor's.
     *
     * @throws ScenarioException naming the field if the counts are out of range or a finger's
     *                           line cannot be followed at this spread
     */
    public Scenario withSpreadHeld(double counts) {
        HandDescription hand = this.hand;
        if (!(counts >= 0 && counts <= hand.spreadCountsMax())) {
            throw new ScenarioException(file + ": field start_counts.M4: must be in [0, " + (long) hand.spreadCountsMax() + "] counts, got " + counts);
        }
        Scenario c = copy();
        c.startCounts[3] = counts;
        c.motors[3] = new Hold(counts, 0);
        JsonObject mot = root != null && root.has("motors") ? root.object("motors") : null;
        double longest = 0;
        try {
            for (int m = 0; m < 4; m++) {
                if (m < 3 && mot != null && mot.has("M" + (m + 1)) && dependsOnSpread(c.motors[m])) {
                    c.motors[m] = c.segments(mot, "M" + (m + 1), m, hand);
                }
                longest = Math.max(longest, c.motors[m].duration());
            }
        } catch (Json.JsonException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
        if (root == null || !root.has("duration_s")) c.duration = longest;
        return c;
    }

    private static boolean dependsOnSpread(Trajectory t) {
        if (t instanceof CartesianLine) return true;
        if (t instanceof Sequence) {
            for (Trajectory s : ((Sequence) t).segments()) if (dependsOnSpread(s)) return true;
        }
        return false;
    }

    /** A copy that writes (or not) a trace and charts and computes (or not) joint torques, as {@code outputs}. */
    public Scenario withOutputs(boolean trace, boolean charts, boolean torques) {
        Scenario c = copy();
        c.writeTrace = trace;
        c.writeCharts = charts;
        c.computeTorques = torques;
        return c;
    }

    /** A copy with torques computed or not (off: only a BLOCKED finger's, which its clutch torque includes). */
    public Scenario withTorques(boolean on) {
        Scenario c = copy();
        c.computeTorques = on;
        return c;
    }
}
