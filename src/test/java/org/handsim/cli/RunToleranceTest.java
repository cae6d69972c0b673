package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.scenario.Home;
import org.junit.jupiter.api.Test;

/** {@code handsim run --tolerance}: the choice on stdout and in summary.json, and its three refusals. */
class RunToleranceTest {
    /** The paper scenario, 50 ms long, with its object replaced by {@code objectFile} (absolute). */
    private static Path scenario(Path dir, Path objectFile) throws Exception {
        Path s = dir.resolve("short.json");
        Files.writeString(s, Files.readString(Home.paperScenario())
            .replace("../vrml/objects/cube.wrl", objectFile.toString().replace("\\", "/"))
            .replace("\"dt_s\": 0.001", "\"dt_s\": 0.001, \"duration_s\": 0.05"));
        return s;
    }

    private static Path ball(Path dir) throws Exception {
        Path f = dir.resolve("ball.wrl");
        Files.writeString(f, "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.04 } }\n");
        return f;
    }

    @Test
    void toleranceChoosesDivisionsAndRecordsThem() throws Exception {
        Path dir = Files.createTempDirectory("handsim-tol");
        Path s = scenario(dir, ball(dir));
        CliTesting.Run r = CliTesting.run("run", s.toString(), "--tolerance", "0.5 mm", "--no-charts",
            "--out", dir.resolve("out").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("tolerance 0.500 mm: divisions 32 (960 triangles), expected worst contact-centre error 0.303 mm"), r.out());
        String summary = Files.readString(dir.resolve("out/summary.json"));
        assertTrue(summary.contains("\"tolerance_m\": 5.0E-4") || summary.contains("\"tolerance_m\": 0.0005"), summary);
        assertTrue(summary.contains("\"divisions\": 32"), summary);
        assertTrue(summary.contains("\"breakaway_time_s\""), "existing keys kept");
        // without --tolerance: neither key
        CliTesting.Run plain = CliTesting.run("run", s.toString(), "--no-charts", "--out", dir.resolve("plain").toString());
        assertEquals(0, plain.code(), plain.err());
        String s2 = Files.readString(dir.resolve("plain/summary.json"));
        assertFalse(s2.contains("tolerance_m") || s2.contains("\"divisions\""), s2);
    }

    @Test
    void badToleranceIsAUsageErrorNamingTheValue() throws Exception {
        Path dir = Files.createTempDirectory("handsim-tol");
        Path s = scenario(dir, ball(dir));
        for (String bad : new String[] {"0.5furlong", "-1mm", "abc"}) {
            CliTesting.Run r = CliTesting.run("run", s.toString(), "--tolerance", bad, "--out", dir.resolve("out").toString());
            assertEquals(2, r.code(), bad);
            assertTrue(r.err().contains("'" + bad + "'") && !r.err().contains("\n"), r.err());
            assertFalse(Files.exists(dir.resolve("out")));
        }
    }

    @Test
    void fixedMeshRunsAsIsWithANote() throws Exception {
        Path dir = Files.createTempDirectory("handsim-tol");
        Path s = scenario(dir, Home.dir().resolve("vrml/objects/cube.wrl").toAbsolutePath());
        CliTesting.Run r = CliTesting.run("run", s.toString(), "--tolerance", "0.5mm", "--no-charts",
            "--out", dir.resolve("out").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("--tolerance has no effect: ") && r.err().contains("cube.wrl is a fixed mesh of 12 triangles"), r.err());
        assertTrue(Files.readString(dir.resolve("out/summary.json")).contains("\"tolerance_m\""));
    }

    @Test
    void unmeetableToleranceSaysTheBestAchievable() throws Exception {
        Path dir = Files.createTempDirectory("handsim-tol");
        Path s = scenario(dir, ball(dir));
        CliTesting.Run r = CliTesting.run("run", s.toString(), "--tolerance", "1um", "--out", dir.resolve("out").toString());
        assertEquals(2, r.code());
        assertTrue(r.err().contains("cannot be met") && r.err().contains("best achievable worst contact-centre error is 0.0204 mm"), r.err());
        assertFalse(Files.exists(dir.resolve("out")));
    }
}
