package org.handsim.dynamics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.handsim.hand.FingerDescription;
import org.handsim.hand.HandDescription;
import org.junit.jupiter.api.Test;

class HandDynamicsTest {
    private static final double[] G = {0, 0, -9.81};

    @Test
    void threeJointLayoutMatchesTheFingerDynamics() {
        HandDynamics hand = HandDynamics.barrettHand();
        assertTrue(hand.finger(1) instanceof ClosedFormFinger);
        double[] q = {0.3, 0.6, 0.4}, qd = {1, -2, 0.5}, qdd = {3, 4, -5}, tau = new double[3];
        hand.inverseDynamics(1, q, qd, qdd, G, tau);
        assertArrayEquals(hand.finger(1).inverseDynamics(q, qd, qdd, G, null), tau);

        double[] q3 = {0, 0.6, 0.4}, qd3 = {0, -2, 0.5}, qdd3 = {0, 4, -5};
        hand.inverseDynamics(3, q3, qd3, qdd3, G, tau);
        double[] two = hand.finger(3).inverseDynamics(new double[] {0.6, 0.4}, new double[] {-2, 0.5}, new double[] {4, -5}, G, null);
        assertEquals(0.0, tau[0]);
        assertEquals(two[0], tau[1]);
        assertEquals(two[1], tau[2]);
    }

    /** The reduced finger-3 model equals the full 3-joint model with joint 1 held still (rows 2, 3). */
    @Test
    void fingerThreeIsTheThreeJointModelWithItsSpreadHeld() {
        HandDynamics hand = HandDynamics.of(HandDescription.barrettHand(), HandDynamics.Method.LAGRANGE_EULER);
        FingerDescription f3 = HandDescription.barrettHand().finger(3);
        ChainDynamics full = new LagrangeEuler(LinkChain.of(f3.dh(), f3.links()));   // all three joints active
        double[] t3 = new double[3];
        hand.inverseDynamics(3, new double[] {0, 0.6, 0.4}, new double[] {0, -2, 0.5}, new double[] {0, 4, -5}, G, t3);
        double[] t = full.inverseDynamics(new double[] {0, 0.6, 0.4}, new double[] {0, -2, 0.5}, new double[] {0, 4, -5}, G, null);
        assertEquals(t[1], t3[1], 1e-15);
        assertEquals(t[2], t3[2], 1e-15);
    }

    @Test
    void fingerThreeRefusesAMovingSpread() {
        HandDynamics hand = HandDynamics.barrettHand();
        double[] tau = new double[3];
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> hand.inverseDynamics(3, new double[] {0.1, 0, 0}, new double[3], new double[3], G, tau));
        assertTrue(e.getMessage().contains("joint 1 is fixed"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> hand.inverseDynamics(3, new double[3], new double[] {1, 0, 0}, new double[3], G, tau));
        assertThrows(IllegalArgumentException.class, () -> hand.finger(4));
    }

    @Test
    void methodsAgree() {
        HandDescription h = HandDescription.barrettHand();
        double[] q = {0.3, 0.6, 0.4}, qd = {1, -2, 0.5}, qdd = {3, 4, -5};
        double[] a = new double[3], b = new double[3], c = new double[3];
        HandDynamics.of(h, HandDynamics.Method.CLOSED_FORM).inverseDynamics(2, q, qd, qdd, G, a);
        HandDynamics.of(h, HandDynamics.Method.LAGRANGE_EULER).inverseDynamics(2, q, qd, qdd, G, b);
        HandDynamics.of(h, HandDynamics.Method.NEWTON_EULER).inverseDynamics(2, q, qd, qdd, G, c);
        assertArrayEquals(b, a, 1e-15);
        assertArrayEquals(b, c, 1e-15);
    }

    /** A hand whose first twist is not 90° cannot use the closed form: it falls back to Newton–Euler. */
    @Test
    void anotherStructureFallsBackToNewtonEuler() throws IOException {
        String text;
        try (InputStream in = HandDescription.class.getResourceAsStream("barretthand.json")) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        String modified = text.replace("\"alpha1_deg\": 90", "\"alpha1_deg\": 80");
        assertTrue(!modified.equals(text));
        HandDynamics hand = HandDynamics.of(HandDescription.parse("modified.json", modified), HandDynamics.Method.CLOSED_FORM);
        assertTrue(hand.finger(1) instanceof NewtonEuler);
    }
}
