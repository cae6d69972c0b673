package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.scenario.Scenario;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.handsim.trace.Recorder;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The free object in the run loop (DESIGN.md decision 7): held until {@code release_s}, it is the
 * fixed object, so every force and torque of the run is today's; released, it is carried by the
 * hand's bodies and the fingers that press on it.
 */
class FreeObjectRunTest {
    static final Path MUG = TestPaths.root().resolve("scenarios/mug-grasp.json");
    static final Path LIFT = TestPaths.root().resolve("scenarios/mug-lift.json");

    /** {@code base} with {@code fields} (JSON object text) added to its object. */
    @SuppressWarnings("unchecked")
    static Scenario with(Path base, String fields) {
        Map<String, Object> j = (Map<String, Object>) Json.parse("scenario", Scenario.readText(base));
        ((Map<String, Object>) j.get("object")).putAll((Map<String, Object>) Json.parse("fields", fields));
        return Scenario.parse(base, JsonWriter.write(j));
    }

    /**
     * The mug grasp with its object free but released after the run's end: every row of the trace
     * (joints, torques, states, contact counts and forces, clutch torques, residuals, carried
     * torques) and every figure of the summary equal the fixed object's, to the last bit.
     */
    @Test
    void aFreeObjectHeldToTheEndGivesTheFixedObjectsForces() {
        HandModel fixed = Simulation.model(Scenario.load(MUG), true);
        HandModel held = Simulation.model(with(MUG, "{\"free\": true, \"mass_kg\": 0.35, \"release_s\": 100}"), true);
        fixed.run(null);
        held.run(null);
        assertTrue(held.objectFree() && !held.objectReleased());
        Recorder a = fixed.recorder(), b = held.recorder();
        assertEquals(a.rows(), b.rows());
        assertTrue(b.objectColumns() && !a.objectColumns());
        for (int r = 0; r < a.rows(); r++) {
            for (int k = 1; k <= 3; k++) {
                for (int c = Recorder.Q; c <= Recorder.TAU3; c++) assertEquals(a.get(k, c, r), b.get(k, c, r), "row " + r + " finger " + k + " col " + c);
                assertEquals(a.state(k, r), b.state(k, r));
                assertEquals(a.contacts(k, r), b.contacts(k, r));
                assertEquals(a.force(k, r), b.force(k, r), "row " + r);
                assertEquals(a.clutch(k, r), b.clutch(k, r));
                assertEquals(a.residual(k, r), b.residual(k, r));
                for (int j = k == 3 ? 2 : 1; j <= 3; j++) assertEquals(a.carried(k, j, r), b.carried(k, j, r));
            }
            assertEquals(0, b.object(Recorder.OBJ_SPEED, r));
            assertEquals(0, b.object(Recorder.OBJ_DISP, r));
        }
        for (int k = 1; k <= 3; k++) {
            assertEquals(fixed.breakawayTime(k), held.breakawayTime(k));
            assertEquals(fixed.breakawayForce(k), held.breakawayForce(k));
            assertEquals(fixed.maxContactForce(k), held.maxContactForce(k));
            assertEquals(fixed.maxWormReaction(k), held.maxWormReaction(k));
        }
        Map<String, Object> s = RunSummary.of(held, 1);
        assertEquals(null, s.get("dropped_at_s"));
        assertEquals(null, s.get("released_at_s"));
        assertEquals(0.0, s.get("max_displacement_m"));
        assertFalse(RunSummary.of(fixed, 1).containsKey("dropped_at_s"));
    }

    /**
     * scenarios/mug-lift.json: the mug grasp, released at 4.7 s, lifted 10 cm at 0.1 m/s with
     * gravity: it stays in the hand, moving less than 5 mm (measured: under 1 µm) and turning
     * less than 1° relative to the palm, and rises with it.
     */
    @Test
    @Tag("slow")
    void theLiftedMugStaysInTheHand() {
        HandModel m = Simulation.model(Scenario.load(LIFT), true);
        m.run(null);
        assertTrue(m.objectReleased());
        assertEquals(4.7, m.objectReleasedAt(), 1e-9);
        assertTrue(m.objectMaxDisplacement() < 0.005, "moved " + m.objectMaxDisplacement() + " m");
        assertTrue(m.objectMaxRotation() < 1, "turned " + m.objectMaxRotation() + " deg");
        assertTrue(Double.isNaN(m.objectDroppedAt()) && Double.isNaN(m.objectSlippedAt()));
        double[] o = m.objectNow();
        Recorder r = m.recorder();
        // the centre of mass rose with the palm by the lift's 0.1 m
        assertEquals(0.1, o[Recorder.OBJ_Z] - r.object(Recorder.OBJ_Z, 0), 1e-4);
        assertTrue(o[Recorder.OBJ_CONTACTS] >= 3, "contact points " + o[Recorder.OBJ_CONTACTS]);
    }

