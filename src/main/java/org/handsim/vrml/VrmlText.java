package org.handsim.vrml;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.GZIPInputStream;
import org.handsim.mesh.MeshLimits;
import org.handsim.files.InputFile;

/**
 * The bytes of one VRML file, with its name for messages, and the mapping from byte offsets to
 * line and column used by every error and warning.
 *
 * <p>Reading a file: the first two bytes decide whether it is gzip (0x1f 0x8b, whatever the
 * file's name, as VRML browsers do; several corpus files are gzip streams named {@code .wrl});
 * the decompressed size is capped so that a small "gzip bomb" cannot exhaust memory. Then the
 * header is checked: the file must begin with {@code #VRML V2.0 utf8}; a VRML 1.0 file, an
 * Open Inventor file or a file with any other first line is refused with an error that says
 * exactly which it is.
 *
 * <p>Offsets are kept everywhere instead of line numbers: the lexer never counts lines on its
 * fast path. The first time a position is needed, one pass builds the table of line starts;
 * each later lookup is a binary search.
 */
final class VrmlText {
    /** The header every VRML97 file starts with (ISO/IEC 14772-1, 4.2.2). */
    static final String HEADER = "#VRML V2.0 utf8";
    /** Largest decompressed/total size accepted (bytes): {@link MeshLimits#MAX_FILE_BYTES}. */
    static final long MAX_BYTES = MeshLimits.MAX_FILE_BYTES;

    final String name;
    /** The file's real path (null when read from a Reader or bytes). */
    Path path;
    final byte[] buf;
    final int length;
    private int[] lineStarts;

    VrmlText(String name, byte[] buf) {
        this.name = name;
        this.buf = buf;
        this.length = buf.length;
    }

    /** Reads a file (gzip detected by content) without checking the header. */
    static VrmlText read(String name, Path file) throws IOException {
        byte[] raw;
        try {
            raw = InputFile.readBytes(file, MAX_BYTES, MeshLimits.FILE_LIMIT);
        } catch (InputFile.InputFileException e) {
            String m = e.getMessage();
            // the message starts with the path: name the file as the caller did
            throw new VrmlParseException(name, 1, 1, m.startsWith(file.toString() + ": ") ? m.substring(file.toString().length() + 2) : m);
        }
        VrmlText t = fromBytes(name, raw);
        t.path = file;
        return t;
    }

    /** Wraps the bytes of {@code file}, read by the caller, as {@link #read} would have read them. */
    static VrmlText fromBytes(String name, byte[] raw, Path file) throws IOException {
        VrmlText t = fromBytes(name, raw);
        t.path = file;
        return t;
    }

    /** Wraps bytes, decompressing them first if they are a gzip stream. */
    static VrmlText fromBytes(String name, byte[] raw) throws IOException {
        if (raw.length >= 2 && (raw[0] & 0xff) == 0x1f && (raw[1] & 0xff) == 0x8b) {
            byte[] plain = gunzip(name, raw);
            return new VrmlText(name, plain);
        }
        return new VrmlText(name, raw);
    }

    /**
     * Decompresses in two streaming passes so that memory never exceeds the result: the first
     * counts the expanded bytes through a fixed 64 KiB buffer and refuses the stream as soon as
     * the count passes {@link #MAX_BYTES} (a gzip bomb costs its compressed size and one
     * buffer, never its expansion); the second fills an array of exactly the counted size.
     */
    private static byte[] gunzip(String name, byte[] raw) {
        byte[] chunk = new byte[1 << 16];
        long total = 0;
        try (InputStream in = new GZIPInputStream(new java.io.ByteArrayInputStream(raw), 1 << 16)) {
            int n;
            while ((n = in.read(chunk)) > 0) {
                total += n;
                if (total > MAX_BYTES) {
                    throw new VrmlParseException(name, 1, 1, "gzip stream expands to more than " + MAX_BYTES + " bytes (" + MeshLimits.FILE_LIMIT + "); refused");
                }
            }
        } catch (IOException e) {
            throw notGzip(name, e);
        }
        byte[] plain = new byte[(int) total];
        try (InputStream in = new GZIPInputStream(new java.io.ByteArrayInputStream(raw), 1 << 16)) {
            int off = 0;
            while (off < plain.length) {
                int n = in.read(plain, off, plain.length - off);
                if (n < 0) break;
                off += n;
            }
        } catch (IOException e) {
            throw notGzip(name, e);
        }
        return plain;
    }

