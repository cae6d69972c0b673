package org.handsim.cli;

import static org.handsim.cli.CliTesting.run;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.handsim.cli.CliTesting.Run;
import org.handsim.collision.TestMeshes;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.handsim.text.JsonWriter;
import org.junit.jupiter.api.Test;

/** {@code handsim collide}: the JSON contract, the argument errors. */
class CollideCommandTest {
    /** The bench scenario sphere_overlap_rot at 320 triangles: FCL's 56 pairs, one patch (a circle). */
    @Test
    void jsonContractOnTheRotatedOverlap() {
        TriangleMesh s = TestMeshes.icosphere(2, 1);
        RigidTransform pose = RigidTransform.fromPose(1.5, 0, 0, 0.18708286933869706, 0.3741657386773941, 0.5612486080160912);
        Map<String, Object> m = CollideCommand.collide(s, s, pose, 18, 5);
        String json = JsonWriter.write(m);
        String untimed = "\\{\"intersecting\":true,\"pairs\":56,\"segments\":56,\"patches\":\\[\\{\"center\":\\[[^]]*\\],\"normal\":\\[[^]]*\\],"
            + "\"area_m2\":[0-9.eE-]+,\"pairs\":56\\}\\],\"counters\":\\{\"node_tests\":[0-9]+,\"tri_tests\":[0-9]+\\}";
        assertTrue(json.matches(untimed + ",\"build_ms\":[0-9.eE-]+,\"query_us_median\":[0-9.eE-]+\\}"), json);
        // not timed unless asked (--timing): the same object without the two times
        String plain = JsonWriter.write(CollideCommand.collide(s, s, pose, 18, 0));
        assertTrue(plain.matches(untimed + "\\}"), plain);
        m.remove("build_ms");
        m.remove("query_us_median");
        assertEquals(JsonWriter.write(m), plain);
    }

    @Test
    void separatedObjectsGiveNoPatches() {
        TriangleMesh s = TestMeshes.icosphere(1, 1);
        String json = JsonWriter.write(CollideCommand.collide(s, s, RigidTransform.translation(2.5, 0, 0), 6, 1));
        assertTrue(json.startsWith("{\"intersecting\":false,\"pairs\":0,\"segments\":0,\"patches\":[],\"counters\":{\"node_tests\":1,\"tri_tests\":0}"), json);
    }

    /**
     * The shared bench meshes through the command: the same intersecting pairs as FCL 0.7
     * (rotated overlap 56 / 122 / 238 / 486, sphere on box 20 / 32 / 56 / 116).
     */
    @Test
    void benchMeshesGiveFclsPairCounts() {
        org.junit.jupiter.api.Assumptions.assumeTrue(org.handsim.TestPaths.hasShared(), "../shared not present");
        java.nio.file.Path dir = org.handsim.TestPaths.shared().resolve("bench-meshes");
        int[] rot = {56, 122, 238, 486}, box = {20, 32, 56, 116};
        for (int level = 2; level <= 5; level++) {
            String s = dir.resolve("icosphere_s" + level + ".wrl").toString();
            Run r = run("collide", s, s, "--pose-b", "1.5,0.0,0.0,0.18708286933869706,0.3741657386773941,0.5612486080160912");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("{\"intersecting\":true,\"pairs\":" + rot[level - 2] + ","), r.out());
            r = run("collide", s, dir.resolve("box_2x2x2.wrl").toString(), "--pose-b", "1.95,0.13,0.07,0.0,0.0,0.0", "--k", "26");
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("{\"intersecting\":true,\"pairs\":" + box[level - 2] + ","), r.out());
        }
        Run sep = run("collide", dir.resolve("icosphere_s3.wrl").toString(), dir.resolve("icosphere_s3.wrl").toString(), "--pose-b", "2.5,0,0,0,0,0");
        assertTrue(sep.out().startsWith("{\"intersecting\":false,\"pairs\":0,"), sep.out());
    }

    @Test
    void unreadableVrmlExitsThree() throws java.io.IOException {
        java.nio.file.Path bad = java.nio.file.Files.createTempFile("bad", ".wrl");
        java.nio.file.Files.writeString(bad, "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 ");
        try {
            Run r = run("collide", bad.toString(), bad.toString());
            assertEquals(3, r.code());
            assertTrue(r.err().startsWith(bad.toString()), r.err());
        } finally {
            java.nio.file.Files.delete(bad);
        }
    }

    @Test
    void helpWorks() {
        Run r = run("collide", "--help");
        assertEquals(0, r.code());
        assertTrue(r.out().contains("--pose-b") && r.out().contains("query_us_median"), r.out());
    }

    @Test
    void badArgumentsExitTwoWithOneLineNamingThem() {
        Run r = run("collide", "a.wrl", "b.wrl", "--k", "24");
        assertEquals(2, r.code());
        assertEquals("handsim: --k must be 6, 14, 18 or 26, got 24", r.err());
        r = run("collide", "a.wrl", "b.wrl", "--k", "x");
        assertEquals(2, r.code());
        assertEquals("handsim: --k: 'x' is not an integer", r.err());
        r = run("collide", "a.wrl", "b.wrl", "--pose-b", "1,2,3");
        assertEquals(2, r.code());
        assertEquals("handsim: --pose-b needs 6 comma-separated numbers, got '1,2,3'", r.err());
        r = run("collide", "a.wrl", "b.wrl", "--timing", "--repeat", "0");
        assertEquals(2, r.code());
        assertEquals("handsim: --repeat must be in 1..10000, got 0", r.err());
        r = run("collide", "a.wrl", "b.wrl", "--repeat", "3");
        assertEquals(2, r.code());
        assertEquals("handsim: --repeat needs --timing", r.err());
        r = run("collide", "a.wrl");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("Missing required parameter: 'B'"), r.err());
    }

    @Test
    void missingFileExitsThree() {
        Run r = run("collide", "/nonexistent/a.wrl", "/nonexistent/b.wrl");
        assertEquals(3, r.code());
        assertEquals("handsim: /nonexistent/a.wrl: no such file", r.err());
    }
}
