package org.handsim.util;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Output that appears under its final name only when complete: bytes go to
 * {@code .name.partial} beside the target and are renamed over it by {@link #commit()}.
 * Closing without commit deletes the temporary file, so a run that fails leaves nothing that
 * looks finished. Use in try-with-resources and call {@code commit()} as the last statement.
 */
public final class AtomicFile implements AutoCloseable {
    private final Path target;
    private final Path temp;
    private final OutputStream out;
    private Writer writer;
    private boolean committed;

    public AtomicFile(Path target) throws IOException {
        this.target = target;
        Path dir = target.toAbsolutePath().getParent();
        if (dir != null) Files.createDirectories(dir);
        this.temp = (dir == null ? Path.of(".") : dir).resolve("." + target.getFileName() + ".partial");
        this.out = Files.newOutputStream(temp);
    }

    /** The raw stream (do not mix with {@link #writer()}). */
    public OutputStream stream() { return out; }

    /** A buffered UTF-8 writer over the temporary file. */
    public Writer writer() {
        if (writer == null) writer = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        return writer;
    }

    /** Flushes, closes and renames the temporary file onto the target. */
    public void commit() throws IOException {
        if (writer != null) writer.close(); else out.close();
        try {
            Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (java.nio.file.AtomicMoveNotSupportedException e) {
            Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
        }
        committed = true;
    }

    @Override
    public void close() throws IOException {
        if (committed) return;
        try {
            if (writer != null) writer.close(); else out.close();
        } finally {
            Files.deleteIfExists(temp);
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
