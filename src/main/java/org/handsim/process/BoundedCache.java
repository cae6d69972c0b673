package org.handsim.process;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;
import java.util.function.ToLongFunction;

/**
 * A thread-safe cache of values that are costly to make and large to keep (meshes, k-DOP
 * trees), bounded by a total weight: each value is made once per key however many threads ask
 * for it at the same time (the others wait for it), and when the values' weights add up to more
 * than the bound the least recently used ones are dropped — never the one just made, so a
 * single value heavier than the bound is still kept until another one is made. A value that is
 * dropped stays valid for whoever holds it. A load that throws leaves nothing behind (the next
 * call loads again).
 *
 * <p>Why not a library: the one that does this (Caffeine) would be a new dependency of the core
 * and of the Spark engine's executors for forty lines; DESIGN.md.
 *
 * @param <K> key (equals/hashCode)
 * @param <V> value, never null
 */
public final class BoundedCache<K, V> {
    private final long maxWeight;
    private final ToLongFunction<? super V> weigher;
    private final LinkedHashMap<K, Slot<V>> slots = new LinkedHashMap<>(16, 0.75f, true);   // least recently used first
    private long weight;

    /** A value being made (weight −1) or made. */
    private static final class Slot<V> {
        V value;
        long weight = -1;
    }

    /**
     * @param maxWeight the bound on the total weight (&gt; 0)
     * @param weigher   a value's weight (≥ 0), asked once, when the value is made
     */
    public BoundedCache(long maxWeight, ToLongFunction<? super V> weigher) {
        if (maxWeight <= 0) throw new IllegalArgumentException("maxWeight must be > 0, got " + maxWeight);
        this.maxWeight = maxWeight;
        this.weigher = Objects.requireNonNull(weigher);
    }

    /**
     * The value for {@code key}, made by {@code load} if the cache does not hold it (once: a
     * caller asking while another thread makes it waits and gets that value).
     *
     * @throws RuntimeException whatever {@code load} throws (nothing is cached then)
     */
    public V get(K key, Function<? super K, ? extends V> load) {
        return get(key, v -> true, load);
    }

    /**
     * As {@link #get(Object, Function)}, but a held value for which {@code valid} is false (the
     * file it was made from has changed since) is dropped and made again.
     */
    public V get(K key, java.util.function.Predicate<? super V> valid, Function<? super K, ? extends V> load) {
        while (true) {
            Slot<V> s;
            synchronized (this) {
                s = slots.computeIfAbsent(key, x -> new Slot<>());
            }
            synchronized (s) {   // lock order: a slot, then the cache; never the reverse
                if (s.value != null) {
                    if (valid.test(s.value)) return s.value;
                    synchronized (this) {
                        if (slots.get(key) == s) {
                            slots.remove(key);
                            if (s.weight >= 0) weight -= s.weight;
                        }
                    }
                    continue;
                }
                synchronized (this) {
                    if (slots.get(key) != s) continue;   // a failed load removed it: start again
                }
                V v;
                try {
                    v = Objects.requireNonNull(load.apply(key), "the cache's load returned null");
                } catch (RuntimeException | Error e) {
                    synchronized (this) {
                        slots.remove(key, s);
                    }
                    throw e;
                }
                long w = Math.max(0, weigher.applyAsLong(v));
                s.value = v;
                synchronized (this) {
                    if (slots.get(key) == s) {
                        s.weight = w;
                        weight += w;
                        evict(key);
                    }
                }
                return v;
            }
        }
    }

    /** Drops the least recently used made values other than {@code keep}'s while over the bound. */
    private void evict(K keep) {
        Iterator<Map.Entry<K, Slot<V>>> it = slots.entrySet().iterator();
        while (weight > maxWeight && it.hasNext()) {
            Map.Entry<K, Slot<V>> e = it.next();
            Slot<V> s = e.getValue();
            if (s.weight < 0 || e.getKey().equals(keep)) continue;
            weight -= s.weight;
            it.remove();
        }
    }

    /** The values held (made and not dropped). */
    public synchronized int size() {
        int n = 0;
        for (Slot<V> s : slots.values()) if (s.weight >= 0) n++;
        return n;
    }

    /** The total weight of the values held. */
    public synchronized long weight() { return weight; }

    /** Whether a value for {@code key} is held (does not count as a use). */
    public synchronized boolean holds(K key) {
        for (Map.Entry<K, Slot<V>> e : slots.entrySet()) {   // iterating leaves the use order as it is
            if (e.getKey().equals(key)) return e.getValue().weight >= 0;
        }
        return false;
    }
}
