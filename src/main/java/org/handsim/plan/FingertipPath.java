package org.handsim.plan;

import org.handsim.hand.HandDescription;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;

/**
 * Where the fingertips go as the FREE fingers close (eqs 3–4: θk2 = q/125°, θk3 = q/375°), in
 * the palm frame: the height above the palm origin at which a closing fingertip comes within a
 * given distance of the palm's axis, and, for a spread, the horizontal direction each finger
 * closes in. The planner uses them to put an object's widest part where the fingertips meet it
 * ({@link StandoffRule}).
 *
 * <p>The path is finger 3's (its base lies on the palm's y axis, so its tip's distance from the
 * axis is the horizontal distance it still has to close); sampled every {@link #STEP_COUNTS}
 * counts over the whole closing, 0 to the hand's largest finger count. The BH8-262's tip rises
 * from 131 mm at 154 mm from the axis (open) to 187 mm at 45 mm (7 500 counts) and crosses the
 * axis at 173 mm (10 400 counts).
 */
public final class FingertipPath {
    /** Sampling step of the closing, encoder counts (0.4° of the inner joint). */
    public static final double STEP_COUNTS = 50;

    private final HandDescription hand;
    private final Transmission tr;
    private final double[] radial, height;   // finger 3's tip: distance from the palm axis, height, per sample
    private final FingerKinematics[] fk = new FingerKinematics[3];
    private final double[][] base = new double[3][12];
    private final double[] frames = new double[FingerKinematics.FRAMES_LENGTH];

    public FingertipPath(HandDescription hand) {
        this.hand = hand;
        this.tr = new Transmission(hand);
        for (int k = 1; k <= 3; k++) {
            fk[k - 1] = new FingerKinematics(hand.finger(k));
            hand.finger(k).baseInPalm().copyTo(base[k - 1], 0);
        }
        int n = (int) Math.ceil(hand.fingerCountsMax() / STEP_COUNTS) + 1;
        radial = new double[n];
        height = new double[n];
        for (int i = 0; i < n; i++) {
            double[] tip = tip(3, 0, Math.min(hand.fingerCountsMax(), i * STEP_COUNTS));
            radial[i] = Math.sqrt(tip[0] * tip[0] + tip[1] * tip[1]);
            height[i] = tip[2];
        }
    }

    /** Finger k's fingertip (the origin of {k3}) in the palm frame, FREE at {@code counts} with the spread at {@code spread}. */
    public double[] tip(int k, double spread, double counts) {
        double[] joints = {hand.finger(k).spreadRadPerCount() * spread, tr.innerAngle(counts), tr.outerAngle(counts)};
        fk[k - 1].framesFrom(base[k - 1], joints, frames);
        return new double[] {frames[36 + 3], frames[36 + 7], frames[36 + 11]};
    }

    /**
     * The height above the palm origin (palm z, metres) at which the closing fingertip first comes
     * within {@code w} of the palm's axis; the open tip's height when it starts within {@code w}
     * (an object wider than the open hand), the last sample's when it never does.
     */
    public double heightAtReach(double w) {
        for (int i = 0; i < radial.length; i++) {
            if (radial[i] <= w) return height[i];
        }
        return height[height.length - 1];
    }

    /**
     * The direction finger k's tip closes in, horizontal in the palm frame (x, y; unit): from the
     * open tip to the tip half-way closed, with the spread at {@code spread} counts.
     */
    public double[] closingDirection(int k, double spread) {
        double[] open = tip(k, spread, 0), half = tip(k, spread, hand.fingerCountsMax() / 2.0);
        double x = half[0] - open[0], y = half[1] - open[1];
        double l = Math.sqrt(x * x + y * y);
        return new double[] {x / l, y / l};
    }
}
