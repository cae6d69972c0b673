package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting.Run;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * OBJ and STL in {@code handsim mesh} and {@code collide}: what {@code mesh --obj}
 * and {@code --stl} write reads back to the same triangles, and the collision of the OBJ and STL
 * twins of a VRML model is the VRML model's; malformed files exit 3 naming the place.
 */
class MeshFormatsTest {
    private Path dir;

    @BeforeEach
    void makeDir() throws Exception {
        dir = Files.createTempDirectory("handsim-formats").toRealPath();
    }

    @AfterEach
    void removeDir() throws Exception {
        VrmlTesting.deleteTree(dir);
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> json(Run r) {
        assertEquals(0, r.code(), r.err());
        return (Map<String, Object>) Json.parse("stdout", r.out());
    }

    @Test
    void meshObjAndStlOutputReadBack() throws Exception {
        Path mug = TestPaths.root().resolve("vrml/objects/mug.wrl");
        Path a = dir.resolve("a.obj"), s = dir.resolve("a.stl"), b = dir.resolve("b.obj");
        Map<String, Object> vrml = json(CliTesting.run("mesh", mug.toString(), "--obj", a.toString(), "--stl", s.toString()));
        Map<String, Object> obj = json(CliTesting.run("mesh", a.toString(), "--obj", b.toString()));
        Map<String, Object> stl = json(CliTesting.run("mesh", s.toString()));
        for (String key : List.of("triangles", "vertices", "degenerate", "closed", "bounds", "area_m2", "volume_m3")) {
            assertEquals(vrml.get(key), obj.get(key), "OBJ read back: " + key);
            assertEquals(vrml.get(key), stl.get(key), "STL read back: " + key);
        }
        // the OBJ written from the OBJ is the same file: same vertices in the same order, same faces
        assertEquals(Files.readString(a).replace("o mug.wrl", "o a.obj"), Files.readString(b));
        assertEquals(84 + 50 * ((Double) vrml.get("triangles")).longValue(), Files.size(s));
    }

    @Test
    void collideGivesTheSameContactsForTheVrmlObjAndStlTwins() throws Exception {
        Path cube = TestPaths.root().resolve("vrml/objects/cube.wrl");
        Path obj = dir.resolve("cube.obj"), stl = dir.resolve("cube.stl");
        json(CliTesting.run("mesh", cube.toString(), "--obj", obj.toString(), "--stl", stl.toString()));
        String pose = "0.03,0.02,0.01,0.3,0.2,0.1";
        Map<String, Object> w = json(CliTesting.run("collide", cube.toString(), cube.toString(), "--pose-b", pose));
        for (Path twin : List.of(obj, stl)) {
            Map<String, Object> t = json(CliTesting.run("collide", twin.toString(), twin.toString(), "--pose-b", pose));
            assertEquals(w.get("intersecting"), t.get("intersecting"), twin.toString());
            assertEquals(w.get("pairs"), t.get("pairs"), twin.toString());
            assertEquals(w.get("patches"), t.get("patches"), twin.toString());
        }
        assertEquals(Boolean.TRUE, w.get("intersecting"));
    }

    @Test
    void malformedFilesExitThreeNamingThePlace() throws Exception {
        Path obj = dir.resolve("bad.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        Run r = CliTesting.run("mesh", obj.toString());
        assertEquals(3, r.code());
        assertEquals(obj + ":4:7: vertex index 4 is out of range: 3 vertices defined so far", r.err());
        r = CliTesting.run("collide", obj.toString(), obj.toString());
        assertEquals(3, r.code());
        assertEquals(obj + ":4:7: vertex index 4 is out of range: 3 vertices defined so far", r.err());

        Path stl = dir.resolve("bad.stl");
        byte[] b = new byte[84 + 50];
        ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(80, 2);
        Files.write(stl, b);
        r = CliTesting.run("mesh", stl.toString());
        assertEquals(3, r.code());
        assertTrue(r.err().startsWith(stl + ": byte 134: the file ends inside triangle 2 of the 2"), r.err());
        assertEquals(1, r.err().lines().count(), r.err());
    }
}
