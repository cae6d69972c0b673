package org.handsim.clutch;

import org.handsim.kinematics.Transmission;

/**
 * The clutch state machine of one finger (DESIGN.md decision 1; paper Section II.D): given the
 * motor position it says where the inner and outer joints are, how fast they move, and how
 * much torque the clutch transmits to a held link. Contact events come from the model
 * ({@link #innerContact}, {@link #outerContact}); the breakaway test is the model's too, which
 * calls {@link #breakAway}.
 *
 * <p>Counts are doubles (set-points interpolate between whole counts). Angles in radians,
 * torques in N·m. Not thread-safe: one per finger, owned by the model.
 */
public final class FingerClutch {
    private final Transmission tr;
    private final double kClutch, stallTorque, theta3Max;
    private ClutchState state = ClutchState.FREE;
    private ClutchState beforeStall = ClutchState.FREE;
    private double qContact = Double.NaN, qBreak = Double.NaN, qStall = Double.NaN;
    private double heldTheta2, heldTheta3;
    private double theta3AtBreak;
    private double tauAtBreak;
    private double motor;
    private boolean atLimit;          // the last stall was at the outer joint's limit

    /**
     * @param tr          the transmission (eqs 3, 4, 10)
     * @param kClutch     Belleville spring stiffness, N·m/rad of inner-joint angle
     * @param stallTorque torque at which a blocked motor stalls, N·m (we use τ_break)
     * @param theta3Max   mechanical limit of the outer joint, radians
     */
    public FingerClutch(Transmission tr, double kClutch, double stallTorque, double theta3Max) {
        this.tr = tr;
        this.kClutch = kClutch;
        this.stallTorque = stallTorque;
        this.theta3Max = theta3Max;
    }

    /** Back to FREE at motor position q. */
    public void reset(double q) {
        state = ClutchState.FREE;
        beforeStall = ClutchState.FREE;
        qContact = qBreak = qStall = Double.NaN;
        tauAtBreak = 0;
        atLimit = false;
        motor = q;
    }

    public ClutchState state() { return state; }

    /**
     * Whether the clutch still couples the inner link to the motor: FREE, BLOCKED, and STALLED
     * when the finger stalled before any breakaway; false in BROKEN and in STALLED after it.
     */
    public boolean engaged() {
        return state == ClutchState.FREE || state == ClutchState.BLOCKED
            || (state == ClutchState.STALLED && beforeStall != ClutchState.BROKEN);
    }

    /**
     * Whether the inner joint is held by its self-locking worm rather than driven, so that the
     * torque the contacts put on it is the worm's reaction (DESIGN.md, "Which torques the contacts
     * carry"): after a breakaway (BROKEN, STALLED after it: the TorqueSwitch's gear free-wheels and
     * the inner link "remains motionless", Barrett), and when the finger stalled before any
     * breakaway — the outer link was blocked first, the stalled motor winds only the outer joint
     * ({@link #transmittedTorque}: nothing for the inner one), and whatever torque the outer link's
     * contacts put on k2 is a reaction of its worm gear, which a load on the link does not
     * back-drive. In FREE and BLOCKED the drive sets its torque.
     */
    public boolean innerHeld() {
        return state == ClutchState.BROKEN || state == ClutchState.STALLED;
    }

    /**
     * The torque the TorqueSwitch transmits, N·m at the inner joint, given the inner joint's
     * τ_dyn (eq 8: what moving the link and holding it against gravity take): while the clutch
     * drives the inner link (FREE, BLOCKED, STALLED before any breakaway) the inner joint's whole
     * torque, τ_dyn + the spring's {@link #transmittedTorque}; after a breakaway 0 — the gear
     * free-wheels on its threaded shaft (Barrett, BH8 manual, "TorqueSwitch operation") and the
     * worm holds the link. The clutch breaks away when this reaches τ_break (eq 9's torque, the
     * paper's 1.26 N·m), whatever share of it gravity and inertia take.
     */
    public double clutchTorque(double tauDynInner) {
        if (!engaged()) return 0;
        return tauDynInner + (state == ClutchState.BLOCKED ? Math.max(0, kClutch * (motor - qContact) * tr.innerRadPerCount()) : 0);
    }

    /**
     * The motor count at which a BLOCKED clutch transmits {@code tau} when the inner joint's
     * τ_dyn is {@code tauDynInner}: the springs are wound linearly from q_contact, so this is
     * q_contact + (τ − τ_dyn)/(k_clutch · rad per count) — exact, no interpolation.
     */
    public double countsWhereClutchTorqueIs(double tau, double tauDynInner) {
        return qContact + (tau - tauDynInner) / (kClutch * tr.innerRadPerCount());
    }

