package org.handsim.gui;

import static org.handsim.gui.GuiWindowTest.differs;
import static org.handsim.gui.GuiWindowTest.needDisplay;
import static org.handsim.gui.GuiWindowTest.regions;
import static org.handsim.gui.GuiWindowTest.runGui;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.scenario.Scenario;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The grasp in the window, end to end in a child JVM on the current
 * display ({@link GuiWindowTest} says how the display reaches the tests). The mug grasp
 * (scenarios/mug-grasp.json) is played to its end:
 * <ul>
 *   <li>the Dynamics panel's Grasp box says force closure, and its ε, volume and minimum hold
 *       are {@code handsim grasp}'s on the same scenario to the digits shown (the command's
 *       value lies within half a unit of the last digit shown);</li>
 *   <li>View ▸ Friction cones draws the cones: the pixels it changes all lie near the contacts
 *       (where the view draws them, {@code log contacts}), and near each finger's contacts they
 *       have that finger's colour; turned off, the view is as before;</li>
 *   <li>with the object's friction set to 0 in the Objects panel the grasp has no force closure
 *       (frictionless point contacts never have it), and a scenario saved then keeps
 *       {@code object.friction} = 0.</li>
 * </ul>
 */
@Tag("slow")   // child JVMs: ./test --all (CI) runs it, the quick ./test does not
class GraspWindowTest {
    /** Radius round a contact's pixel within which its cone is drawn: 20 mm high, 10 mm wide at μ = 0.5, ~45 px here. */
    static final double CONE_REACH_PX = 70;

    @Test
    void theMugGraspShowsHandsimGraspsQualityAndItsFrictionCones() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-grasp-window").toRealPath();
        Path mug = TestPaths.root().resolve("scenarios/mug-grasp.json");
        Path off = dir.resolve("cones-off.png"), on = dir.resolve("cones-on.png"), offAgain = dir.resolve("cones-off-again.png");
        Path saved = dir.resolve("frictionless.json");
        Path script = dir.resolve("grasp.txt");
        Files.writeString(script, String.join("\n",
            "press Dynamics",
            "speed max",
            "play end",
            "assert-runstate finished",
            "log grasp",
            "log contacts",
            "screenshot " + off,
            "menu view.cones",
            "screenshot " + on,
            "show cones off",
            "screenshot " + offAgain,
            "press Objects",
            "set obj.friction 0",
            "assert-status friction μ = 0 applied",
            "press Dynamics",
            "play end",
            "log grasp",
            "save-scenario " + saved,
            ""));
        GuiWindowTest.Child c = runGui(dir, mug.toString(), "--script", script.toString());
        assertEquals(0, c.code(), c.log());

        // the numbers: handsim grasp on the same scenario
        CliTesting.Run g = CliTesting.run("grasp", mug.toString());
        assertEquals(0, g.code(), g.err());
        @SuppressWarnings("unchecked")
        Map<String, Object> cli = (Map<String, Object>) Json.parse("grasp", g.out().trim());
        assertEquals(Boolean.TRUE, cli.get("force_closure"));
        Matcher m = Pattern.compile("gui: grasp: force_closure=(\\S+)  epsilon=(\\S+)  volume=(\\S+)  hold_min=(\\S+) N  (\\d+) contacts").matcher(c.log());
        assertTrue(m.find(), c.log());
        assertEquals("yes", m.group(1), "force closure with μ = 0.5");
        assertShown(((Number) cli.get("epsilon")).doubleValue(), m.group(2), "epsilon");
        assertShown(((Number) cli.get("volume")).doubleValue(), m.group(3), "volume");
        assertShown(((Number) cli.get("hold_min_N")).doubleValue(), m.group(4), "hold_min_N");
        assertEquals(((List<?>) cli.get("contacts")).size(), Integer.parseInt(m.group(5)), "contacts");
        assertTrue(m.group(2).replace(".", "").replaceFirst("^0+", "").length() >= 4, "ε shown with 4 digits: " + m.group(2));

        // friction 0: no force closure, ε 0; the saved scenario keeps the friction
        assertTrue(m.find(), c.log());
        assertEquals("no", m.group(1), "frictionless: no force closure");
        assertEquals("0", m.group(2));
        assertTrue(c.log().contains("μ 0, 8 cone edges"), c.log());
        assertEquals(0.0, Scenario.load(saved).friction(), "saved object.friction");

        // the cones: pixels that change lie near the contacts, in their finger's colour
        List<double[]> contacts = new ArrayList<>();   // {finger, x, y}
        Matcher ct = Pattern.compile("gui: contact: finger (\\d) at \\([^)]*\\) m, pixel \\(([-0-9.]+), ([-0-9.]+)\\)").matcher(c.log());
        while (ct.find()) contacts.add(new double[] {Integer.parseInt(ct.group(1)), Double.parseDouble(ct.group(2)), Double.parseDouble(ct.group(3))});
        assertEquals(((List<?>) cli.get("contacts")).size(), contacts.size(), "log contacts lists every contact");
        Rectangle view = regions(c.log(), on)[0];
        BufferedImage a = ImageIO.read(off.toFile()), b = ImageIO.read(on.toFile()), a2 = ImageIO.read(offAgain.toFile());
        int changed = 0, near = 0, offChanged = 0;
        int[] fingerColoured = new int[3];
        for (int y = view.y; y < view.y + view.height; y++) {
            for (int x = view.x; x < view.x + view.width; x++) {
                if (differs(a.getRGB(x, y), a2.getRGB(x, y), 30)) offChanged++;
                if (!differs(a.getRGB(x, y), b.getRGB(x, y), 30)) continue;
                changed++;
                double best = Double.POSITIVE_INFINITY;
                int finger = 0;
                for (double[] p : contacts) {
                    double d = Math.hypot(x - p[1], y - p[2]);
                    if (d < best) { best = d; finger = (int) p[0]; }
                }
                if (best <= CONE_REACH_PX) {
                    near++;
                    if (!differs(b.getRGB(x, y), TraceCharts.FINGER_RGB[finger - 1], 90)) fingerColoured[finger - 1]++;
                }
            }
        }
        System.out.printf("friction cones: %d pixels changed, %d within %.0f px of a contact; in the finger's colour: %d, %d, %d;"
            + " off again: %d pixels differ%n", changed, near, CONE_REACH_PX, fingerColoured[0], fingerColoured[1], fingerColoured[2], offChanged);
        assertTrue(changed >= 300, "the cones change the view: " + changed + " pixels");
        assertTrue(near >= 0.97 * changed, "the changed pixels are near the contacts: " + near + " of " + changed);
        for (int k = 0; k < 3; k++) assertTrue(fingerColoured[k] >= 20, "finger " + (k + 1) + "'s cones in its colour: " + fingerColoured[k]);
        assertTrue(offChanged <= 0.02 * changed, "turned off, the cones are gone: " + offChanged + " pixels differ");
        VrmlTesting.deleteTree(dir);
    }

    /** {@code value} rounds to {@code shown}: within half a unit of the last digit shown. */
    static void assertShown(double value, String shown, String what) {
        BigDecimal s = new BigDecimal(shown);
        double halfUnit = s.ulp().doubleValue() / 2;
        assertTrue(Math.abs(value - s.doubleValue()) <= halfUnit * (1 + 1e-12),
            what + ": handsim grasp says " + value + ", the window shows " + shown);
    }
}
