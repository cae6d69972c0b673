package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.grasp.GraspAssessment;
import org.handsim.grasp.GraspQuality;
import org.handsim.hand.HandDescription;
import org.handsim.math.RigidTransform;
import org.handsim.model.SceneGeometry;
import org.handsim.scenario.Scenario;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * The parts of the planner that sample for the object's size and shape, each against a value
 * derived by hand, and the plan of an object too small for the hand.
 */
class PlanAnyShapeTest {
    private static final Path BOX = TestPaths.root().resolve("docs/plan-shapes/box40x40x120.obj");

    /** The 40 × 40 × 120 mm box, turned a quarter turn about x: its long axis is the world's y, 120 mm; the others 40 mm. */
    @Test
    void theBoxsPrincipalAxesAndExtents() {
        RigidTransform turned = RigidTransform.fromPose(0.1, 0.2, 0.3, Math.PI / 2, 0, 0);
        Scenario.ObjectPlacement o = new Scenario.ObjectPlacement(BOX, turned, 1.0, 24);
        SceneGeometry g = new SceneGeometry(o, SceneGeometry.DEFAULT_K);
        double[] c = g.centroidAndRadius();
        ObjectFrame f = new ObjectFrame(g.objectMesh(), g.worldFromObject(), new double[] {c[0], c[1], c[2]});
        assertArrayEquals(new double[] {0.1, 0.2, 0.3}, f.centroid(), 1e-12);
        // the OBJ loader keeps coordinates as floats: 1e-8 m. The square cross-section's two axes
        // share an eigenvalue: any pair in its plane is principal, so their extents lie between
        // the side and the diagonal
        assertEquals(0.120, f.extent(0), 1e-8);
        assertEquals(1, Math.abs(f.axis(0)[1]), 1e-9, "the long axis is the world's y: " + java.util.Arrays.toString(f.axis(0)));
        for (int j = 1; j <= 2; j++) {
            assertTrue(f.extent(j) > 0.040 - 1e-8 && f.extent(j) < 0.040 * Math.sqrt(2) + 1e-8, "extent " + j + ": " + f.extent(j));
            assertEquals(0, f.axis(j)[1], 1e-9, "across the long axis");
        }
        assertEquals(0.060, f.support(new double[] {0, 1, 0}), 1e-8);
        assertEquals(0.020 * Math.sqrt(2), f.support(new double[] {Math.sqrt(0.5), 0, Math.sqrt(0.5)}), 1e-8, "the corner edge");
    }

    /**
     * The open fingertip, by hand from the hand file: finger 3's base at 84 mm above the palm
     * origin, link 1 reaching 50 mm out; θ32 = Φ2 = 2.46°, so joint 33 is 70 cos 2.46° further out
     * and 70 sin 2.46° up; the outer link at Φ2 + Φ3 = 52.46°: the tip 154.07 mm from the axis at
     * 131.41 mm. An object wider than that meets the open tips there; a narrower one higher up.
     */
    @Test
    void theFingertipPathStartsWhereTheHandFileSays() {
        FingertipPath p = new FingertipPath(HandDescription.barrettHand());
        double phi2 = Math.toRadians(2.46), phi23 = Math.toRadians(52.46);
        double reach = 0.050 + 0.070 * Math.cos(phi2) + 0.056 * Math.cos(phi23);
        double height = 0.084 + 0.070 * Math.sin(phi2) + 0.056 * Math.sin(phi23);
        double[] tip = p.tip(3, 0, 0);
        assertEquals(reach, tip[1], 1e-12);
        assertEquals(height, tip[2], 1e-12);
        assertEquals(height, p.heightAtReach(0.2), 1e-12);
        assertTrue(p.heightAtReach(0.045) > 0.180, "the tips rise above 180 mm while closing in: " + p.heightAtReach(0.045));
        double[] d3 = p.closingDirection(3, 0);
        assertEquals(-1, d3[1], 1e-12, "finger 3 closes along -y");
        double[] d1 = p.closingDirection(1, 1050);   // 60°: the three fingers 120° apart
        assertEquals(Math.cos(Math.toRadians(30)) * (d1[0] > 0 ? 1 : -1), d1[0], 1e-9);
        assertEquals(0.5, d1[1], 1e-9);
    }

    /** A wrap backs off by 10 mm times the draw; the fingertip rule puts the centroid in [h − 30 mm, h + 10 mm). */
    @Test
    void theStandoffFollowsTheRule() {
        Scenario.ObjectPlacement o = new Scenario.ObjectPlacement(BOX, RigidTransform.IDENTITY, 1.0, 24);
        SceneGeometry g = new SceneGeometry(o, SceneGeometry.DEFAULT_K);
        double[] c = g.centroidAndRadius();
        ObjectFrame f = new ObjectFrame(g.objectMesh(), g.worldFromObject(), new double[] {c[0], c[1], c[2]});
        FingertipPath path = new FingertipPath(HandDescription.barrettHand());
        StandoffRule rule = new StandoffRule(f, path);
        RigidTransform down = RigidTransform.fromPose(0, 0, 0, Math.PI, 0, 0);   // palm z = −z: approaching the box's end
        Autograsp.Touch t = new Autograsp.Touch(new double[] {Math.PI, 0, 0}, down, new double[] {0, 0, -1}, c, 0.09, true, 1);
        assertEquals(0.0035, rule.standoff(new TrialParameters(0, t.approach(), 0, 0, true, 0.35), t), 1e-15);
        // from the end the fingers meet the box's 20 mm half-width (spread 0: fingers 1, 2 and 3 close along ±y)
        double w = rule.reach(down, 0);
        assertEquals(0.020, w, 1e-8);
        double h = path.heightAtReach(w);
        assertEquals(h - 0.030 - 0.09, rule.standoff(new TrialParameters(0, t.approach(), 0, 0, false, 0), t), 1e-12);
        assertEquals(h + 0.010 * 0.5 - 0.030 * 0.5 - 0.09, rule.standoff(new TrialParameters(0, t.approach(), 0, 0, false, 0.5), t), 1e-12);
    }

