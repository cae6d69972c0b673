package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.model.Simulation;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;
import org.junit.jupiter.api.Test;

/**
 * The free object's fields in a scenario ({@code "object": {"free": true, ...}}): read with their
 * defaults, written back as read, and every value that is no body refused naming the field.
 */
class FreeObjectTest {
    static final Path MUG = TestPaths.root().resolve("scenarios/mug-grasp.json");

    /** The mug scenario with {@code fields} (JSON object text) added to its object. */
    static Scenario mugWith(String fields) {
        return mugWith(fields, null, null);
    }

    /**
     * The mug scenario with {@code fields} added to its object and, when {@code field} is not
     * null, {@code value} (JSON text) as the scenario's field ({@code "hand.moves"}: the hand's).
     */
    @SuppressWarnings("unchecked")
    static Scenario mugWith(String fields, String field, String value) {
        Map<String, Object> j = (Map<String, Object>) Json.parse("mug", Scenario.readText(MUG));
        ((Map<String, Object>) j.get("object")).putAll((Map<String, Object>) Json.parse("fields", fields));
        if (field != null) {
            Map<String, Object> into = field.startsWith("hand.") ? (Map<String, Object>) j.get("hand") : j;
            into.put(field.substring(field.indexOf('.') + 1), Json.parse(field, value));
        }
        return Scenario.parse(MUG, JsonWriter.write(j));
    }

    @Test
    void disturbancesAreReadWrittenBackAndRefusedNamingTheField() {
        Scenario s = mugWith("{\"free\": true, \"mass_kg\": 0.3}", "disturbances",
            "[{\"from_s\": 1, \"to_s\": 1.5, \"force_N\": [0, 2, 0]}, {\"from_s\": 2, \"to_s\": 2.1, \"torque_N_m\": [0, 0, 0.1]}]");
        assertEquals(2, s.disturbances().size());
        Disturbance d = s.disturbances().get(0);
        assertArrayEquals(new double[] {0, 2, 0}, d.forceN());
        assertArrayEquals(new double[3], d.torqueNm());
        assertTrue(d.actsAt(1) && d.actsAt(1.4999) && !d.actsAt(1.5) && !d.actsAt(0.999));
        assertArrayEquals(new double[] {0, 0, 0.1}, s.disturbances().get(1).torqueNm());
        Path dir = MUG.getParent();
        Map<String, Object> json = s.toJson(dir);
        Scenario back = Scenario.parse(MUG, JsonWriter.write(json));
        assertEquals(JsonWriter.pretty(json), JsonWriter.pretty(back.toJson(dir)));
        assertEquals(0, Scenario.load(MUG).disturbances().size());
        String[][] bad = {
            {"{}", "[{\"from_s\": 1, \"to_s\": 2, \"force_N\": [1, 0, 0]}]", "field disturbances: push a free object: add \"free\": true"},
            {"{\"free\": true, \"mass_kg\": 0.3}", "[{\"from_s\": 2, \"to_s\": 2, \"force_N\": [1, 0, 0]}]",
                "field disturbances[0].to_s: must be after from_s (2 s), got 2 s"},
            {"{\"free\": true, \"mass_kg\": 0.3}", "[{\"from_s\": 0, \"to_s\": 1, \"force_N\": [1, 0, 0]}, {\"from_s\": 3, \"to_s\": 1, \"force_N\": [1, 0, 0]}]",
                "field disturbances[1].to_s: must be after from_s (3 s), got 1 s"},
            {"{\"free\": true, \"mass_kg\": 0.3}", "[{\"from_s\": -1, \"to_s\": 1, \"force_N\": [1, 0, 0]}]", "field disturbances[0].from_s: must be >= 0"},
            {"{\"free\": true, \"mass_kg\": 0.3}", "[{\"from_s\": 0, \"to_s\": 1}]", "field disturbances[0].force_N: missing: give force_N, torque_N_m or both"},
            {"{\"free\": true, \"mass_kg\": 0.3}", "[{\"from_s\": 0, \"to_s\": 1, \"force_N\": [1, 0]}]", "field disturbances[0].force_N: must have 3 numbers"},
            {"{\"free\": true, \"mass_kg\": 0.3}", "[{\"from_s\": 0, \"to_s\": 1, \"force\": [1, 0, 0]}]", "force"},
        };
        for (String[] b : bad) {
            ScenarioException e = assertThrows(ScenarioException.class, () -> mugWith(b[0], "disturbances", b[1]), b[1]);
            assertTrue(e.getMessage().contains(b[2]), b[1] + " -> " + e.getMessage());
        }
    }

