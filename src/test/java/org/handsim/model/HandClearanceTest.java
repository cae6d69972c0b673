package org.handsim.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.math.RigidTransform;
import org.handsim.plan.Autograsp;
import org.handsim.plan.TrialParameters;
import org.handsim.plan.TrialSampler;
import org.handsim.scenario.Scenario;
import org.junit.jupiter.api.Test;

/**
 * {@link HandClearance} places the links as {@link HandModel} does: a hand it calls clear
 * starts the simulation without contacts, and a hand the model finds touching at t = 0 it calls
 * touching (it also tests the palm, which the model does not collide).
 */
class HandClearanceTest {
    static final Path MUG = TestPaths.root().resolve("vrml/objects/mug.wrl");

    static String scenario(RigidTransform palm, int spread) {
        double[] p = palm.origin(), r = palm.rotationVector();
        return "{\"name\":\"c\",\"object\":{\"file\":\"" + MUG + "\"},\"hand\":{\"position_m\":[" + p[0] + "," + p[1] + "," + p[2]
            + "],\"rotation_rad\":[" + r[0] + "," + r[1] + "," + r[2] + "]},\"start_counts\":{\"M4\":" + spread
            + "},\"dt_s\":0.01,\"duration_s\":0.01,\"outputs\":{\"trace\":false,\"charts\":false,\"torques\":false}}";
    }

    @Test
    void clearMeansNoContactAtTheStartAndContactMeansTouching() {
        HandClearance hc = new HandClearance(new Scenario.ObjectPlacement(MUG, RigidTransform.IDENTITY, 1.0, 24));
        TrialSampler s = new TrialSampler(30, 17, null);
        int clear = 0, touching = 0;
        for (int i = 0; i < 30; i++) {
            TrialParameters p = s.sample(i);
            Autograsp.Approach ap = Autograsp.approach(hc, p.approach(), p.roll(), p.spreadCounts(), new double[3], 0);
            for (double in : new double[] {0, 0.001, 0.004}) {
                double[] o = ap.position(), a = p.approach(), v = ap.rotation();
                RigidTransform pose = RigidTransform.fromPose(o[0] + in * a[0], o[1] + in * a[1], o[2] + in * a[2], v[0], v[1], v[2]);
                Scenario sc = Scenario.parse(MUG, scenario(pose, p.spreadCounts()));
                HandModel m = Simulation.model(sc, false);
                int contacts = m.contacts(1).size() + m.contacts(2).size() + m.contacts(3).size();
                boolean touches = hc.touches(sc.worldFromPalm(), p.spreadCounts(), new double[3]);
                if (!touches) {
                    assertEquals(0, contacts, "trial " + i + ", " + in + " m in: clear, yet the model has contacts");
                    clear++;
                }
                if (contacts > 0) {
                    assertTrue(touches, "trial " + i + ", " + in + " m in: the model has contacts, the clearance test says clear");
                    touching++;
                }
            }
        }
        assertTrue(clear >= 30 && touching >= 10, "both cases exercised: " + clear + " clear, " + touching + " touching");
    }

    /**
     * Fingers FREE at 17 500 counts with the spread at 60° close past each other's tips (the three
     * tips meet on the palm axis at 10 400 counts): their links intersect; open, or at 5 000
     * counts, they are apart. At spread 0 fingers 1 and 2 close beside finger 3 (50 mm apart
     * across x) and pass its tip: apart at 15 000 counts, crossed by the end of the closing.
     */
    @Test
    void fingersThatCloseThroughEachOtherCross() {
        HandClearance hc = new HandClearance(new Scenario.ObjectPlacement(MUG, RigidTransform.IDENTITY, 1.0, 24));
        org.handsim.kinematics.Transmission tr = org.handsim.kinematics.Transmission.barrettHand();
        org.handsim.hand.HandDescription hand = tr.hand();
        java.util.function.BiFunction<Double, Double, double[][]> frames = (spread, counts) -> {
            double[][] f = new double[3][org.handsim.kinematics.FingerKinematics.FRAMES_LENGTH];
            for (int k = 1; k <= 3; k++) {
                double[] j = {hand.finger(k).spreadRadPerCount() * spread, tr.innerAngle(counts), tr.outerAngle(counts)};
                new org.handsim.kinematics.FingerKinematics(hand.finger(k)).framesInPalm(j, f[k - 1]);
            }
            return f;
        };
        org.junit.jupiter.api.Assertions.assertTrue(hc.fingersCross(frames.apply(1050.0, 17500.0)));
        org.junit.jupiter.api.Assertions.assertFalse(hc.fingersCross(frames.apply(1050.0, 0.0)));
        org.junit.jupiter.api.Assertions.assertFalse(hc.fingersCross(frames.apply(1050.0, 5000.0)));
        org.junit.jupiter.api.Assertions.assertFalse(hc.fingersCross(frames.apply(0.0, 15000.0)));
        org.junit.jupiter.api.Assertions.assertTrue(hc.fingersCross(frames.apply(0.0, 17500.0)));
    }
}
