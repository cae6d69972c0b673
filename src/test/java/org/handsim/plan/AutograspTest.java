package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.SplittableRandom;
import org.handsim.TestPaths;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.HandClearance;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.SceneMeshes;
import org.junit.jupiter.api.Test;

class AutograspTest {
    static final Path CUBE = TestPaths.root().resolve("vrml/objects/cube.wrl");

    static HandClearance cube() {
        return new HandClearance(new Scenario.ObjectPlacement(CUBE, RigidTransform.IDENTITY, 1.0, 24));
    }

    /** The palm's z axis is the approach, x and y are unit and orthogonal, the roll turns x about a. */
    @Test
    void palmFrameFollowsTheApproachAndTheRoll() {
        SplittableRandom r = new SplittableRandom(11);
        for (int i = 0; i < 500; i++) {
            double[] a = {r.nextGaussian(), r.nextGaussian(), r.nextGaussian()};
            double l = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            for (int j = 0; j < 3; j++) a[j] /= l;
            double roll = 2 * Math.PI * r.nextDouble();
            double[] v = Autograsp.palmRotation(a, roll);
            RigidTransform t = RigidTransform.fromPose(0, 0, 0, v[0], v[1], v[2]);
            double[] z = t.axis(2), x = t.axis(0);
            for (int j = 0; j < 3; j++) assertEquals(a[j], z[j], 1e-12);
            double[] v0 = Autograsp.palmRotation(a, 0);
            double[] x0 = RigidTransform.fromPose(0, 0, 0, v0[0], v0[1], v0[2]).axis(0);
            double cos = x[0] * x0[0] + x[1] * x0[1] + x[2] * x0[2];
            assertEquals(Math.cos(roll), cos, 1e-12);
        }
    }

    /**
     * Straight down onto the cube's top face (z = 0.03), palm turned over (a = −z, roll 0: R =
     * rotation by π about x, so a hand point p of the palm frame is at world z = c_z + d − p_z).
     * The hand meets the flat face first at a vertex, the one with the largest p_z among those
     * above the face (|x|, |y| ≤ 0.03 in the world): d = 0.03 − c_z + max p_z. Computed here from
     * the meshes and forward kinematics, without the collision query.
     */
    @Test
    void firstTouchOnTheCubeIsTheLowestHandVertexAboveTheFace() {
        HandClearance hc = cube();
        double[] c = hc.objectCentroid();
        assertEquals(0, c[0], 1e-15);
        assertEquals(0, c[2], 1e-15);
        double best = Double.NEGATIVE_INFINITY;
        best = Math.max(best, highestAboveFace(SceneMeshes.mesh(SceneMeshes.palmFile(), SceneMeshes.LINK_DIVISIONS, 1.0),
            RigidTransform.IDENTITY.toArray(), 0, c));
        double[] frames = new double[48];
        for (int k = 1; k <= 3; k++) {
            FingerKinematics.of(k).framesInPalm(new double[3], frames);
            for (int j = 1; j <= 3; j++) {
                best = Math.max(best, highestAboveFace(SceneMeshes.mesh(SceneMeshes.linkFile(j), SceneMeshes.LINK_DIVISIONS, 1.0), frames, 12 * j, c));
            }
        }
        double expected = 0.03 - c[2] + best;
        Autograsp.Approach ap = Autograsp.approach(hc, new double[] {0, 0, -1}, 0, 0, new double[3], 0);
        assertTrue(ap.touched());
        assertEquals(expected, ap.distance(), 2 * Autograsp.TOL_M, "first-touch distance");
        assertTrue(ap.distance() >= expected - 1e-12, "the returned pose is on the clear side");
    }

    private static double highestAboveFace(TriangleMesh m, double[] w, int o, double[] c) {
        double[] v = m.vertices();
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < v.length; i += 3) {
            double x = w[o] * v[i] + w[o + 1] * v[i + 1] + w[o + 2] * v[i + 2] + w[o + 3];
            double y = w[o + 4] * v[i] + w[o + 5] * v[i + 1] + w[o + 6] * v[i + 2] + w[o + 7];
            double z = w[o + 8] * v[i] + w[o + 9] * v[i + 1] + w[o + 10] * v[i + 2] + w[o + 11];
            // world x = c_x + x, world y = c_y − y (rotation by π about x)
            if (Math.abs(c[0] + x) <= 0.03 && Math.abs(c[1] - y) <= 0.03) best = Math.max(best, z);
        }
        return best;
    }

    /** The approach's pose is clear of the object; a hair further in, the hand touches; the standoff backs off exactly. */
    @Test
    void poseIsClearAndTheStandoffBacksOff() {
        HandClearance hc = cube();
        TrialSampler s = new TrialSampler(40, 5, null);
        double[] counts = new double[3];
        int touched = 0;
        for (int i = 0; i < 40; i++) {
            TrialParameters p = s.sample(i);
            Autograsp.Approach ap = Autograsp.approach(hc, p.approach(), p.roll(), p.spreadCounts(), counts, 0);
            if (!ap.touched()) continue;
            touched++;
            assertFalse(hc.touches(ap.worldFromPalm(), p.spreadCounts(), counts), "trial " + i + ": the approach ends clear");
            double[] a = p.approach(), o = ap.position(), v = ap.rotation();
            double in = 3 * Autograsp.TOL_M;
            RigidTransform closer = RigidTransform.fromPose(o[0] + in * a[0], o[1] + in * a[1], o[2] + in * a[2], v[0], v[1], v[2]);
            assertTrue(hc.touches(closer, p.spreadCounts(), counts), "trial " + i + ": 3 µm further in, the hand touches");
            Autograsp.Approach back = Autograsp.approach(hc, p.approach(), p.roll(), p.spreadCounts(), counts, 0.007);
            assertEquals(ap.distance() + 0.007, back.distance(), 1e-15);
        }
        assertTrue(touched >= 38, "approaches toward the centroid of a cube meet it: " + touched);
    }
}
