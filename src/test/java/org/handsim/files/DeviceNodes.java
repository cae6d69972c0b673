package org.handsim.files;

import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Character devices of a test's own (mknod in its folder, as root in CI) and the check that a
 * path still is one: never test first against the machine's /dev/null, which every process
 * shares.
 */
public final class DeviceNodes {
    private DeviceNodes() {}

    /** {@code dir/name} as character device major:minor (1:3 null, 1:7 full); null when this user may not make one. */
    public static Path charDevice(Path dir, String name, int major, int minor) throws Exception {
        Path p = dir.resolve(name);
        Process mk = new ProcessBuilder("mknod", p.toString(), "c", Integer.toString(major), Integer.toString(minor))
            .redirectErrorStream(true).start();
        mk.getInputStream().readAllBytes();
        if (!mk.waitFor(30, TimeUnit.SECONDS) || mk.exitValue() != 0) return null;
        return isCharDevice(p) ? p : null;
    }

    /** Whether {@code p} itself (not a link to it) is a character device. */
    public static boolean isCharDevice(Path p) {
        try {
            int mode = (Integer) Files.getAttribute(p, "unix:mode", LinkOption.NOFOLLOW_LINKS);
            return (mode & 0170000) == 0020000;
        } catch (Exception e) {
            return false;
        }
    }

    /** Whether {@code p} is a FIFO. */
    public static boolean isFifo(Path p) {
        try {
            int mode = (Integer) Files.getAttribute(p, "unix:mode", LinkOption.NOFOLLOW_LINKS);
            return (mode & 0170000) == 0010000;
        } catch (Exception e) {
            return false;
        }
    }

    /** A FIFO {@code dir/name}; null when mkfifo is not available. */
    public static Path fifo(Path dir, String name) throws Exception {
        Path p = dir.resolve(name);
        Process mk = new ProcessBuilder("mkfifo", p.toString()).redirectErrorStream(true).start();
        mk.getInputStream().readAllBytes();
        if (!mk.waitFor(30, TimeUnit.SECONDS) || mk.exitValue() != 0) return null;
        return isFifo(p) ? p : null;
    }

    /**
     * Puts the machine's /dev/null or /dev/full back if a test (through a regression) replaced it
     * with a regular file, so one failing test does not break every process on the machine.
     * Returns whether it was intact.
     */
    public static boolean restoreIfBroken(String dev, int minor) throws Exception {
        Path p = Path.of(dev);
        if (isCharDevice(p)) return true;
        Files.deleteIfExists(p);
        new ProcessBuilder("mknod", "-m", "666", dev, "c", "1", Integer.toString(minor)).start().waitFor(30, TimeUnit.SECONDS);
        return false;
    }
}