    /** The motor count where the inner link met the object (BLOCKED and after), NaN before. */
    public double contactCounts() { return qContact; }

    /**
     * Whether the finger stalled because its outer joint reached its limit (not on the object):
     * the joint's stop then holds the stalled motor's torque.
     */
    public boolean stalledAtOuterLimit() {
        return state == ClutchState.STALLED && atLimit;
    }

    /** The motor's actual position (counts): the set-point, except while STALLED when closing. */
    public double motor() { return motor; }

    /**
     * Advances with the motor set-point; handles re-engagement on opening.
     *
     * @param q set-point, counts
     */
    public void follow(double q) {
        switch (state) {
            case FREE:
                motor = q;
                break;
            case BLOCKED:
                motor = q;
                if (q < qContact) state = ClutchState.FREE; // opened past the contact: link leaves the object
                break;
            case BROKEN:
                motor = q;
                if (q <= qBreak) {
                    // re-engage where the breakaway happened: the spur gear grips again with the
                    // Belleville springs still wound by qBreak − qContact, so the held links stay
                    // put (BLOCKED) until the motor has unwound them (FREE below qContact)
                    state = ClutchState.BLOCKED;
                    heldTheta3 = theta3AtBreak;
                    qBreak = Double.NaN;
                    tauAtBreak = 0;
                    if (q < qContact) state = ClutchState.FREE;
                }
                break;
            case STALLED:
                if (q < qStall) { // opening: the motor follows again
                    state = beforeStall;
                    motor = q;
                    follow(q);
                } else {
                    motor = Math.min(q, qStallMotorLimit());
                }
                break;
            default:
                throw new IllegalStateException();
        }
        if (state == ClutchState.BROKEN && outerAngleRaw() > theta3Max) stallAtLimit();
    }

    private void stallAtLimit() {
        stall(qAtOuterLimit());
        atLimit = true;
    }

    private double qStallMotorLimit() {
        // while stalled, the motor winds on through the spring until the stall torque
        return qStall + stallTorque / kClutch / tr.outerRadPerCount(beforeStall == ClutchState.BROKEN);
    }

    private double qAtOuterLimit() {
        // eq (10) (continuous form, see brokenOuterAngle) solved for q at θ3 = θ3max
        return qBreak + (theta3Max - theta3AtBreak) / tr.outerRadPerCount(true);
    }

    private double outerAngleRaw() {
        return brokenOuterAngle(motor);
    }

    /**
     * Eq (10) in the form that keeps the outer joint continuous: θk3 = θk3,break + 4/375°·(q − q_break).
     * The paper has no wind-up phase, so there θk3,break = q_break/375° and this is exactly
     * 4/375·q − 3/375·q_break; here the links were held from q_contact, so θk3,break = q_contact/375°.
     */
    private double brokenOuterAngle(double q) {
        return theta3AtBreak + tr.outerRadPerCount(true) * (q - qBreak);
    }

    /** The inner link met the object at motor count q while closing: FREE → BLOCKED. */
    public void innerContact(double q) {
        if (state != ClutchState.FREE) return;
        heldTheta2 = tr.innerAngle(clampCounts(q));
        heldTheta3 = tr.outerAngle(clampCounts(q));
        qContact = q;
        state = ClutchState.BLOCKED;
    }

    /** The outer link met the object at motor count q: FREE or BROKEN → STALLED. */
    public void outerContact(double q) {
        if (state != ClutchState.FREE && state != ClutchState.BROKEN) return;
        stall(q);
    }

    /** FREE or BROKEN → STALLED at motor count q: the links held where the current state puts them at q. */
    private void stall(double q) {
        heldTheta2 = theta2For(q);
        heldTheta3 = Math.min(theta3Max, theta3For(q));
        beforeStall = state;
        atLimit = false;
        qStall = q;
        motor = Math.min(motor, qStallMotorLimit());
        state = ClutchState.STALLED;
    }

    /**
     * BLOCKED → BROKEN at motor count qb (where the clutch torque reaches τ_break), keeping the
     * transmitted torque — the contacts' share of τ_break, τ_break − τ_dyn — at its breakaway
     * value: the load the worm keeps on the held inner link.
     */
    public void breakAway(double qb, double tauAtBreak) {
        if (state != ClutchState.BLOCKED) return;
        qBreak = qb;
        theta3AtBreak = heldTheta3;
        this.tauAtBreak = tauAtBreak;
        state = ClutchState.BROKEN;
        if (outerAngleRaw() > theta3Max) stallAtLimit();
    }

