package org.handsim.model;

import org.handsim.body.BodyContacts;
import org.handsim.body.FreeBody;
import org.handsim.math.Quaternion;

/**
 * What the run reports of its free object (DESIGN.md decision 7; trace.csv's object columns,
 * summary.json's object keys): its pose and speeds now, its contact points and largest
 * penetration, and its displacement and rotation relative to the palm since the start — the
 * centre of mass in the palm frame, R_Pᵀ(x − o_P), and the orientation q_P* ⊗ q — with their
 * largest values, when it first moved more than {@link #SLIP_M} relative to the palm, and
 * whether it dropped: it lost every contact with the hand and, by the end, had moved more than
 * {@link #DROP_M} relative to the palm since.
 *
 * <p>Allocation-free per step.
 */
final class FreeObjectState {
    /** A displacement relative to the palm beyond this is a slip ({@code slipped_at_s}), m. */
    static final double SLIP_M = 0.005;
    /** An object out of contact with the hand that moved this far relative to the palm since has dropped, m. */
    static final double DROP_M = 0.01;

    final double[] x = new double[3], q = new double[4], v = new double[3], w = new double[3];
    private final double[] relStart = new double[3], qRelStart = new double[4], rel = new double[3], qRel = new double[4];
    private final double[] palmQ = new double[4], lostRel = new double[3];
    final double[] innerForce = new double[3];
    double speed, spin, penetration, disp, rot, maxDisp, maxRot;
    int contacts, handContacts;
    double releasedAt = Double.NaN, slippedAt = Double.NaN, lostAt = Double.NaN;
    /** Steps whose Coulomb fixed point did not settle (the step used the last exact solve): summary.json's {@code unconverged_steps}. */
    long unconverged;

    /** At the start: the palm and the object where they are, the references of the displacement and rotation. */
    void reset(double[] palm, FreeObjectScene s) {
        pose(palm, s.body());
        System.arraycopy(rel, 0, relStart, 0, 3);
        System.arraycopy(qRel, 0, qRelStart, 0, 4);
        speed = spin = penetration = disp = rot = maxDisp = maxRot = 0;
        contacts = handContacts = 0;
        releasedAt = slippedAt = lostAt = Double.NaN;
        unconverged = 0;
        java.util.Arrays.fill(innerForce, 0);
    }

    /** The object held in place at time t (before its release): no speed, no contact points of its own. */
    void held(double t, double[] palm, FreeObjectScene s) {
        pose(palm, s.body());
        speed = spin = penetration = 0;
        contacts = handContacts = 0;
        relative(t);
    }

    /** After the object's step ending at time t. */
    void stepped(double t, double[] palm, FreeObjectScene s) {
        FreeBody b = s.body();
        pose(palm, b);
        b.stepVelocity(v);
        b.stepAngularVelocity(w);
        speed = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        spin = Math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        BodyContacts c = s.contacts();
        contacts = c.size();
        penetration = c.largestPenetration();
        handContacts = 0;
        for (int i = 0; i < contacts; i++) if (c.body(i) < FreeObjectScene.HAND_BODIES) handContacts++;
        relative(t);
        if (handContacts == 0) {
            if (Double.isNaN(lostAt)) {
                lostAt = t;
                System.arraycopy(rel, 0, lostRel, 0, 3);
            }
        } else {
            lostAt = Double.NaN;
        }
    }

    private void relative(double t) {
        double dx = rel[0] - relStart[0], dy = rel[1] - relStart[1], dz = rel[2] - relStart[2];
        disp = Math.sqrt(dx * dx + dy * dy + dz * dz);
        rot = Math.toDegrees(Quaternion.angleBetween(qRelStart, 0, qRel, 0));
        maxDisp = Math.max(maxDisp, disp);
        maxRot = Math.max(maxRot, rot);
        if (disp > SLIP_M && Double.isNaN(slippedAt)) slippedAt = t;
    }

    /** The object's pose, and its pose relative to the palm (world ← palm, 12 values). */
    private void pose(double[] palm, FreeBody b) {
        b.position(x);
        b.orientation(q);
        double ox = x[0] - palm[3], oy = x[1] - palm[7], oz = x[2] - palm[11];
        rel[0] = palm[0] * ox + palm[4] * oy + palm[8] * oz;
        rel[1] = palm[1] * ox + palm[5] * oy + palm[9] * oz;
        rel[2] = palm[2] * ox + palm[6] * oy + palm[10] * oz;
        Quaternion.fromMatrix(palm, 0, 4, palmQ, 0);
        palmQ[1] = -palmQ[1]; palmQ[2] = -palmQ[2]; palmQ[3] = -palmQ[3];
        Quaternion.multiply(palmQ, 0, q, 0, qRel, 0);
    }

    /**
     * When the object dropped: the start of its last stretch out of contact with the hand, if
     * that stretch lasts to now and it has since moved more than {@link #DROP_M} relative to the
     * palm; NaN otherwise.
     */
    double droppedAt() {
        if (Double.isNaN(lostAt)) return Double.NaN;
        double dx = rel[0] - lostRel[0], dy = rel[1] - lostRel[1], dz = rel[2] - lostRel[2];
        return dx * dx + dy * dy + dz * dz > DROP_M * DROP_M ? lostAt : Double.NaN;
    }
}
