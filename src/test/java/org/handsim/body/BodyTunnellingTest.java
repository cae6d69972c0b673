package org.handsim.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * {@link Tunnelling} through {@link BodyScene} and {@link BodyStepper}: the first step whose
 * travel exceeds the margin, found by hand from the step's kinematics.
 */
class BodyTunnellingTest {
    static final double G = 9.80665;
    static final TriangleMesh BOX = BoxMesh.of("box", 0.06, 0.04, 0.02);
    static final TriangleMesh TABLE = BoxMesh.of("table", 0.8, 0.6, 0.02);

    /** The box's reach: half its diagonal, √(0.03² + 0.02² + 0.01²) m. */
    @Test
    void reachIsTheFarthestVertexFromTheCentreOfMass() {
        assertEquals(Math.sqrt(0.03 * 0.03 + 0.02 * 0.02 + 0.01 * 0.01), Tunnelling.reach(BOX, MassProperties.ofSolid(BOX, 1000)), 1e-15);
    }

    /**
     * Free fall at h = 5 ms, margin 1 mm: the drift of step k (ending at kh) moves at g(k − ½)h
     * (kick–drift–kick), so the first step that travels more than 1 mm is the first k with
     * g(k − ½)h² &gt; 1e-3, k = 5 (4.079 &lt; k − ½): t = 0.025 s, 0.2206 m/s; after 0.1 s
     * (k = 20) every step from k = 5 on has tunnelled, 16 of them, the last the fastest.
     */
    @Test
    void aFallingBoxTunnelsFromTheFirstStepThatOutrunsTheMargin() {
        double h = 0.005;
        BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), RigidTransform.fromPose(0, 0, 1, 0, 0, 0));
        s.addSupport(TABLE, RigidTransform.fromPose(0, 0, -0.01, 0, 0, 0));
        for (int i = 0; i < 4; i++) s.step(h);
        assertFalse(s.tunnelling().any(), "4 steps: " + s.tunnelling().warning());
        for (int i = 4; i < 20; i++) s.step(h);
        Tunnelling t = s.tunnelling();
        System.out.println(t.warning());
        assertEquals(16, t.steps());
        assertEquals(0.025, t.firstTimeS(), 1e-15);
        assertEquals(G * 4.5 * h, t.firstSpeedMS(), 1e-12);
        assertEquals(0.1, t.fastestTimeS(), 1e-14);
        assertEquals(G * 19.5 * h, t.fastestSpeedMS(), 1e-12);
        assertTrue(t.warning().contains("t = 0.0250 s") && t.warning().contains("0.221 m/s"), t.warning());
    }

    /**
     * A spinning box, no gravity, ω = 30 rad/s about its principal axis z: the free rotation is
     * three Cayley steps of γ₁h, γ₂h, γ₁h (Yoshida), each turning by 2·atan(ωγh/2), and the drift's
     * angular velocity is the one whose Cayley map over h gives their sum Θ, (2/h)·tan(Θ/2); the
     * speed bound is that times r;
     * it tunnels at h = 1 ms (1.12 mm a step), not at 0.5 ms (0.56 mm).
     */
    @Test
    void aSpinTunnelsByItsReach() {
        double r = Math.sqrt(0.03 * 0.03 + 0.02 * 0.02 + 0.01 * 0.01);
        for (double h : new double[] {0.001, 0.0005}) {
            BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), RigidTransform.fromPose(0, 0, 1, 0, 0, 0)).gravity(0, 0, 0);
            s.body().setVelocity(new double[3], new double[] {0, 0, 30});
            for (int i = 0; i < 10; i++) s.step(h);
            Tunnelling t = s.tunnelling();
            if (30 * r * h > 1e-3) {
                assertEquals(10, t.steps(), "h " + h);
                double g1 = 1 / (2 - Math.cbrt(2)), g2 = 1 - 2 * g1;
                double turn = 2 * (2 * Math.atan(30 * g1 * h / 2) + Math.atan(30 * g2 * h / 2));
                assertEquals(2 / h * Math.tan(turn / 2) * r, t.firstSpeedMS(), 1e-12, "h " + h);
                assertEquals(h, t.firstTimeS(), 1e-15);
            } else {
                assertFalse(t.any(), "h " + h + ": " + t.warning());
            }
        }
    }

    /** Resting on the table for 1 s: no step tunnels, and the clock counted the steps. */
    @Test
    void aRestingBoxDoesNotTunnel() {
        BodyScene s = new BodyScene(BOX, MassProperties.ofSolid(BOX, 1000), RigidTransform.fromPose(0, 0, 0.01, 0, 0, 0));
        s.addSupport(TABLE, RigidTransform.fromPose(0, 0, -0.01, 0, 0, 0));
        for (int i = 0; i < 1000; i++) s.step(0.001);
        assertFalse(s.tunnelling().any());
        assertNull(s.tunnelling().warning());
        assertEquals(1.0, s.stepper().time(), 1e-12);
    }
}
