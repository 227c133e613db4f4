package org.scenes.match;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import org.scenes.scene.Scene;

/**
 * k-nearest-neighbour search of a query scene against a knowledge base: the one implementation
 * behind validation, the live agent and benchmarks. It keeps the k best in a bounded max-heap;
 * equal distances are ordered by knowledge-base index, so results never depend on timing or
 * threads. Metrics with an {@link EncodedMetric} fast path have the knowledge base encoded once
 * here and are asked with the current k-th best distance as bound, so they can stop early.
 * Safe to use from several threads: each thread gets its own metric instance.
 */
public final class Recognizer {
    private final KnowledgeBase knowledge;
    private final int k;
    private final ThreadLocal<SceneMetric> metrics;
    private final Object[] encoded;

    public Recognizer(KnowledgeBase knowledge, Supplier<SceneMetric> metricFactory, int k) {
        if (k < 1) {
            throw new IllegalArgumentException("k must be at least 1, not " + k);
        }
        if (knowledge.size() == 0) {
            throw new IllegalArgumentException("the knowledge base holds no scenes");
        }
        this.knowledge = knowledge;
        this.k = k;
        this.metrics = ThreadLocal.withInitial(metricFactory);
        SceneMetric first = metricFactory.get();
        if (first instanceof EncodedMetric<?> fast) {
            encoded = new Object[knowledge.size()];
            for (int i = 0; i < encoded.length; i++) {
                encoded[i] = fast.encode(knowledge.scene(i));
            }
        } else {
            encoded = null;
        }
    }

    public KnowledgeBase knowledge() {
        return knowledge;
    }

    public int k() {
        return k;
    }

    public SceneMetric metric() {
        return metrics.get();
    }

    /** The min(k, size) stored scenes nearest to the query, nearest first, ties by index. */
    public List<Neighbour> nearest(Scene query) {
        int capacity = Math.min(k, knowledge.size());
        double[] heapDistance = new double[capacity];
        int[] heapIndex = new int[capacity];
        int size = 0;
        SceneMetric metric = metrics.get();
        if (encoded != null) {
            @SuppressWarnings("unchecked")
            EncodedMetric<Object> fast = (EncodedMetric<Object>) metric;
            Object q = fast.encode(query);
            for (int i = 0; i < encoded.length; i++) {
                double bound = size < capacity ? Double.POSITIVE_INFINITY : heapDistance[0];
                double distance = fast.distance(q, encoded[i], bound);
                size = offer(heapDistance, heapIndex, size, capacity, distance, i);
            }
        } else {
            for (int i = 0; i < knowledge.size(); i++) {
                size = offer(heapDistance, heapIndex, size, capacity, metric.distance(query, knowledge.scene(i)), i);
            }
        }
        Integer[] order = new Integer[size];
        for (int i = 0; i < size; i++) {
            order[i] = i;
        }
        final double[] d = heapDistance;
        final int[] idx = heapIndex;
        Arrays.sort(order, (a, b) -> compare(d[a], idx[a], d[b], idx[b]));
        List<Neighbour> result = new ArrayList<>(size);
        for (int slot : order) {
            result.add(new Neighbour(knowledge.scene(idx[slot]), idx[slot], d[slot]));
        }
        return result;
    }

    /** Orders by distance, then index; NaN distances count as farthest. */
    static int compare(double distanceA, int indexA, double distanceB, int indexB) {
        int byDistance = Double.compare(distanceA, distanceB);
        return byDistance != 0 ? byDistance : Integer.compare(indexA, indexB);
    }

    /** Max-heap on (distance, index): the root is the worst of the k kept. */
    private static int offer(double[] distance, int[] index, int size, int capacity, double newDistance, int newIndex) {
        if (size < capacity) {
            int child = size;
            distance[child] = newDistance;
            index[child] = newIndex;
            while (child > 0) {
                int parent = (child - 1) / 2;
                if (compare(distance[parent], index[parent], distance[child], index[child]) >= 0) {
                    break;
                }
                swap(distance, index, parent, child);
                child = parent;
            }
            return size + 1;
        }
        if (compare(newDistance, newIndex, distance[0], index[0]) >= 0) {
            return size;
        }
        distance[0] = newDistance;
        index[0] = newIndex;
        int parent = 0;
        while (true) {
            int left = 2 * parent + 1;
            int right = left + 1;
            int largest = parent;
            if (left < size && compare(distance[left], index[left], distance[largest], index[largest]) > 0) {
                largest = left;
            }
            if (right < size && compare(distance[right], index[right], distance[largest], index[largest]) > 0) {
                largest = right;
            }
            if (largest == parent) {
                return size;
            }
            swap(distance, index, parent, largest);
            parent = largest;
        }
    }

    private static void swap(double[] distance, int[] index, int a, int b) {
        double d = distance[a];
        distance[a] = distance[b];
        distance[b] = d;
        int i = index[a];
        index[a] = index[b];
        index[b] = i;
    }
}
