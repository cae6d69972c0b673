package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.handsim.hold.HoldReport;
import org.handsim.scenario.Home;
import org.handsim.text.Json;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim hold-test}: the README's contracts (hold-test.json's keys, hold-test.csv's
 * header, six verdicts printed, exit 0 whatever the verdict) and its clear errors: a push, a
 * time or a threshold that is not positive (exit 2, naming the option and the value as typed),
 * an object whose mass cannot be known (exit 3, naming the file and what to add).
 */
class HoldTestCommandTest {
    static final List<String> KEYS = List.of("scenario", "frame", "force_N", "duration_s", "dt_s", "gravity", "friction",
        "max_displacement_m", "max_rotation_deg", "contact_margin_m", "object", "closing", "contacts_at_release", "settling",
        "directions", "passed", "held", "smallest_margin");
    static final List<String> DIRECTION_KEYS = List.of("direction", "unit", "passed", "displacement_m", "rotation_deg",
        "final_displacement_m", "final_rotation_deg", "margin", "failed_at_s", "contact_lost_s", "settled_s", "settled_bound_m",
        "settled_bound_deg", "simulated_s", "unconverged_steps", "contacts");
    static final List<String> SETTLING_KEYS = List.of("displacement_m", "rotation_deg", "time_s", "dropped", "unconverged_steps");

    @Test
    @SuppressWarnings("unchecked")
    void writesTheSixVerdictsAndExitsZeroWhateverTheyAre() throws Exception {
        Path dir = Files.createTempDirectory("hold-test-cmd");
        try {
            Path scenario = org.handsim.hold.HoldTestTest.farCube(dir);
            Path out = dir.resolve("out");
            CliTesting.Run r = CliTesting.run("hold-test", scenario.toString(), "--mass", "0.1", "--duration", "0.2", "--out", out.toString());
            assertEquals(0, r.code(), r.err());
            String[] lines = r.out().split("\n");
            assertTrue(lines[0].startsWith("mug-grasp: hold test, F = 1.000 N (object 0.1000 kg, given), 0.2 s per direction, gravity off, mu 0.5;"
                + " world frame"), lines[0]);
            for (int d = 0; d < 6; d++) {
                assertTrue(lines[1 + d].startsWith("  " + List.of("-x", "+x", "-y", "+y", "-z", "+z").get(d) + "  FAILED  moved 200.0 mm"),
                    lines[1 + d]);
            }
            assertTrue(lines[7].startsWith("0 of 6 directions held (smallest margin "), lines[7]);
            assertTrue(lines[8].startsWith("wrote "), lines[8]);
            for (String f : List.of("hold-test.json", "hold-test.csv", "hold-test.png", "hold-test.svg")) {
                assertTrue(Files.isRegularFile(out.resolve(f)), f);
            }
            Map<String, Object> j = (Map<String, Object>) Json.parse("hold-test.json", Files.readString(out.resolve("hold-test.json")));
            assertEquals(KEYS, new ArrayList<>(j.keySet()));
            assertEquals(SETTLING_KEYS, new ArrayList<>(((Map<String, Object>) j.get("settling")).keySet()));
            assertFalse(r.err().contains("Coulomb's fixed point"), "no contact, no unsettled step to note: " + r.err());
            List<Object> ds = (List<Object>) j.get("directions");
            assertEquals(6, ds.size());
            for (Object o : ds) assertEquals(DIRECTION_KEYS, new ArrayList<>(((Map<String, Object>) o).keySet()));
            List<String> csv = Files.readAllLines(out.resolve("hold-test.csv"));
            assertEquals(HoldReport.CSV_HEADER, csv.get(0));
            assertEquals(7, csv.size());
            String[] row = csv.get(1).split(",", -1);
            assertEquals("-x", row[0]);
            assertEquals("false", row[1]);
            assertEquals(0.2, Double.parseDouble(row[2]), 1e-12, "displacement_m: ½·10 m/s²·(0.2 s)²");
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void aPushTimeOrThresholdThatIsNotPositiveIsRefusedNamingIt() {
        String mug = Home.scenarios().resolve("mug-grasp.json").toString();
        String[][] cases = {
            {"--force", "0"}, {"--force", "-2"}, {"--duration", "0"}, {"--duration", "-1"}, {"--max-displacement", "0"},
            {"--max-rotation", "-15"}, {"--ramp-displacement", "0"}, {"--ramp-rotation", "0"}, {"--mass", "0"}, {"--density", "-1"}};
        for (String[] c : cases) {
            CliTesting.Run r = CliTesting.run("hold-test", mug, c[0], c[1]);
            assertEquals(2, r.code(), String.join(" ", c) + ": " + r.err());
            assertTrue(r.err().startsWith("handsim: " + c[0] + " must be a finite number > 0, got "), r.err());
            assertTrue(r.err().contains(c[1]), "the value as typed: " + r.err());
        }
        CliTesting.Run both = CliTesting.run("hold-test", mug, "--mass", "0.1", "--density", "1000");
        assertEquals(2, both.code());
        assertEquals("handsim: give --mass or --density, not both", both.err());
    }

    @Test
    void anObjectWhoseMassCannotBeKnownIsRefusedNamingItsFile() throws Exception {
        Path dir = Files.createTempDirectory("hold-test-open");
        try {
            // an open surface: a square of two triangles
            Path obj = dir.resolve("sheet.obj");
            Files.writeString(obj, "v 0 0 0\nv 0.05 0 0\nv 0.05 0.05 0\nv 0 0.05 0\nf 1 2 3\nf 1 3 4\n");
            String s = Files.readString(Home.scenarios().resolve("mug-grasp.json"))
                .replace("\"../vrml/objects/mug.wrl\"", "\"sheet.obj\"").replace("\"scale\": 1.2", "\"scale\": 1.0");
            Path scenario = dir.resolve("sheet.json");
            Files.writeString(scenario, s);
            CliTesting.Run r = CliTesting.run("hold-test", scenario.toString(), "--out", dir.resolve("out").toString());
            assertEquals(3, r.code(), r.err());
            assertTrue(r.err().contains("sheet.obj"), r.err());
            assertTrue(r.err().contains("the surface is not closed"), r.err());
            assertTrue(r.err().contains("give \"mass_kg\""), r.err());
            assertTrue(!Files.exists(dir.resolve("out")), "nothing written");
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
