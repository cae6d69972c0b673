package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.handsim.TestPaths;
import org.handsim.files.Folders;
import org.junit.jupiter.api.Test;

/**
 * The runnable jar's models unpacked where nobody else can change them (scenario.Home): into the
 * user's private cache, checked file by file against the jar's SHA-256 before every use; a
 * copy planted where the old versions looked is never read; a damaged or replaced copy is not
 * used; a cache others can write is not used at all (a private temporary folder instead); and
 * concurrent first runs leave exactly one copy and nothing else.
 */
class HomeUnpackTest {
    static final Map<String, String> FILES = Map.of(
        "vrml/hand/palm.wrl", "#VRML V2.0 utf8\n# palm\n",
        "scenarios/paper-breakaway.json", "{\"name\": \"paper-breakaway\"}\n",
        "vrml/objects/cube.wrl", "#VRML V2.0 utf8\n# cube\n");

    /** A jar with the given handsim-home/ files (and one class-like entry outside it). */
    static Path jar(Path dir, Map<String, String> files) throws Exception {
        Path jar = dir.resolve("handsim-test.jar");
        try (OutputStream o = Files.newOutputStream(jar); ZipOutputStream z = new ZipOutputStream(o)) {
            z.putNextEntry(new ZipEntry("org/handsim/Dummy.class"));
            z.write(new byte[] {1, 2, 3});
            for (Map.Entry<String, String> e : files.entrySet()) {
                z.putNextEntry(new ZipEntry(Home.JAR_FOLDER + e.getKey()));
                z.write(e.getValue().getBytes(StandardCharsets.UTF_8));
            }
        }
        return jar;
    }

    static void assertHolds(Path home) throws Exception {
        for (Map.Entry<String, String> e : FILES.entrySet()) assertEquals(e.getValue(), Files.readString(home.resolve(e.getKey())), e.getKey());
    }