    private static VrmlParseException notGzip(String name, IOException e) {
        return new VrmlParseException(name, 1, 1, "file starts with the gzip signature (1f 8b) but cannot be decompressed: "
            + e.getMessage());
    }

    /**
     * Checks the first line. Accepts {@code #VRML V2.0 utf8} followed by a space, a tab or the
     * end of the line (Cosmo Worlds writes a comment after the header); refuses everything
     * else with the reason.
     *
     * @return the offset just after the header line
     */
    int checkHeader() {
        int eol = 0;
        while (eol < length && buf[eol] != '\n' && buf[eol] != '\r') eol++;
        String first = new String(buf, 0, Math.min(eol, 200), StandardCharsets.ISO_8859_1);
        if (first.startsWith(HEADER)) {
            if (first.length() == HEADER.length() || first.charAt(HEADER.length()) == ' ' || first.charAt(HEADER.length()) == '\t') {
                return eol;
            }
        }
        String why;
        if (length == 0) {
            why = "empty file: a VRML97 file must start with the header '" + HEADER + "'";
        } else if (first.startsWith("#VRML V1.0")) {
            why = "VRML 1.0 file ('" + clip(first) + "'): VRML 1.0 is not supported, only VRML97 ('" + HEADER + "')";
        } else if (first.startsWith("#Inventor")) {
            why = "Open Inventor file ('" + clip(first) + "'): not supported, only VRML97 ('" + HEADER + "')";
        } else if (first.startsWith("#X3D") || first.startsWith("<?xml")) {
            why = "X3D file ('" + clip(first) + "'): not supported, only VRML97 ('" + HEADER + "')";
        } else if (first.startsWith("#VRML V2.0")) {
            why = "unsupported VRML97 encoding in header '" + clip(first) + "': only '" + HEADER + "' is supported";
        } else if (first.startsWith("#VRML")) {
            why = "unsupported VRML version in header '" + clip(first) + "': only VRML97 ('" + HEADER + "') is supported";
        } else if (looksBinary()) {
            why = "binary data, not a VRML97 file: missing the header '" + HEADER + "'";
        } else {
            // not a VRML file at all: nothing of its content is quoted (it may be any file, /etc/shadow)
            why = "not a VRML97 file: the first line is not the header '" + HEADER + "'";
        }
        throw new VrmlParseException(name, 1, 1, why);
    }

    private boolean looksBinary() {
        int n = Math.min(length, 512);
        for (int i = 0; i < n; i++) {
            int b = buf[i] & 0xff;
            if (b < 0x20 && b != '\n' && b != '\r' && b != '\t') return true;
        }
        return false;
    }

    private static String clip(String s) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < s.length() && sb.length() < 60; i++) {
            char c = s.charAt(i);
            sb.append(c < 0x20 || c >= 0x7f ? '?' : c);
        }
        if (s.length() > 60) sb.append("...");
        return sb.toString();
    }

    private void index() {
        if (lineStarts != null) return;
        int[] starts = new int[64];
        int n = 0;
        starts[n++] = 0;
        for (int i = 0; i < length; i++) {
            if (buf[i] == '\n') {
                if (n == starts.length) starts = Arrays.copyOf(starts, n * 2);
                starts[n++] = i + 1;
            }
        }
        lineStarts = Arrays.copyOf(starts, n);
    }

    /** 1-based line of a byte offset. */
    int line(int offset) {
        index();
        int i = Arrays.binarySearch(lineStarts, Math.max(0, Math.min(offset, length)));
        return (i >= 0 ? i : -i - 2) + 1;
    }

    /** 1-based column (in characters: UTF-8 continuation bytes are not counted) of a byte offset. */
    int column(int offset) {
        offset = Math.max(0, Math.min(offset, length));
        int start = lineStarts()[line(offset) - 1];
        int col = 1;
        for (int i = start; i < offset; i++) {
            if ((buf[i] & 0xc0) != 0x80) col++;
        }
        return col;
    }

    private int[] lineStarts() {
        index();
        return lineStarts;
    }

    /** An error at a byte offset. */
    VrmlParseException error(int offset, String message) {
        return new VrmlParseException(name, line(offset), column(offset), message);
    }

    /** A warning line {@code FILE:LINE:COL: warning: message}. */
    String warning(int offset, String message) {
        return name + ":" + line(offset) + ":" + column(offset) + ": warning: " + message;
    }
}
