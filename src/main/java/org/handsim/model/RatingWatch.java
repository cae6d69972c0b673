package org.handsim.model;

import java.util.List;
import java.util.Locale;
import org.handsim.hand.HandDescription;
import org.handsim.text.Decimal;

/**
 * Forces above Barrett's rating, as warnings (DESIGN.md, "Ratings are warnings"). Barrett rates
 * each finger for 2 kg (support wiki, "BarrettHand BH-262 Safety and Cautions": "Do not exceed the
 * load limit of the fingers, 2 kg per finger"), 19.61 N at the tip of the stretched finger
 * ({@link HandDescription#fingerRatingN}). A step's forces exceed it when a contact force on a
 * link does, or when a joint's torque — the torque it actually carries, τ_dyn + Jᵀf — over that
 * joint's lever to the fingertip ({@link HandDescription#leverToTip}) does: the force at the tip
 * that would load the joint as much. Each stretch of steps above the rating becomes one warning
 * per finger and link or joint, naming the finger, the stretch's start and end time, the largest
 * force and its time, and the rating. Nothing is capped: the simulation reports what the contacts
 * carry; the rating only says where Barrett's specification ends.
 *
 * <p>Not thread-safe; one per model.
 */
final class RatingWatch {
    private final HandDescription hand;
    private final double rating;
    private final Stretches stretches;
    // keys: finger i (0..2) × 6 + (0..2: contact force on link j+1; 3..5: joint j−2's fingertip-equivalent)
    private final double[] largest = new double[6];

    RatingWatch(HandDescription hand) {
        this.hand = hand;
        this.rating = hand.fingerRatingN();
        this.stretches = new Stretches(18, rating, HandModel.MAX_EPISODE_WARNINGS, new Stretches.Wording() {
            @Override
            public String stretch(int key, double start, double end, double max, double maxAt) {
                return String.format(Locale.ROOT, "finger %d: %s above Barrett's rating of %.4g N (%s kg per finger) from t = %s s to %s s:"
                    + " up to %s at t = %s s", key / 6 + 1, subject(key), rating, Decimal.format(hand.fingerRatingKg()), Decimal.format(start),
                    Decimal.format(end), amount(key, max), Decimal.format(maxAt));
            }

            @Override
            public String more(int key, int more, double max) {
                return String.format(Locale.ROOT, "finger %d: %d more stretches of %s above Barrett's rating of %.4g N (up to %s)",
                    key / 6 + 1, more, subject(key), rating, amount(key, max));
            }
        });
    }

    /** What key names: "a contact force on link 2", "the torque of joint 32 (a fingertip-equivalent force)". */
    private static String subject(int key) {
        int k = key / 6 + 1, q = key % 6;
        return q < 3 ? "a contact force on link " + (q + 1)
            : "the torque of joint " + k + (q - 2) + " as a force at the fingertip";
    }

    /** The force, and for a joint its torque and lever too. */
    private String amount(int key, double force) {
        int q = key % 6;
        if (q < 3) return String.format(Locale.ROOT, "%.4g N", force);
        double lever = hand.leverToTip(q - 2);
        return String.format(Locale.ROOT, "%.4g N (%.4g N*m over its %.4g m lever to the tip)", force, force * lever, lever);
    }

    void clear() {
        stretches.clear();
    }

    /**
     * Finger k's step at time t: its contacts' forces, and the torques its joints carry
     * ({@code carried[0..2]}, N·m; finger 3 has no joint k1).
     */
    void watch(int k, ContactSet cs, double[] carried, double t) {
        java.util.Arrays.fill(largest, 0);
        for (int c = 0; c < cs.size(); c++) {
            int link = cs.links[c] - 1;
            largest[link] = Math.max(largest[link], cs.forces[c]);
        }
        for (int j = k == 3 ? 1 : 0; j < 3; j++) largest[3 + j] = Math.abs(carried[j]) / hand.leverToTip(j + 1);
        int base = 6 * (k - 1);
        for (int q = 0; q < 6; q++) stretches.watch(base + q, largest[q], t);
    }

    /** The warnings so far ({@link Stretches#warnings}). */
    List<String> warnings() {
        return stretches.warnings();
    }
}