    @Test
    void supportsAreReadWrittenBackAndRefusedNamingTheField() {
        String free = "{\"free\": true, \"mass_kg\": 0.3}";
        Scenario s = mugWith(free, "supports", "[{\"box_m\": [0.5, 0.4, 0.02], \"position_m\": [0, 0, 0.05]},"
            + " {\"file\": \"../vrml/objects/cube.wrl\", \"position_m\": [1, 0, 0], \"rotation_rad\": [0, 0, 0.5]}]");
        assertEquals(2, s.supports().size());
        assertArrayEquals(new double[] {0.5, 0.4, 0.02}, s.supports().get(0).boxM());
        assertArrayEquals(new double[] {0, 0, 0.05}, s.supports().get(0).worldFromSupport().origin());
        assertEquals(TestPaths.root().resolve("vrml/objects/cube.wrl").toAbsolutePath().normalize(), s.supports().get(1).file().toAbsolutePath());
        assertEquals(0.5, s.supports().get(1).worldFromSupport().rotationVector()[2], 1e-15);
        Path dir = MUG.getParent();
        Map<String, Object> json = s.toJson(dir);
        Scenario back = Scenario.parse(MUG, JsonWriter.write(json));
        assertEquals(JsonWriter.pretty(json), JsonWriter.pretty(back.toJson(dir)));
        String[][] bad = {
            {"{}", "[{\"box_m\": [1, 1, 1]}]", "field supports: hold up a free object: add \"free\": true"},
            {free, "[{\"box_m\": [1, 0, 1]}]", "field supports[0].box_m[1]: must be > 0, got 0"},
            {free, "[{\"position_m\": [0, 0, 0]}]", "field supports[0].box_m: missing: give box_m (edge lengths) or file (a mesh)"},
            {free, "[{\"box_m\": [1, 1, 1], \"file\": \"a.stl\"}]", "field supports[0].file: give box_m or file, not both"},
            {free, "[{\"box_m\": [1, 1, 1]}, {\"file\": \"no-such-table.stl\"}]", "field supports[1].file: "},
            {free, "[{\"box_m\": [1, 1, 1], \"rotation_rad\": [0, 0]}]", "field supports[0].rotation_rad: must have 3 numbers"},
        };
        for (String[] b : bad) {
            ScenarioException e = assertThrows(ScenarioException.class, () -> mugWith(b[0], "supports", b[1]), b[1]);
            assertTrue(e.getMessage().contains(b[2]), b[1] + " -> " + e.getMessage());
        }
    }

