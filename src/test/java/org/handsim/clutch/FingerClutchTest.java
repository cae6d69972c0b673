package org.handsim.clutch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.handsim.kinematics.Transmission;
import org.junit.jupiter.api.Test;

/**
 * The clutch state machine of DESIGN.md decision 1, row by row: each row drives one finger's
 * clutch from FREE through a few events and states where it must be, with the angles worked by
 * hand from the paper's transmission (θk2 = q/125°, θk3 = q/375° coupled, 4/375° per count after
 * the breakaway, eqs 3, 4, 10) and the spring (k_clutch = 7.2192 N·m/rad, so τ_break = 1.26 N·m
 * is 10° of inner-joint wind-up, 1 250 counts). The outer joint after a breakaway is continuous:
 * it starts where the links were held, at the contact (q_contact/375°), not at q_break/375°.
 */
class FingerClutchTest {
    static final double K = 7.2192, TAU = 1.26, THETA3_MAX_DEG = 48;
    static final double TOL_DEG = 1e-9, TOL_COUNTS = 1e-6;

    /**
     * One row: the events, then the expected state, θk2 and θk3 (degrees), whether the clutch
     * still couples the inner link, and the motor's position (counts).
     */
    record Row(String events, ClutchState state, double theta2Deg, double theta3Deg, boolean engaged, double motor) {}

    static final Row[] TABLE = {
        // FREE: both joints follow the motor, eqs 3 and 4
        new Row("follow 6000", ClutchState.FREE, 48, 16, true, 6000),
        // FREE -> BLOCKED when the inner link touches; the links hold while the motor winds the spring
        new Row("inner 5000, follow 6000", ClutchState.BLOCKED, 40, 5000 / 375.0, true, 6000),
        // BLOCKED, opening past the contact: FREE again
        new Row("inner 5000, follow 6000, follow 4999", ClutchState.FREE, 4999 / 125.0, 4999 / 375.0, true, 4999),
        // BLOCKED -> BROKEN at tau_break (1 250 counts past the contact): θk2 held, θk3 on eq 10 from where it was held
        new Row("inner 5000, follow 6250, break 6250, follow 7000", ClutchState.BROKEN, 40, 5000 / 375.0 + 4 * 750 / 375.0, false, 7000),
        // BROKEN, opening to the breakaway count: the clutch re-engages with its springs wound (BLOCKED) ...
        new Row("inner 5000, follow 6250, break 6250, follow 7000, follow 6000", ClutchState.BLOCKED, 40, 5000 / 375.0, true, 6000),
        // ... and below the contact count it is FREE
        new Row("inner 5000, follow 6250, break 6250, follow 7000, follow 4000", ClutchState.FREE, 32, 4000 / 375.0, true, 4000),
        // FREE -> STALLED when the outer link touches; the motor winds on through the spring up to the stall torque:
        // τ_break / k_clutch of the outer joint (10.0003°: k_clutch is rounded) at 1/375° a count, some 3 750 counts
        new Row("follow 9000, outer 9000, follow 20000", ClutchState.STALLED, 72, 24, true, 9000 + Math.toDegrees(TAU / K) * 375),
        // STALLED, opening below the stall: FREE again
        new Row("follow 9000, outer 9000, follow 20000, follow 8000", ClutchState.FREE, 64, 8000 / 375.0, true, 8000),
        // BROKEN -> STALLED at the outer joint's limit: 48° = 5000/375° + 4/375°·(q − 6250) at q = 9 500
        new Row("inner 5000, follow 6250, break 6250, follow 10000", ClutchState.STALLED, 40, THETA3_MAX_DEG, false, 10_000),
        // BROKEN -> STALLED when the outer link touches
        new Row("inner 5000, follow 6250, break 6250, follow 7000, outer 7000", ClutchState.STALLED, 40, 5000 / 375.0 + 4 * 750 / 375.0, false, 7000),
        // events that do not apply in a state change nothing
        new Row("break 3000, follow 3000", ClutchState.FREE, 24, 8, true, 3000),
        new Row("inner 5000, follow 6000, inner 6000", ClutchState.BLOCKED, 40, 5000 / 375.0, true, 6000),
    };

    static FingerClutch clutch() {
        FingerClutch c = new FingerClutch(Transmission.barrettHand(), K, TAU, Math.toRadians(THETA3_MAX_DEG));
        c.reset(0);
        return c;
    }

    static FingerClutch run(String events) {
        FingerClutch c = clutch();
        for (String e : events.split(",\\s*")) {
            String[] w = e.trim().split(" ");
            double q = Double.parseDouble(w[1]);
            switch (w[0]) {
                case "follow" -> c.follow(q);
                case "inner" -> c.innerContact(q);
                case "outer" -> c.outerContact(q);
                case "break" -> c.breakAway(q, 1.0);
                default -> throw new IllegalArgumentException(e);
            }
        }
        return c;
    }

    @Test
    void everyRowOfTheStateTable() {
        for (Row r : TABLE) {
            FingerClutch c = run(r.events());
            assertEquals(r.state(), c.state(), r.events());
            assertEquals(r.theta2Deg(), Math.toDegrees(c.theta2()), TOL_DEG, r.events() + ": θk2");
            assertEquals(r.theta3Deg(), Math.toDegrees(c.theta3()), TOL_DEG, r.events() + ": θk3");
            assertEquals(r.engaged(), c.engaged(), r.events() + ": engaged");
            assertEquals(r.motor(), c.motor(), TOL_COUNTS, r.events() + ": motor");
        }
    }

    /** How fast the joints move per count in each state (the rates the model's velocities come from). */
    @Test
    void jointRatesPerState() {
        double deg = Math.PI / 180;
        double[][] want = {{deg / 125, deg / 375}, {0, 0}, {0, 4 * deg / 375}, {0, 0}};
        String[] events = {"follow 6000", "inner 5000, follow 6000", "inner 5000, follow 6250, break 6250, follow 7000",
            "follow 9000, outer 9000"};
        for (int i = 0; i < events.length; i++) {
            double[] rates = new double[2];
            run(events[i]).jointRates(rates);
            assertEquals(want[i][0], rates[0], 1e-18, events[i]);
            assertEquals(want[i][1], rates[1], 1e-18, events[i]);
        }
    }

    /**
     * The torque through the clutch: BLOCKED, the spring's k·Δθ (1 000 counts = 8°: 1.00798 N·m);
     * BROKEN, the load left at the breakaway (1.0 here); STALLED, the outer joint's wind-up capped
     * at the stall torque.
     */
    @Test
    void transmittedTorquePerState() {
        double[] t = new double[2];
        run("inner 5000, follow 6000").transmittedTorque(t);
        assertEquals(K * Math.toRadians(8), t[0], 1e-12);
        assertEquals(0, t[1]);
        run("inner 5000, follow 6250, break 6250, follow 7000").transmittedTorque(t);
        assertEquals(1.0, t[0]);
        assertEquals(0, t[1]);
        run("follow 9000, outer 9000, follow 10875").transmittedTorque(t);   // 1 875 counts = 5° of the outer joint
        assertEquals(0, t[0]);
        assertEquals(K * Math.toRadians(5), t[1], 1e-12);
        run("follow 9000, outer 9000, follow 20000").transmittedTorque(t);
        assertEquals(TAU, t[1], 1e-12);
    }
}
