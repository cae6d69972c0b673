package org.handsim.plan;

import org.handsim.scenario.NotFound;
import java.io.Serializable;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.grasp.FrictionCone;
import org.handsim.scenario.UnitRule;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.model.SceneGeometry;
import org.handsim.files.FileName;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;

/**
 * Everything a trial needs, as plain serialisable values (a Spark executor rebuilds its
 * {@link TrialRunner} from it): the trial template — a scenario as JSON text whose object file
 * is an absolute path —, the number of trials, the seed and the friction.
 * The template's hand pose and spread motor are replaced by each trial's; its object, finger
 * motors (the closing profile), time step, gravity and outputs are kept.
 *
 * @param name         the plan's name (output folder {@code plan-<name>}): the object file's stem or the scenario's name
 * @param target       TARGET as given on the command line
 * @param templateJson the template scenario, JSON text (object file absolute)
 * @param templateFile where the template's relative paths were resolved (absolute; error messages)
 * @param trials       number of trials N ≥ 1
 * @param seed         the seed of the whole plan
 * @param mu           Coulomb friction coefficient of the evaluation
 * @param edges        friction-cone edges of the evaluation
 * @param hold         the hold test run on every trial's grasp, or null (none)
 */
public record PlanSpec(String name, String target, String templateJson, String templateFile, int trials, long seed,
                       double mu, int edges, PlanHold hold) implements Serializable {
    private static final long serialVersionUID = 3L;

    /** A spec without the hold test. */
    public PlanSpec(String name, String target, String templateJson, String templateFile, int trials, long seed, double mu, int edges) {
        this(name, target, templateJson, templateFile, trials, seed, mu, edges, null);
    }

    /** This spec with the hold test {@code h} (null: none) run on every trial's grasp. */
    public PlanSpec withHold(PlanHold h) {
        return new PlanSpec(name, target, templateJson, templateFile, trials, seed, mu, edges, h);
    }

    /** The closing profile of an object-file target: every finger motor 0 → 17 500 counts (as scenarios/mug-grasp.json). */
    public static final double CLOSE_TO_COUNTS = 17_500, CLOSE_V_MAX = 5_000, CLOSE_A_MAX = 25_000;
    /** Time step of an object-file target's trials, seconds (events are located inside the step; docs/BENCHMARKS.md, Planning). */
    public static final double DEFAULT_DT = 0.05;
    /**
     * Most trials of one plan: a million — at the measured 140 to 340 trials/s of a two-core
     * machine (docs/BENCHMARKS.md, Planning) one to two hours and a plan.csv of about 200 MB;
     * 2 147 483 647 would take a year.
     */
    public static final int MAX_TRIALS = 1_000_000;

    public PlanSpec {
        if (trials < 1 || trials > MAX_TRIALS) throw new IllegalArgumentException("--trials must be in [1, " + MAX_TRIALS + "], got " + trials);
        if (!(mu >= 0) || !Double.isFinite(mu)) throw new IllegalArgumentException("--friction must be a finite number >= 0, got " + mu);
        if (edges < 1 || edges > 1024) throw new IllegalArgumentException("friction cone edges must be in [1, 1024], got " + edges);
    }

    /**
     * The spec of {@code handsim plan TARGET}: an object file (any mesh format the scenarios
     * read) is placed at the origin with the default closing profile; a {@code .json} file is a
     * scenario used as template (it must have an object).
     *
     * @param mu the Coulomb friction of the trials and of the evaluation; null: the template's
     *           {@code object.friction}, else {@link FrictionCone#DEFAULT_MU}. Written into the
     *           trials' scenarios ({@code object.friction}), so the closing and the evaluation use it
     * @throws ScenarioException naming the file (exit 3): unreadable, not a scenario, no object
     */
    public static PlanSpec forTarget(Path target, int trials, long seed, Double mu, int edges) {
        return forTarget(target, trials, seed, mu, edges, null);
    }

    /**
     * As {@link #forTarget(Path, int, long, Double, int)}, with the unit of the object file's
     * coordinates ({@code handsim plan --units}).
     *
     * @param units the object file's unit, written into the template ({@code object.units}); null
     *              ("auto"): a scenario template's own {@code object.units}, and for an object file
     *              the unit its size suggests ({@link UnitRule}: metres for a model at
     *              most 2 units across, else millimetres, as the window's import does) — so a
     *              millimetre STL (GraspIt!'s unit) is planned at its real size, not 1000 times it
     */
    public static PlanSpec forTarget(Path target, int trials, long seed, Double mu, int edges, Scenario.Units units) {
        Path abs = target.toAbsolutePath().normalize();
        String why = NotFound.problem(target);
        if (why != null) throw new ScenarioException(target + ": " + why);
        Map<String, Object> t;
        String name;
        boolean json = abs.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".json");
        if (json) {
            Scenario s = Scenario.load(abs);
            if (s.object() == null) throw new ScenarioException(target + ": field object: the template scenario has no object to grasp");
            t = parse(abs);
            @SuppressWarnings("unchecked")
            Map<String, Object> o = (Map<String, Object>) t.get("object");
            o.put("file", s.object().file().toAbsolutePath().normalize().toString());
            name = s.name();
        } else {
            name = stem(abs);
            t = objectTemplate(abs, name);
        }
        @SuppressWarnings("unchecked")
        Map<String, Object> obj = (Map<String, Object>) t.get("object");
        // the unit rule (UnitRule): a template's object.units, else the file's size; written into
        // the template, so the trials and best/*.json read the file in the unit chosen here
        if (units == null && !json) units = UnitRule.resolve(abs, Scenario.DEFAULT_DIVISIONS, null).units();
        if (units != null) obj.put("units", units.id());
        double friction = mu != null ? mu : obj.get("friction") instanceof Number ? ((Number) obj.get("friction")).doubleValue()
            : FrictionCone.DEFAULT_MU;
        obj.put("friction", friction);
        String text = JsonWriter.write(t);
        Scenario.parse(abs, text);   // the template must be a valid scenario as it will be run
        return new PlanSpec(name, target.toString(), text, abs.toString(), trials, seed, friction, edges);
    }

    /**
     * This spec with hand parameters ({@code handsim plan --tau-break}, ...) on top of the
     * template's own {@code hand.parameters}; the trials and {@code best/*.json} run with them.
     *
     * @throws ScenarioException naming the field if a value is out of range
     */
    @SuppressWarnings("unchecked")
    public PlanSpec withHandParameters(org.handsim.hand.HandParameters more) {
        if (more == null || more.isEmpty()) return this;
        Map<String, Object> t = template();
        Map<String, Object> hand = t.get("hand") instanceof Map ? (Map<String, Object>) t.get("hand") : new LinkedHashMap<>();
        Scenario s = Scenario.parse(Path.of(templateFile), templateJson);
        org.handsim.hand.HandParameters merged = s.handParameters().and(more);
        String why = merged.problem();
        if (why != null) throw new ScenarioException(templateFile + ": hand.parameters." + why);
        hand.put("parameters", merged.toJson());
        t.put("hand", hand);
        String text = JsonWriter.write(t);
        Scenario.parse(Path.of(templateFile), text);
        return new PlanSpec(name, target, text, templateFile, trials, seed, mu, edges, hold);
    }

    /** The template of a bare object file: at the origin, scale 1, the default closing profile and time step. */
    static Map<String, Object> objectTemplate(Path file, String name) {
        Map<String, Object> t = new LinkedHashMap<>();
        t.put("name", name);
        t.put("description", "grasp-planning template for " + file.getFileName());
        Map<String, Object> o = new LinkedHashMap<>();
        o.put("file", file.toString());
        o.put("position_m", List.of(0.0, 0.0, 0.0));
        o.put("rotation_rad", List.of(0.0, 0.0, 0.0));
        t.put("object", o);
        Map<String, Object> motors = new LinkedHashMap<>();
        for (String m : new String[] {"M1", "M2", "M3"}) {
            Map<String, Object> seg = new LinkedHashMap<>();
            seg.put("type", "trapezoid");
            seg.put("to", CLOSE_TO_COUNTS);
            seg.put("v_max", CLOSE_V_MAX);
            seg.put("a_max", CLOSE_A_MAX);
            motors.put(m, List.of(seg));
        }
        t.put("motors", motors);
        t.put("dt_s", DEFAULT_DT);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("trace", true);
        out.put("charts", true);
        out.put("torques", true);
        t.put("outputs", out);
        return t;
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> parse(Path file) {
        try {
            Object v = Json.parse(file.toString(), Scenario.readText(file));
            if (!(v instanceof Map)) throw new ScenarioException(file + ":1:1: a scenario must be a JSON object");
            return (Map<String, Object>) v;
        } catch (Json.JsonException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
    }

    /** A file name without its extension, reduced to the characters a scenario name allows. */
    static String stem(Path file) {
        String n = file.getFileName().toString();
        int dot = n.lastIndexOf('.');
        if (n.endsWith(".gz") && dot > 0) {
            n = n.substring(0, dot);
            dot = n.lastIndexOf('.');
        }
        if (dot > 0) n = n.substring(0, dot);
        n = n.replaceAll("[^A-Za-z0-9._-]", "_");
        return FileName.problem(n) != null ? "object" : n;
    }

    /** The unit of the object file's coordinates the trials use (the template's {@code object.units}). */
    public Scenario.Units units() {
        return Scenario.parse(Path.of(templateFile), templateJson).object().units();
    }

    /** The template as a fresh mutable map (deep copy). */
    @SuppressWarnings("unchecked")
    Map<String, Object> template() {
        return (Map<String, Object>) Json.parse(templateFile, templateJson);
    }
}