    /**
     * The hand's moves: a 10 cm lift at 0.1 m/s and 1 m/s² takes 0.1 + 0.9 + 0.1 = 1.1 s (ramps
     * of v/a = 0.1 s over 5 mm each, cruise 90 mm); a rotation's sign goes into its axis.
     */
    @Test
    void handMovesAreReadWrittenBackAndRefusedNamingTheField() {
        String free = "{\"free\": true, \"mass_kg\": 0.3}";
        Scenario s = mugWith(free, "hand.moves", "[{\"type\": \"hold\", \"duration_s\": 4.7},"
            + " {\"type\": \"line\", \"by_m\": [0, 0, 0.1], \"v_max\": 0.1, \"a_max\": 1},"
            + " {\"type\": \"rotate\", \"axis\": [0, 2, 0], \"angle_rad\": -0.5, \"v_max\": 1, \"a_max\": 5}]");
        assertEquals(3, s.moves().size());
        assertEquals(4.7, s.moves().get(0).profile().duration());
        HandMove lift = s.moves().get(1);
        assertArrayEquals(new double[] {0, 0, 1}, lift.direction());
        assertEquals(1.1, lift.profile().duration(), 1e-12);
        double[] at = new double[3];
        lift.profile().sample(0.1, at);
        assertEquals(0.005, at[0], 1e-15);
        lift.profile().sample(1.1, at);
        assertEquals(0.1, at[0], 1e-15);
        assertArrayEquals(new double[] {0, -1, 0}, s.moves().get(2).direction());
        assertEquals(0.5, s.moves().get(2).profile().end());
        Path dir = MUG.getParent();
        Map<String, Object> json = s.toJson(dir);
        Scenario back = Scenario.parse(MUG, JsonWriter.write(json));
        assertEquals(JsonWriter.pretty(json), JsonWriter.pretty(back.toJson(dir)));
        String[][] bad = {
            {"{}", "[{\"type\": \"hold\", \"duration_s\": 1}]", "field hand.moves: carry a free object: add \"free\": true"},
            {free, "[{\"type\": \"jump\"}]", "field hand.moves[0].type: must be line, rotate or hold, got \"jump\""},
            {free, "[{\"type\": \"line\", \"by_m\": [0, 0, 0], \"v_max\": 0.1, \"a_max\": 1}]", "field hand.moves[0].by_m: must not be zero"},
            {free, "[{\"type\": \"line\", \"by_m\": [0, 0, 0.1], \"v_max\": 0, \"a_max\": 1}]", "field hand.moves[0].v_max: must be > 0, got 0"},
            {free, "[{\"type\": \"line\", \"by_m\": [0, 0, 0.1], \"v_max\": 0.1}]", "field hand.moves[0].a_max: missing"},
            {free, "[{\"type\": \"rotate\", \"axis\": [0, 0, 0], \"angle_rad\": 1, \"v_max\": 1, \"a_max\": 1}]", "field hand.moves[0].axis: must not be zero"},
            {free, "[{\"type\": \"rotate\", \"axis\": [0, 0, 1], \"angle_rad\": 0, \"v_max\": 1, \"a_max\": 1}]",
                "field hand.moves[0].angle_rad: must be non-zero and within ±4π, got 0"},
            {free, "[{\"type\": \"hold\", \"duration_s\": -1}]", "field hand.moves[0].duration_s: must be > 0"},
        };
        for (String[] b : bad) {
            ScenarioException e = assertThrows(ScenarioException.class, () -> mugWith(b[0], "hand.moves", b[1]), b[1]);
            assertTrue(e.getMessage().contains(b[2]), b[1] + " -> " + e.getMessage());
        }
    }

    @Test
    void theFieldsAreReadWithTheirDefaultsAndWrittenBackAsRead() {
        assertNull(Scenario.load(MUG).freeObject(), "without \"free\": true the object is fixed");
        assertNull(mugWith("{\"free\": false}").freeObject());
        FreeObject f = mugWith("{\"free\": true, \"density_kg_m3\": 1200}").freeObject();
        assertEquals(1200, f.densityKgM3());
        assertTrue(Double.isNaN(f.massKg()) && f.fromMesh() && f.comM() == null);
        assertArrayEquals(new double[3], f.velocityMS());
        assertArrayEquals(new double[3], f.angularVelocityRadS());
        assertEquals(0, f.releaseS());
        String full = "{\"free\": true, \"mass_kg\": 0.3, \"inertia_kg_m2\": [[2e-4, 0, 1e-5], [0, 3e-4, 0], [1e-5, 0, 4e-4]],"
            + " \"com_m\": [0, 0.001, 0.05], \"velocity_m_s\": [0.1, 0, -0.2], \"angular_velocity_rad_s\": [0, 1, 0], \"release_s\": 2.5}";
        Scenario s = mugWith(full);
        f = s.freeObject();
        assertEquals(0.3, f.massKg());
        assertArrayEquals(new double[] {2e-4, 0, 1e-5, 0, 3e-4, 0, 1e-5, 0, 4e-4}, f.inertiaKgM2());
        assertArrayEquals(new double[] {0, 0.001, 0.05}, f.comM());
        assertArrayEquals(new double[] {0.1, 0, -0.2}, f.velocityMS());
        assertArrayEquals(new double[] {0, 1, 0}, f.angularVelocityRadS());
        assertEquals(2.5, f.releaseS());
        // written and read back: the same fields, the same text
        Path dir = MUG.getParent();
        Map<String, Object> json = s.toJson(dir);
        Scenario back = Scenario.parse(MUG, JsonWriter.write(json));
        assertEquals(JsonWriter.pretty(json), JsonWriter.pretty(back.toJson(dir)));
        assertArrayEquals(f.inertiaKgM2(), back.freeObject().inertiaKgM2());
        assertEquals(2.5, back.freeObject().releaseS());
        assertNull(s.withObject(null).freeObject());
    }

