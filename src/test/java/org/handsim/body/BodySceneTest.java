package org.handsim.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.collision.TestMeshes;
import org.handsim.math.Quaternion;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * {@link BodyScene}: a box on a table (a support mesh), contacts found by proximity: it rests,
 * and on a tilted table it stays or slides as Coulomb says, against the closed forms; a plate
 * that a pressing joint turns closes its gap once and pinches the box against a wall.
 */
class BodySceneTest {
    static final double G = 9.80665, H = 0.001;
    static final double HX = 0.03, HY = 0.02, HZ = 0.01;
    static final TriangleMesh BOX = TestMeshes.box(HX, HY, HZ, 2);
    static final TriangleMesh TABLE = TestMeshes.box(0.4, 0.3, 0.01, 3);

    /** A box resting on a table for 10 s: drift below 0.1 mm and 0.1°; its four corners carry its weight. */
    @Test
    void aBoxRestsOnATable() {
        double[] r = run(0, 0.5, 10.0);
        System.out.printf("rest on the table 10 s: %.3e m, %.3e rad, %d contacts%n", r[0], r[1], (int) r[3]);
        assertTrue(r[0] < 1e-4, "drift " + r[0] + " m");
        assertTrue(r[1] < Math.toRadians(0.1), "turned " + r[1] + " rad");
        assertTrue(r[3] >= 4, "contacts " + r[3]);
    }

    /** On a table tilted by a: stays if tan a &lt; μ, else slides ½g(sin a − μ cos a)t² within 2 % after 0.5 s (μ = 0.5). */
    @Test
    void aBoxOnATiltedTableStaysOrSlides() {
        double mu = 0.5;
        for (double deg : new double[] {20, 25, 28, 35}) {
            double a = Math.toRadians(deg);
            double[] r = run(a, mu, 0.5);
            double want = Math.tan(a) < mu ? 0 : 0.5 * G * (Math.sin(a) - mu * Math.cos(a)) * 0.25;
            System.out.printf("tilted %.0f°: slid %.6e m, want %.6e; turned %.2e rad%n", deg, r[2], want, r[1]);
            if (want == 0) assertTrue(Math.abs(r[2]) < 1e-5, deg + "°: slid " + r[2]);
            else assertEquals(want, r[2], 0.02 * want, deg + "°");
        }
    }

    /** {drift of the centre, rotation, displacement down the slope, contacts at the end}. */
    static double[] run(double a, double mu, double t) {
        double[] n = {Math.sin(a), 0, Math.cos(a)};
        RigidTransform boxPose = RigidTransform.fromPose(HZ * n[0], 0, HZ * n[2], 0, a, 0);
        BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), boxPose).friction(mu);
        // the table's top face through the origin, tilted by a about y
        RigidTransform table = RigidTransform.fromPose(-0.01 * n[0], 0, -0.01 * n[2], 0, a, 0);
        s.addSupport(TABLE, table);
        double[] x0 = s.body().position(new double[3]), q0 = s.body().orientation(new double[4]);
        int steps = (int) Math.round(t / H);
        for (int i = 0; i < steps; i++) {
            assertEquals(ContactSolver.Outcome.CONVERGED, s.step(H), "step " + i);
        }
        double[] x = s.body().position(new double[3]);
        double dx = x[0] - x0[0], dy = x[1] - x0[1], dz = x[2] - x0[2];
        double[] down = {Math.cos(a), 0, -Math.sin(a)};
        return new double[] {Math.sqrt(dx * dx + dy * dy + dz * dz), Quaternion.angleBetween(q0, 0, s.body().orientation(new double[4]), 0),
            dx * down[0] + dy * down[1] + dz * down[2], s.contacts().size()};
    }

    /**
     * A box between a fixed wall (touching its −x face) and a plate 0.3 mm off its +x face, the
     * plate hung from a joint 0.1 m above it (axis y: closing moves it along −x) that presses
     * with 1 N·m, held against opening by its worm; gravity off. Turning, the plate's face tilts
     * and first meets the box's lower edge, r = 0.1 + 0.01 m below the pivot: it must turn by the
     * gap over r, 2.73 mrad, once — the link is where its joint turned it, so the gap is gone —
     * and then pinch the box at that edge with τ/r = 9.09 N against the wall, the box at rest.
     * (A plate left where it was added would close the same gap every step, turning on without
     * end.)
     */
    @Test
    void aPressingPlateClosesItsGapOnceAndPinchesTheBox() {
        double gap = 3e-4, arm = 0.1, tau = 1, plateHalf = 0.005;
        TriangleMesh plate = TestMeshes.box(plateHalf, 0.03, 0.02, 2);
        BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), RigidTransform.IDENTITY).gravity(0, 0, 0).friction(0.5);
        s.addSupport(plate, RigidTransform.translation(-HX - plateHalf, 0, 0));
        double px = HX + gap + plateHalf;
        int p = s.addSupport(plate, RigidTransform.translation(px, 0, 0));
        int j = s.addJoint(new double[] {0, 1, 0}, new double[] {px, 0, arm}, 1e-4, tau, true);
        s.moves(j, p);
        for (int i = 0; i < 500; i++) assertEquals(ContactSolver.Outcome.CONVERGED, s.step(H), "step " + i);
        double turned = s.jointTurns()[1];
        System.out.printf("pressing plate: turned %.4e rad (gap/r %.4e), joint speed %.2e rad/s%n", turned, gap / (arm + HZ), s.jointVelocity(j));
        double r = arm + HZ;
        assertEquals(gap / r, turned, 0.02 * gap / r, "turned by the gap over the arm, once");
        double[] pose = s.supportPose(p);
        // the plate's centre, 0.1 m below the pivot, swung by the angle turned: x = px − 0.1·sin θ
        // (placed at the last step's start: its own turn, h·ω·0.1 m, is not in it yet)
        assertEquals(px - arm * Math.sin(turned), pose[3], H * Math.abs(s.jointVelocity(j)) * arm * 1.01);
        double[] v = s.body().velocity(new double[3]);
        assertTrue(Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) < 1e-5, "the box is at rest: " + java.util.Arrays.toString(v));
        double fx = 0;
        for (int c = 0; c < s.contacts().size(); c++) if (s.contacts().body(c) == p) fx += s.contacts().impulse(c, new double[3])[0] / H;
        System.out.printf("pressing plate: force along x %.4f N (tau/r %.4f N)%n", fx, tau / r);
        assertEquals(-tau / r, fx, 0.02 * tau / r, "the plate presses the box with tau/r along -x");
    }
}
