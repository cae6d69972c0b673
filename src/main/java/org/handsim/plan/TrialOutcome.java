package org.handsim.plan;

import org.handsim.grasp.GraspAssessment;

/**
 * How a trial's grasp ended, in the terms of why it can lack force closure — what the plan says
 * when no trial reaches it ({@link #advice}). Classified from the contacts at the end and the
 * approach a (palm toward object): a contact with push direction n (into the object) and
 * friction μ can push the object with a component along +a only if the angle θ between n and a
 * is below 90° + atan μ (its friction cone then leans past the plane normal to a), and along −a
 * only if θ exceeds 90° − atan μ. When no contact can push along one of ±a, no contact force
 * balances a load along it — the palm, which would, carries no force in the simulator — so the
 * grasp is not force closure whatever else it has.
 */
public enum TrialOutcome {
    /** Force closure. */
    FORCE_CLOSURE,
    /** The fingers closed without touching the object. */
    NO_CONTACT,
    /** Only one finger touched. */
    ONE_FINGER,
    /** Every contact pushes the object toward the palm (fingertips over its far side). */
    ALL_TOWARD_PALM,
    /** Every contact pushes the object away from the palm (only the near side touched). */
    ALL_AWAY_FROM_PALM,
    /** Contacts on several sides that still do not close (too few, too little friction, lined up). */
    OTHER,
    /**
     * The fingers closed through each other (the simulator stops a finger at the object, not at
     * another finger): no pose the hand can reach, whatever its contacts.
     */
    FINGERS_CROSS;

    /** The outcome of an evaluated grasp approached along the unit vector {@code a}. */
    public static TrialOutcome of(GraspAssessment g, double[] a) {
        if (g.quality().forceClosure()) return FORCE_CLOSURE;
        if (g.contacts().isEmpty()) return NO_CONTACT;
        int fingers = 0;
        for (int k = 1; k <= 3; k++) {
            for (GraspAssessment.Contact c : g.contacts()) {
                if (c.finger() == k) {
                    fingers++;
                    break;
                }
            }
        }
        if (fingers < 2) return ONE_FINGER;
        double lean = StrictMath.atan(g.friction());
        boolean away = false, toward = false;
        for (GraspAssessment.Contact c : g.contacts()) {
            double[] n = c.normal();
            double cos = (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / StrictMath.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            double theta = StrictMath.acos(Math.max(-1, Math.min(1, cos)));
            if (theta < StrictMath.PI / 2 + lean) away = true;
            if (theta > StrictMath.PI / 2 - lean) toward = true;
        }
        if (!away) return ALL_TOWARD_PALM;
        if (!toward) return ALL_AWAY_FROM_PALM;
        return OTHER;
    }

    /**
     * The one line a plan without force closure prints: why (the most common outcome, of how many
     * trials) and what to try.
     *
     * @param counts   trials per outcome (index: ordinal)
     * @param extentM  the object's largest extent, metres
     */
    public static String advice(long[] counts, long trials, double extentM) {
        TrialOutcome worst = null;
        for (TrialOutcome o : values()) {
            if (o != FORCE_CLOSURE && (worst == null || counts[o.ordinal()] > counts[worst.ordinal()])) worst = o;
        }
        long n = counts[worst.ordinal()];
        String size = String.format(java.util.Locale.ROOT, "%.0f mm", extentM * 1000);
        String of = "in " + n + " of " + trials + " trials ";
        switch (worst) {
            case FINGERS_CROSS:
                return of + "the fingertips closed past the object into each other: the object (" + size + " across) is too small"
                    + " for the hand to enclose (its fingertips meet); try a larger --units (or scale) if its file is not in metres,"
                    + " or a larger object";
            case NO_CONTACT:
            case ONE_FINGER:
                return of + "the fingers closed " + (worst == NO_CONTACT ? "without touching the object" : "with one finger on the object")
                    + ": the object (" + size + " across) may be too small or too thin for the hand to enclose; try a larger --units"
                    + " (or scale) if its file is not in metres, or a larger object";
            case ALL_TOWARD_PALM:
                return of + "the fingertips closed over the object's far side only, pushing it toward the palm (which carries no force"
                    + " here): the object (" + size + " across) may be smaller than the hand's reach; try a larger --units (or scale)"
                    + " if its file is not in metres, more --trials, or more --friction";
            case ALL_AWAY_FROM_PALM:
                return of + "the fingers touched only the object's near side, pushing it away from the palm: the object (" + size
                    + " across) may be larger than the hand can close round; try more --trials, or a smaller --units (or scale) if its"
                    + " file is not in metres";
            default:
                return of + "the contacts lay on several sides but did not close; try more --friction, more --trials, or a template"
                    + " scenario that closes the fingers differently";
        }
    }
}
