package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.handsim.scenario.Home;
import org.handsim.text.Json;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim grasp}, the {@code "grasp"} of {@code handsim run}'s summary.json and the grasp
 * columns of {@code handsim sweep}: the README's contracts, and the check that the
 * three-finger mug grasp is force closure with μ = 0.5 and not with μ = 0 (frictionless point
 * contacts never are, with fewer than seven of them: here six).
 */
class GraspCommandTest {
    static final String MUG = Home.scenarios().resolve("mug-grasp.json").toString();
    static final List<String> KEYS = List.of("time_s", "contacts", "force_closure", "epsilon", "volume", "hold_N", "hold_min_N",
        "hold_joint_limits_Nm", "hold_cap_N", "torque_residual_Nm", "joint_torques_Nm", "center_m", "radius_m", "friction", "cone_edges");

    @SuppressWarnings("unchecked")
    static Map<String, Object> json(String text) {
        return (Map<String, Object>) Json.parse("output", text);
    }

    @SuppressWarnings("unchecked")
    static void contract(Map<String, Object> g) {
        List<String> keys = new ArrayList<>(g.keySet());
        // the command adds the run's largest worm reactions (summary.json's grasp has them per finger)
        if (keys.get(keys.size() - 1).equals("max_worm_reaction_Nm")) {
            keys.remove(keys.size() - 1);
            assertEquals(3, ((List<Object>) g.get("max_worm_reaction_Nm")).size(), "one per finger");
        }
        assertEquals(KEYS, keys, "the README's keys, in order");
        List<Object> carried = (List<Object>) g.get("joint_torques_Nm");
        assertEquals(List.of(3, 3, 2), List.of(((List<Object>) carried.get(0)).size(), ((List<Object>) carried.get(1)).size(),
            ((List<Object>) carried.get(2)).size()), "joints k1..k3 of fingers 1, 2; k2, k3 of finger 3");
        List<Object> limits = (List<Object>) g.get("hold_joint_limits_Nm");
        assertEquals(3, limits.size());
        for (Object o : (List<Object>) g.get("contacts")) {
            assertEquals(List.of("finger", "link", "point", "normal", "force_N"), new ArrayList<>(((Map<String, Object>) o).keySet()));
        }
        Map<String, Object> hold = (Map<String, Object>) g.get("hold_N");
        assertEquals(List.of("+x", "-x", "+y", "-y", "+z", "-z"), new ArrayList<>(hold.keySet()));
        double min = Double.POSITIVE_INFINITY;
        for (Object v : hold.values()) min = Math.min(min, ((Number) v).doubleValue());
        assertEquals(min, ((Number) g.get("hold_min_N")).doubleValue());
        List<Object> residual = (List<Object>) g.get("torque_residual_Nm");
        assertEquals(3, residual.size(), "one residual per finger");
        for (Object v : residual) assertTrue(((Number) v).doubleValue() >= 0);
    }

    @Test
    @SuppressWarnings("unchecked")
    void theMugGraspIsForceClosureWithFrictionAndNotWithout() {
        CliTesting.Run r = CliTesting.run("grasp", MUG);
        assertEquals(0, r.code(), r.err());
        Map<String, Object> g = json(r.out());
        contract(g);
        assertEquals(4.7, ((Number) g.get("time_s")).doubleValue(), 1e-9, "the scenario's end");
        assertEquals(6, ((List<Object>) g.get("contacts")).size(), "inner and outer link of each finger");
        assertEquals(true, g.get("force_closure"));
        assertTrue(((Number) g.get("epsilon")).doubleValue() > 0);
        assertTrue(((Number) g.get("volume")).doubleValue() > 0);
        for (Object v : (List<Object>) g.get("torque_residual_Nm")) {
            assertTrue(((Number) v).doubleValue() <= 1e-9, "the forces carry every finger's torques: " + v);
        }
        // every inner joint is held by its worm at the end: its torque is the largest worm reaction so far
        List<Object> worm = (List<Object>) g.get("max_worm_reaction_Nm"), carried = (List<Object>) g.get("joint_torques_Nm");
        for (int k = 0; k < 3; k++) {
            double t2 = ((Number) ((List<Object>) carried.get(k)).get(k == 2 ? 0 : 1)).doubleValue();
            assertTrue(t2 > 2.5, "finger " + (k + 1) + ": the worm holds the preload and the outer contact's share: " + t2);
            assertEquals(t2, ((Number) worm.get(k)).doubleValue(), 1e-12);
        }

        CliTesting.Run r0 = CliTesting.run("grasp", MUG, "--friction", "0");
        assertEquals(0, r0.code(), r0.err());
        Map<String, Object> g0 = json(r0.out());
        contract(g0);
        assertEquals(false, g0.get("force_closure"));
        assertEquals(0, ((Number) g0.get("epsilon")).doubleValue());
        assertEquals(0, ((Number) g0.get("volume")).doubleValue(), "six frictionless wrenches: a hull of at most five dimensions, volume 0");
        assertEquals(0, ((Number) g0.get("hold_min_N")).doubleValue(), 1e-9, "frictionless: some direction is not held at all");
    }