    @Test
    void unpacksOnceIntoThePrivateCacheAndReusesTheVerifiedCopy() throws Exception {
        Path t = Files.createTempDirectory("handsim-home-test");
        try {
            Path jar = jar(t, FILES);
            Path cache = t.resolve("cache").resolve("handsim");
            Path home = Home.unpack(jar, cache);
            assertTrue(home.startsWith(cache), home.toString());
            assertHolds(home);
            assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(cache)));
            assertEquals(List.of(home.getFileName().toString()), TestPaths.names(cache), "one copy, no unpacking folder left");
            Path before = home.resolve("vrml/hand/palm.wrl");
            long modified = Files.getLastModifiedTime(before).toMillis();
            Files.setLastModifiedTime(before, java.nio.file.attribute.FileTime.fromMillis(modified - 60_000));
            assertEquals(home, Home.unpack(jar, cache));
            assertEquals(modified - 60_000, Files.getLastModifiedTime(before).toMillis(), "a verified copy is used as it is, not unpacked again");
        } finally {
            Folders.deleteTree(t);
        }
    }

    /** The old location (a predictable name in the temporary folder, trusted on a marker) is never read. */
    @Test
    void aFolderPlantedWhereOldVersionsLookedIsIgnored() throws Exception {
        Path t = Files.createTempDirectory("handsim-home-test");
        try {
            Path jar = jar(t, FILES);
            Path planted = Path.of(System.getProperty("java.io.tmpdir"),
                "handsim-home-" + Files.size(jar) + "-" + Files.getLastModifiedTime(jar).toMillis());
            Files.createDirectories(planted.resolve("scenarios"));
            Files.createDirectories(planted.resolve("vrml/hand"));
            Files.writeString(planted.resolve(".complete"), "");
            Files.writeString(planted.resolve("scenarios/paper-breakaway.json"), "{\"name\": \"evil\", \"object\": {\"file\": \"/etc/shadow\"}}");
            try {
                Path home = Home.unpack(jar, t.resolve("cache/handsim"));
                assertFalse(home.startsWith(planted), home.toString());
                assertHolds(home);
            } finally {
                Folders.deleteTree(planted);
            }
        } finally {
            Folders.deleteTree(t);
        }
    }

    /** A copy whose file was changed, added to, or replaced by a link fails the check and is replaced by the jar's. */
    @Test
    void aChangedCopyIsReplacedByTheJarsFiles() throws Exception {
        Path t = Files.createTempDirectory("handsim-home-test");
        try {
            Path jar = jar(t, FILES);
            Path cache = t.resolve("cache/handsim");
            Path home = Home.unpack(jar, cache);
            Path scenario = home.resolve("scenarios/paper-breakaway.json");
            Files.writeString(scenario, "{\"name\": \"changed\", \"object\": {\"file\": \"/etc/shadow\"}}");
            assertEquals(home, Home.unpack(jar, cache));
            assertHolds(home);
            Files.writeString(home.resolve("scenarios/extra.json"), "{}");
            assertEquals(home, Home.unpack(jar, cache));
            assertFalse(Files.exists(home.resolve("scenarios/extra.json")), "a file the jar does not have fails the check");
            Files.delete(scenario);
            Files.createSymbolicLink(scenario, t.resolve("elsewhere.json"));
            Files.writeString(t.resolve("elsewhere.json"), FILES.get("scenarios/paper-breakaway.json"));
            assertEquals(home, Home.unpack(jar, cache));
            assertFalse(Files.isSymbolicLink(scenario), "a link (even to the right bytes) fails the check");
            assertHolds(home);
            assertEquals(List.of(home.getFileName().toString()), TestPaths.names(cache), "the damaged copies are gone");
        } finally {
            Folders.deleteTree(t);
        }
    }

    /** A jar with other models gets its own copy (named by the digest of its files). */
    @Test
    void anotherJarGetsAnotherCopy() throws Exception {
        Path t = Files.createTempDirectory("handsim-home-test");
        try {
            Path cache = t.resolve("cache/handsim");
            Path a = Home.unpack(jar(Files.createDirectories(t.resolve("a")), FILES), cache);
            Map<String, String> other = new java.util.HashMap<>(FILES);
            other.put("vrml/objects/cube.wrl", "#VRML V2.0 utf8\n# another cube\n");
            Path b = Home.unpack(jar(Files.createDirectories(t.resolve("b")), other), cache);
            assertNotEquals(a, b);
            assertEquals("#VRML V2.0 utf8\n# another cube\n", Files.readString(b.resolve("vrml/objects/cube.wrl")));
            assertHolds(a);
        } finally {
            Folders.deleteTree(t);
        }
    }

    /** A cache folder others can write is not trusted: the models go to a fresh private temporary folder instead. */
    @Test
    void aCacheOthersCanWriteIsNotUsed() throws Exception {
        Path t = Files.createTempDirectory("handsim-home-test");
        try {
            Path cache = Files.createDirectories(t.resolve("cache/handsim"));
            Files.setPosixFilePermissions(cache, PosixFilePermissions.fromString("rwxrwxrwx"));
            Path home = Home.unpack(jar(t, FILES), cache);
            assertFalse(home.startsWith(cache), home.toString());
            assertHolds(home);
            assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(home)));
            assertEquals(List.of(), TestPaths.names(cache), "nothing left in the untrusted folder");
            Path fresh = Home.unpack(jar(t, FILES), cache);
            assertNotEquals(home, fresh, "a fresh temporary folder each time");
            Folders.deleteTree(home);
            Folders.deleteTree(fresh);
        } finally {
            Folders.deleteTree(t);
        }
    }

    /** Eight first runs at once: one copy, every run gets it, no unpacking folder is left behind. */
    @Test
    void concurrentFirstRunsLeaveOneCopyAndNothingElse() throws Exception {
        Path t = Files.createTempDirectory("handsim-home-test");
        ExecutorService pool = Executors.newFixedThreadPool(8);
        try {
            Path jar = jar(t, FILES);
            Path cache = t.resolve("cache/handsim");
            CountDownLatch go = new CountDownLatch(1);
            List<Future<Path>> runs = new ArrayList<>();
            for (int i = 0; i < 8; i++) {
                Callable<Path> c = () -> {
                    go.await();
                    return Home.unpack(jar, cache);
                };
                runs.add(pool.submit(c));
            }
            go.countDown();
            Set<Path> homes = new HashSet<>();
            for (Future<Path> f : runs) homes.add(f.get());
            assertEquals(1, homes.size(), homes.toString());
            Path home = homes.iterator().next();
            assertTrue(home.startsWith(cache));
            assertHolds(home);
            assertEquals(List.of(home.getFileName().toString()), TestPaths.names(cache));
        } finally {
            pool.shutdownNow();
            Folders.deleteTree(t);
        }
    }
}