    @Test
    void aValueThatIsNoBodyIsRefusedNamingTheField() {
        String[][] bad = {
            {"{\"mass_kg\": 0.3}", "field object.mass_kg: belongs to a free object: add \"free\": true"},
            {"{\"free\": true}", "field object.free: a free object needs its mass: add \"mass_kg\" or \"density_kg_m3\""},
            {"{\"free\": true, \"mass_kg\": 1, \"density_kg_m3\": 1000}", "field object.density_kg_m3: give mass_kg or density_kg_m3, not both"},
            {"{\"free\": true, \"mass_kg\": 0}", "field object.mass_kg: must be > 0, got 0"},
            {"{\"free\": true, \"mass_kg\": -2}", "field object.mass_kg: must be > 0, got -2"},
            {"{\"free\": true, \"density_kg_m3\": 0}", "field object.density_kg_m3: must be > 0"},
            {"{\"free\": \"yes\", \"mass_kg\": 1}", "field object.free: must be true or false"},
            {"{\"free\": true, \"mass_kg\": 1, \"inertia_kg_m2\": [[1, 0, 0], [0, 1, 0], [0, 0, -1]], \"com_m\": [0, 0, 0]}",
                "field object.inertia_kg_m2: must be positive definite (principal moments -1, 1, 1 kg·m²)"},
            {"{\"free\": true, \"mass_kg\": 1, \"inertia_kg_m2\": [[1, 0, 0], [0, 1, 0], [0, 0, 3]], \"com_m\": [0, 0, 0]}",
                "field object.inertia_kg_m2: breaks the triangle inequality"},
            {"{\"free\": true, \"mass_kg\": 1, \"inertia_kg_m2\": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]], \"com_m\": [0, 0, 0]}",
                "field object.inertia_kg_m2: must be symmetric: [0][1] = 0.5 but [1][0] = 0"},
            {"{\"free\": true, \"mass_kg\": 1, \"inertia_kg_m2\": [[1, 0, 0], [0, 1, 0]], \"com_m\": [0, 0, 0]}",
                "field object.inertia_kg_m2: must be 3 rows of 3 numbers, got 2 rows"},
            {"{\"free\": true, \"mass_kg\": 1, \"inertia_kg_m2\": [[1, 0, 0], [0, 1, 0], [0, \"x\", 1]], \"com_m\": [0, 0, 0]}",
                "field object.inertia_kg_m2[2][1]: must be a finite number"},
            {"{\"free\": true, \"density_kg_m3\": 1000, \"inertia_kg_m2\": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], \"com_m\": [0, 0, 0]}",
                "field object.inertia_kg_m2: given with density_kg_m3: give mass_kg with it"},
            {"{\"free\": true, \"mass_kg\": 1, \"com_m\": [0, 0, 0]}", "field object.com_m: given without inertia_kg_m2"},
            {"{\"free\": true, \"mass_kg\": 1, \"inertia_kg_m2\": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}", "field object.inertia_kg_m2: given without com_m"},
            {"{\"free\": true, \"mass_kg\": 1, \"velocity_m_s\": [0, 0]}", "field object.velocity_m_s: must have 3 numbers, got 2"},
            {"{\"free\": true, \"mass_kg\": 1, \"release_s\": -1}", "field object.release_s: must be >= 0, got -1"},
        };
        for (String[] b : bad) {
            ScenarioException e = assertThrows(ScenarioException.class, () -> mugWith(b[0]), b[0]);
            assertTrue(e.getMessage().contains(b[1]), b[0] + " -> " + e.getMessage());
            assertTrue(e.getMessage().contains("mug-grasp.json"), e.getMessage());
        }
    }

