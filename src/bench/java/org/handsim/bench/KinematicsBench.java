package org.handsim.bench;

import java.util.Random;
import org.handsim.kinematics.CoupledReach;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.InverseKinematics;

/** ns per forward and inverse kinematics call. */
final class KinematicsBench implements BenchMain.Suite {
    @Override
    public void run() {
        int n = 1024;
        Random rnd = new Random(42);
        double[][] joints = new double[n][];
        double[][] targets = new double[n][];
        double[][] far = new double[n][];
        FingerKinematics fk = FingerKinematics.of(2);
        InverseKinematics ik = InverseKinematics.of(2);
        for (int i = 0; i < n; i++) {
            joints[i] = new double[] {rnd.nextDouble() * Math.PI, rnd.nextDouble() * 2.44, rnd.nextDouble() * 1.7};
            targets[i] = fk.fingertip(joints[i]);
            far[i] = new double[] {0.3 + rnd.nextDouble(), rnd.nextDouble(), -rnd.nextDouble()};
        }
        double[] frames = new double[FingerKinematics.FRAMES_LENGTH];
        double[] tip = new double[3];
        int[] i = {0};
        Bench.measure("FK all 4 frames in {k0} (frames)", () -> {
            fk.frames(joints[i[0]++ & (n - 1)], frames);
            return frames[47];
        });
        Bench.measure("FK all 4 frames in {P} (framesInPalm)", () -> {
            fk.framesInPalm(joints[i[0]++ & (n - 1)], frames);
            return frames[47];
        });
        Bench.measure("FK fingertip only (closed form)", () -> {
            fk.fingertip(joints[i[0]++ & (n - 1)], tip);
            return tip[2];
        });
        Bench.measure("IK reachable target (eqs 5-7, all branches)", () -> ik.solve(targets[i[0]++ & (n - 1)]).errorM());
        Bench.measure("IK unreachable target (closest point)", () -> ik.solve(far[i[0]++ & (n - 1)]).errorM());
        CoupledReach reach = CoupledReach.of(2);
        Bench.measure("Coupled reach: closest integer counts (17 501 evaluated)",
            () -> reach.closest(targets[i[0]++ & (n - 1)]).errorM(), 500, 11, 50);
    }
}
