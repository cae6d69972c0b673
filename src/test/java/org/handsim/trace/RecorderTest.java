package org.handsim.trace;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.handsim.clutch.ClutchState;
import org.junit.jupiter.api.Test;

/**
 * {@link Recorder#bounded}: the streamed trace.csv is byte for byte what the in-memory recorder
 * writes for the same rows, memory keeps every stride-th row and the last, and a run that does
 * not finish leaves no file.
 */
class RecorderTest {
    /** Fills the same seeded rows into both recorders (3 001 rows: 11 chunks of 256 and a partial one). */
    private static void fill(Recorder a, Recorder b, int rows) {
        Random rnd = new Random(7);
        ClutchState[] states = ClutchState.values();
        for (int r = 0; r < rows; r++) {
            double t = r / 1000.0;
            a.beginRow(t);
            b.beginRow(t);
            for (int k = 1; k <= 3; k++) {
                for (int c = Recorder.Q; c <= Recorder.TAU3; c++) {
                    double v = rnd.nextInt(4) == 0 ? 0 : rnd.nextGaussian() * Math.pow(10, rnd.nextInt(8) - 4);
                    if (rnd.nextInt(50) == 0) v = -3e-19;   // rounding noise, written as 0
                    a.set(k, c, v);
                    b.set(k, c, v);
                }
                ClutchState s = states[rnd.nextInt(states.length)];
                a.setState(k, s);
                b.setState(k, s);
                int n = rnd.nextInt(3);
                double f = n * rnd.nextDouble() * 20;
                a.setContacts(k, n, f);
                b.setContacts(k, n, f);
            }
            a.setSpread(r);
            b.setSpread(r);
        }
    }

    @Test
    void theStreamedTraceIsTheInMemoryTraceAndMemoryKeepsTheChartRows() throws Exception {
        Path dir = Files.createTempDirectory("handsim-recorder");
        try {
            int rows = 3001;
            Recorder memory = new Recorder();
            Recorder bounded = Recorder.bounded(dir.resolve("trace.csv"), rows);
            fill(memory, bounded, rows);
            bounded.finish();
            bounded.close();
            memory.writeCsv(dir.resolve("memory.csv"));
            assertArrayEquals(Files.readAllBytes(dir.resolve("memory.csv")), Files.readAllBytes(dir.resolve("trace.csv")));
            String text = Files.readString(dir.resolve("trace.csv"));
            assertFalse(text.contains("e-19") || text.contains(".0,") || text.contains("-0,"), "clean numbers");
            assertEquals(rows + 1, text.split("\n").length);
            // memory: rows 0, 2, 4, ... (stride 3001 / 1500 = 2) and the last
            assertEquals(2, bounded.stride());
            assertEquals(1501, bounded.rows());
            assertEquals(rows, bounded.totalRows());
            for (int i = 0; i < bounded.rows(); i++) {
                int r = Math.min(2 * i, rows - 1);
                assertEquals(memory.time(r), bounded.time(i));
                assertEquals(memory.get(3, Recorder.TAU2, r), bounded.get(3, Recorder.TAU2, i));
                assertEquals(memory.state(2, r), bounded.state(2, i));
            }
            assertTrue(bounded.moved(1) && memory.moved(1));
        } finally {
            org.handsim.cli.ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void aRunThatDoesNotFinishLeavesNoFile() throws Exception {
        Path dir = Files.createTempDirectory("handsim-recorder");
        try {
            Recorder bounded = Recorder.bounded(dir.resolve("out/trace.csv"), 10_000);
            fill(new Recorder(), bounded, 5000);
            bounded.close();   // as a failed run does
            try (var s = Files.walk(dir)) {
                assertEquals(0, s.filter(Files::isRegularFile).count(), "neither trace.csv nor its temporary file");
            }
        } finally {
            org.handsim.cli.ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void aMotorThatNeverMovesIsNotMoved() {
        Recorder r = Recorder.bounded(null, 100);
        for (int i = 0; i < 100; i++) {
            r.beginRow(i);
            r.set(1, Recorder.Q, 5);
            r.set(2, Recorder.Q, i == 99 ? 6 : 5);   // only in the last row
        }
        assertFalse(r.moved(1));
        assertTrue(r.moved(2));
    }
}
