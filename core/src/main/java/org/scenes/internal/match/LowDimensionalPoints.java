package org.scenes.internal.match;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.scenes.api.ActionType;
import org.scenes.api.Scene;

/**
 * The distinct points of a knowledge base as {@link LowDimensionalIndex} compares them. A slot is
 * a weighted group of the scene, then (with memory) of its previous scene, each with its group
 * and weight. Per point its floats (slot after slot, stride each), its slot mask (which slots
 * hold an object), its previous action class (-1 for none) and, from {@code indexStart}, the
 * indices of the scenes it stands for.
 */
record LowDimensionalPoints(ObjectSetMetric metric, int[] slotGroup, boolean[] slotPrevious, double[] slotWeight,
                            float[] values, int[] mask, int[] actionClass, int[] indexStart, int[] indices) {
    /**
     * The points of the scenes, or null when some weighted group holds more than one object in a
     * stored scene (or there are more than 30 slots), where the other paths serve.
     */
    static LowDimensionalPoints of(ObjectSetMetric metric, List<Scene> scenes) {
        ObjectSetMetric.Settings settings = metric.settings();
        List<Integer> groups = new ArrayList<>();
        for (int g = 0; g < ObjectSetMetric.GROUPS; g++) {
            if (metric.groupWeight(g) != 0) {
                groups.add(g);
            }
        }
        boolean remember = settings.memoryWeight() > 0;
        int slots = groups.size() * (remember ? 2 : 1);
        if (slots == 0 || slots > 30) {
            return null;
        }
        int[] slotGroup = new int[slots];
        boolean[] slotPrevious = new boolean[slots];
        double[] slotWeight = new double[slots];
        for (int s = 0; s < slots; s++) {
            slotGroup[s] = groups.get(s % groups.size());
            slotPrevious[s] = s >= groups.size();
            // as ObjectSetMetric.distance weighs them: scale times the group's weight
            slotWeight[s] = (slotPrevious[s] ? settings.memoryWeight() : 1) * metric.groupWeight(slotGroup[s]);
        }
        int stride = metric.stride();
        int width = slots * stride;
        int n = scenes.size();
        // one pass (each stored scene is decoded once): encode, and give up at a group of two objects
        float[] all = new float[Math.multiplyExact(n, width)];
        if (ActionType.values().length * 3 > 31) {
            return null; // previous action classes (and none) must fit a node's bits
        }
        int[] sceneMask = new int[n];
        int[] sceneClass = new int[n];
        for (int i = 0; i < n; i++) {
            Scene scene = scenes.get(i);
            float[][] current = metric.encode(scene, false).groups();
            float[][] previous = remember ? metric.encodePrevious(scene.previous()).groups() : null;
            for (int s = 0; s < slots; s++) {
                float[] objects = (slotPrevious[s] ? previous : current)[slotGroup[s]];
                if (objects.length > stride) {
                    return null;
                }
                if (objects.length > 0) {
                    sceneMask[i] |= 1 << s;
                    System.arraycopy(objects, 0, all, i * width + s * stride, stride);
                }
            }
            sceneClass[i] = settings.memoryActionWeight() > 0 && scene.previous() != null
                    ? ObjectSetMetric.actionClass(scene.previous()) : -1;
        }
        // scenes in order of (mask, class, floats, index): equal runs are points, buckets contiguous
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (x, y) -> {
            int c = Integer.compare(sceneMask[x], sceneMask[y]);
            if (c != 0) {
                return c;
            }
            c = Integer.compare(sceneClass[x], sceneClass[y]);
            if (c != 0) {
                return c;
            }
            for (int f = 0; f < width; f++) {
                c = Integer.compare(Float.floatToIntBits(all[x * width + f]), Float.floatToIntBits(all[y * width + f]));
                if (c != 0) {
                    return c;
                }
            }
            return Integer.compare(x, y);
        });
        List<Integer> starts = new ArrayList<>();
        for (int r = 0; r < n; r++) {
            if (r == 0 || !samePoint(all, width, sceneMask, sceneClass, order[r - 1], order[r])) {
                starts.add(r);
            }
        }
        int points = starts.size();
        float[] values = new float[points * width];
        int[] mask = new int[points];
        int[] actionClass = new int[points];
        int[] indexStart = new int[points + 1];
        int[] indices = new int[n];
        for (int p = 0; p < points; p++) {
            int first = order[starts.get(p)];
            System.arraycopy(all, first * width, values, p * width, width);
            mask[p] = sceneMask[first];
            actionClass[p] = sceneClass[first];
            indexStart[p] = starts.get(p);
        }
        indexStart[points] = n;
        for (int r = 0; r < n; r++) {
            indices[r] = order[r];
        }
        return new LowDimensionalPoints(metric, slotGroup, slotPrevious, slotWeight, values, mask, actionClass, indexStart, indices);
    }

    private static boolean samePoint(float[] all, int width, int[] mask, int[] classes, int x, int y) {
        if (mask[x] != mask[y] || classes[x] != classes[y]) {
            return false;
        }
        for (int f = 0; f < width; f++) {
            if (Float.floatToIntBits(all[x * width + f]) != Float.floatToIntBits(all[y * width + f])) {
                return false;
            }
        }
        return true;
    }

    /** These points in the given order, each with its scene indices. */
    LowDimensionalPoints inOrder(int[] order) {
        int points = mask.length;
        int width = slotGroup.length * metric.stride();
        // points in tree order, with their indices
        float[] sortedValues = new float[values.length];
        int[] sortedMask = new int[points];
        int[] sortedClass = new int[points];
        int[] sortedStart = new int[points + 1];
        int[] sortedIndices = new int[indices.length];
        int at = 0;
        for (int r = 0; r < points; r++) {
            int p = order[r];
            System.arraycopy(values, p * width, sortedValues, r * width, width);
            sortedMask[r] = mask[p];
            sortedClass[r] = actionClass[p];
            sortedStart[r] = at;
            for (int i = indexStart[p]; i < indexStart[p + 1]; i++) {
                sortedIndices[at++] = indices[i];
            }
        }
        sortedStart[points] = at;
        return new LowDimensionalPoints(metric, slotGroup, slotPrevious, slotWeight, sortedValues, sortedMask, sortedClass,
                sortedStart, sortedIndices);
    }
}
