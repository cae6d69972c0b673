package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.handsim.cli.ChildJvm;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The tessellated-mesh cache: hits equal a fresh load, keys follow content, damaged entries are misses, writers race safely. */
class MeshCacheTest {
    Path dir;
    String before;

    @BeforeEach
    void folder() throws Exception {
        dir = Files.createTempDirectory("handsim-meshcache");
        before = System.getProperty("handsim.cache");
        System.setProperty("handsim.cache", dir.toString());
    }

    @AfterEach
    void clean() throws Exception {
        if (before == null) System.clearProperty("handsim.cache"); else System.setProperty("handsim.cache", before);
        ChildJvm.deleteTree(dir);
    }

    static TriangleMesh load(Path f, int divisions, double scale) {
        return MeshFiles.load(f, divisions, scale).mesh();
    }

    /** A loader that counts its calls. */
    static TriangleMesh counted(AtomicInteger calls, Path f, int divisions, double scale) {
        calls.incrementAndGet();
        return load(f, divisions, scale);
    }

    static void same(TriangleMesh a, TriangleMesh b) {
        assertEquals(a.name(), b.name());
        assertArrayEquals(a.vertices(), b.vertices());
        assertArrayEquals(a.triangles(), b.triangles());
        assertArrayEquals(a.normals(), b.normals());
    }

    /** Entries are trusted: a cache folder that others may write (a planted mesh would change results) is not used. */
    @Test
    void aFolderOthersMayWriteIsNotUsed() throws Exception {
        Path mug = Files.copy(Home.dir().resolve("vrml/objects/mug.wrl"), dir.resolve("mug.wrl"));
        Files.createDirectory(dir.resolve("meshes"));
        Files.setPosixFilePermissions(dir.resolve("meshes"), java.nio.file.attribute.PosixFilePermissions.fromString("rwxrwxrwx"));
        AtomicInteger calls = new AtomicInteger();
        MeshCache.get(mug, MeshFiles.read(mug), 24, 1.2, () -> counted(calls, mug, 24, 1.2));
        MeshCache.get(mug, MeshFiles.read(mug), 24, 1.2, () -> counted(calls, mug, 24, 1.2));
        assertEquals(2, calls.get(), "no hit");
        try (var entries = Files.list(dir.resolve("meshes"))) {
            assertEquals(0, entries.count(), "nothing written there");
        }
        // the same folder made private is used
        Files.setPosixFilePermissions(dir.resolve("meshes"), java.nio.file.attribute.PosixFilePermissions.fromString("rwx------"));
        MeshCache.get(mug, MeshFiles.read(mug), 24, 1.2, () -> counted(calls, mug, 24, 1.2));
        MeshCache.get(mug, MeshFiles.read(mug), 24, 1.2, () -> counted(calls, mug, 24, 1.2));
        assertEquals(3, calls.get(), "a hit");
    }

    @Test
    void aHitIsTheFreshMeshBitForBit() throws Exception {
        Path mug = Files.copy(Home.dir().resolve("vrml/objects/mug.wrl"), dir.resolve("mug.wrl"));
        AtomicInteger calls = new AtomicInteger();
        TriangleMesh first = MeshCache.get(mug, MeshFiles.read(mug), 24, 1.2, () -> counted(calls, mug, 24, 1.2));
        TriangleMesh second = MeshCache.get(mug, MeshFiles.read(mug), 24, 1.2, () -> counted(calls, mug, 24, 1.2));
        assertEquals(1, calls.get(), "the second came from the cache");
        same(load(mug, 24, 1.2), first);
        same(first, second);
        // other divisions or scale: other entries
        MeshCache.get(mug, MeshFiles.read(mug), 12, 1.2, () -> counted(calls, mug, 12, 1.2));
        MeshCache.get(mug, MeshFiles.read(mug), 24, 1.0, () -> counted(calls, mug, 24, 1.0));
        assertEquals(3, calls.get());
        // the same bytes under another name hit; changed bytes miss
        Path copy = Files.copy(mug, dir.resolve("copy.wrl"));
        MeshCache.get(copy, MeshFiles.read(copy), 24, 1.2, () -> counted(calls, copy, 24, 1.2));
        assertEquals(3, calls.get(), "keyed by content, not name");
        Files.writeString(copy, Files.readString(copy) + "\n# edited\n");
        MeshCache.get(copy, MeshFiles.read(copy), 24, 1.2, () -> counted(calls, copy, 24, 1.2));
        assertEquals(4, calls.get(), "an edited file misses");
    }

