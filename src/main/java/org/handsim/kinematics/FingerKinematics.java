package org.handsim.kinematics;

import org.handsim.hand.DhRow;
import org.handsim.hand.FingerDescription;
import org.handsim.hand.HandDescription;
import org.handsim.math.RigidTransform;

/**
 * Forward kinematics of one finger (paper Section II.A, Table I): the frames {k1}, {k2}, {k3}
 * in the finger base frame {k0} by the standard DH product
 * {@code T(k0 → kj) = Π_{i ≤ j} Rz(θi + offset_i)·Tz(d_i)·Tx(a_i)·Rx(α_i)}; the fingertip is
 * the origin of {k3}.
 *
 * <p>Worked example (BarrettHand, all joint angles 0): the DH angles are 0, Φ2 = 2.46°,
 * Φ3 = 50°; link 1 reaches (A1, 0, 0) = (0.050, 0, 0); links 2 and 3 lie in the x–z plane of
 * {k0} (α1 = 90° turns the joint-2 axis to −y), so the fingertip is at
 * x = A1 + A2 cos Φ2 + A3 cos(Φ2 + Φ3), y = 0, z = A2 sin Φ2 + A3 sin(Φ2 + Φ3).
 *
 * <p>The array form {@link #frames(double[], double[])} is allocation-free for the
 * simulator's step. Thread-safe (no mutable state).
 */
public final class FingerKinematics {
    /** Number of doubles {@link #frames} writes: 4 frames × 12 (row-major 3×4). */
    public static final int FRAMES_LENGTH = 48;

    private final FingerDescription finger;
    private final DhRow r1, r2, r3;
    private final double[] base = new double[12];
    private final double ca1, sa1, ca2, sa2, ca3, sa3;   // cos and sin of the constant twists

    public FingerKinematics(FingerDescription finger) {
        this.finger = finger;
        this.r1 = finger.dh(0);
        this.r2 = finger.dh(1);
        this.r3 = finger.dh(2);
        finger.baseInPalm().copyTo(base, 0);
        ca1 = Math.cos(r1.alpha());
        sa1 = Math.sin(r1.alpha());
        ca2 = Math.cos(r2.alpha());
        sa2 = Math.sin(r2.alpha());
        ca3 = Math.cos(r3.alpha());
        sa3 = Math.sin(r3.alpha());
    }

    /** Finger k of the BarrettHand. */
    public static FingerKinematics of(int k) {
        return new FingerKinematics(HandDescription.barrettHand().finger(k));
    }

    public FingerDescription finger() { return finger; }

    /**
     * Writes the frames {k0}, {k1}, {k2}, {k3} expressed in {k0} into {@code out[0..47]}, 12
     * row-major values each (frame j at offset 12·j; {k0} is the identity).
     *
     * @param joints {θk1, θk2, θk3} in radians (θk1 must be 0 for a finger without spread)
     * @param out    at least {@link #FRAMES_LENGTH} doubles
     * @throws IllegalArgumentException if a joint is not finite, or θ31 ≠ 0
     */
    public void frames(double[] joints, double[] out) {
        checkJoints(joints);
        out[0] = 1; out[1] = 0; out[2] = 0; out[3] = 0;
        out[4] = 0; out[5] = 1; out[6] = 0; out[7] = 0;
        out[8] = 0; out[9] = 0; out[10] = 1; out[11] = 0;
        RigidTransform.dhInto(joints[0] + r1.thetaOffset(), r1.d(), r1.a(), ca1, sa1, out, 12);
        appendLinks2And3(joints, out);
    }

    /**
     * As {@link #frames(double[], double[])}, expressed in the palm frame {P}
     * (allocation-free: {k0} is the base placement, then each DH link is appended).
     */
    public void framesInPalm(double[] joints, double[] out) {
        framesFrom(base, joints, out);
    }

    /**
     * As {@link #framesInPalm}, with {k0} placed by the given 12-value transform {@code base}
     * (e.g. world ← k0) instead of the palm placement (allocation-free; out must not overlap base).
     */
    public void framesFrom(double[] base, double[] joints, double[] out) {
        checkJoints(joints);
        System.arraycopy(base, 0, out, 0, 12);
        RigidTransform.multiplyDh(out, 0, joints[0] + r1.thetaOffset(), r1.d(), r1.a(), ca1, sa1, out, 12);
        appendLinks2And3(joints, out);
    }

    /**
     * As {@link #framesFrom} when {@code out} already holds what it wrote for the same base and
     * the same θk1 (frames {k0}, {k1} at out[0..23]): writes only {k2}, {k3} from θk2, θk3, the
     * same values the full call would (the simulator's step, where the spread rarely moves).
     */
    public void framesFromKeepingLink1(double[] joints, double[] out) {
        checkJoints(joints);
        appendLinks2And3(joints, out);
    }

    /** Frames {k2}, {k3} at out[24..47] from {k1} at out[12..23]. */
    private void appendLinks2And3(double[] joints, double[] out) {
        RigidTransform.multiplyDh(out, 12, joints[1] + r2.thetaOffset(), r2.d(), r2.a(), ca2, sa2, out, 24);
        RigidTransform.multiplyDh(out, 24, joints[2] + r3.thetaOffset(), r3.d(), r3.a(), ca3, sa3, out, 36);
    }

    /** The fingertip (origin of {k3}) in {k0}, metres (closed form, allocation-free). */
    public void fingertip(double[] joints, double[] out) {
        checkJoints(joints);
        double p2 = joints[1] + r2.thetaOffset();
        double p23 = p2 + joints[2] + r3.thetaOffset();
        double reach = r1.a() + r2.a() * Math.cos(p2) + r3.a() * Math.cos(p23);
        double height = r2.a() * Math.sin(p2) + r3.a() * Math.sin(p23);
        double t1 = joints[0] + r1.thetaOffset();
        out[0] = reach * Math.cos(t1);
        out[1] = reach * Math.sin(t1);
        out[2] = height;
    }

    /** The fingertip in {k0} as a new array. */
    public double[] fingertip(double[] joints) {
        double[] p = new double[3];
        fingertip(joints, p);
        return p;
    }

    /** {k0} in the palm frame: {@code P ← k0}. */
    public RigidTransform baseInPalm() {
        return finger.baseInPalm();
    }

    private void checkJoints(double[] joints) {
        if (joints.length < 3) throw new IllegalArgumentException("need 3 joint angles, got " + joints.length);
        for (int i = 0; i < 3; i++) {
            if (!Double.isFinite(joints[i])) {
                throw new IllegalArgumentException("joint angle t" + (i + 1) + " = " + joints[i] + " is not finite");
            }
        }
        if (!finger.hasSpread() && joints[0] != 0) {
            throw new IllegalArgumentException("finger " + finger.finger() + " has no spread: t1 must be 0, got " + joints[0]);
        }
    }
}
