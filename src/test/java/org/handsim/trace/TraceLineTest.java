package org.handsim.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.handsim.clutch.ClutchState;
import org.handsim.text.Decimal;
import org.junit.jupiter.api.Test;

/**
 * {@link TraceLine} writes the bytes of the plain definition of a trace.csv line — every cell
 * formatted afresh by {@link Decimal}, joined by commas — for rows whose cells repeat, change,
 * flip sign, cross zero and the rounding-noise limit, and reach the ends of the double range;
 * NaN and infinities are refused as before.
 */
class TraceLineTest {
    private static final ClutchState[] STATES = ClutchState.values();

    /** The line by its definition (the reference: each cell on its own through {@link Decimal#append}, as one line of text). */
    private static String reference(double[] row, boolean object) {
        StringBuilder sb = new StringBuilder();
        int i = 0;
        Decimal.append(sb, row[i++]);
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < Recorder.FINGER_COLUMNS.length; c++) Decimal.append(sb.append(','), Decimal.clean(row[i++]));
            sb.append(',').append(STATES[(int) row[i++]].name());
            sb.append(',').append((long) row[i++]);
            Decimal.append(sb.append(','), Decimal.clean(row[i++]));
        }
        while (i < Recorder.WIDTH) Decimal.append(sb.append(','), Decimal.clean(row[i++]));
        for (int c = 0; object && c < Recorder.OBJECT_COLUMNS.length; c++) {
            if (c == Recorder.OBJ_CONTACTS) sb.append(',').append((long) row[i++]);
            else Decimal.append(sb.append(','), Decimal.clean(row[i++]));
        }
        return sb.append('\n').toString();
    }

    /** Values a cell takes: the awkward ones often, ordinary ones otherwise. */
    private static final double[] EDGES = {0.0, -0.0, 1e-12, -1e-12, 9.99e-13, -3e-19, 1e-6, 9.99e-7, -1e-7, 4.9e-324, -4.9e-324,
        Double.MIN_NORMAL, 1e21, 9.99e20, -1e21, 1.5e21, Double.MAX_VALUE, -Double.MAX_VALUE, 0x1p53, 0x1p53 + 2, -0x1p53 - 2, 44732,
        -44732, 0.1, -0.1, 8.947000000000001, 0.0005, 1.0, -1.0, 123456789.125, 1e23, 5e-324, 2.5e-7};

    private static double value(Random rnd, double previous) {
        return switch (rnd.nextInt(6)) {
            case 0 -> EDGES[rnd.nextInt(EDGES.length)];
            case 1 -> -previous;
            case 2 -> (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(50) - 25);
            case 3 -> Double.longBitsToDouble(rnd.nextLong() & 0x7fefffffffffffffL) * (rnd.nextBoolean() ? 1 : -1);
            case 4 -> Math.rint(rnd.nextGaussian() * 1000);
            default -> rnd.nextGaussian();
        };
    }

    @Test
    void everyLineIsItsDefinitionByteForByte() throws Exception {
        for (boolean object : new boolean[] {false, true}) {
            Random rnd = new Random(object ? 11 : 10);
            int width = Recorder.WIDTH + (object ? Recorder.OBJECT_COLUMNS.length : 0);
            TraceLine line = new TraceLine(object);
            double[] row = new double[width];
            int repeated = 0;
            for (int r = 0; r < 20_000; r++) {
                for (int c = 0; c < width; c++) {
                    if (r > 0 && rnd.nextInt(4) != 0) {
                        repeated++;
                        continue;   // most cells keep the row above's value
                    }
                    row[c] = value(rnd, row[c]);
                }
                row[0] = r % 7 == 0 ? value(rnd, row[0]) : r * 0.001;   // t_s: not cleaned
                int perFinger = Recorder.FINGER_COLUMNS.length + 3;
                for (int k = 0; k < 3; k++) {
                    int at = 1 + k * perFinger + Recorder.FINGER_COLUMNS.length;
                    row[at] = rnd.nextInt(STATES.length);                                          // the clutch state
                    row[at + 1] = rnd.nextInt(10) == 0 ? rnd.nextInt(1 << 20) : rnd.nextInt(3);     // the contacts
                }
                if (object) row[Recorder.WIDTH + Recorder.OBJ_CONTACTS] = rnd.nextInt(40);
                int n = line.encode(row);
                String got = new String(line.bytes(), 0, n, StandardCharsets.US_ASCII);
                assertEquals(reference(row, object), got, "row " + r + (object ? " (with the object)" : ""));
            }
            assertTrue(repeated > 20_000 * width / 2, "most cells repeat, as in a trace");
        }
    }

    @Test
    void nanAndInfinitiesAreRefused() throws Exception {
        for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
            for (int c : new int[] {0, 2, Recorder.WIDTH - 1}) {
                TraceLine line = new TraceLine(false);
                double[] row = new double[Recorder.WIDTH];
                String zeros = reference(row, false);
                assertEquals(zeros, text(line, row));
                row[c] = bad;
                assertThrows(IllegalArgumentException.class, () -> line.encode(row), "column " + c + ": " + bad);
                assertThrows(IllegalArgumentException.class, () -> reference(row, false), "as the definition");
                row[c] = 0;
                assertEquals(zeros, text(line, row), "a refused value leaves nothing behind");
            }
        }
    }

    private static String text(TraceLine line, double[] row) throws java.io.IOException {
        return new String(line.bytes(), 0, line.encode(row), StandardCharsets.US_ASCII);
    }
}
