package org.handsim.files;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import org.handsim.text.SafeText;

/**
 * The one gate every input file passes before it is opened: scenarios, sweep files and their
 * bases, object and mesh files, plan targets, CSV inputs, window scripts and the window's
 * open/import.
 *
 * <p><b>Regular files only.</b> Opening a FIFO blocks until a writer comes, a character device
 * such as {@code /dev/zero} never ends, and a directory cannot be read; so a path that is not a
 * regular file (after following links) is refused <em>before</em> it is opened, with the words
 * "is not a regular file" and what it is: {@code (a directory)}, {@code (a FIFO)},
 * {@code (a character device)}, {@code (a block device)}, {@code (a socket)}.
 *
 * <p><b>Bounded.</b> {@link #readBytes} and {@link #readText} read at most a given number of
 * bytes; a larger file is refused by its size without reading it (and a file that grows while it
 * is read is refused once the limit is passed), so no input can exhaust memory by its length.
 *
 * <p><b>Text is UTF-8.</b> {@link #readText} drops one leading byte-order mark (U+FEFF, as
 * {@link CsvInput} does) and decodes strictly: a byte sequence that is not UTF-8 is refused with
 * the file, line and column and the byte's value and offset ({@link #decode}), never replaced
 * silently and never reported as a bare {@code MalformedInputException}.
 *
 * <p>Every refusal is an {@link InputFileException} whose message is one line starting with the
 * file; the commands exit with code 3 on it.
 */
public final class InputFile {
    /** Bytes of the UTF-8 byte-order mark. */
    private static final byte[] BOM = {(byte) 0xef, (byte) 0xbb, (byte) 0xbf};

    /** {@link #problem}'s words for a path where there is nothing. */
    public static final String NO_SUCH_FILE = "no such file";

    private InputFile() {}