    /**
     * A box without its lid (10 triangles, 4 open edges after welding) bounds no solid: a free
     * object of it without its inertia is refused naming the file and what to add; with its mass,
     * inertia and centre given it needs no volume.
     */
    @Test
    @SuppressWarnings("unchecked")
    void anOpenMeshWithoutMassAndInertiaIsRefusedNamingTheFile() throws Exception {
        Path dir = java.nio.file.Files.createTempDirectory("handsim-free");
        try {
            Path obj = dir.resolve("open-box.obj");
            java.nio.file.Files.writeString(obj, "v 0 0 0\nv 0.05 0 0\nv 0.05 0.05 0\nv 0 0.05 0\n"
                + "v 0 0 0.05\nv 0.05 0 0.05\nv 0.05 0.05 0.05\nv 0 0.05 0.05\n"
                + "f 1 3 2\nf 1 4 3\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
            Map<String, Object> j = (Map<String, Object>) Json.parse("mug", Scenario.readText(MUG));
            Map<String, Object> o = (Map<String, Object>) j.get("object");
            o.put("file", obj.toString());
            o.put("scale", 1.0);
            o.put("free", true);
            o.put("mass_kg", 0.3);
            Path f = dir.resolve("free.json");
            Scenario s = Scenario.parse(f, JsonWriter.write(j));
            ScenarioException e = assertThrows(ScenarioException.class, () -> Simulation.model(s, false));
            assertTrue(e.getMessage().startsWith(f + ": field object.free: "), e.getMessage());
            assertTrue(e.getMessage().contains("open-box.obj: the surface is not closed (4 edges are not shared by exactly two triangles"),
                e.getMessage());
            assertTrue(e.getMessage().contains("give \"mass_kg\" and \"inertia_kg_m2\" (and \"com_m\"), or close the mesh"), e.getMessage());
            o.put("inertia_kg_m2", java.util.List.of(java.util.List.of(1e-4, 0.0, 0.0), java.util.List.of(0.0, 1e-4, 0.0),
                java.util.List.of(0.0, 0.0, 1e-4)));
            o.put("com_m", java.util.List.of(0.025, 0.025, 0.025));
            Scenario given = Scenario.parse(f, JsonWriter.write(j));
            assertTrue(Simulation.model(given, false).objectFree(), "given mass, inertia and centre: the open mesh runs free");
        } finally {
            try (var files = java.nio.file.Files.walk(dir)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    /**
     * The mug (scaled 1.2, axis along x at z = 0.125 m: body radius 48 mm, so its lowest point at
     * z = 0.077 m) over a table whose top is at z = 0.070, 0.077 (resting) and 0.080 m: refused
     * only when it starts inside, 3 mm deep.
     */
    @Test
    void anObjectThatStartsInsideASupportIsRefusedWithTheDepth() {
        String free = "{\"free\": true, \"mass_kg\": 0.3}";
        for (double top : new double[] {0.070, 0.077}) {
            Scenario s = mugWith(free, "supports", "[{\"box_m\": [0.4, 0.4, 0.02], \"position_m\": [0, 0, " + (top - 0.01) + "]}]");
            assertTrue(Simulation.model(s, false).objectFree(), top + ": below or touching the mug, the table is no overlap");
        }
        Scenario s = mugWith(free, "supports", "[{\"box_m\": [0.4, 0.4, 0.02], \"position_m\": [0, 0, 0.07]}]");
        ScenarioException e = assertThrows(ScenarioException.class, () -> Simulation.model(s, false));
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("field supports\\[0\\]: the object starts inside it, ([0-9.]+) mm deep at")
            .matcher(e.getMessage());
        assertTrue(m.find(), e.getMessage());
        assertEquals(3.0, Double.parseDouble(m.group(1)), 0.05, e.getMessage());
    }
}
