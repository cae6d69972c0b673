package org.handsim.server;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import org.handsim.files.Folders;

/**
 * The files of the servers in their folder — per server {@code KEY.lock}, {@code KEY.sock},
 * {@code KEY.log} and the folder {@code KEY.warm-up} — and the rule that keeps them from piling up:
 * a server removes its own when it ends, and whatever a killed one left (its lock no longer held)
 * is removed by the next server that starts and by {@code handsim server status|stop}.
 */
final class ServerFiles {
    private ServerFiles() {}

    /** Files younger than this are left alone: a server starting now has made its log but not yet taken its lock. */
    static final long YOUNG_MS = 30_000;

    private static final String RELEASED = "released\n";

    /**
     * A server's lock: a POSIX record lock on {@code KEY.lock}, held for the server's whole life.
     * Its holder marks it released before deleting it, so that whoever then wins the lock of the
     * deleted file knows to try the file at the path again (as {@code OutputSet}'s lock does).
     */
    static final class Lock {
        private final Path file;
        private final FileChannel ch;
        private final FileLock lock;

        private Lock(Path file, FileChannel ch, FileLock lock) {
            this.file = file;
            this.ch = ch;
            this.lock = lock;
        }

        /** The lock of {@code file} (made if missing), or null when another holds it. */
        static Lock take(Path file) throws IOException {
            for (int attempt = 0; attempt < 20; attempt++) {
                FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.READ, StandardOpenOption.WRITE,
                    LinkOption.NOFOLLOW_LINKS);
                FileLock l;
                try {
                    l = ch.tryLock();
                } catch (OverlappingFileLockException e) {
                    l = null;   // this JVM holds it
                }
                if (l == null) {
                    ch.close();
                    return null;
                }
                ByteBuffer b = ByteBuffer.allocate(RELEASED.length());
                ch.read(b, 0);
                if (new String(b.array(), 0, b.position(), StandardCharsets.US_ASCII).equals(RELEASED)) {
                    l.release();   // a file its holder deleted: the one at the path now, if any, is the lock
                    ch.close();
                    continue;
                }
                ch.truncate(0);
                ch.write(ByteBuffer.wrap(("pid " + ProcessHandle.current().pid() + "\n").getBytes(StandardCharsets.US_ASCII)), 0);
                return new Lock(file, ch, l);
            }
            return null;
        }

        /** Marks the file released, deletes it, then lets the lock go. */
        void releaseAndDelete() {
            try {
                ch.truncate(0);
                ch.write(ByteBuffer.wrap(RELEASED.getBytes(StandardCharsets.US_ASCII)), 0);
                Files.deleteIfExists(file);
            } catch (IOException e) {
                // left for the next server: its lock is free
            }
            try {
                lock.release();
                ch.close();
            } catch (IOException e) {
                // closing the channel lets it go in any case
            }
        }
    }

    /** Deletes a file or a folder with everything in it; nothing if it cannot. */
    static void deleteQuietly(Path p) {
        try {
            if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) Folders.deleteTree(p); else Files.deleteIfExists(p);
        } catch (IOException | RuntimeException e) {
            // removed as stale later
        }
    }

    /**
     * Removes what servers that are gone left in {@code dir}: for each key whose lock nobody holds
     * and whose files are older than {@link #YOUNG_MS}, its socket, log, warm-up folder and lock.
     */
    static void removeStale(Path dir) {
        Map<String, Set<Path>> byKey = new TreeMap<>();
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir)) {
            for (Path p : s) {
                String n = p.getFileName().toString();
                int dot = n.indexOf('.');
                if (dot != 16 || !n.substring(0, 16).matches("[0-9a-f]{16}")) continue;
                String kind = n.substring(17);
                if (!kind.equals("sock") && !kind.equals("log") && !kind.equals("lock") && !kind.equals("warm-up")) continue;
                byKey.computeIfAbsent(n.substring(0, 16), k -> new TreeSet<>()).add(p);
            }
        } catch (IOException | RuntimeException e) {
            return;
        }
        long now = System.currentTimeMillis();
        for (Map.Entry<String, Set<Path>> e : byKey.entrySet()) {
            boolean young = false;
            for (Path p : e.getValue()) {
                try {
                    young |= now - Files.getLastModifiedTime(p, LinkOption.NOFOLLOW_LINKS).toMillis() < YOUNG_MS;
                } catch (IOException ex) {
                    // gone meanwhile
                }
            }
            if (young) continue;
            Lock lock;
            try {
                lock = Lock.take(Client.lockFile(dir, e.getKey()));
            } catch (IOException ex) {
                continue;
            }
            if (lock == null) continue;   // a live server's
            for (Path p : e.getValue()) if (!p.equals(Client.lockFile(dir, e.getKey()))) deleteQuietly(p);
            lock.releaseAndDelete();
        }
    }

    /** Removes {@code dir} if it is a short folder of {@link Client#folder()} (under /tmp) and empty. */
    static void removeIfEmptyShort(Path dir) {
        if (dir.getParent() == null || !dir.getParent().toString().equals("/tmp") || !dir.getFileName().toString().startsWith("handsim-")) return;
        try {
            Files.deleteIfExists(dir);
        } catch (IOException e) {
            // not empty: another server's files are there
        }
    }

    /** This process's resident memory in bytes (Linux: VmRSS of /proc/self/status), -1 if unknown. */
    static long residentBytes() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/self/status"), StandardCharsets.ISO_8859_1)) {
                if (l.startsWith("VmRSS:")) return Long.parseLong(l.replaceAll("[^0-9]", "")) * 1024;
            }
        } catch (IOException | RuntimeException e) {
            return -1;
        }
        return -1;
    }
}