    /**
     * Why {@code file} cannot be read as an input, or null when it is a readable regular file:
     * {@code no such file}, {@code is not a regular file (a FIFO)} (and the other kinds),
     * {@code cannot be read (permission denied)}. Never opens the file.
     */
    public static String problem(Path file) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(file, BasicFileAttributes.class);   // follows links
        } catch (NoSuchFileException e) {
            return NO_SUCH_FILE;
        } catch (AccessDeniedException e) {
            return "cannot be read (permission denied)";
        } catch (FileSystemException e) {
            return "cannot be read (" + (e.getReason() != null ? e.getReason() : e.getClass().getSimpleName()) + ")";
        } catch (IOException | SecurityException e) {
            return "cannot be read (" + e.getMessage() + ")";
        }
        if (!a.isRegularFile()) return "is not a regular file (" + kind(file, a) + ")";
        if (!Files.isReadable(file)) return "cannot be read (permission denied)";
        return null;
    }

    /** What a path that is not a regular file is: a directory, a FIFO, a device or a socket. */
    static String kind(Path file, BasicFileAttributes a) {
        if (a.isDirectory()) return "a directory";
        try {
            int type = ((Integer) Files.getAttribute(file, "unix:mode")) & 0170000;
            switch (type) {
                case 0010000: return "a FIFO";
                case 0020000: return "a character device";
                case 0060000: return "a block device";
                case 0140000: return "a socket";
                default: break;
            }
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException | SecurityException e) {
            // not a Unix file system: no finer name
        }
        return "a special file";
    }

    /**
     * Checks {@code file} is a readable regular file ({@link #problem}).
     *
     * @throws InputFileException {@code FILE: <problem>}
     */
    public static void require(Path file) {
        String p = problem(file);
        if (p != null) throw new InputFileException(file + ": " + p);
    }

    /**
     * The bytes of a regular file of at most {@code maxBytes} bytes.
     *
     * @param what names the limit's reason in the message, e.g. "the limit of scenario files"
     * @throws InputFileException not a readable regular file, larger than the limit, or a read error
     */
    public static byte[] readBytes(Path file, long maxBytes, String what) {
        require(file);
        try {
            long size = Files.size(file);
            if (size > maxBytes) throw tooLarge(file, size, maxBytes, what);
            try (InputStream in = Files.newInputStream(file)) {
                // a file may grow after its size was read: never read past the limit
                byte[] b = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
                if (b.length > maxBytes) throw tooLarge(file, b.length, maxBytes, what);
                return b;
            }
        } catch (IOException e) {
            throw new InputFileException(file + ": cannot be read (" + e.getMessage() + ")", e);
        }
    }

    /**
     * At most the first {@code maxBytes} bytes of a regular file (a sniff of its head: a colour, a
     * header), whatever its length.
     *
     * @throws InputFileException not a readable regular file, or a read error
     */
    public static byte[] head(Path file, int maxBytes) {
        require(file);
        try (InputStream in = Files.newInputStream(file)) {
            return in.readNBytes(maxBytes);
        } catch (IOException e) {
            throw new InputFileException(file + ": cannot be read (" + e.getMessage() + ")", e);
        }
    }

    private static InputFileException tooLarge(Path file, long size, long max, String what) {
        return new InputFileException(file + ": " + (size > max ? "is " + size + " bytes" : "is larger") + ", more than " + what
            + " (" + max + " bytes)");
    }

    /**
     * The text of a UTF-8 file of at most {@code maxBytes} bytes, without a leading byte-order
     * mark.
     *
     * @throws InputFileException as {@link #readBytes}, or for bytes that are not UTF-8
     *                            ({@code FILE:LINE:COL: ...})
     */
    public static String readText(Path file, long maxBytes, String what) {
        return decode(file.toString(), readBytes(file, maxBytes, what));
    }

    /**
     * Strict UTF-8 text of {@code bytes} without a leading byte-order mark.
     *
     * @param name names the source in the message
     * @throws InputFileException {@code NAME:LINE:COL: not UTF-8: byte 0xNN (offset K) ...} at the
     *                            first byte that is not part of a valid UTF-8 sequence
     */
    public static String decode(String name, byte[] bytes) {
        int start = startsWithBom(bytes) ? BOM.length : 0;
        CharsetDecoder dec = StandardCharsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, bytes.length - start);
        CharBuffer out = CharBuffer.allocate(bytes.length - start);
        CoderResult r = dec.decode(in, out, true);
        if (!r.isError()) r = dec.flush(out);
        if (r.isError()) throw notUtf8(name, bytes, in.position());
        out.flip();
        return out.toString();
    }

    /** True if the bytes start with the UTF-8 byte-order mark. */
    public static boolean startsWithBom(byte[] b) {
        return b.length >= 3 && b[0] == BOM[0] && b[1] == BOM[1] && b[2] == BOM[2];
    }

    /** The error for the byte at {@code offset}: line and column (characters, 1-based) and the byte. */
    static InputFileException notUtf8(String name, byte[] bytes, int offset) {
        int line = 1, lineStart = 0;
        for (int i = 0; i < offset; i++) {
            if (bytes[i] == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        int col = 1;
        for (int i = lineStart; i < offset; i++) if ((bytes[i] & 0xc0) != 0x80) col++;
        return new InputFileException(name + ":" + line + ":" + col + ": not UTF-8: byte 0x"
            + String.format(java.util.Locale.ROOT, "%02x", bytes[offset] & 0xff) + " at offset " + offset
            + " is not part of a UTF-8 character (save the file as UTF-8)");
    }

    /**
     * The lines of a UTF-8 text file read one at a time (for inputs of any length: bulk CSV).
     * The same rules as {@link #readText}: regular files only, one leading byte-order mark
     * dropped, strict UTF-8 ({@code FILE:LINE:COL} of the first bad byte); a line longer than
     * {@code maxLineBytes} is refused with its line number. Line ends: LF or CR LF.
     */
    public static final class Lines implements AutoCloseable {
        private final String name;
        private final InputStream in;
        private final int maxLineBytes;
        private final boolean strict;
        private final byte[] chunk = new byte[1 << 16];
        private int chunkPos, chunkEnd;
        private byte[] buf = new byte[256];
        private long offset;
        private int line;

        /** Opens {@code file} ({@link #require} first: a FIFO is refused, never opened). */
        public Lines(Path file, int maxLineBytes) {
            this(file, maxLineBytes, true);
        }

        /**
         * As {@link #Lines(Path, int)}; with {@code strict} false a byte that is not UTF-8 is kept
         * as the lone surrogate U+DC00 + byte ({@link SafeText#decodeUtf8}), which a message
         * quoting it shows as that byte, for formats whose text besides the numbers is free
         * (names and comments of an OBJ file).
         */
        public Lines(Path file, int maxLineBytes, boolean strict) {
            require(file);
            this.name = file.toString();
            this.maxLineBytes = maxLineBytes;
            this.strict = strict;
            try {
                this.in = Files.newInputStream(file);
            } catch (IOException e) {
                throw new InputFileException(file + ": cannot be read (" + e.getMessage() + ")", e);
            }
        }

        /**
         * The lines of bytes the caller read from {@code name} (through {@link #readBytes}), as
         * {@link #Lines(Path, int, boolean)} reads them from the file: one read of a file serves
         * both a digest of its bytes and its lines.
         */
        public Lines(String name, byte[] bytes, int maxLineBytes, boolean strict) {
            this.name = name;
            this.maxLineBytes = maxLineBytes;
            this.strict = strict;
            this.in = new java.io.ByteArrayInputStream(bytes);
        }

        /** The 1-based number of the line {@link #next} returned last. */
        public int line() { return line; }

        /**
         * The next line without its line end, or null at the end of the file.
         *
         * @throws InputFileException for a line that is too long or not UTF-8
         * @throws IOException        if reading fails
         */
        public String next() throws IOException {
            int n = 0;
            long lineOffset = offset;
            boolean any = false;
            while (true) {
                if (chunkPos == chunkEnd) {
                    chunkEnd = in.read(chunk);
                    chunkPos = 0;
                    if (chunkEnd <= 0) {
                        chunkEnd = 0;
                        break;
                    }
                }
                any = true;
                int i = chunkPos;
                while (i < chunkEnd && chunk[i] != '\n') i++;
                int len = i - chunkPos;
                if (n + len > maxLineBytes) {
                    throw new InputFileException(name + ":" + (line + 1) + ": line longer than " + maxLineBytes + " bytes");
                }
                if (n + len > buf.length) buf = java.util.Arrays.copyOf(buf, Math.max(n + len, Math.min(2 * buf.length, maxLineBytes)));
                System.arraycopy(chunk, chunkPos, buf, n, len);
                n += len;
                offset += len;
                chunkPos = i;
                if (i < chunkEnd) {      // the line end
                    chunkPos++;
                    offset++;
                    break;
                }
            }
            if (!any) return null;
            line++;
            if (n > 0 && buf[n - 1] == '\r') n--;
            int start = line == 1 && n >= 3 && startsWithBom(buf) ? BOM.length : 0;
            if (!strict) return SafeText.decodeUtf8(buf, start, n - start);
            CharsetDecoder dec = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
            ByteBuffer bb = ByteBuffer.wrap(buf, start, n - start);
            CharBuffer out = CharBuffer.allocate(n - start);
            CoderResult r = dec.decode(bb, out, true);
            if (r.isError()) {
                int at = bb.position();
                int col = 1;
                for (int i = start; i < at; i++) if ((buf[i] & 0xc0) != 0x80) col++;
                throw new InputFileException(name + ":" + line + ":" + col + ": not UTF-8: byte 0x"
                    + String.format(java.util.Locale.ROOT, "%02x", buf[at] & 0xff) + " at offset " + (lineOffset + at)
                    + " is not part of a UTF-8 character (save the file as UTF-8)");
            }
            out.flip();
            return out.toString();
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }

    /** A file that cannot be used as an input; the message is one line starting with the file. */
    public static final class InputFileException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public InputFileException(String message) {
            super(SafeText.line(message));
        }

        public InputFileException(String message, Throwable cause) {
            super(SafeText.line(message), cause);
        }
    }
}
