package org.handsim.files;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.handsim.text.Decimal;
import org.handsim.text.SafeText;

/**
 * Reads a plain comma-separated file (no quoting: our bulk inputs are numbers) with a required
 * exact header. Each row comes with its 1-based line number so errors can name it; blank
 * lines are skipped. Use as {@code while (in.next()) { in.number(2) ... }}. The file is read
 * through {@link InputFile.Lines}: a FIFO, directory or device is refused before it is opened,
 * a leading byte-order mark is dropped, and a byte that is not UTF-8 or a line longer than
 * {@link #MAX_LINE_BYTES} is an {@link InputFile.InputFileException} naming the line.
 */
public final class CsvInput implements AutoCloseable {
    /** Longest line accepted: a row of our inputs is a few hundred bytes. */
    public static final int MAX_LINE_BYTES = 1 << 16;

    private final Path file;
    private final InputFile.Lines reader;
    private final List<String> header;
    private String[] row;
    private int line;

    /**
     * Opens {@code file} and checks its first line equals {@code expectedHeader} (column names
     * separated by commas, spaces around them ignored).
     *
     * @throws CsvException naming the file and line
     * @throws InputFile.InputFileException if the file is not a readable regular file or not UTF-8
     */
    public CsvInput(Path file, String expectedHeader) throws IOException {
        this.file = file;
        this.reader = new InputFile.Lines(file, MAX_LINE_BYTES);
        String first = reader.next();
        line = 1;
        if (first == null) throw error("empty file, expected the header " + expectedHeader);
        this.header = Arrays.asList(split(first));
        List<String> want = Arrays.asList(split(expectedHeader));
        if (!header.equals(want)) throw error("header must be exactly '" + expectedHeader + "', got '" + SafeText.quote(first.trim()) + "'");
    }

    private static String[] split(String s) {
        String[] p = s.split(",", -1);
        for (int i = 0; i < p.length; i++) p[i] = p[i].trim();
        return p;
    }

    /** Advances to the next non-blank row; false at the end. */
    public boolean next() throws IOException {
        String s;
        do {
            s = reader.next();
            line++;
            if (s == null) return false;
        } while (s.isBlank());
        row = split(s);
        if (row.length != header.size()) {
            throw error("expected " + header.size() + " columns, got " + row.length);
        }
        return true;
    }

    /** The current row's 1-based line number. */
    public int line() { return line; }

    /** The raw text of column i of the current row. */
    public String text(int i) { return row[i]; }

    /** Column i of the current row as a finite number. */
    public double number(int i) {
        try {
            double d = Decimal.parse(row[i]);
            if (!Double.isFinite(d)) throw error("column " + header.get(i) + " = " + SafeText.quote(row[i]) + " is not finite");
            return d;
        } catch (NumberFormatException e) {
            throw error("column " + header.get(i) + " = '" + SafeText.quote(row[i]) + "' is not a number");
        }
    }

    /** Column i of the current row as an integer. */
    public int integer(int i) {
        double d = number(i);
        if (d != Math.rint(d)) throw error("column " + header.get(i) + " = " + SafeText.quote(row[i]) + " is not an integer");
        return (int) d;
    }

    /** An error naming this file and the current line. */
    public CsvException error(String message) {
        return new CsvException(file + ":" + line + ": " + message);
    }

    @Override
    public void close() throws IOException {
        reader.close();
    }

    /** A malformed input row or header; the message starts with {@code FILE:LINE:}. */
    public static final class CsvException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public CsvException(String message) {
            super(SafeText.line(message));
        }
    }
}
