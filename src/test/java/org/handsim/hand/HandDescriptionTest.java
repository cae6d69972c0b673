package org.handsim.hand;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class HandDescriptionTest {
    private static String resourceText() throws IOException {
        try (InputStream in = HandDescription.class.getResourceAsStream("barretthand.json")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static String messageFor(String text) {
        return assertThrows(HandDescriptionException.class, () -> HandDescription.parse("bad.json", text)).getMessage();
    }

    @Test
    void barrettHandValuesFromThePaper() {
        HandDescription h = HandDescription.barrettHand();
        assertEquals(0.050, h.a1());
        assertEquals(0.070, h.a2());
        assertEquals(0.056, h.a3());
        assertEquals(Math.toRadians(2.46), h.finger(1).dh(1).thetaOffset(), 1e-15);
        assertEquals(Math.toRadians(50), h.finger(2).dh(2).thetaOffset(), 1e-15);
        assertEquals(Math.PI / 2, h.finger(3).dh(0).alpha(), 1e-15);
        assertTrue(h.finger(1).hasSpread());
        assertTrue(h.finger(2).hasSpread());
        assertFalse(h.finger(3).hasSpread());
        assertEquals(2, h.finger(3).activeJoints());
        assertEquals(0.16252678, h.finger(1).link(0).mass());
        assertEquals(-0.03629026, h.finger(3).link(2).com()[0]);
        // Table III prints +∫xy dm = 0.0000572 (about the origin of {k1}); the matrix entry is its negative
        assertEquals(-0.0000572, h.finger(2).link(0).inertia()[LinkInertia.XY]);
        assertEquals(0.0000658, h.finger(2).link(0).inertia()[LinkInertia.XX]);
        assertEquals(1.26, h.tauBreak());
        assertEquals(17500, h.fingerCountsMax());
        assertEquals(3150, h.spreadCountsMax());
        // base of finger 2 at (Aw, 0, Dw)
        double[] o = h.finger(2).baseInPalm().origin();
        assertEquals(0.025, o[0], 1e-15);
        assertEquals(0.084, o[2], 1e-15);
    }

    @Test
    void missingFieldIsNamed() throws IOException {
        String t = resourceText().replace("\"A2_m\": 0.070,", "");
        assertTrue(messageFor(t).contains("field links.A2_m: missing"), messageFor(t));
    }

    @Test
    void negativeMassIsNamed() throws IOException {
        String t = resourceText().replace("\"mass_kg\": 0.05795741", "\"mass_kg\": -0.05795741");
        String m = messageFor(t);
        assertTrue(m.contains("mass_properties.links[1].mass_kg") && m.contains("> 0"), m);
    }

    @Test
    void negativeLengthIsNamed() throws IOException {
        String t = resourceText().replace("\"A3_m\": 0.056", "\"A3_m\": -0.056");
        assertTrue(messageFor(t).contains("links.A3_m: must be > 0"), messageFor(t));
    }

    @Test
    void nanIsASyntaxErrorWithLineAndColumn() throws IOException {
        String t = resourceText().replace("\"A1_m\": 0.050", "\"A1_m\": NaN");
        String m = messageFor(t);
        assertTrue(m.matches("bad\\.json:\\d+:\\d+: .*"), m);
    }

    @Test
    void nonPositiveDefiniteInertiaIsNamed() throws IOException {
        String t = resourceText().replace("\"xx\": 0.0000047", "\"xx\": -0.0000047");
        String m = messageFor(t);
        assertTrue(m.contains("mass_properties.links[1].inertia_kgm2") && m.contains("positive definite"), m);
    }

    /**
     * Link 1's listed product with the other sign (as if +5.72e-5 were the matrix element) is no
     * body about the centre of mass (an eigenvalue of −5.44e-5 kg·m², TableThreeReadingTest):
     * refused, naming the link.
     */
    @Test
    void aTensorNoBodyHasIsNamed() throws IOException {
        String t = resourceText().replace("\"xy\": 0.0000572", "\"xy\": -0.0000572");
        String m = messageFor(t);
        assertTrue(m.contains("mass_properties.links[0].inertia_kgm2") && m.contains("not a physical body"), m);
    }

    @Test
    void wrongTypeIsNamed() throws IOException {
        String t = resourceText().replace("\"tau_break_Nm\": 1.26", "\"tau_break_Nm\": \"high\"");
        assertTrue(messageFor(t).contains("clutch.tau_break_Nm: must be a number"), messageFor(t));
    }

    @Test
    void spreadOnFingerThreeIsRefused() throws IOException {
        String t = resourceText().replace("\"spread_deg_per_count\": 0,", "\"spread_deg_per_count\": 0.1,");
        assertTrue(messageFor(t).contains("fingers[2].spread_deg_per_count"), messageFor(t));
    }
}
