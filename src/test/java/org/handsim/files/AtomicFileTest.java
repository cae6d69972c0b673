package org.handsim.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.junit.jupiter.api.Test;

/**
 * AtomicFile replaces only regular files: a character device or FIFO is written in place and
 * stays what it was (before the fix, writing to /dev/null as root replaced it with a 357-byte
 * regular file for the whole machine); a link to a file is followed and stays a link; a folder is
 * refused; a replaced file keeps its permissions; two writers of one name never collide on a
 * temporary name; SIGKILL's leftovers are removed by the next writer.
 */
class AtomicFileTest {
    @Test
    void aCharacterDeviceIsWrittenInPlaceAndStaysADevice() throws Exception {
        Path dir = Files.createTempDirectory("handsim-atomic");
        try {
            Path nul = DeviceNodes.charDevice(dir, "null", 1, 3), full = DeviceNodes.charDevice(dir, "full", 1, 7);
            assumeTrue(nul != null && full != null, "mknod needs root (CI runs as root)");
            try (AtomicFile f = new AtomicFile(nul)) {
                assertTrue(f.inPlace());
                f.writer().write("x".repeat(100_000));
                f.commit();
            }
            assertTrue(DeviceNodes.isCharDevice(nul), "still a character device");
            IOException e = assertThrows(IOException.class, () -> AtomicFile.writeString(full, "x".repeat(100_000)));
            assertTrue(e.getMessage().contains("No space left on device"), e.getMessage());
            assertTrue(DeviceNodes.isCharDevice(full));
            assertEquals(List.of("full", "null"), TestPaths.names(dir), "no temporary file beside them");
            // proven on our own nodes: now the machine's, which must stay devices too
            try {
                AtomicFile.writeString(Path.of("/dev/null"), "written to /dev/null by AtomicFileTest\n");
                assertThrows(IOException.class, () -> AtomicFile.writeString(Path.of("/dev/full"), "x".repeat(100_000)));
            } finally {
                assertTrue(DeviceNodes.restoreIfBroken("/dev/null", 3), "/dev/null was replaced (restored)");
                assertTrue(DeviceNodes.restoreIfBroken("/dev/full", 7), "/dev/full was replaced (restored)");
            }
        } finally {
            Folders.deleteTree(dir);
        }
    }

    @Test
    void aFifoIsWrittenInPlace() throws Exception {
        Path dir = Files.createTempDirectory("handsim-atomic");
        try {
            Path fifo = DeviceNodes.fifo(dir, "pipe");
            assumeTrue(fifo != null, "mkfifo");
            CompletableFuture<String> read = CompletableFuture.supplyAsync(() -> {
                try {
                    return Files.readString(fifo);
                } catch (IOException e) {
                    return "failed: " + e;
                }
            });
            AtomicFile.writeString(fifo, "through the pipe\n");
            assertEquals("through the pipe\n", read.get(30, TimeUnit.SECONDS));
            assertTrue(DeviceNodes.isFifo(fifo));
            assertEquals(List.of("pipe"), TestPaths.names(dir));
        } finally {
            Folders.deleteTree(dir);
        }
    }

    @Test
    void aLinkIsFollowedAndAReplacedFileKeepsItsPermissions() throws Exception {
        Path dir = Files.createTempDirectory("handsim-atomic");
        try {
            Path real = dir.resolve("real.csv"), link = dir.resolve("link.csv");
            Files.writeString(real, "old\n");
            Files.setPosixFilePermissions(real, PosixFilePermissions.fromString("rw-------"));
            Files.createSymbolicLink(link, Path.of("real.csv"));
            AtomicFile.writeString(link, "new\n");
            assertTrue(Files.isSymbolicLink(link), "the link stays a link");
            assertEquals("new\n", Files.readString(real));
            assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
            Path dangling = dir.resolve("dangling.csv");
            Files.createSymbolicLink(dangling, Path.of("made.csv"));
            AtomicFile.writeString(dangling, "made\n");
            assertTrue(Files.isSymbolicLink(dangling));
            assertEquals("made\n", Files.readString(dir.resolve("made.csv")));
            assertEquals(List.of("dangling.csv", "link.csv", "made.csv", "real.csv"), TestPaths.names(dir));
        } finally {
            Folders.deleteTree(dir);
        }
    }

    @Test
    void aFolderIsRefusedAndLeftAsItWas() throws Exception {
        Path dir = Files.createTempDirectory("handsim-atomic");
        try {
            Path empty = Files.createDirectory(dir.resolve("empty"));
            IOException e = assertThrows(IOException.class, () -> AtomicFile.writeString(empty, "x"));
            assertTrue(e.getMessage().contains("is a folder"), e.getMessage());
            assertTrue(Files.isDirectory(empty), "an empty folder is not replaced by a file");
            assertEquals(List.of("empty"), TestPaths.names(dir));
        } finally {
            Folders.deleteTree(dir);
        }
    }

    /** Two writers of one name at once each write their own temporary file; the name ends up whole, one writer's. */
    @Test
    void twoWritersOfOneNameDoNotCollide() throws Exception {
        Path dir = Files.createTempDirectory("handsim-atomic");
        try {
            Path target = dir.resolve("trace.csv");
            CountDownLatch both = new CountDownLatch(2);
            List<CompletableFuture<Void>> writers = new ArrayList<>();
            for (String text : new String[] {"a", "b"}) {
                writers.add(CompletableFuture.runAsync(() -> {
                    try (AtomicFile f = new AtomicFile(target)) {
                        both.countDown();
                        both.await();
                        for (int i = 0; i < 10_000; i++) f.writer().write(text + i + "\n");
                        f.commit();
                    } catch (Exception e) {
                        throw new RuntimeException(e);
                    }
                }));
            }
            for (CompletableFuture<Void> w : writers) w.get(60, TimeUnit.SECONDS);
            List<String> lines = Files.readAllLines(target, StandardCharsets.UTF_8);
            assertEquals(10_000, lines.size());
            String who = lines.get(0).substring(0, 1);
            for (int i = 0; i < lines.size(); i++) assertEquals(who + i, lines.get(i), "one writer's whole file");
            assertEquals(List.of("trace.csv"), TestPaths.names(dir));
        } finally {
            Folders.deleteTree(dir);
        }
    }

    /** What SIGKILL left (a temporary name with the process id of a process that is gone) goes; a live process's stays. */
    @Test
    void theNextWriterRemovesTheTemporaryFileOfAKilledOne() throws Exception {
        Path dir = Files.createTempDirectory("handsim-atomic");
        try {
            long dead = 4_000_000;
            while (ProcessHandle.of(dead).isPresent()) dead++;
            Path killed = Files.writeString(dir.resolve(".out.csv." + dead + "-1.partial"), "half");
            Path live = Files.writeString(dir.resolve(".out.csv.1-1.partial"), "pid 1 is alive");
            Path other = Files.writeString(dir.resolve(".other.csv." + dead + "-1.partial"), "another name's");
            AtomicFile.writeString(dir.resolve("out.csv"), "whole\n");
            assertFalse(Files.exists(killed));
            assertTrue(Files.exists(live) && Files.exists(other));
            assertEquals("whole\n", Files.readString(dir.resolve("out.csv")));
        } finally {
            Folders.deleteTree(dir);
        }
    }
}