    /** Every damaged entry — each byte flipped in turn, or cut short — is a miss, and is replaced by a good one. */
    @Test
    void damagedEntriesAreMisses() throws Exception {
        Path cube = Files.copy(Home.dir().resolve("vrml/objects/cube.wrl"), dir.resolve("cube.wrl"));
        TriangleMesh fresh = MeshCache.get(cube, MeshFiles.read(cube), 32, 1.0, () -> load(cube, 32, 1.0));
        Path entry;
        try (var s = Files.list(dir.resolve("meshes"))) {
            entry = s.filter(p -> p.toString().endsWith(".mesh")).findFirst().orElseThrow();
        }
        byte[] good = Files.readAllBytes(entry);
        String key = MeshCache.key(32, 1.0);
        byte[] source = Files.readAllBytes(cube);
        assertNotNull(MeshCache.read(entry, key, source));
        assertNull(MeshCache.read(entry, key + " other", source), "another key");
        byte[] other = source.clone();
        other[other.length / 2] ^= 1;
        assertNull(MeshCache.read(entry, key, other), "another file (here: of the same length, as one with the same CRCs would be)");
        for (int i = 0; i < good.length; i++) {
            byte[] bad = good.clone();
            bad[i] ^= 0x10;
            Files.write(entry, bad);
            assertNull(MeshCache.read(entry, key, source), "byte " + i + " flipped");
        }
        for (int n : new int[] {0, 5, good.length / 2, good.length - 1}) {
            Files.write(entry, java.util.Arrays.copyOf(good, n));
            assertNull(MeshCache.read(entry, key, source), "cut to " + n + " bytes");
        }
        AtomicInteger calls = new AtomicInteger();
        same(fresh, MeshCache.get(cube, MeshFiles.read(cube), 32, 1.0, () -> counted(calls, cube, 32, 1.0)));
        assertEquals(1, calls.get(), "reloaded");
        assertArrayEquals(good, Files.readAllBytes(entry), "and rewritten");
    }

    /** Eight threads load the same and different meshes at once: every answer is right, no temporary file is left. */
    @Test
    void concurrentWritersLeaveWholeEntries() throws Exception {
        Path cube = Files.copy(Home.dir().resolve("vrml/objects/cube.wrl"), dir.resolve("cube.wrl"));
        Path sphere = Files.copy(Home.dir().resolve("vrml/objects/sphere.wrl"), dir.resolve("sphere.wrl"));
        TriangleMesh c = load(cube, 32, 1.0), s = load(sphere, 16, 1.0);
        ExecutorService pool = Executors.newFixedThreadPool(8);
        try {
            List<Future<?>> f = new ArrayList<>();
            for (int i = 0; i < 64; i++) {
                boolean even = i % 2 == 0;
                f.add(pool.submit(() -> {
                    if (even) same(c, MeshCache.get(cube, MeshFiles.read(cube), 32, 1.0, () -> load(cube, 32, 1.0)));
                    else same(s, MeshCache.get(sphere, MeshFiles.read(sphere), 16, 1.0, () -> load(sphere, 16, 1.0)));
                    return null;
                }));
            }
            for (Future<?> x : f) x.get();
        } finally {
            pool.shutdown();
        }
        try (var files = Files.list(dir.resolve("meshes"))) {
            List<String> names = files.map(p -> p.getFileName().toString()).toList();
            assertEquals(2, names.size(), names.toString());
            assertTrue(names.stream().allMatch(n -> n.endsWith(".mesh")), names.toString());
        }
    }

    /** A VRML file that inlines another is not cached (its mesh depends on a file the key does not see); "off" turns the cache off. */
    @Test
    void filesThatReadOtherFilesAreNotCached() throws Exception {
        Files.copy(Home.dir().resolve("vrml/objects/cube.wrl"), dir.resolve("cube.wrl"));
        Path inl = dir.resolve("inl.wrl");
        Files.writeString(inl, "#VRML V2.0 utf8\nInline { url \"cube.wrl\" }\n");
        AtomicInteger calls = new AtomicInteger();
        MeshCache.get(inl, MeshFiles.read(inl), 32, 1.0, () -> counted(calls, inl, 32, 1.0));
        MeshCache.get(inl, MeshFiles.read(inl), 32, 1.0, () -> counted(calls, inl, 32, 1.0));
        assertEquals(2, calls.get());
        System.setProperty("handsim.cache", "off");
        assertNull(MeshCache.folder());
        Path cube = dir.resolve("cube.wrl");
        MeshCache.get(cube, MeshFiles.read(cube), 32, 1.0, () -> counted(calls, cube, 32, 1.0));
        MeshCache.get(cube, MeshFiles.read(cube), 32, 1.0, () -> counted(calls, cube, 32, 1.0));
        assertEquals(4, calls.get());
    }
}
