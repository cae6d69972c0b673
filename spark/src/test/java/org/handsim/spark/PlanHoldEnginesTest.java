package org.handsim.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.handsim.hold.HoldSettings;
import org.handsim.plan.LocalEngine;
import org.handsim.plan.PlanHold;
import org.handsim.plan.PlanJob;
import org.handsim.plan.PlanSpec;
import org.handsim.plan.TrialEngine;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** {@code plan --hold-test} on every engine: the same table. */
class PlanHoldEnginesTest {
    /**
     * {@code plan --hold-test}'s table (the six verdicts and the smallest margin after the
     * trial's columns) is the same, timing aside, on one local thread, two local threads and
     * Spark local[2]: each trial's hold test depends on its index alone (three trials, 0.3 s
     * pushes, so the test stays short).
     */
    @Test
    @Tag("slow")   // three trials' hold tests on three engines and a Spark context: about a minute
    void holdTestTablesAreTheSameOnEveryEngine() throws Exception {
        PlanSpec s = spec();
        List<String> one = new ArrayList<>(), two = new ArrayList<>(), spark = new ArrayList<>();
        new LocalEngine().run(new PlanJob(s), s.trials(), new TrialEngine.Settings(1, null, "t"), r -> one.add(r.csvRow(true)));
        new LocalEngine().run(new PlanJob(s), s.trials(), new TrialEngine.Settings(2, null, "t"), r -> two.add(r.csvRow(true)));
        new SparkEngine().run(new PlanJob(s), s.trials(), new TrialEngine.Settings(2, "local[2]", "test"), r -> spark.add(r.csvRow(true)));
        assertEquals(3, one.size());
        for (String row : one) {
            String[] f = row.split(",", -1);
            assertTrue(f[f.length - 2].equals("true") || f[f.length - 2].equals("false"), "a verdict before the margin: " + row);
            Double.parseDouble(f[f.length - 1]);
        }
        one.replaceAll(r -> SparkEngineTest.withoutTiming(List.of(r)).get(0));
        assertEquals(one, SparkEngineTest.withoutTiming(two), "two threads");
        assertEquals(one, SparkEngineTest.withoutTiming(spark), "Spark local[2]");
    }

    /** Three mug trials with 0.3 s pushes (short enough for a slow test). */
    static PlanSpec spec() {
        return SparkEngineTest.spec(3).withHold(new PlanHold(
            new HoldSettings(Double.NaN, 0.3, 0.001, false, 0.05, 15, 0.005, 5, 10, 58.84), Double.NaN, Double.NaN, false));
    }

    /** {@code s}'s table, with its hold columns, on one local thread, timing aside. */
    static List<String> oneThread(PlanSpec s) throws Exception {
        List<String> rows = new ArrayList<>();
        new LocalEngine().run(new PlanJob(s), s.trials(), new TrialEngine.Settings(1, null, "t"), r -> rows.add(r.csvRow(true)));
        return SparkEngineTest.withoutTiming(rows);
    }

}