    /**
     * grasp prints its wrench scaling (the mug's centroid and largest centroid-to-vertex distance,
     * as the mesh gives them) and quality, given grasp's output with its default options, computes
     * the same ε and volume to the last bit; given the same contacts as a CSV file and
     * {@code --object} the scenario, again the same.
     */
    @Test
    @SuppressWarnings("unchecked")
    void qualityOfGraspsOutputGivesGraspsEpsilon() throws Exception {
        CliTesting.Run r = CliTesting.run("grasp", MUG);
        assertEquals(0, r.code(), r.err());
        Map<String, Object> g = json(r.out());
        org.handsim.scenario.Scenario s = org.handsim.scenario.Scenario.load(Path.of(MUG));
        double[] cr = new org.handsim.model.SceneGeometry(s.object(), org.handsim.model.SceneGeometry.DEFAULT_K).centroidAndRadius();
        List<Object> c = (List<Object>) g.get("center_m");
        for (int i = 0; i < 3; i++) assertEquals(cr[i], ((Number) c.get(i)).doubleValue());
        assertEquals(cr[3], ((Number) g.get("radius_m")).doubleValue());
        assertEquals(0.5, ((Number) g.get("friction")).doubleValue());
        assertEquals(8, ((Number) g.get("cone_edges")).intValue());
        Path dir = Files.createTempDirectory("grasp-quality");
        try {
            Path out = Files.writeString(dir.resolve("grasp.json"), r.out());
            CliTesting.Run q = CliTesting.run("quality", out.toString());
            assertEquals(0, q.code(), q.err());
            assertEquals("", q.err());
            Map<String, Object> qm = json(q.out());
            assertEquals(g.get("epsilon"), qm.get("epsilon"), q.out());
            assertEquals(g.get("volume"), qm.get("volume"), q.out());
            assertEquals(g.get("center_m"), qm.get("center_m"));
            assertEquals(g.get("radius_m"), qm.get("radius_m"));
            StringBuilder csv = new StringBuilder("x,y,z,nx,ny,nz\n");
            for (Object o : (List<Object>) g.get("contacts")) {
                Map<String, Object> ct = (Map<String, Object>) o;
                List<Object> p = (List<Object>) ct.get("point"), n = (List<Object>) ct.get("normal");
                csv.append(p.get(0)).append(',').append(p.get(1)).append(',').append(p.get(2)).append(',')
                    .append(n.get(0)).append(',').append(n.get(1)).append(',').append(n.get(2)).append('\n');
            }
            Path rows = Files.writeString(dir.resolve("contacts.csv"), csv);
            q = CliTesting.run("quality", rows.toString(), "--object", MUG);
            assertEquals(0, q.code(), q.err());
            assertEquals(g.get("epsilon"), json(q.out()).get("epsilon"), q.out());
            // without the scaling, the 1 m default of the CSV gives another number
            q = CliTesting.run("quality", rows.toString());
            assertFalse(g.get("epsilon").equals(json(q.out()).get("epsilon")), q.out());
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** --at picks the first step at or after T; the inner links alone already hold the mug at 2 s (all BLOCKED). */
    @Test
    @SuppressWarnings("unchecked")
    void atATime() {
        CliTesting.Run r = CliTesting.run("grasp", MUG, "--at", "2.0");
        assertEquals(0, r.code(), r.err());
        Map<String, Object> g = json(r.out());
        contract(g);
        assertEquals(2.0, ((Number) g.get("time_s")).doubleValue(), 1e-9);
        for (Object o : (List<Object>) g.get("contacts")) assertEquals(2, ((Number) ((Map<String, Object>) o).get("link")).intValue());
        CliTesting.Run start = CliTesting.run("grasp", MUG, "--at", "0");
        Map<String, Object> g0 = json(start.out());
        contract(g0);
        assertEquals(0, ((List<Object>) g0.get("contacts")).size());
        assertEquals(false, g0.get("force_closure"));
    }

    @Test
    void badArgumentsExit2AndAMissingFileExits3() {
        CliTesting.Run r = CliTesting.run("grasp", MUG, "--friction", "-0.5");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("--friction must be in [0, 10] (measured coefficients stay below 2; beyond 10 the friction cone is numerically a half-space), got -0.5"), r.err());
        r = CliTesting.run("grasp", MUG, "--edges", "0");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("--edges must be between 1 and 1024, got 0"), r.err());
        r = CliTesting.run("grasp", MUG, "--at", "9");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("--at must be in [0, 4.7]"), r.err());
        r = CliTesting.run("grasp", MUG, "--every", "0.1");
        assertEquals(2, r.code());
        r = CliTesting.run("grasp", "no-such-scenario.json");
        assertEquals(3, r.code());
        assertFalse(r.err().contains("Exception"), r.err());
    }

    @Test
    @SuppressWarnings("unchecked")
    void runSummaryHasTheGraspWithFrictionAndNoneWithout() throws Exception {
        Path dir = Files.createTempDirectory("handsim-grasp");
        CliTesting.Run r = CliTesting.run("run", MUG, "--no-charts", "--out", dir.resolve("mu05").toString());
        assertEquals(0, r.code(), r.err());
        Map<String, Object> s = json(Files.readString(dir.resolve("mu05").resolve("summary.json")));
        Map<String, Object> g = (Map<String, Object>) s.get("grasp");
        contract(g);
        assertEquals(true, g.get("force_closure"));
        CliTesting.Run r0 = CliTesting.run("run", MUG, "--no-charts", "--friction", "0", "--out", dir.resolve("mu0").toString());
        assertEquals(0, r0.code(), r0.err());
        Map<String, Object> g0 = (Map<String, Object>) json(Files.readString(dir.resolve("mu0").resolve("summary.json"))).get("grasp");
        contract(g0);
        assertEquals(false, g0.get("force_closure"));
        // the grasp of run and of grasp agree
        Map<String, Object> direct = json(CliTesting.run("grasp", MUG).out());
        assertEquals(direct.get("epsilon"), g.get("epsilon"));
        assertEquals(direct.get("hold_N"), g.get("hold_N"));
    }

    /** The sweep's grasp columns, with object.friction set per run (the scenario field). */
    @Test
    void sweepColumnsFollowObjectFriction() throws Exception {
        Path dir = Files.createTempDirectory("handsim-grasp");
        Path base = dir.resolve("base.json");
        Files.writeString(base, Files.readString(Path.of(MUG))
            .replace("../vrml/objects/mug.wrl", Home.dir().resolve("vrml/objects/mug.wrl").toString().replace("\\", "/")));
        Path sweep = dir.resolve("sweep.json");
        Files.writeString(sweep, "{\"name\":\"g\",\"base\":\"base.json\",\"runs\":["
            + "{\"label\":\"mu 0.5\",\"set\":{}},{\"label\":\"mu 0\",\"set\":{\"object.friction\":0}}]}");
        CliTesting.Run r = CliTesting.run("sweep", sweep.toString(), "--out", dir.resolve("out").toString(), "--threads", "1");
        assertEquals(0, r.code(), r.err());
        List<String> rows = Files.readAllLines(dir.resolve("out").resolve("summary.csv"));
        assertTrue(rows.get(0).endsWith(",error,force_closure,epsilon,volume,hold_min_N"), rows.get(0));
        String[] with = rows.get(1).split(",", -1), without = rows.get(2).split(",", -1);
        assertEquals(SweepCommand.HEADER.split(",").length, with.length);
        assertEquals("", with[18], "no error");
        assertEquals("true", with[19]);
        assertTrue(Double.parseDouble(with[20]) > 0);
        assertEquals("false", without[19]);
        assertEquals(0, Double.parseDouble(without[20]));
    }

    @Test
    void chartFilesAndTheirTable() throws Exception {
        Path dir = Files.createTempDirectory("handsim-grasp");
        Path base = dir.resolve("mug");
        CliTesting.Run r = CliTesting.run("grasp", MUG, "--chart", base.toString(), "--every", "0.1");
        assertEquals(0, r.code(), r.err());
        contract(json(r.out()));
        assertTrue(Files.size(Path.of(base + ".png")) > 10_000);
        assertTrue(Files.readString(Path.of(base + ".svg")).contains("<svg"));
        List<String> csv = Files.readAllLines(Path.of(base + ".csv"));
        assertEquals(GraspCommand.CHART_HEADER, csv.get(0));
        assertEquals("time_s,force_closure,epsilon,volume,hold_min_N", csv.get(0), "the README's header");
        assertEquals(1 + 48, csv.size(), "t = 0, 0.1, ..., 4.7");
        assertTrue(csv.get(1).startsWith("0,false,0,"), csv.get(1));
        for (String line : csv) {
            assertFalse(line.matches(".*(\\.0(,|$)|E-|-0(,|$)).*"), "numbers as text.Decimal writes them: " + line);
        }
        assertTrue(csv.get(csv.size() - 1).startsWith("4.7,true,"), csv.get(csv.size() - 1));
    }
}
