package org.handsim.hold;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.body.MassProperties;
import org.handsim.body.ProximityContacts;
import org.handsim.clutch.ClutchState;
import org.handsim.model.FreeObjectMass;
import org.handsim.model.HandModel;
import org.handsim.model.SceneGeometry;
import org.handsim.scenario.Scenario;
import org.handsim.text.Decimal;

/**
 * A whole hold test of a scenario: close the fingers as the scenario says, until every finger has
 * stalled or the scenario ends (the planner's rule); lock the grasp ({@link LockedGrasp}); free the
 * object there, with the mass the scenario or the caller gives, else its mesh's at
 * {@link ObjectMass#DEFAULT_DENSITY_KG_M3}; push it along the six directions ({@link HoldTest}),
 * and with {@code ramp} find how hard each direction can be pushed. Its outputs, hold-test.json
 * and hold-test.csv (README, output contracts), are {@link #toJson} and {@link #csv}.
 *
 * @param scenario    the scenario's name
 * @param closeS      the simulated time the closing took, s
 * @param states      each finger's clutch state when the closing ended
 * @param massSource  where the mass came from: {@code given}, {@code density}, {@code scenario} (its free
 *                    object's {@code mass_kg} or {@code density_kg_m3}, and {@code inertia_kg_m2}, {@code com_m}
 *                    when given), {@code mesh at 1000 kg/m3}, or {@code shell} (an open mesh: a thin shell of
 *                    the given mass)
 * @param mass        the object's mass properties (mesh frame)
 * @param comWorld    its centre of mass at release, world, m
 * @param releaseContacts the contacts with the hand at release
 * @param test        the test (its grasp and settings)
 * @param directions  the six pushes, in {@link HoldTest#DIRECTIONS}' order
 * @param ramps       the six ramps, or null without {@code ramp}
 */
