package org.handsim.model;

import java.util.List;
import org.handsim.math.RigidTransform;
import org.handsim.scenario.HandMove;

/**
 * Where the hand's base is at time t, and how fast it moves (DESIGN.md decision 7, scenario
 * field {@code hand.moves}): the segments are played one after the other from the scenario's
 * palm pose, as the motors' segments are; a {@code line} moves the palm's origin along its
 * world direction by the distance its trapezoid has covered, a {@code rotate} turns the palm
 * about its world axis through the palm's origin by the angle covered (Rodrigues' formula), a
 * {@code hold} keeps it; after the last segment the palm stays where it ended.
 *
 * <p>Immutable after construction; {@link #sample} allocates nothing.
 */
final class HandPath {
    private final int n;
    private final double[] start;          // each segment's start time, s
    private final double[][] origin;       // the palm's origin at each segment's start (world)
    private final double[][] rotation;     // the palm's rotation (world ← palm, 9 row-major) at each segment's start
    private final List<HandMove> moves;
    private final double[] end12 = new double[12];
    private final double[] sample = new double[3];

    HandPath(RigidTransform worldFromPalm, List<HandMove> moves) {
        this.moves = moves;
        this.n = moves.size();
        start = new double[n + 1];
        origin = new double[n + 1][3];
        rotation = new double[n + 1][9];
        double[] p = worldFromPalm.toArray();
        origin[0] = new double[] {p[3], p[7], p[11]};
        rotation[0] = new double[] {p[0], p[1], p[2], p[4], p[5], p[6], p[8], p[9], p[10]};
        for (int i = 0; i < n; i++) {
            HandMove m = moves.get(i);
            start[i + 1] = start[i] + m.profile().duration();
            double s = m.profile().end();
            place(m, s, origin[i], rotation[i], origin[i + 1], rotation[i + 1]);
        }
        end12[0] = rotation[n][0]; end12[1] = rotation[n][1]; end12[2] = rotation[n][2]; end12[3] = origin[n][0];
        end12[4] = rotation[n][3]; end12[5] = rotation[n][4]; end12[6] = rotation[n][5]; end12[7] = origin[n][1];
        end12[8] = rotation[n][6]; end12[9] = rotation[n][7]; end12[10] = rotation[n][8]; end12[11] = origin[n][2];
    }

    /** @return true when the base moves at some time (a segment other than a hold) */
    boolean moves() {
        for (HandMove m : moves) if (!m.type().equals("hold")) return true;
        return false;
    }

    /** The time the last segment ends, s. */
    double duration() { return start[n]; }

    /**
     * The palm's pose at time t (world ← palm, 12 row-major values into {@code pose}) and its
     * twist ({@code twist}: the velocity of the palm's origin, m/s, then the angular velocity,
     * rad/s, both world).
     */
    void sample(double t, double[] pose, double[] twist) {
        java.util.Arrays.fill(twist, 0);
        int i = 0;
        while (i < n && t >= start[i + 1]) i++;
        if (i == n) {
            System.arraycopy(end12, 0, pose, 0, 12);
            return;
        }
        HandMove m = moves.get(i);
        m.profile().sample(t - start[i], sample);
        double[] o = origin[i], r = rotation[i];
        double[] no = scratchO, nr = scratchR;
        place(m, sample[0], o, r, no, nr);
        pose[0] = nr[0]; pose[1] = nr[1]; pose[2] = nr[2]; pose[3] = no[0];
        pose[4] = nr[3]; pose[5] = nr[4]; pose[6] = nr[5]; pose[7] = no[1];
        pose[8] = nr[6]; pose[9] = nr[7]; pose[10] = nr[8]; pose[11] = no[2];
        double[] d = m.direction();
        if (m.type().equals("line")) {
            twist[0] = d[0] * sample[1]; twist[1] = d[1] * sample[1]; twist[2] = d[2] * sample[1];
        } else if (m.type().equals("rotate")) {
            twist[3] = d[0] * sample[1]; twist[4] = d[1] * sample[1]; twist[5] = d[2] * sample[1];
        }
    }

    private final double[] scratchO = new double[3], scratchR = new double[9];

    /** The palm after segment m has covered s (m or rad) from origin o and rotation r, into no, nr. */
    private static void place(HandMove m, double s, double[] o, double[] r, double[] no, double[] nr) {
        double[] d = m.direction();
        System.arraycopy(o, 0, no, 0, 3);
        if (m.type().equals("line")) {
            no[0] += d[0] * s; no[1] += d[1] * s; no[2] += d[2] * s;
            System.arraycopy(r, 0, nr, 0, 9);
        } else if (m.type().equals("rotate")) {
            // Rodrigues: Rot(d, s) = I + sin s [d]x + (1 − cos s) [d]x²
            double c = Math.cos(s), sn = Math.sin(s), v = 1 - c, x = d[0], y = d[1], z = d[2];
            double r00 = c + x * x * v, r01 = x * y * v - z * sn, r02 = x * z * v + y * sn;
            double r10 = y * x * v + z * sn, r11 = c + y * y * v, r12 = y * z * v - x * sn;
            double r20 = z * x * v - y * sn, r21 = z * y * v + x * sn, r22 = c + z * z * v;
            for (int col = 0; col < 3; col++) {
                double a = r[col], b = r[3 + col], e = r[6 + col];
                nr[col] = r00 * a + r01 * b + r02 * e;
                nr[3 + col] = r10 * a + r11 * b + r12 * e;
                nr[6 + col] = r20 * a + r21 * b + r22 * e;
            }
        } else {
            System.arraycopy(r, 0, nr, 0, 9);
        }
    }
}