    /**
     * The outcome of a grasp without force closure from its contacts, approached along +z with
     * μ = 0.5 (friction cones of half-angle atan 0.5 = 26.57°): pushes within 90° + 26.57° of +z
     * can push the object away from the palm, pushes beyond 90° − 26.57° toward it.
     */
    @Test
    void theOutcomeSaysWhichWayTheContactsPush() {
        double[] a = {0, 0, 1};
        double lean = Math.atan(0.5);
        assertEquals(TrialOutcome.NO_CONTACT, TrialOutcome.of(grasp(), a));
        assertEquals(TrialOutcome.ONE_FINGER, TrialOutcome.of(grasp(contact(1, 3.0), contact(1, 2.0)), a));
        assertEquals(TrialOutcome.ALL_TOWARD_PALM, TrialOutcome.of(grasp(contact(1, Math.PI), contact(2, Math.PI / 2 + lean + 0.01)), a));
        assertEquals(TrialOutcome.OTHER, TrialOutcome.of(grasp(contact(1, Math.PI), contact(2, Math.PI / 2 + lean - 0.01)), a));
        assertEquals(TrialOutcome.ALL_AWAY_FROM_PALM, TrialOutcome.of(grasp(contact(1, 0.2), contact(3, Math.PI / 2 - lean - 0.01)), a));
        assertEquals(TrialOutcome.OTHER, TrialOutcome.of(grasp(contact(1, 0.2), contact(3, Math.PI / 2 - lean + 0.01)), a));
    }

    /** A contact of finger k pushing at angle θ from +z (in the x–z plane). */
    private static GraspAssessment.Contact contact(int k, double theta) {
        return new GraspAssessment.Contact(k, 3, new double[3], new double[] {Math.sin(theta), 0, Math.cos(theta)}, new double[3]);
    }

    private static GraspAssessment grasp(GraspAssessment.Contact... c) {
        return new GraspAssessment(0, GraspQuality.none(c.length, 8), new double[6], 0, new double[3][3], 58.84, List.of(c), new double[3],
            new double[3], 0.05, 0.5, 8, new double[3][3]);
    }

    /**
     * A 5 mm sphere is too small for the hand to enclose: the fingertips close past it into each
     * other. The plan says so in one line on standard error, with what to try, and writes no best
     * grasp (plan.json: no force closure, best ε 0).
     */
    @Test
    void aSphereTooSmallForTheHandGetsOneLineAndNoBestGrasp() throws Exception {
        Path dir = Files.createTempDirectory("plan-small");
        try {
            Path sphere = dir.resolve("sphere5.obj");
            StringBuilder obj = new StringBuilder();
            int n = 16, m = 8;
            double r = 0.0025;
            obj.append("v 0 0 ").append(-r).append('\n');
            for (int b = 1; b < m; b++) {
                double phi = -Math.PI / 2 + Math.PI * b / m;
                for (int s = 0; s < n; s++) {
                    double th = 2 * Math.PI * s / n;
                    obj.append(String.format(java.util.Locale.ROOT, "v %.9f %.9f %.9f%n", r * Math.cos(phi) * Math.cos(th), r * Math.cos(phi) * Math.sin(th), r * Math.sin(phi)));
                }
            }
            obj.append("v 0 0 ").append(r).append('\n');
            int top = 2 + (m - 1) * n;
            for (int s = 0; s < n; s++) obj.append("f 1 ").append(2 + (s + 1) % n).append(' ').append(2 + s).append('\n');
            for (int b = 0; b < m - 2; b++) {
                for (int s = 0; s < n; s++) {
                    int p = 2 + b * n + s, q = 2 + b * n + (s + 1) % n, u = p + n, v = q + n;
                    obj.append("f ").append(p).append(' ').append(q).append(' ').append(v).append('\n');
                    obj.append("f ").append(p).append(' ').append(v).append(' ').append(u).append('\n');
                }
            }
            for (int s = 0; s < n; s++) obj.append("f ").append(2 + (m - 2) * n + s).append(' ').append(2 + (m - 2) * n + (s + 1) % n).append(' ').append(top).append('\n');
            Files.writeString(sphere, obj);
            Path out = dir.resolve("plan");
            CliTesting.Run run = CliTesting.run("plan", sphere.toString(), "--trials", "40", "--seed", "1", "--units", "m", "--out", out.toString());
            assertEquals(0, run.code(), run.err());
            String[] lines = run.err().strip().split("\n");
            String last = lines[lines.length - 1];
            assertTrue(last.startsWith("handsim plan: no grasp with force closure, so no best/ grasps: in "), run.err());
            assertTrue(last.contains("too small for the hand to enclose") && last.contains("try "), last);
            assertEquals(1, run.err().split("no grasp with force closure", -1).length - 1, "said once: " + run.err());
            assertFalse(Files.exists(out.resolve("best/01.json")), "nothing labelled best");
            assertTrue(run.out().contains("{plan.csv, plan.json, epsilon-histogram"), run.out());
            String plan = Files.readString(out.resolve("plan.json"));
            assertTrue(plan.contains("\"force_closure\": 0") && plan.contains("\"best_epsilon\": 0"), plan);
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
