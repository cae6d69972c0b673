package org.handsim.grasp;

import java.util.Arrays;

/**
 * A binary min-heap of (key, facet, generation) triples on primitive arrays, for the best-first
 * hull of {@link ConvexHull#epsilon}: entries of facets deleted since they were pushed are
 * recognised by their generation and skipped by the caller (lazy deletion). Reused across
 * calls; grows by doubling, never shrinks.
 */
final class FacetHeap {
    private double[] keys = new double[64];
    private int[] facets = new int[64];
    private int[] gens = new int[64];
    private int size;

    void clear() { size = 0; }

    boolean isEmpty() { return size == 0; }

    void push(double key, int facet, int gen) {
        if (size == keys.length) {
            keys = Arrays.copyOf(keys, 2 * size);
            facets = Arrays.copyOf(facets, 2 * size);
            gens = Arrays.copyOf(gens, 2 * size);
        }
        int i = size++;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            if (keys[parent] <= key) break;
            keys[i] = keys[parent]; facets[i] = facets[parent]; gens[i] = gens[parent];
            i = parent;
        }
        keys[i] = key; facets[i] = facet; gens[i] = gen;
    }

    /** The smallest key (the heap must not be empty). */
    double topKey() { return keys[0]; }

    /** The facet of the smallest key (valid until the next push or pop). */
    int topFacet() { return facets[0]; }

    /** The generation the top facet had when it was pushed. */
    int topGen() { return gens[0]; }

    /** Removes the smallest entry. */
    void pop() {
        int last = --size;
        if (last == 0) return;
        double key = keys[last];
        int facet = facets[last], gen = gens[last];
        int i = 0;
        while (true) {
            int c = 2 * i + 1;
            if (c >= last) break;
            if (c + 1 < last && keys[c + 1] < keys[c]) c++;
            if (keys[c] >= key) break;
            keys[i] = keys[c]; facets[i] = facets[c]; gens[i] = gens[c];
            i = c;
        }
        keys[i] = key; facets[i] = facet; gens[i] = gen;
    }
}