public record HoldReport(String scenario, double closeS, ClutchState[] states, String massSource, MassProperties mass,
                         double[] comWorld, int releaseContacts, HoldTest test, List<DirectionResult> directions,
                         List<RampResult> ramps) {
    /** The header of hold-test.csv (contract). */
    public static final String CSV_HEADER = "direction,passed,displacement_m,rotation_deg,final_displacement_m,final_rotation_deg,margin,"
        + "failed_at_s,contact_lost_s,settled_s,contacts_at_end,ramp_force_N,ramp_held_at_max,ramp_force_at_rest_N";

    /**
     * Closes, locks and tests.
     *
     * @param massKg    the object's mass, kg, or NaN (with densityKg NaN: a free object's from the
     *                  scenario's fields, else the mesh's at {@link ObjectMass#DEFAULT_DENSITY_KG_M3})
     * @param densityKg its density, kg/m³, or NaN
     * @throws IllegalArgumentException when the object's mass cannot be known, or the scenario has no object
     * @throws org.handsim.model.SimulationException when the closing fails
     */
    public static HoldReport of(Scenario scenario, double massKg, double densityKg, HoldSettings settings, boolean ramp) {
        if (scenario.object() == null) throw new IllegalArgumentException(scenario.name() + ": the scenario has no object to push");
        SceneGeometry geometry = new SceneGeometry(scenario.object(), SceneGeometry.DEFAULT_K);
        boolean fromScenario = Double.isNaN(massKg) && Double.isNaN(densityKg) && scenario.freeObject() != null;
        // refused before the closing runs
        MassProperties props = fromScenario ? FreeObjectMass.of(scenario, geometry.objectMesh())
            : ObjectMass.of(geometry.objectMesh(), massKg, densityKg);
        String source = fromScenario ? "scenario" : !Double.isNaN(massKg) ? (Double.isNaN(props.volume()) ? "shell" : "given")
            : !Double.isNaN(densityKg) ? "density" : "mesh at " + (int) ObjectMass.DEFAULT_DENSITY_KG_M3 + " kg/m3";
        HandModel model = org.handsim.model.Simulation.model(scenario, geometry);
        close(model);
        return test(model, geometry, props, source, settings, ramp);
    }

    /** Steps {@code model} until every finger has stalled or its scenario ends. */
    public static void close(HandModel model) {
        while (model.running() && !(model.state(1) == ClutchState.STALLED && model.state(2) == ClutchState.STALLED
            && model.state(3) == ClutchState.STALLED)) {
            model.step();
        }
    }

    /** Locks the grasp {@code model} reached and tests it. */
    public static HoldReport test(HandModel model, SceneGeometry geometry, MassProperties props, String source, HoldSettings settings,
                                  boolean ramp) {
        LockedGrasp grasp = LockedGrasp.of(model, geometry, props);
        HoldTest test = new HoldTest(grasp, settings);
        List<DirectionResult> d = test.run();
        List<RampResult> r = ramp ? test.ramps() : null;
        double[] com = props.centreOfMass();
        double[] world = grasp.worldFromObjectTransform().apply(com);
        int contacts = 0;
        for (int k = 1; k <= 3; k++) contacts += model.contacts(k).size();
        return new HoldReport(model.scenario().name(), model.time(), new ClutchState[] {model.state(1), model.state(2), model.state(3)},
            source, props, world, contacts, test, d, r);
    }

    /** Directions held. */
    public int passedCount() {
        int n = 0;
        for (DirectionResult d : directions) if (d.passed()) n++;
        return n;
    }

    /** The smallest margin over the six directions ({@link DirectionResult#margin}). */
    public double smallestMargin() {
        double m = Double.POSITIVE_INFINITY;
        for (DirectionResult d : directions) m = Math.min(m, d.margin());
        return m;
    }

    /** The ramp's weakest direction (the smallest force held), or null without a ramp. */
    public RampResult weakest() {
        if (ramps == null) return null;
        RampResult w = null;
        for (RampResult r : ramps) if (w == null || r.forceN() < w.forceN()) w = r;
        return w;
    }

    /** hold-test.json (the contract, README). */
    public Map<String, Object> toJson() {
        HoldSettings s = test.settings();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("scenario", scenario);
        m.put("frame", "world");
        m.put("force_N", test.forceN());
        m.put("duration_s", s.durationS());
        m.put("dt_s", s.dtS());
        m.put("gravity", s.gravity());
        m.put("friction", test.grasp().friction());
        m.put("max_displacement_m", s.maxDisplacementM());
        m.put("max_rotation_deg", s.maxRotationDeg());
        m.put("contact_margin_m", ProximityContacts.DEFAULT_MARGIN);
        Map<String, Object> obj = new LinkedHashMap<>();
        obj.put("mass_kg", mass.mass());
        obj.put("mass_source", massSource);
        obj.put("com_m", comWorld);
        obj.put("inertia_kg_m2", mass.inertia());
        m.put("object", obj);
        Map<String, Object> c = new LinkedHashMap<>();
        c.put("time_s", closeS);
        List<Object> st = new ArrayList<>();
        for (ClutchState x : states) st.add(x.name());
        c.put("final_states", st);
        m.put("closing", c);
        m.put("contacts_at_release", releaseContacts);
        double[] settled = test.settling();
        Map<String, Object> settle = new LinkedHashMap<>();
        settle.put("displacement_m", settled[0]);
        settle.put("rotation_deg", settled[1]);
        settle.put("time_s", settled[2]);
        settle.put("dropped", settled[3] != 0);
        settle.put("unconverged_steps", (long) settled[4]);
        m.put("settling", settle);
        List<Object> ds = new ArrayList<>();
        for (DirectionResult d : directions) ds.add(direction(d));
        m.put("directions", ds);
        m.put("passed", passedCount());
        m.put("held", passedCount() == 6);
        m.put("smallest_margin", smallestMargin());
        if (ramps != null) {
            List<Object> rs = new ArrayList<>();
            for (RampResult r : ramps) {
                Map<String, Object> o = new LinkedHashMap<>();
                o.put("direction", r.direction());
                o.put("force_N", r.forceN());
                o.put("held_at_max", r.heldAtMax());
                o.put("force_at_rest_N", r.forceAtRestN());
                o.put("crossed_at_s", nullIfNaN(r.crossedAtS()));
                rs.add(o);
            }
            Map<String, Object> ramp = new LinkedHashMap<>();
            ramp.put("rate_N_per_s", s.rampRateNPerS());
            ramp.put("max_N", s.rampMaxN());
            ramp.put("max_displacement_m", s.rampDisplacementM());
            ramp.put("max_rotation_deg", s.rampRotationDeg());
            ramp.put("directions", rs);
            ramp.put("weakest", weakest().direction());
            ramp.put("weakest_force_N", weakest().forceN());
            m.put("ramp", ramp);
        }
        return m;
    }

    private static Map<String, Object> direction(DirectionResult d) {
        Map<String, Object> o = new LinkedHashMap<>();
        o.put("direction", d.direction());
        o.put("unit", d.unit());
        o.put("passed", d.passed());
        o.put("displacement_m", d.displacementM());
        o.put("rotation_deg", d.rotationDeg());
        o.put("final_displacement_m", d.finalDisplacementM());
        o.put("final_rotation_deg", d.finalRotationDeg());
        o.put("margin", d.margin());
        o.put("failed_at_s", nullIfNaN(d.failedAtS()));
        o.put("contact_lost_s", nullIfNaN(d.contactLostS()));
        o.put("settled_s", nullIfNaN(d.settledS()));
        o.put("settled_bound_m", d.settledBoundM());
        o.put("settled_bound_deg", d.settledBoundDeg());
        o.put("simulated_s", d.simulatedS());
        o.put("unconverged_steps", d.unconvergedSteps());
        List<Object> cs = new ArrayList<>();
        for (DirectionResult.Contact c : d.contacts()) {
            Map<String, Object> x = new LinkedHashMap<>();
            x.put("body", c.body());
            x.put("point", c.point());
            x.put("normal", c.normal());
            x.put("force_N", Decimal.clean(c.forceN()));
            x.put("gap_m", c.gapM());
            cs.add(x);
        }
        o.put("contacts", cs);
        return o;
    }

    private static Object nullIfNaN(double v) {
        return Double.isNaN(v) ? null : (Object) v;
    }

    /** hold-test.csv (the contract, README): the header and one row per direction, the ramp's columns empty without it. */
    public String csv() {
        StringBuilder sb = new StringBuilder(CSV_HEADER).append('\n');
        for (int i = 0; i < directions.size(); i++) {
            DirectionResult d = directions.get(i);
            sb.append(d.direction()).append(',').append(d.passed());
            for (double v : new double[] {d.displacementM(), d.rotationDeg(), d.finalDisplacementM(), d.finalRotationDeg(), d.margin(),
                d.failedAtS(), d.contactLostS(), d.settledS()}) {
                sb.append(',').append(Decimal.orEmpty(v));
            }
            sb.append(',').append(d.contacts().size());
            if (ramps != null) {
                RampResult r = ramps.get(i);
                sb.append(',').append(Decimal.orEmpty(r.forceN())).append(',').append(r.heldAtMax()).append(',')
                    .append(Decimal.orEmpty(r.forceAtRestN()));
            } else {
                sb.append(",,,");
            }
            sb.append('\n');
        }
        return sb.toString();
    }
}
