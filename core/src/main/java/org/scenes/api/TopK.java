package org.scenes.api;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.IntFunction;

/**
 * The k best (distance, index) pairs seen so far, as a bounded max-heap whose root is the worst
 * kept. Equal distances are ordered by index, so a scan in index order keeps the earliest scene,
 * whatever the order of offers. NaN distances count as farthest. One per query; not thread-safe.
 */
public final class TopK {
    private final double[] distance;
    private final int[] index;
    private int size;

    /** @param capacity how many pairs to keep, k, at least 1 */
    public TopK(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be at least 1, not " + capacity);
        }
        distance = new double[capacity];
        index = new int[capacity];
    }

    /**
     * The largest distance that can still enter: the worst kept once full, +Infinity before.
     * A scan in index order may skip any scene whose distance is not below it.
     *
     * @return the bound for the next offer
     */
    public double bound() {
        return size < distance.length ? Double.POSITIVE_INFINITY : distance[0];
    }

    /** @return how many pairs are kept now */
    public int size() {
        return size;
    }

    /** @return how many pairs are kept at most (k) */
    public int capacity() {
        return distance.length;
    }

    /**
     * The index of the worst kept pair once full (a scene at exactly {@link #bound()} enters
     * only with a lower index), Integer.MAX_VALUE before.
     *
     * @return that index
     */
    public int worstIndex() {
        return size < distance.length ? Integer.MAX_VALUE : index[0];
    }

    /**
     * Keeps the pair if it is among the k best so far.
     *
     * @param newDistance the stored scene's distance from the query
     * @param newIndex the stored scene's knowledge-base index
     */
    public void offer(double newDistance, int newIndex) {
        if (size < distance.length) {
            int child = size++;
            distance[child] = newDistance;
            index[child] = newIndex;
            while (child > 0) {
                int parent = (child - 1) / 2;
                if (compare(parent, child) >= 0) {
                    break;
                }
                swap(parent, child);
                child = parent;
            }
            return;
        }
        if (compare(newDistance, newIndex, distance[0], index[0]) >= 0) {
            return;
        }
        distance[0] = newDistance;
        index[0] = newIndex;
        int parent = 0;
        while (true) {
            int left = 2 * parent + 1;
            int right = left + 1;
            int largest = parent;
            if (left < size && compare(left, largest) > 0) {
                largest = left;
            }
            if (right < size && compare(right, largest) > 0) {
                largest = right;
            }
            if (largest == parent) {
                return;
            }
            swap(parent, largest);
            parent = largest;
        }
    }

    /**
     * The kept pairs as neighbours, nearest first (ties by index).
     *
     * @param scenes the stored scene of each index
     * @return at most {@link #capacity()} neighbours
     */
    public List<Neighbour> neighbours(IntFunction<Scene> scenes) {
        Integer[] order = new Integer[size];
        for (int i = 0; i < size; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> compare(a, b));
        List<Neighbour> result = new ArrayList<>(size);
        for (int slot : order) {
            result.add(new Neighbour(scenes.apply(index[slot]), index[slot], distance[slot]));
        }
        return result;
    }

    /** Orders by distance, then index; NaN distances count as farthest. */
    static int compare(double distanceA, int indexA, double distanceB, int indexB) {
        int byDistance = Double.compare(distanceA, distanceB);
        return byDistance != 0 ? byDistance : Integer.compare(indexA, indexB);
    }

    private int compare(int a, int b) {
        return compare(distance[a], index[a], distance[b], index[b]);
    }

    private void swap(int a, int b) {
        double d = distance[a];
        distance[a] = distance[b];
        distance[b] = d;
        int i = index[a];
        index[a] = index[b];
        index[b] = i;
    }
}
