package org.handsim.trace;

import java.io.IOException;
import org.handsim.clutch.ClutchState;
import org.handsim.text.Decimal;

/**
 * One trace.csv line as ASCII bytes, from a row of {@link Recorder#WIDTH} numbers (and the
 * object's): the time as it is, per finger its numbers, clutch state (its name), contact count
 * and force, then the remaining columns, every physical value {@link Decimal#clean cleaned} and
 * written by {@link Decimal} (the column order: {@link Recorder}). Each column keeps the text of
 * the value it wrote last with that value's bits; a cell whose value has the same bits copies
 * those bytes instead of formatting again — most cells of a trace repeat the row above (92 % of
 * the paper's) — and a new value is formatted by {@link Decimal}. Same bits, same text: the
 * format depends on the value alone.
 *
 * <p>Why: in JFR's samples of a paper run on the resident server, formatting each cell on its
 * own (a thread-local table of recent texts looked up per cell, the characters then copied into
 * the line and again into bytes) took three quarters of the trace writer's time. The tests hold
 * this class to the plain definition (every cell formatted afresh, joined by commas) byte for
 * byte.
 */
final class TraceLine {
    /** How a column is written: a time (as it is), a physical value ({@link Decimal#clean}), a clutch state, a count. */
    private static final byte TIME = 0, VALUE = 1, STATE = 2, COUNT = 3;
    private static final ClutchState[] STATES = ClutchState.values();
    /** The longest text of a cell: a double's is at most 24 characters, a state's name shorter. */
    private static final int CELL = 32;

    private final byte[] kind;
    private final long[] bits;
    private final byte[][] text;
    private final int[] length;    // 0: nothing held yet
    private final StringBuilder scratch = new StringBuilder(CELL);
    private final byte[] line;
    private int n;

    /** A line of {@link Recorder#WIDTH} columns, and the object's when {@code object}. */
    TraceLine(boolean object) {
        int width = Recorder.WIDTH + (object ? Recorder.OBJECT_COLUMNS.length : 0);
        kind = new byte[width];
        int i = 0;
        kind[i++] = TIME;
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < Recorder.FINGER_COLUMNS.length; c++) kind[i++] = VALUE;
            kind[i++] = STATE;
            kind[i++] = COUNT;
            kind[i++] = VALUE;
        }
        while (i < Recorder.WIDTH) kind[i++] = VALUE;
        for (int c = 0; c < (object ? Recorder.OBJECT_COLUMNS.length : 0); c++) kind[i++] = c == Recorder.OBJ_CONTACTS ? COUNT : VALUE;
        bits = new long[width];
        text = new byte[width][CELL];
        length = new int[width];
        line = new byte[width * (CELL + 1) + 1];
    }

    /**
     * Writes the line of {@code row} into {@link #bytes()}, its length returned.
     *
     * @throws IllegalArgumentException for a value {@link Decimal} refuses (NaN, an infinity)
     * @throws IOException for a text that is not ASCII
     */
    int encode(double[] row) throws IOException {
        n = 0;
        for (int c = 0; c < kind.length; c++) {
            if (c > 0) line[n++] = ',';
            double v = kind[c] == VALUE ? Decimal.clean(row[c]) : row[c];
            long b = Double.doubleToRawLongBits(v);
            if (length[c] == 0 || bits[c] != b) remember(c, v, b);
            System.arraycopy(text[c], 0, line, n, length[c]);
            n += length[c];
        }
        line[n++] = '\n';
        return n;
    }

    /** The bytes of the last line, {@link #encode}'s length of them. */
    byte[] bytes() { return line; }

    /** Formats column {@code c}'s new value {@code v} (bits {@code b}) and keeps its text. */
    private void remember(int c, double v, long b) throws IOException {
        scratch.setLength(0);
        switch (kind[c]) {
            case STATE -> scratch.append(STATES[(int) v].name());
            case COUNT -> scratch.append((long) v);
            default -> Decimal.append(scratch, v);
        }
        int len = scratch.length();
        if (len > CELL) throw new IOException("a trace cell longer than " + CELL + " characters: " + scratch);
        byte[] t = text[c];
        for (int i = 0; i < len; i++) {
            char ch = scratch.charAt(i);
            if (ch >= 0x80) throw new IOException("a trace line that is not ASCII");
            t[i] = (byte) ch;
        }
        bits[c] = b;
        length[c] = len;
    }
}
