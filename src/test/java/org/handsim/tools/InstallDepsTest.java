package org.handsim.tools;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * {@code tools/install-deps} waits for the package lock another apt or dpkg holds (here: a lock
 * this JVM takes on a stand-in file, HANDSIM_APT_LOCKS), says so in one line, and goes on when
 * it is released; past its limit it stops with one line.
 */
class InstallDepsTest {
    private record Result(int code, String err, double seconds) {}

    private static Result waitLock(Path lockFile, int limitS) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(TestPaths.root().resolve("tools/install-deps").toString(), "--wait-lock-only");
        pb.environment().put("HANDSIM_APT_LOCKS", lockFile.toString());
        pb.environment().put("HANDSIM_APT_WAIT", String.valueOf(limitS));
        Path err = Files.createTempFile("install-deps", ".err");
        pb.redirectError(err.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD);
        long t0 = System.nanoTime();
        Process p = pb.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "install-deps did not finish");
        Result r = new Result(p.exitValue(), Files.readString(err).trim(), (System.nanoTime() - t0) / 1e9);
        Files.delete(err);
        return r;
    }

    @Test
    void waitsForAHeldPackageLockSayingSoOnce() throws Exception {
        Path dir = Files.createTempDirectory("handsim-lock");
        Path lock = dir.resolve("lock-frontend");
        try (FileChannel ch = FileChannel.open(lock, StandardOpenOption.CREATE, StandardOpenOption.WRITE)) {
            // free: no wait, nothing said
            Result free = waitLock(lock, 300);
            assertEquals(0, free.code(), free.err());
            assertEquals("", free.err());
            // held past the limit: one line saying it waits, one saying it gave up, exit 1
            try (FileLock held = ch.lock()) {
                Result stuck = waitLock(lock, 1);
                assertEquals(1, stuck.code(), stuck.err());
                String[] lines = stuck.err().split("\n");
                assertEquals(2, lines.length, stuck.err());
                assertTrue(lines[0].startsWith("handsim: another package manager (") && lines[0].endsWith("waiting for it, up to 1 s"), lines[0]);
                assertTrue(lines[1].startsWith("handsim: the apt/dpkg lock is still held after 1 s"), lines[1]);
            }
            // held for 1 s, then released: it waits, says so in one line, and goes on
            FileLock held = ch.lock();
            Thread release = new Thread(() -> {
                try {
                    Thread.sleep(1000);
                    held.release();
                } catch (InterruptedException | IOException e) {
                    throw new IllegalStateException(e);
                }
            });
            release.start();
            Result waited = waitLock(lock, 300);
            release.join();
            assertEquals(0, waited.code(), waited.err());
            assertEquals(1, waited.err().split("\n").length, waited.err());
            assertTrue(waited.err().endsWith("holds the apt/dpkg lock: waiting for it, up to 5 min"), waited.err());
            assertTrue(waited.seconds() >= 0.5, "it waited: " + waited.seconds() + " s");
        } finally {
            VrmlTesting.deleteTree(dir);
        }
    }
}
