package org.handsim.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * The shared cache of meshes and trees: made once per key however many threads ask at once,
 * the weights bounded by dropping the least recently used, a failed load cached nowhere.
 */
class BoundedCacheTest {
    /** A value whose weight is its length. */
    private static int[] value(int weight) {
        return new int[weight];
    }

    @Test
    void eightThreadsAskingAtOnceMakeTheValueOnceAndAllGetIt() throws Exception {
        BoundedCache<String, int[]> cache = new BoundedCache<>(100, v -> v.length);
        AtomicInteger loads = new AtomicInteger();
        CountDownLatch start = new CountDownLatch(1), inLoad = new CountDownLatch(1);
        ExecutorService pool = Executors.newFixedThreadPool(8);
        try {
            List<Future<int[]>> got = new ArrayList<>();
            for (int t = 0; t < 8; t++) {
                got.add(pool.submit(() -> {
                    start.await();
                    return cache.get("mug", k -> {
                        loads.incrementAndGet();
                        inLoad.countDown();
                        try {
                            Thread.sleep(200);   // the others arrive while this one loads
                        } catch (InterruptedException e) {
                            throw new IllegalStateException(e);
                        }
                        return value(10);
                    });
                }));
            }
            start.countDown();
            assertTrue(inLoad.await(10, TimeUnit.SECONDS));
            int[] first = got.get(0).get(10, TimeUnit.SECONDS);
            for (Future<int[]> f : got) assertSame(first, f.get(10, TimeUnit.SECONDS));
            assertEquals(1, loads.get());
            assertEquals(1, cache.size());
            assertEquals(10, cache.weight());
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void theLeastRecentlyUsedGoFirstWhenTheWeightsPassTheBound() {
        BoundedCache<String, int[]> cache = new BoundedCache<>(100, v -> v.length);
        int[] a = cache.get("a", k -> value(40));
        cache.get("b", k -> value(40));
        assertSame(a, cache.get("a", k -> value(40)), "a hit: a is now the most recently used");
        cache.get("c", k -> value(40));   // 120 > 100: b, the least recently used, goes
        assertTrue(cache.holds("a"));
        assertFalse(cache.holds("b"));
        assertTrue(cache.holds("c"));
        assertEquals(80, cache.weight());
        assertEquals(2, cache.size());
        AtomicInteger loads = new AtomicInteger();
        cache.get("b", k -> {
            loads.incrementAndGet();
            return value(40);
        });
        assertEquals(1, loads.get(), "b was dropped: made again");
        assertFalse(cache.holds("a"), "a was the least recently used then");
    }

    @Test
    void aValueHeavierThanTheBoundIsKeptUntilTheNextOne() {
        BoundedCache<String, int[]> cache = new BoundedCache<>(100, v -> v.length);
        cache.get("small", k -> value(30));
        int[] big = cache.get("big", k -> value(500));
        assertEquals(1, cache.size());
        assertEquals(500, cache.weight());
        assertSame(big, cache.get("big", k -> value(1)));
        cache.get("next", k -> value(30));
        assertFalse(cache.holds("big"));
        assertEquals(30, cache.weight());
    }

    @Test
    void aLoadThatThrowsLeavesNothingAndTheNextCallLoadsAgain() {
        BoundedCache<String, int[]> cache = new BoundedCache<>(100, v -> v.length);
        IllegalStateException e = assertThrows(IllegalStateException.class,
            () -> cache.get("bad", k -> { throw new IllegalStateException("bad.obj:3:1: no vertex 9"); }));
        assertEquals("bad.obj:3:1: no vertex 9", e.getMessage());
        assertEquals(0, cache.size());
        assertEquals(0, cache.weight());
        assertEquals(7, cache.get("bad", k -> value(7)).length);
        assertEquals(7, cache.weight());
    }

    @Test
    void badBoundIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new BoundedCache<String, int[]>(0, v -> v.length));
    }
}
