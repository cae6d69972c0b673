package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.plan.PlanTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** {@code handsim plan}: the outputs of a small plan, and one-line errors with exit 2 or 3 for bad targets and options. */
class PlanCommandTest {
    static final String MUG = PlanTesting.MUG.toString();

    @Test
    void aSmallPlanWritesEveryOutput() throws Exception {
        Path dir = Files.createTempDirectory("plan-cmd");
        try {
            CliTesting.Run r = CliTesting.run("plan", MUG, "--trials", "8", "--seed", "2", "--threads", "2", "--out", dir.toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("plan-mug: 8 trials (0 failed)"), r.out());
            for (String f : new String[] {"plan.csv", "plan.json", "epsilon-histogram.png",
                "epsilon-histogram.svg", "epsilon-directions.png", "epsilon-directions.svg"}) {
                assertTrue(Files.isRegularFile(dir.resolve(f)), f);
            }
            List<String> csv = Files.readAllLines(dir.resolve("plan.csv"));
            assertEquals(9, csv.size());
            // one best file per trial with force closure, and only those
            long closure = csv.stream().skip(1).filter(l -> l.split(",")[9].equals("true")).count();
            assertTrue(closure >= 1, "seed 2 has a grasp with force closure in its 8 trials: " + csv);
            for (int i = 1; i <= 8; i++) {
                assertEquals(i <= closure, Files.isRegularFile(dir.resolve(String.format("best/%02d.json", i))), "best/" + i);
            }
            // the same plan on one thread: the same table
            Path one = dir.resolve("one");
            assertEquals(0, CliTesting.run("plan", MUG, "--trials", "8", "--seed", "2", "--threads", "1", "--out", one.toString()).code());
            assertEquals(PlanTesting.withoutTiming(csv), PlanTesting.withoutTiming(Files.readAllLines(one.resolve("plan.csv"))));
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    /**
     * best/01.json is the best trial as a scenario: run to its end as {@code handsim run} runs it
     * (trace on, torques on, no early stop), its grasp has the row's ε, force closure and contacts.
     */
    @Test
    @Tag("slow")   // a plan, then a run of its best grasp, end to end: ./test --all (CI)
    void bestScenarioReproducesItsRow() throws Exception {
        Path dir = Files.createTempDirectory("plan-best");
        try {
            CliTesting.Run r = CliTesting.run("plan", MUG, "--trials", "500", "--seed", "1", "--out", dir.toString());
            assertEquals(0, r.code(), r.err());
            Map<String, String> best = null;
            List<String> csv = Files.readAllLines(dir.resolve("plan.csv"));
            String[] head = csv.get(0).split(",");
            double bestEps = -1;
            for (String line : csv.subList(1, csv.size())) {
                String[] f = line.split(",", -1);
                if (!f[1].equals("ok")) continue;
                double e = Double.parseDouble(f[10]);
                if (e > bestEps) {
                    bestEps = e;
                    best = new java.util.HashMap<>();
                    for (int i = 0; i < head.length; i++) best.put(head[i], f[i]);
                }
            }
            assertTrue(bestEps > 0, "a 500-trial plan on the mug finds force-closure grasps");
            Scenario s = Scenario.load(dir.resolve("best/01.json"));
            assertTrue(s.writeTrace() && s.computeTorques(), "the best scenario keeps the template's outputs");
            HandModel m = Simulation.model(s, true);
            m.run(null);
            GraspAssessment g = GraspAssessment.of(m.graspInput(), s.friction(), s.coneEdges());
            assertEquals(bestEps, g.quality().epsilon(), "epsilon of trial " + best.get("trial") + ", to the last bit");
            assertEquals(Boolean.parseBoolean(best.get("force_closure")), g.quality().forceClosure());
            assertEquals(Integer.parseInt(best.get("contacts")), g.contacts().size());
            for (int k = 1; k <= 3; k++) assertEquals(best.get("final_state" + k), m.state(k).name());
            // and through the command itself: handsim run best/01.json (summary.json's "grasp", once run reports it)
            CliTesting.Run run = CliTesting.run("run", dir.resolve("best/01.json").toString(), "--no-charts", "--out", dir.resolve("run").toString());
            assertEquals(0, run.code(), run.err());
            @SuppressWarnings("unchecked")
            Map<String, Object> summary = (Map<String, Object>) org.handsim.text.Json.parse("summary.json",
                Files.readString(dir.resolve("run/summary.json")));
            if (summary.get("grasp") instanceof Map) {
                @SuppressWarnings("unchecked")
                Map<String, Object> grasp = (Map<String, Object>) summary.get("grasp");
                assertEquals(bestEps, ((Number) grasp.get("epsilon")).doubleValue(), "handsim run's epsilon, to the last bit");
            }
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    /**
     * An OBJ and a millimetre STL target. The STL is the mug of vrml/objects/mug.wrl written in
     * millimetres (binary, 32-bit floats): found to be in millimetres by its size (or told by
     * {@code --units mm}), it is planned at the mug's real size, so the same seed gives the VRML
     * mug's table — the same contacts and force closure trial by trial, ε within the STL's float
     * rounding — which taken as metres (a mug 100 m long) it does not. The OBJ (a cylinder in
     * metres) runs and its trials find contacts.
     */
    @Test
    @Tag("slow")   // four plans end to end (the unit rule alone: UnitRuleTest): ./test --all (CI)
    void plansAnObjAndAMillimetreStl() throws Exception {
        Path dir = Files.createTempDirectory("plan-formats");
        try {
            Path stl = PlanTesting.MUG.resolveSibling("mug_mm.stl"), obj = PlanTesting.MUG.resolveSibling("cylinder.obj");
            CliTesting.Run wrl = CliTesting.run("plan", MUG, "--trials", "14", "--seed", "1", "--out", dir.resolve("wrl").toString());
            CliTesting.Run auto = CliTesting.run("plan", stl.toString(), "--trials", "14", "--seed", "1", "--out", dir.resolve("auto").toString());
            CliTesting.Run mm = CliTesting.run("plan", stl.toString(), "--trials", "14", "--seed", "1", "--units", "mm", "--out", dir.resolve("mm").toString());
            CliTesting.Run metres = CliTesting.run("plan", stl.toString(), "--trials", "14", "--seed", "1", "--units", "m", "--out", dir.resolve("m").toString());
            for (CliTesting.Run r : List.of(wrl, auto, mm, metres)) assertEquals(0, r.code(), r.err());
            assertTrue(auto.err().contains("handsim plan: mug_mm.stl: units mm by its size (--units to choose)"), auto.err());
            assertTrue(wrl.err().contains("handsim plan: mug.wrl: units m by its size"), wrl.err());
            assertFalse(mm.err().contains("by its size"), mm.err());
            assertEquals(Scenario.Units.MM, Scenario.load(dir.resolve("auto/best/01.json")).object().units(), "best/01.json keeps the units");
            List<String[]> a = rows(dir.resolve("wrl")), b = rows(dir.resolve("auto")), c = rows(dir.resolve("mm")), d = rows(dir.resolve("m"));
            assertEquals(PlanTesting.withoutTiming(Files.readAllLines(dir.resolve("auto/plan.csv"))),
                PlanTesting.withoutTiming(Files.readAllLines(dir.resolve("mm/plan.csv"))), "auto found mm");
            int closure = 0, differ = 0;
            for (int i = 0; i < a.size(); i++) {
                String[] x = a.get(i), y = b.get(i);
                assertEquals("ok", y[1], "trial " + i);
                assertEquals(x[8], y[8], "contacts of trial " + i);
                assertEquals(x[9], y[9], "force closure of trial " + i);
                double ex = Double.parseDouble(x[10]), ey = Double.parseDouble(y[10]);
                assertEquals(ex, ey, 1e-3 * Math.max(ex, 1e-3), "epsilon of trial " + i);
                if (x[9].equals("true")) closure++;
                if (!x[8].equals(d.get(i)[8]) || !x[12].equals(d.get(i)[12])) differ++;
            }
            assertTrue(closure >= 1, "the 14 trials of seed 1 include force-closure grasps");
            assertTrue(differ >= a.size() / 2, "in metres the STL is another object: " + differ + " of " + a.size() + " trials differ");
            assertEquals(a.size(), c.size());

            CliTesting.Run o = CliTesting.run("plan", obj.toString(), "--trials", "4", "--seed", "2", "--out", dir.resolve("obj").toString());
            assertEquals(0, o.code(), o.err());
            assertTrue(o.out().startsWith("plan-cylinder: 4 trials (0 failed)"), o.out());
            for (String[] r : rows(dir.resolve("obj"))) {
                assertEquals("ok", r[1]);
                assertTrue(Integer.parseInt(r[8]) > 0, "a trial on the OBJ cylinder finds contacts: " + String.join(",", r));
            }
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    private static List<String[]> rows(Path planDir) throws java.io.IOException {
        List<String[]> out = new java.util.ArrayList<>();
        List<String> lines = Files.readAllLines(planDir.resolve("plan.csv"));
        for (String l : lines.subList(1, lines.size())) out.add(l.split(",", -1));
        return out;
    }

    @Test
    void badTargetsAreOneLineExit3() throws Exception {
        Path dir = Files.createTempDirectory("plan-bad");
        try {
            CliTesting.Run missing = CliTesting.run("plan", dir.resolve("nothing.wrl").toString());
            assertEquals(3, missing.code());
            assertOneLine(missing.err(), "nothing.wrl");

            Path broken = dir.resolve("broken.wrl");
            Files.writeString(broken, "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 ] } } }\n");
            CliTesting.Run bad = CliTesting.run("plan", broken.toString(), "--out", dir.resolve("o").toString());
            assertEquals(3, bad.code());
            assertOneLine(bad.err(), "broken.wrl:");
            assertFalse(Files.exists(dir.resolve("o/plan.csv")), "nothing written");

            Path stl = dir.resolve("truncated.stl");   // binary: the header announces 2 triangles, one is there
            byte[] bytes = new byte[84 + 50];
            java.nio.ByteBuffer.wrap(bytes).order(java.nio.ByteOrder.LITTLE_ENDIAN).putInt(80, 2);
            Files.write(stl, bytes);
            CliTesting.Run st = CliTesting.run("plan", stl.toString(), "--out", dir.resolve("o").toString());
            assertEquals(3, st.code());
            assertOneLine(st.err(), "truncated.stl: byte ");
            Path obj = dir.resolve("broken.obj");
            Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
            CliTesting.Run ob = CliTesting.run("plan", obj.toString(), "--units", "mm", "--out", dir.resolve("o").toString());
            assertEquals(3, ob.code());
            assertOneLine(ob.err(), "broken.obj:4:");
            assertFalse(Files.exists(dir.resolve("o/plan.csv")), "nothing written");

            Path noObject = dir.resolve("empty.json");
            Files.writeString(noObject, "{\"name\": \"empty\", \"dt_s\": 0.001, \"duration_s\": 1}");
            CliTesting.Run none = CliTesting.run("plan", noObject.toString());
            assertEquals(3, none.code());
            assertOneLine(none.err(), "no object");

            Path badJson = dir.resolve("bad.json");
            Files.writeString(badJson, "{\"name\": \"x\", \"dt_s\": -1}");
            CliTesting.Run bj = CliTesting.run("plan", badJson.toString());
            assertEquals(3, bj.code());
            assertOneLine(bj.err(), "dt_s");
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    @Test
    void badOptionsAreOneLineExit2() {
        String[][] cases = {
            {"--trials", "0"}, {"--trials", "many"}, {"--threads", "0"}, {"--friction", "-0.5"}, {"--friction", "NaN"},
            {"--engine", "hadoop"}, {"--master", "local[2]"}, {"--seed", "1.5"}, {"--units", "inch"}};
        String[] expect = {"--trials", "many", "--threads", "--friction", "--friction", "hadoop", "--master", "1.5", "inch"};
        for (int c = 0; c < cases.length; c++) {
            String[] args = new String[2 + cases[c].length];
            args[0] = "plan";
            args[1] = MUG;
            System.arraycopy(cases[c], 0, args, 2, cases[c].length);
            CliTesting.Run r = CliTesting.run(args);
            assertEquals(2, r.code(), String.join(" ", args) + ": " + r.err());
            assertTrue(r.err().contains(expect[c]), String.join(" ", args) + ": " + r.err());
            assertFalse(r.err().contains("Exception"), r.err());
        }
    }

    /** Without the spark/ build on the class path, --engine spark says how to get it, exit 2. */
    @Test
    void sparkEngineOutsideItsBuildSaysWhy() {
        CliTesting.Run r = CliTesting.run("plan", MUG, "--engine", "spark");
        assertEquals(2, r.code());
        assertOneLine(r.err(), "./handsim");
    }

    static void assertOneLine(String err, String mentions) {
        assertEquals(1, err.lines().count(), err);
        assertTrue(err.contains(mentions), err);
        assertFalse(err.contains("Exception"), err);
    }

    @Test
    void noTargetIsExit2() {
        assertEquals(2, CliTesting.run("plan").code());
    }
}
