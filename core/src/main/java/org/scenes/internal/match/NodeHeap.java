package org.scenes.internal.match;

import java.util.Arrays;

/** A min-heap of tree nodes by lower bound, for {@link LowDimensionalIndex}'s best-first search. */
final class NodeHeap {
    private double[] bounds = new double[64];
    private int[] nodes = new int[64];
    int size;

    void push(double bound, int node) {
        if (size == nodes.length) {
            bounds = Arrays.copyOf(bounds, size * 2);
            nodes = Arrays.copyOf(nodes, size * 2);
        }
        int child = size++;
        while (child > 0) {
            int parent = (child - 1) >>> 1;
            if (bounds[parent] <= bound) {
                break;
            }
            bounds[child] = bounds[parent];
            nodes[child] = nodes[parent];
            child = parent;
        }
        bounds[child] = bound;
        nodes[child] = node;
    }

    double topBound() {
        return bounds[0];
    }

    int topNode() {
        return nodes[0];
    }

    void pop() {
        size--;
        if (size == 0) {
            return;
        }
        double bound = bounds[size];
        int node = nodes[size];
        int parent = 0;
        while (true) {
            int child = 2 * parent + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && bounds[child + 1] < bounds[child]) {
                child++;
            }
            if (bounds[child] >= bound) {
                break;
            }
            bounds[parent] = bounds[child];
            nodes[parent] = nodes[child];
            parent = child;
        }
        bounds[parent] = bound;
        nodes[parent] = node;
    }
}
