package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The same seed gives the same table whatever the thread count; a throwing trial is a failed row; the local engine's order. */
class PlanEnginesTest {
    static List<String> rows(PlanJob job, int n, int threads) throws Exception {
        List<String> rows = new ArrayList<>();
        new LocalEngine().run(job, n, new TrialEngine.Settings(threads, null, "test"), r -> rows.add(r.csvRow()));
        return PlanTesting.withoutTiming(rows);
    }

    @Test
    void oneAndTwoThreadsGiveTheSameRows() throws Exception {
        PlanSpec spec = PlanTesting.mugPlan(12, 77);
        List<String> one = rows(new PlanJob(spec), 12, 1);
        List<String> two = rows(new PlanJob(spec), 12, 2);
        assertEquals(one, two);
        // and a runner used out of order gives each trial the same row
        TrialRunner r = new TrialRunner(spec);
        String row7 = PlanTesting.withoutTiming(List.of(r.run(7).csvRow())).get(0);
        assertEquals(one.get(7), row7);
        for (int i = 0; i < 12; i++) assertTrue(one.get(i).startsWith(i + ",ok,"), one.get(i));
    }

    @Test
    void aTrialThatThrowsIsAFailedRowAndTheOthersGoOn() throws Exception {
        PlanSpec spec = PlanTesting.mugPlan(6, 3);
        TrialRunner clean = new TrialRunner(spec);
        TrialRunner faulty = new TrialRunner(spec, i -> {
            if (i == 2) throw new IllegalStateException("injected, with a comma");
        });
        for (int i = 0; i < 6; i++) {
            TrialResult a = clean.run(i), b = faulty.run(i);
            if (i == 2) {
                assertFalse(b.ok());
                String row = b.csvRow();
                assertTrue(row.startsWith("2,failed,"), row);
                assertTrue(row.endsWith(",\"injected, with a comma\""), row);
                assertEquals(19, splitCsv(row).size(), "a failed row has every column: " + row);
                // the failed row keeps the trial's parameters (approach, roll, spread, standoff); the outcome columns are empty
                assertEquals(splitCsv(a.csvRow()).subList(2, 8), splitCsv(row).subList(2, 8));
                assertEquals(List.of("", "", "", "", "", "", "", "", ""), splitCsv(row).subList(8, 17));
            } else {
                assertEquals(PlanTesting.withoutTiming(List.of(a.csvRow())), PlanTesting.withoutTiming(List.of(b.csvRow())));
            }
        }
    }

    /** The local engine hands results over in index order, each once, whatever order the tasks finish in. */
    @Test
    void localEngineDeliversInOrderEachOnce() throws Exception {
        for (int threads : new int[] {1, 2, 3, 7}) {
            for (int n : new int[] {1, 5, 100, 1000}) {
                List<Integer> got = new ArrayList<>();
                IndexedJob<Integer> job = i -> {
                    if (new SplittableRandom(i).nextInt(10) == 0) Thread.onSpinWait();
                    return i;
                };
                new LocalEngine().run(job, n, new TrialEngine.Settings(threads, null, "t"), got::add);
                assertEquals(n, got.size());
                for (int i = 0; i < n; i++) assertEquals(i, (int) got.get(i));
            }
        }
    }

    @Test
    void aTaskThatThrowsFailsTheLocalEngine() {
        IndexedJob<Integer> job = i -> {
            if (i == 40) throw new IllegalStateException("boom at 40");
            return i;
        };
        Exception e = assertThrows(IllegalStateException.class,
            () -> new LocalEngine().run(job, 100, new TrialEngine.Settings(2, null, "t"), x -> { }));
        assertEquals("boom at 40", e.getMessage());
    }

    @Test
    void unknownEngineIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Engines.find("hadoop"));
        assertTrue(e.getMessage().contains("'hadoop'"), e.getMessage());
        assertEquals("local", Engines.find("local").name());
    }

    static List<String> splitCsv(String row) {
        List<String> out = new ArrayList<>();
        StringBuilder f = new StringBuilder();
        boolean q = false;
        for (int i = 0; i < row.length(); i++) {
            char ch = row.charAt(i);
            if (q) {
                if (ch == '"' && i + 1 < row.length() && row.charAt(i + 1) == '"') { f.append('"'); i++; }
                else if (ch == '"') q = false;
                else f.append(ch);
            } else if (ch == '"') q = true;
            else if (ch == ',') { out.add(f.toString()); f.setLength(0); }
            else f.append(ch);
        }
        out.add(f.toString());
        return out;
    }
}
