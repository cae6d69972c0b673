package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.math.RigidTransform;
import org.junit.jupiter.api.Test;

/** The view's mesh source on HandSim's own models, its error messages, and the placement fields' rotation round trip. */
class MeshSourceTest {
    @Test
    void readsTheCommittedModelsWithTheirCountsAndColours() throws IOException {
        Path v = TestPaths.root().resolve("vrml");
        MeshSource.Model cube = MeshSource.load(v.resolve("objects/cube.wrl"), 24);
        assertEquals(12, cube.mesh().triangleCount());
        assertEquals(2.16e-4, cube.mesh().signedVolume(), 1e-10);   // the loader stores float coordinates
        assertArrayEquals(new float[] {0.85f, 0.25f, 0.2f}, cube.colour());
        String[][] expect = {{"hand/palm.wrl", "216"}, {"hand/finger_link1.wrl", "80"}, {"hand/finger_link2.wrl", "140"},
            {"hand/finger_link3.wrl", "140"}, {"objects/mug.wrl", "720"}, {"objects/sphere.wrl", "960"}};
        for (String[] e : expect) {
            MeshSource.Model m = MeshSource.load(v.resolve(e[0]), 24);
            assertEquals(Integer.parseInt(e[1]), m.mesh().triangleCount(), e[0]);
            assertTrue(m.mesh().isClosed(), e[0]);
        }
    }

    @Test
    void objAndStlLoadWithTheirColours() throws IOException {
        Path dir = Files.createTempDirectory("handsim-mesh-test");
        try {
            Path obj = dir.resolve("t.obj"), mtl = dir.resolve("t.mtl"), bare = dir.resolve("bare.obj");
            String tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
            Files.writeString(obj, "mtllib t.mtl\nusemtl dark\n" + tetra);
            Files.writeString(mtl, "newmtl dark\nKa 0 0 0\nKd 0.1 0.2 0.3\n");
            Files.writeString(bare, tetra);
            MeshSource.Model m = MeshSource.load(obj, 24);
            assertEquals(4, m.mesh().triangleCount());
            assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f}, m.colour(), "Kd of the OBJ's material library");
            assertEquals(null, MeshSource.load(bare, 24).colour(), "no library: the caller's default");
            MeshSource.Model stl = MeshSource.load(TestPaths.root().resolve("vrml/objects/mug_mm.stl"), 24);
            assertEquals(720, stl.mesh().triangleCount());
            assertEquals(null, stl.colour());
        } finally {
            for (String f : new String[] {"t.obj", "t.mtl", "bare.obj"}) Files.deleteIfExists(dir.resolve(f));
            Files.delete(dir);
        }
    }

    @Test
    void badFilesAreErrorsNamingTheFileAndLine() throws IOException {
        Path dir = Files.createTempDirectory("handsim-mesh-test");
        try {
            Path notVrml = dir.resolve("a.wrl");
            Files.writeString(notVrml, "solid cube\n");
            IOException e = assertThrows(IOException.class, () -> MeshSource.load(notVrml, 24));
            assertTrue(e.getMessage().startsWith(notVrml + ":1:1: "), e.getMessage());
            Path badIndex = dir.resolve("b.wrl");
            Files.writeString(badIndex, "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 1 0 0, 0 1 0] }"
                + " coordIndex [0, 1, 7, -1] } }\n");
            e = assertThrows(IOException.class, () -> MeshSource.load(badIndex, 24));
            assertTrue(e.getMessage().startsWith(badIndex.toString()), e.getMessage());
            assertTrue(e.getMessage().contains("7"), e.getMessage());
            Path empty = dir.resolve("c.wrl");
            Files.writeString(empty, "#VRML V2.0 utf8\nGroup { }\n");
            e = assertThrows(IOException.class, () -> MeshSource.load(empty, 24));
            assertTrue(e.getMessage().contains("c.wrl:1:1: the file has no triangles"), e.getMessage());
        } finally {
            for (String f : new String[] {"a.wrl", "b.wrl", "c.wrl"}) Files.deleteIfExists(dir.resolve(f));
            Files.delete(dir);
        }
    }
}
