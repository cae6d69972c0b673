package org.handsim.body;

import java.util.Arrays;

/**
 * The contact points of one step between the free object and the bodies around it (supports,
 * finger links), world frame: for each, the point p, the unit normal n along which the other
 * body pushes the object (into the object), the gap g along n (&gt; 0 apart, &lt; 0
 * penetrating), Coulomb's μ, the other body's velocity at p, which body it is, and which
 * following joints move that body (a finger link pressed against the object,
 * {@link BodyStepper#addFollower}). Filled by the proximity query ({@link ProximityContacts})
 * or by hand; read by {@link BodyStepper}, which writes each contact's impulse back.
 *
 * <p>Buffers grow and are kept: no allocation per step once grown. Not thread-safe.
 */
public final class BodyContacts {
    /** Most following joints one contact can depend on (a finger link: its inner and outer joint, and the spread). */
    public static final int MAX_JOINTS = 3;

    int n;
    double[] point = new double[48], normal = new double[48], gap = new double[16], mu = new double[16], other = new double[48];
    double[] impulse = new double[48];
    int[] body = new int[16], joints = new int[16 * MAX_JOINTS];

    /** Empties the list. */
    public void clear() { n = 0; }

    /**
     * Adds a contact.
     *
     * @param p             the point, world, m
     * @param nrm           unit normal into the object (the direction the other body pushes it)
     * @param gapM          the gap along the normal, m (negative: penetration)
     * @param friction      Coulomb's μ ≥ 0
     * @param otherVelocity the other body's velocity at p, world, m/s (null: at rest)
     * @param bodyId        which body it is (the caller's numbering: reported back)
     * @return its index
     */
    public int add(double[] p, double[] nrm, double gapM, double friction, double[] otherVelocity, int bodyId) {
        return add(p[0], p[1], p[2], nrm[0], nrm[1], nrm[2], gapM, friction, otherVelocity, bodyId);
    }

    /** {@link #add(double[], double[], double, double, double[], int)} with the point and normal as numbers. */
    public int add(double px, double py, double pz, double nx, double ny, double nz, double gapM, double friction,
                   double[] otherVelocity, int bodyId) {
        if (n == gap.length) grow();
        int i = n++;
        point[3 * i] = px; point[3 * i + 1] = py; point[3 * i + 2] = pz;
        normal[3 * i] = nx; normal[3 * i + 1] = ny; normal[3 * i + 2] = nz;
        gap[i] = gapM;
        mu[i] = friction;
        if (otherVelocity == null) {
            other[3 * i] = other[3 * i + 1] = other[3 * i + 2] = 0;
        } else {
            other[3 * i] = otherVelocity[0]; other[3 * i + 1] = otherVelocity[1]; other[3 * i + 2] = otherVelocity[2];
        }
        body[i] = bodyId;
        Arrays.fill(joints, MAX_JOINTS * i, MAX_JOINTS * i + MAX_JOINTS, -1);
        impulse[3 * i] = impulse[3 * i + 1] = impulse[3 * i + 2] = 0;
        return i;
    }

    /** Says that contact i's other body is moved by follower {@code follower} ({@link BodyStepper#addFollower}). */
    public void dependsOn(int i, int follower) {
        for (int k = 0; k < MAX_JOINTS; k++) {
            if (joints[MAX_JOINTS * i + k] == follower) return;
            if (joints[MAX_JOINTS * i + k] < 0) {
                joints[MAX_JOINTS * i + k] = follower;
                return;
            }
        }
        throw new IllegalArgumentException("contact " + i + " already depends on " + MAX_JOINTS + " followers");
    }

    private void grow() {
        int cap = 2 * gap.length;
        point = Arrays.copyOf(point, 3 * cap);
        normal = Arrays.copyOf(normal, 3 * cap);
        other = Arrays.copyOf(other, 3 * cap);
        impulse = Arrays.copyOf(impulse, 3 * cap);
        gap = Arrays.copyOf(gap, cap);
        mu = Arrays.copyOf(mu, cap);
        body = Arrays.copyOf(body, cap);
        joints = Arrays.copyOf(joints, MAX_JOINTS * cap);
    }

    /** @return the number of contacts */
    public int size() { return n; }

    /** Contact i's point (world, m) into out; returns out. */
    public double[] point(int i, double[] out) { System.arraycopy(point, 3 * i, out, 0, 3); return out; }

    /** Contact i's unit normal into the object (world) into out; returns out. */
    public double[] normal(int i, double[] out) { System.arraycopy(normal, 3 * i, out, 0, 3); return out; }

    /** @return contact i's gap, m (negative: penetration) */
    public double gap(int i) { return gap[i]; }

    /** @return contact i's body id */
    public int body(int i) { return body[i]; }

    /** @return contact i's μ */
    public double friction(int i) { return mu[i]; }

    /** The impulse the other body gave the object at contact i over the last step (world, N·s) into out; returns out. */
    public double[] impulse(int i, double[] out) { System.arraycopy(impulse, 3 * i, out, 0, 3); return out; }

    /** @return the largest penetration among the contacts, m (0 when none penetrates) */
    public double largestPenetration() {
        double d = 0;
        for (int i = 0; i < n; i++) d = Math.max(d, -gap[i]);
        return d;
    }
}
