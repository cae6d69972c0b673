package org.handsim.hold;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The protocol's values: DexGraspBench's defaults, and every value that is not a push refused naming its option. */
class HoldSettingsTest {
    @Test
    void theDefaultsAreDexGraspBenchs() {
        HoldSettings s = HoldSettings.defaults(58.8399);
        assertEquals(2.33, s.force(0.233), 1e-15, "10 m/s² × the mass");
        assertEquals(7.0, s.withForce(7).force(0.233), "a given force is kept");
        assertEquals(2.0, s.durationS());
        assertEquals(0.001, s.dtS());
        assertEquals(0.05, s.maxDisplacementM());
        assertEquals(15.0, s.maxRotationDeg());
        assertEquals(false, s.gravity());
        assertEquals(0.005, s.rampDisplacementM());
        assertEquals(5.0, s.rampRotationDeg());
    }

    @Test
    void valuesThatAreNoPushAreRefusedNamingTheOption() {
        String[][] cases = {{"0", "--force"}, {"-1", "--force"}, {"inf", "--force"}};
        for (String[] c : cases) {
            double f = c[0].equals("inf") ? Double.POSITIVE_INFINITY : Double.parseDouble(c[0]);
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> HoldSettings.defaults(58.8).withForce(f));
            assertTrue(e.getMessage().startsWith(c[1] + " must be a finite number > 0, got "), e.getMessage());
        }
        assertMessage("--duration", () -> new HoldSettings(Double.NaN, 0, 0.001, false, 0.05, 15, 0.005, 5, 10, 58.8));
        assertMessage("--dt", () -> new HoldSettings(Double.NaN, 2, -0.001, false, 0.05, 15, 0.005, 5, 10, 58.8));
        assertMessage("--max-displacement", () -> new HoldSettings(Double.NaN, 2, 0.001, false, 0, 15, 0.005, 5, 10, 58.8));
        assertMessage("--max-rotation", () -> new HoldSettings(Double.NaN, 2, 0.001, false, 0.05, -15, 0.005, 5, 10, 58.8));
        assertMessage("--ramp-displacement", () -> new HoldSettings(Double.NaN, 2, 0.001, false, 0.05, 15, Double.NaN, 5, 10, 58.8));
        assertMessage("--ramp-rotation", () -> new HoldSettings(Double.NaN, 2, 0.001, false, 0.05, 15, 0.005, 0, 10, 58.8));
        assertMessage("--ramp-rate", () -> new HoldSettings(Double.NaN, 2, 0.001, false, 0.05, 15, 0.005, 5, 0, 58.8));
        assertMessage("--ramp-max", () -> new HoldSettings(Double.NaN, 2, 0.001, false, 0.05, 15, 0.005, 5, 10, -1));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> new HoldSettings(Double.NaN, 0.01, 0.02, false, 0.05, 15, 0.005, 5, 10, 58.8));
        assertTrue(e.getMessage().startsWith("--dt (0.02 s) must not exceed --duration"), e.getMessage());
    }

    private static void assertMessage(String option, org.junit.jupiter.api.function.Executable make) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, make);
        assertTrue(e.getMessage().startsWith(option + " must be a finite number > 0, got "), e.getMessage());
    }
}
