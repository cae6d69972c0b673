package org.handsim.files;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFileAttributeView;
import java.util.concurrent.atomic.AtomicLong;
import org.handsim.process.ExitCleanup;

/**
 * Output that appears under its final name only when complete: bytes go to a temporary file
 * {@code .NAME.PID-N.partial} beside the target and are renamed over it by {@link #commit()}.
 * Closing without commit deletes the temporary file, so a run that fails leaves nothing that
 * looks finished; so does SIGINT or SIGTERM ({@link ExitCleanup}); what SIGKILL leaves is removed
 * by the next writer of the same name (its process id names a process that is gone).
 *
 * <p>Only a regular file (or a new name) is ever replaced. The rules, for the path as given:
 * <ul>
 *   <li>a symbolic link to a regular file: the file it leads to is replaced (the link stays);
 *       a dangling link: its target is created;</li>
 *   <li>an existing device, FIFO or socket ({@code /dev/null}, {@code /dev/stdout} on a pipe):
 *       written in place — opened and written, never renamed over or deleted;</li>
 *   <li>a folder: refused.</li>
 * </ul>
 * A replaced file keeps its permissions. Use in try-with-resources and call {@code commit()} as
 * the last statement.
 */
public final class AtomicFile implements AutoCloseable {
    private static final AtomicLong SERIAL = new AtomicLong();
    private static final long PID = ProcessHandle.current().pid();
    private static final String PARTIAL = ".partial";

    private final Path target;
    private final Path temp;          // null: written in place
    private final OutputStream out;
    private final Runnable cleanup;
    private Writer writer;
    private boolean committed;

    public AtomicFile(Path target) throws IOException {
        Path t = whereBytesGo(target);
        this.target = t;
        if (Files.isDirectory(t)) throw new IOException(target + " is a folder, not a file");
        if (Files.exists(t) && !Files.isRegularFile(t)) {   // a device, FIFO or socket: never ours to replace
            this.temp = null;
            this.cleanup = null;
            this.out = Files.newOutputStream(t, StandardOpenOption.WRITE);
            return;
        }
        if (ExitCleanup.stopping()) throw new IOException("not writing " + target + ": the program is being stopped");
        Path dir = t.toAbsolutePath().getParent();
        if (dir != null) Files.createDirectories(dir);
        if (t.getFileName().toString().getBytes(StandardCharsets.UTF_8).length > 255) {   // the rename at the end would fail: say so first
            throw new java.nio.file.FileSystemException(t.toString(), null, "File name too long");
        }
        String name = stem(t.getFileName().toString());
        removeDeadPartials(dir == null ? Path.of(".") : dir, name);
        this.temp = (dir == null ? Path.of(".") : dir).resolve("." + name + "." + PID + "-" + SERIAL.incrementAndGet() + PARTIAL);
        this.out = Files.newOutputStream(temp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        Path tmp = temp;
        this.cleanup = () -> {
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException e) {
                // best effort at exit
            }
        };
        ExitCleanup.register(cleanup);
    }

    /**
     * The path the bytes are written under: an existing regular file reached through links is
     * replaced where it really is; a dangling link is followed to the name it points at; any
     * other path is used as given.
     */
    static Path whereBytesGo(Path target) throws IOException {
        if (Files.isRegularFile(target) && Files.isSymbolicLink(target)) return target.toRealPath();
        Path p = target;
        for (int hops = 0; hops < 40 && !Files.exists(p) && Files.isSymbolicLink(p); hops++) {
            Path to = Files.readSymbolicLink(p);
            Path parent = p.toAbsolutePath().getParent();
            p = parent == null ? to : parent.resolve(to);
        }
        return p;
    }

    /**
     * The part of {@code name} the temporary file's name keeps: all of it, or as many of its first
     * characters as leave room for the dot, the process, the serial and ".partial" within the
     * 255 bytes a name may have (a target name near that length must not fail for its temporary
     * file alone).
     */
    static String stem(String name) {
        int room = 255 - 1 - 1 - 20 - 1 - 19 - PARTIAL.length();
        if (name.getBytes(StandardCharsets.UTF_8).length <= room) return name;
        int end = 0, bytes = 0;
        while (end < name.length()) {
            int cp = name.codePointAt(end);
            int b = new String(Character.toChars(cp)).getBytes(StandardCharsets.UTF_8).length;
            if (bytes + b > room) break;
            bytes += b;
            end += Character.charCount(cp);
        }
        return name.substring(0, end);
    }

    /** Removes {@code .NAME.PID-N.partial} files in {@code dir} whose process is gone (left by SIGKILL). */
    private static void removeDeadPartials(Path dir, String name) {
        String prefix = "." + name + ".";
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir, p -> {
            String n = p.getFileName().toString();
            return n.startsWith(prefix) && n.endsWith(PARTIAL);
        })) {
            for (Path p : s) {
                String mid = p.getFileName().toString().substring(prefix.length());
                int dash = mid.indexOf('-');
                if (dash <= 0) continue;
                try {
                    long pid = Long.parseLong(mid.substring(0, dash));
                    if (pid != PID && ProcessHandle.of(pid).isEmpty() && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) Files.deleteIfExists(p);
                } catch (NumberFormatException | IOException e) {
                    // not one of ours, or already gone
                }
            }
        } catch (IOException | RuntimeException e) {
            // an unreadable folder: the write itself will say what is wrong
        }
    }

    /** The raw stream (do not mix with {@link #writer()}). */
    public OutputStream stream() { return out; }

    /** A buffered UTF-8 writer over the temporary file. */
    public Writer writer() {
        if (writer == null) writer = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        return writer;
    }

    /** Whether the target is a device, FIFO or socket written in place (nothing is renamed). */
    public boolean inPlace() { return temp == null; }

    /** Flushes, closes and renames the temporary file onto the target. */
    public void commit() throws IOException {
        if (writer != null) writer.close(); else out.close();
        if (temp != null) {
            if (Files.exists(target, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(target, LinkOption.NOFOLLOW_LINKS)) {
                throw new IOException(target + " is no longer a regular file (a folder, device or link appeared): not replaced");
            }
            keepPermissions(target, temp);
            try {
                Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            ExitCleanup.unregister(cleanup);
        }
        committed = true;
    }

    /** Gives the new file the permissions (and, where allowed, the owner) of the file it replaces. */
    private static void keepPermissions(Path old, Path fresh) {
        try {
            PosixFileAttributes a = Files.readAttributes(old, PosixFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
            PosixFileAttributeView v = Files.getFileAttributeView(fresh, PosixFileAttributeView.class);
            v.setPermissions(a.permissions());
            if (!a.owner().equals(Files.getOwner(fresh))) v.setOwner(a.owner());
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            // no old file, no POSIX attributes, or not allowed: the new file keeps the defaults
        }
    }

    @Override
    public void close() throws IOException {
        if (committed) return;
        try {
            if (writer != null) writer.close(); else out.close();
        } finally {
            if (temp != null) {
                Files.deleteIfExists(temp);
                ExitCleanup.unregister(cleanup);
            }
        }
    }

    /** Writes a whole text file atomically. */
    public static void writeString(Path target, String text) throws IOException {
        try (AtomicFile f = new AtomicFile(target)) {
            f.writer().write(text);
            f.commit();
        }
    }
}
