package org.scenes.internal.match;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * {@link LowDimensionalIndex}'s k-d tree under construction, in growable lists, node after node
 * (see {@link LowDimensionalTreeBuilder}); the index packs it into flat arrays once grown.
 */
final class LowDimensionalTree {
    final List<Integer> from = new ArrayList<>();
    final List<Integer> to = new ArrayList<>();
    final List<Integer> left = new ArrayList<>();
    final List<Integer> right = new ArrayList<>();
    final List<Integer> some = new ArrayList<>();
    final List<Integer> all = new ArrayList<>();
    final List<Integer> classes = new ArrayList<>();
    final FloatList min = new FloatList();
    final FloatList max = new FloatList();
    final List<Double> penalty = new ArrayList<>();
    final List<Long> category = new ArrayList<>();
    final List<Integer> index = new ArrayList<>();
    /** Per slot its distinct additive tuples; per point and slot the index of its tuple there. */
    float[][] categoryValues;
    int[] categoryCount;
    int[] pointCategory;

    static final class FloatList {
        private float[] data = new float[64];
        private int size;

        void add(float value) {
            if (size == data.length) {
                data = Arrays.copyOf(data, size * 2);
            }
            data[size++] = value;
        }

        float get(int i) {
            return data[i];
        }

        float[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }
}
