package org.handsim.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.handsim.scenario.Scenario;
import org.handsim.text.Json;
import org.junit.jupiter.api.Test;

/** plan.csv, plan.json and best/ as the README's contracts say; the bounded-memory summaries against direct computation. */
class PlanOutputTest {
    /** Results with chosen ε, without running trials (the parameters are the sampler's). */
    static TrialResult fake(TrialRunner r, int i, boolean ok, boolean fc, double eps, double hold) {
        TrialParameters p = r.parameters(i);
        if (!ok) return TrialResult.failed(p, 0.004, 0.001, "no");
        return new TrialResult(i, true, p.approach(), p.roll(), p.spreadCounts(), 0.004, 3, fc, eps, fc ? 1e-3 : 0, hold,
            new String[] {"STALLED", "BROKEN", "FREE"}, 2.0, 0.01, "", new double[] {0.01 * i, 0, 0.2}, new double[] {0, 0.1 * i, 0},
            fc ? TrialOutcome.FORCE_CLOSURE : TrialOutcome.OTHER);
    }

    @Test
    void tableJsonAndTheTenBestAsTheContractSays() throws Exception {
        Path dir = Files.createTempDirectory("plan-output");
        try {
            PlanSpec spec = PlanTesting.mugPlan(30, 9);
            TrialRunner r = new TrialRunner(spec);
            double[] eps = new double[30];
            try (PlanOutput o = new PlanOutput(dir, r, null)) {
                for (int i = 0; i < 30; i++) {
                    boolean ok = i % 7 != 3, fc = i % 3 != 0;
                    eps[i] = fc ? 0.01 * ((i * 37) % 30) + 0.001 : 0;
                    o.accept(fake(r, i, ok, fc, eps[i], i));
                    if (!ok) eps[i] = -1;
                }
                Map<String, Object> json = o.finish(2.5, "local");
                assertEquals(List.of("target", "trials", "force_closure", "best_epsilon", "wall_time_s", "trials_per_s", "engine", "seed"),
                    new ArrayList<>(json.keySet()));
            }
            List<String> lines = Files.readAllLines(dir.resolve("plan.csv"));
            assertEquals("trial,status,approach_x,approach_y,approach_z,roll_rad,spread_counts,standoff_m,contacts,force_closure,"
                + "epsilon,volume,hold_min_N,final_state1,final_state2,final_state3,sim_time_s,wall_s,error", lines.get(0));
            assertEquals(31, lines.size());
            @SuppressWarnings("unchecked")
            Map<String, Object> pj = (Map<String, Object>) Json.parse("plan.json", Files.readString(dir.resolve("plan.json")));
            long fcCount = 0;
            double best = 0;
            List<Integer> order = new ArrayList<>();
            for (int i = 0; i < 30; i++) {
                if (eps[i] > 0) fcCount++;
                if (eps[i] > best) best = eps[i];
                if (eps[i] >= 0) order.add(i);
            }
            order.sort((a, b) -> eps[a] != eps[b] ? Double.compare(eps[b], eps[a]) : Integer.compare(b, a)); // ties: larger hold = larger i
            assertEquals(fcCount, ((Number) pj.get("force_closure")).longValue());
            assertEquals(best, ((Number) pj.get("best_epsilon")).doubleValue());
            assertEquals(30, ((Number) pj.get("trials")).intValue());
            assertEquals(12.0, ((Number) pj.get("trials_per_s")).doubleValue());
            assertEquals("local", pj.get("engine"));
            assertEquals(9, ((Number) pj.get("seed")).intValue());
            for (int b = 1; b <= 10; b++) {
                Path f = dir.resolve(String.format("best/%02d.json", b));
                assertTrue(Files.isRegularFile(f), f.toString());
                Scenario s = Scenario.load(f);   // opens as it is: the object file is found relative to best/
                assertEquals(PlanTesting.MUG.toAbsolutePath().normalize(), s.object().file());
                int i = order.get(b - 1);
                assertEquals(0.01 * i, s.worldFromPalm().origin()[0], 1e-15, "best " + b + " is trial " + i);
                assertEquals(r.parameters(i).spreadCounts(), s.startCounts(3));
            }
            assertFalse(Files.exists(dir.resolve("best/11.json")));
            assertFalse(Files.exists(dir.resolve(".plan.csv.partial")));
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    @Test
    void rowsOutOfOrderAreRefusedAndNothingLooksFinished() throws Exception {
        Path dir = Files.createTempDirectory("plan-output");
        try {
            TrialRunner r = new TrialRunner(PlanTesting.mugPlan(3, 1));
            try (PlanOutput o = new PlanOutput(dir, r, null)) {
                o.accept(fake(r, 0, true, true, 0.1, 1));
                assertThrows(IllegalStateException.class, () -> o.accept(fake(r, 2, true, true, 0.1, 1)));
                assertThrows(IllegalStateException.class, () -> o.accept(fake(r, 0, true, true, 0.1, 1)));
                assertThrows(IllegalStateException.class, () -> o.finish(1, "local"));
            }
            assertFalse(Files.exists(dir.resolve("plan.csv")));
            assertFalse(Files.exists(dir.resolve(".plan.csv.partial")));
        } finally {
            PlanTesting.deleteTree(dir);
        }
    }

    /** The doubling histogram equals binning all values at the final width. */
    @Test
    void histogramMatchesDirectBinning() {
        SplittableRandom rnd = new SplittableRandom(8);
        EpsilonHistogram h = new EpsilonHistogram();
        List<Double> all = new ArrayList<>();
        long zeros = 0;
        for (int i = 0; i < 5000; i++) {
            double e = i % 5 == 0 ? 0 : Math.pow(rnd.nextDouble(), 3) * (i < 100 ? 0.01 : 0.3);
            h.add(e > 0, e);
            if (e > 0) all.add(e); else zeros++;
        }
        long[] direct = new long[EpsilonHistogram.BINS];
        for (double e : all) direct[(int) Math.floor(e / h.width())]++;
        long[] got = h.counts();
        for (int b = 0; b < EpsilonHistogram.BINS; b++) assertEquals(direct[b], got[b], "bin " + b);
        assertEquals(zeros, h.noClosure());
        assertTrue(all.stream().mapToDouble(Double::doubleValue).max().getAsDouble() < h.width() * EpsilonHistogram.BINS);
        assertTrue(all.stream().mapToDouble(Double::doubleValue).max().getAsDouble() >= h.width() * EpsilonHistogram.BINS / 2,
            "the range is at most twice the largest value");
    }

    @Test
    void directionCellsByHand() {
        // 500 trials, 8 a cell: 62.5 cells of side sqrt(4π / 62.5) = 0.448: round(2 / 0.448) = 4 bands
        // of z = sin(elevation), round(62.5 / 4) = 16 azimuth cells of 22.5°
        DirectionMap m = new DirectionMap(500);
        assertEquals(4, m.zCells());
        assertEquals(16, m.azimuthCells());
        // a = (0, 1, 0): azimuth 90° → cell (90 + 180) / 22.5 = 12; z = 0 → band (0 + 1) / 0.5 = 2
        assertEquals(12, m.azimuthCell(new double[] {0, 1, 0}));
        assertEquals(2, m.zCell(new double[] {0, 1, 0}));
        // straight down: the first band; straight up: the last
        assertEquals(0, m.zCell(new double[] {0, 0, -1}));
        assertEquals(3, m.zCell(new double[] {0, 0, 1}));
        // elevation 29° has z = 0.485 < 0.5: band 2; 31°: band 3 (the bands' edges are at ±30°)
        assertEquals(2, m.zCell(new double[] {Math.cos(Math.toRadians(29)), 0, Math.sin(Math.toRadians(29))}));
        assertEquals(3, m.zCell(new double[] {Math.cos(Math.toRadians(31)), 0, Math.sin(Math.toRadians(31))}));
        m.add(new double[] {0, 1, 0}, 0.2);
        m.add(new double[] {0, 1, 0}, 0.5);
        m.add(new double[] {0, 1, 0}, 0);
        assertEquals(0.5, m.best()[12][2]);
        assertEquals(3, m.count()[12][2]);
    }

    /**
     * The cells have equal areas: directions spread evenly over the sphere (a Fibonacci lattice,
     * built here independently of the planner's sampler) fill them evenly — every cell within a
     * factor 1.5 of the 8 trials it is sized for — where 10° cells in elevation left most empty.
     */
    @Test
    void evenlySpreadDirectionsFillTheCellsEvenly() {
        for (int trials : new int[] {100, 500, 5000}) {
            DirectionMap m = new DirectionMap(trials);
            double golden = Math.PI * (3 - Math.sqrt(5));
            for (int i = 0; i < trials; i++) {
                double z = 1 - (i + 0.5) * 2.0 / trials, r = Math.sqrt(1 - z * z);
                m.add(new double[] {r * Math.cos(golden * i), r * Math.sin(golden * i), z}, 0);
            }
            int[][] c = m.count();
            int total = 0, min = Integer.MAX_VALUE, max = 0;
            for (int[] row : c) for (int n : row) { total += n; min = Math.min(min, n); max = Math.max(max, n); }
            double mean = trials / (double) (m.azimuthCells() * m.zCells());
            assertEquals(trials, total);
            assertTrue(mean >= 6 && mean <= 10.5, trials + " trials: " + mean + " a cell");
            assertTrue(min >= mean / 1.5 && max <= mean * 1.5, trials + " trials: cells hold " + min + ".." + max + ", mean " + mean);
        }
    }
}
