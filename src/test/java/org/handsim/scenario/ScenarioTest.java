package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;

class ScenarioTest {
    private static final String OK = "{\"name\":\"t\",\"dt_s\":0.001,\"motors\":{\"M3\":[{\"type\":\"trapezoid\",\"to\":17500,\"v_max\":5000,\"a_max\":25000},"
        + "{\"type\":\"hold\",\"duration_s\":0.5},{\"type\":\"quintic\",\"to\":0,\"duration_s\":2}]}}";

    private static String error(String json) {
        return assertThrows(ScenarioException.class, () -> Scenario.parse(Path.of("s.json"), json)).getMessage();
    }

    @Test
    void goodFileAndDefaults() {
        Scenario s = Scenario.parse(Path.of("s.json"), OK);
        assertEquals("t", s.name());
        assertEquals(3.7 + 0.5 + 2, s.duration(), 1e-12, "duration defaults to the longest motor");
        assertEquals(0, s.motor(0).duration());
        assertEquals(-9.81, s.gravity()[2]);
        assertEquals(17500, s.motor(2).position(3.7), 1e-9);
        assertEquals(0.002, s.withDt(0.002).dt());
        assertEquals(0.001, s.dt(), "copies leave the original alone");
    }

    @Test
    void badFieldsAreNamed() {
        assertTrue(error(OK.replace("\"v_max\":5000", "\"v_max\":-1")).contains("field motors.M3[0].v_max: must be > 0, got -1"));
        assertTrue(error(OK.replace("\"to\":17500", "\"to\":20000")).contains("field motors.M3[0].to: must be in [0, 17500] counts"));
        assertTrue(error(OK.replace("\"dt_s\":0.001", "\"dt_s\":\"fast\"")).contains("field dt_s: must be a number"));
        assertTrue(error(OK.replace("\"dt_s\":0.001,", "")).contains("field dt_s: missing"));
        assertTrue(error(OK.replace("\"type\":\"hold\"", "\"type\":\"jump\"")).contains("field motors.M3[1].type: must be trapezoid, quintic, hold or line"));
        assertTrue(error(OK.replace("\"name\":\"t\"", "\"name\":\"a/b\"")).contains("field name"));
        assertTrue(error(OK.replace("\"motors\"", "\"motor\"")).contains("field motor: is not a known field"));
        assertTrue(error(OK.replace("\"M3\"", "\"M5\"")).contains("field motors.M5: is not a known field"));
        assertTrue(error(OK.replace("}]}}", "}]},\"object\":{\"file\":\"nowhere.wrl\"}}")).contains("field object.file: no such file"));
        String syntax = error(OK.replace("\"dt_s\":0.001", "\"dt_s\" 0.001"));
        assertTrue(syntax.startsWith("s.json:1:"), syntax);
    }

    @Test
    void sweepOverridesByPath() {
        String out = Sweep.applyOverrides(Path.of("s.json"), OK, Map.of("motors.M3[0].v_max", 3000.0, "dt_s", 0.002));
        Scenario s = Scenario.parse(Path.of("s.json"), out);
        assertEquals(0.002, s.dt());
        assertEquals(17500.0 / 3000 + 3000.0 / 25000, s.motor(2).duration() - 2.5, 1e-9);
        ScenarioException e = assertThrows(ScenarioException.class,
            () -> Sweep.applyOverrides(Path.of("s.json"), OK, Map.of("motors.M3[7].v_max", 1.0)));
        assertTrue(e.getMessage().contains("no element 7"), e.getMessage());
    }

    /** object.friction: Coulomb μ, default 0.5, ≥ 0; a bad value names the field. */
    @Test
    void objectFriction() {
        String cube = Home.dir().resolve("vrml/objects/cube.wrl").toString().replace("\\", "/");
        String withObject = OK.replace("\"dt_s\"", "\"object\":{\"file\":\"" + cube + "\"},\"dt_s\"");
        assertEquals(0.5, Scenario.parse(Path.of("s.json"), withObject).friction());
        assertEquals(0.5, Scenario.parse(Path.of("s.json"), withObject).object().friction());
        assertEquals(8, Scenario.parse(Path.of("s.json"), withObject).coneEdges());
        String mu = withObject.replace("\"file\":", "\"friction\":0.3,\"file\":");
        assertEquals(0.3, Scenario.parse(Path.of("s.json"), mu).friction());
        assertEquals(0, Scenario.parse(Path.of("s.json"), mu).withFriction(0).friction(), "--friction overrides the file");
        assertEquals(0.3, Scenario.parse(Path.of("s.json"), mu).friction(), "copies leave the original alone");
        assertEquals(12, Scenario.parse(Path.of("s.json"), mu).withConeEdges(12).coneEdges());
        assertTrue(error(withObject.replace("\"file\":", "\"friction\":-0.1,\"file\":")).contains("field object.friction: must be in [0, 10] (measured coefficients stay below 2; beyond 10 the friction cone is numerically a half-space), got -0.1"),
            error(withObject.replace("\"file\":", "\"friction\":-0.1,\"file\":")));
        assertTrue(error(withObject.replace("\"file\":", "\"friction\":\"high\",\"file\":")).contains("field object.friction: must be a number"));
        // no object: the default, or what withFriction sets (analytic contact back ends)
        assertEquals(0.5, Scenario.parse(Path.of("s.json"), OK).friction());
        assertEquals(0.25, Scenario.parse(Path.of("s.json"), OK).withFriction(0.25).friction());
        assertThrows(IllegalArgumentException.class, () -> Scenario.parse(Path.of("s.json"), OK).withFriction(-1));
        assertThrows(IllegalArgumentException.class, () -> Scenario.parse(Path.of("s.json"), OK).withConeEdges(0));
    }
}
