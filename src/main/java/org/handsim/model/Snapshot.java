package org.handsim.model;

import org.handsim.clutch.ClutchState;

/**
 * An immutable copy of the model's state after a step, for views on other threads (the GUI
 * reads snapshots; only the simulation thread touches the {@link HandModel}).
 *
 * @param time          simulated time, s
 * @param step          step index
 * @param fingers       per finger 1..3 (index 0..2)
 * @param spreadCounts  spread motor position, counts
 * @param worldFromPalm the palm's pose, world ← palm, 12 row-major values (it follows {@code hand.moves})
 * @param object        the free object's state, or null when the object is fixed (or there is none)
 */
public record Snapshot(double time, long step, FingerSnapshot[] fingers, double spreadCounts, double[] worldFromPalm, ObjectSnapshot object) {
    /**
     * The free object at this step (DESIGN.md decision 7), what {@code handsim run} writes of it.
     *
     * @param worldFromMesh    world ← object (its mesh's frame), 12 row-major values ({@link HandModel#objectPose})
     * @param now              trace.csv's object columns at this step, in the order of
     *                         {@link org.handsim.trace.Recorder#OBJECT_COLUMNS} ({@link HandModel#objectNow})
     * @param released         whether it is free yet (before {@code release_s} it is held in place)
     * @param releasedAtS      summary.json's {@code released_at_s} so far, s (NaN: not yet)
     * @param slippedAtS       summary.json's {@code slipped_at_s} so far, s (NaN: not yet)
     * @param droppedAtS       summary.json's {@code dropped_at_s} as it stands now, s (NaN: not dropped)
     * @param maxDisplacementM summary.json's {@code max_displacement_m} so far, m
     * @param maxRotationDeg   summary.json's {@code max_rotation_deg} so far, degrees
     */
    public record ObjectSnapshot(double[] worldFromMesh, double[] now, boolean released, double releasedAtS, double slippedAtS,
                                 double droppedAtS, double maxDisplacementM, double maxRotationDeg) {
        /** trace.csv's value of the column {@code c} ({@link org.handsim.trace.Recorder#OBJ_X} … {@link org.handsim.trace.Recorder#OBJ_ROT}). */
        public double column(int c) { return now[c]; }
    }

    /**
     * One finger.
     *
     * @param state        clutch state
     * @param motorCounts  motor position, counts
     * @param joints       θk1, θk2, θk3, rad
     * @param velocities   θ̇, rad/s
     * @param accelerations θ̈, rad/s²
     * @param torques      τk1, τk2, τk3, N·m
     * @param framesWorld  frames {k0}..{k3} in the world, 4 × 12 row-major
     * @param contactPoints  3 per contact, world frame, m
     * @param contactNormals 3 per contact, outward object normal, world frame
     * @param contactForces  per contact, N (along −normal)
     * @param contactLinks   per contact, link 1..3
     */
    public record FingerSnapshot(ClutchState state, double motorCounts, double[] joints, double[] velocities,
                                 double[] accelerations, double[] torques, double[] framesWorld,
                                 double[] contactPoints, double[] contactNormals, double[] contactForces, int[] contactLinks) {
        /** @return the number of contacts */
        public int contactCount() { return contactForces.length; }

        /** @return the sum of the contact force magnitudes, N */
        public double forceSum() {
            double s = 0;
            for (double f : contactForces) s += f;
            return s;
        }
    }

    /** Copies the model's current state. */
    static Snapshot of(HandModel m) {
        FingerSnapshot[] f = new FingerSnapshot[3];
        for (int k = 1; k <= 3; k++) {
            ContactSet cs = m.contacts(k);
            int n = cs.size();
            double[] p = new double[3 * n], nn = new double[3 * n], force = new double[n];
            int[] links = new int[n];
            for (int i = 0; i < n; i++) {
                System.arraycopy(cs.points, 3 * i, p, 3 * i, 3);
                System.arraycopy(cs.normals, 3 * i, nn, 3 * i, 3);
                force[i] = cs.forces[i];
                links[i] = cs.links[i];
            }
            f[k - 1] = new FingerSnapshot(m.state(k), m.motorCounts(k), m.joints(k), m.velocities(k), m.accelerations(k),
                m.torques(k), m.framesWorld(k), p, nn, force, links);
        }
        ObjectSnapshot o = !m.objectFree() ? null : new ObjectSnapshot(m.objectPose(), m.objectNow(), m.objectReleased(),
            m.objectReleasedAt(), m.objectSlippedAt(), m.objectDroppedAt(), m.objectMaxDisplacement(), m.objectMaxRotation());
        return new Snapshot(m.time(), m.stepIndex(), f, m.spreadCounts(), m.worldFromPalm(), o);
    }
}