    /**
     * The held links gave way closing by dθk2, dθk3 (rad, ≥ 0): a free object moved and the
     * links pressing on it followed (DESIGN.md decision 7). BLOCKED: the inner link turned, so
     * the springs unwind — the contact count moves on by dθk2 in counts — and once they are
     * unwound (the contact count reaches the motor's) the motor drives the finger again: FREE.
     * BROKEN (and STALLED after it): the load the worm keeps on the inner link falls by
     * {@code unloadNmPerRad}·dθk2, the stiffness that stored it. STALLED: the outer link turned,
     * so the stalled motor's winding unwinds by dθk3 in counts (the motor then winds on to its
     * stall torque as it follows its set-point).
     */
    public void giveWay(double dTheta2, double dTheta3, double unloadNmPerRad) {
        switch (state) {
            case BLOCKED:
                heldTheta2 += dTheta2;
                heldTheta3 = Math.min(theta3Max, heldTheta3 + dTheta3);
                qContact += dTheta2 / tr.innerRadPerCount();
                if (qContact >= motor) {
                    qContact = Double.NaN;
                    state = ClutchState.FREE;
                }
                break;
            case BROKEN:
                heldTheta2 += dTheta2;
                tauAtBreak = Math.max(0, tauAtBreak - unloadNmPerRad * dTheta2);
                break;
            case STALLED:
                heldTheta2 += dTheta2;
                if (beforeStall == ClutchState.BROKEN) tauAtBreak = Math.max(0, tauAtBreak - unloadNmPerRad * dTheta2);
                heldTheta3 = Math.min(theta3Max, heldTheta3 + dTheta3);
                qStall = Math.min(motor, qStall + dTheta3 / tr.outerRadPerCount(beforeStall == ClutchState.BROKEN));
                break;
            default:
        }
    }

    private double clampCounts(double q) {
        return Math.max(0, Math.min(tr.hand().fingerCountsMax(), q));
    }

    /** θk2 in radians now. */
    public double theta2() {
        return theta2For(motor);
    }

    /** θk3 in radians now. */
    public double theta3() {
        return theta3For(motor);
    }

    /** θk2 for a hypothetical motor position q in the current state (for event location). */
    public double theta2For(double q) {
        return state == ClutchState.FREE ? tr.innerAngle(clampCounts(q)) : heldTheta2;
    }

    /** θk3 for a hypothetical motor position q in the current state (for event location). */
    public double theta3For(double q) {
        switch (state) {
            case FREE: return tr.outerAngle(clampCounts(q));
            case BROKEN: return brokenOuterAngle(q);
            default: return heldTheta3;
        }
    }

    /** dθk2/dq and dθk3/dq (rad/count) in the current state, into out[0..1]. */
    public void jointRates(double[] out) {
        switch (state) {
            case FREE:
                out[0] = tr.innerRadPerCount();
                out[1] = tr.outerRadPerCount(false);
                break;
            case BROKEN:
                out[0] = 0;
                out[1] = tr.outerRadPerCount(true);
                break;
            default:
                out[0] = 0;
                out[1] = 0;
        }
    }

    /**
     * The torque the clutch transmits to the object through the held links, beyond what moving
     * the links takes (N·m), into out[0] (inner joint) and out[1] (outer joint).
     * BLOCKED: k_clutch·(q − q_contact)/125° on the inner joint; BROKEN (and STALLED after a
     * breakaway): the load the clutch left on the inner link at the breakaway, which its worm
     * keeps (τ_break less gravity's share); STALLED: the motor winds the blocked outer joint
     * through the same spring up to the stall torque.
     */
    public void transmittedTorque(double[] out) {
        out[0] = 0;
        out[1] = 0;
        switch (state) {
            case BLOCKED:
                out[0] = Math.max(0, kClutch * (motor - qContact) * tr.innerRadPerCount());
                break;
            case BROKEN:
                out[0] = tauAtBreak;
                break;
            case STALLED:
                if (beforeStall == ClutchState.BROKEN) out[0] = tauAtBreak;
                out[1] = Math.min(stallTorque, Math.max(0,
                    kClutch * (motor - qStall) * tr.outerRadPerCount(beforeStall == ClutchState.BROKEN)));
                break;
            default:
        }
    }
}