    /**
     * The mug lift turned so that it runs along the mug's axis (gravity along -x, the palm rising
     * 0.1 m along +x), where only friction holds it: the grasp squeezes the mug with some 250 N,
     * so μ = 0.1 (25 N of friction against its 3.43 N weight) holds it, as MuJoCo's rig holds it
     * at μ = 0.1 and 0.01 with the weight pushed along every direction
     * (tools/lift-friction-vs-mujoco); μ = 0.001 cannot, and the summary says when it slipped (as
     * 34 ms after its release) and when it left the hand.
     */
    @Test
    @Tag("slow")
    void aLiftAlongTheMugsAxisSlipsOnlyWhenFrictionCannotCarryItsWeight() {
        HandModel held = Simulation.model(alongTheAxis(0.1), true);
        held.run(null);
        assertTrue(held.objectMaxDisplacement() < 0.005, "mu 0.1 moved " + held.objectMaxDisplacement() + " m");
        assertTrue(Double.isNaN(held.objectSlippedAt()) && Double.isNaN(held.objectDroppedAt()));
        HandModel slips = Simulation.model(alongTheAxis(0.001), true);
        slips.run(null);
        double slipped = slips.objectSlippedAt(), dropped = slips.objectDroppedAt();
        // no sooner than a free fall of 5 mm (31.9 ms), and soon after: 0.001 x 250 N is 7 % of its weight
        assertTrue(slipped >= 4.7 + Math.sqrt(2 * 0.005 / 9.81) && slipped < 4.75, "slipped at " + slipped);
        assertTrue(dropped > slipped && dropped < 5.0, "dropped at " + dropped);
        Map<String, Object> s = RunSummary.of(slips, 1);
        assertEquals(slipped, (Double) s.get("slipped_at_s"), 1e-9);
        assertEquals(dropped, (Double) s.get("dropped_at_s"), 1e-9);
        // a lift whose Coulomb fixed point settles at every step, through the slip and the drop
        assertEquals(0L, s.get("unconverged_steps"));
        assertEquals(0L, RunSummary.of(held, 1).get("unconverged_steps"));
    }

    @SuppressWarnings("unchecked")
    static Scenario alongTheAxis(double mu) {
        Map<String, Object> j = (Map<String, Object>) Json.parse("scenario", Scenario.readText(LIFT));
        j.put("gravity_m_s2", List.of(-9.81, 0.0, 0.0));
        for (Object m : (List<Object>) ((Map<String, Object>) j.get("hand")).get("moves")) {
            Map<String, Object> move = (Map<String, Object>) m;
            if ("line".equals(move.get("type"))) move.put("by_m", List.of(0.1, 0.0, 0.0));
        }
        ((Map<String, Object>) j.get("object")).put("friction", mu);
        return Scenario.parse(LIFT, JsonWriter.write(j));
    }

    /**
     * scenarios/mug-table-lift.json: the mug lying on a table, free from the start: it rests on
     * the table (two contact points: a cylinder on a plane touches along a line) while the fingers
     * close on it, and the lift takes it 0.1 m up, off the table, without it moving in the hand.
     */
    @Test
    @Tag("slow")
    void theMugOnATableIsPickedUp() {
        HandModel m = Simulation.model(Scenario.load(TestPaths.root().resolve("scenarios/mug-table-lift.json")), true);
        m.run(null);
        Recorder r = m.recorder();
        assertEquals(0, m.objectReleasedAt());
        int before = (int) Math.round(1.0 / 0.001);   // resting on the table, the fingers still open
        assertEquals(2, (int) r.object(Recorder.OBJ_CONTACTS, before));
        assertEquals(0, r.contacts(1, before) + r.contacts(2, before) + r.contacts(3, before));
        assertEquals(0, r.object(Recorder.OBJ_Z, before) - r.object(Recorder.OBJ_Z, 0), 1e-6, "at rest on the table");
        int last = r.rows() - 1;
        assertEquals(0.1, r.object(Recorder.OBJ_Z, last) - r.object(Recorder.OBJ_Z, 0), 1e-4, "lifted with the palm");
        int hand = r.contacts(1, last) + r.contacts(2, last) + r.contacts(3, last);
        assertEquals(hand, (int) r.object(Recorder.OBJ_CONTACTS, last), "off the table: every contact is the hand's");
        assertTrue(m.objectMaxDisplacement() < 0.005, "moved " + m.objectMaxDisplacement() + " m in the hand");
        assertTrue(Double.isNaN(m.objectDroppedAt()));
    }
}
