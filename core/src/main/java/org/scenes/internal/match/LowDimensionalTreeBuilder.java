package org.scenes.internal.match;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Grows {@link LowDimensionalIndex}'s k-d tree over its points (see the index for the layout):
 * buckets by held groups and previous action class under one root, then within a bucket splits
 * at the widest weighted float, between two values near the median.
 */
final class LowDimensionalTreeBuilder {
    private static final int LEAF = 16;

    private final LowDimensionalPoints points;
    private final ObjectSetMetric metric;
    private final int stride;
    private final int width;

    LowDimensionalTreeBuilder(LowDimensionalPoints points) {
        this.points = points;
        this.metric = points.metric();
        this.stride = metric.stride();
        this.width = points.slotGroup().length * stride;
    }

    /**
     * Grows the tree over the points into {@code tree}: the points reordered within each bucket so
     * that every node is a contiguous range. Returns that order, or null beyond 64 additive tuples
     * in some slot.
     */
    int[] grow(LowDimensionalTree tree) {
        int pointCount = points.mask().length;
        int[] order = new int[pointCount];
        for (int p = 0; p < pointCount; p++) {
            order[p] = p;
        }
        List<Integer> bucketStarts = new ArrayList<>();
        for (int p = 0; p <= pointCount; p++) {
            if (p == 0 || p == pointCount || points.mask()[p] != points.mask()[p - 1]
                    || points.actionClass()[p] != points.actionClass()[p - 1]) {
                bucketStarts.add(p);
            }
        }
        if (!categorize(tree)) {
            return null;
        }
        int root = node(tree, order, 0, pointCount);
        buckets(tree, order, bucketStarts.stream().mapToInt(Integer::intValue).toArray(), 0, bucketStarts.size() - 1, root);
        return order;
    }

    /**
     * Numbers each slot's distinct additive tuples (weighted row, sides: a few values each) into
     * the tree: a node then keeps which of them its points hold as bits, which bounds their cost
     * more tightly and more cheaply than a box. False beyond 64 in some slot.
     */
    private boolean categorize(LowDimensionalTree tree) {
        int slots = points.slotGroup().length;
        int additiveAt = metric.additiveAt();
        int additive = stride - additiveAt;
        int pointCount = points.mask().length;
        tree.categoryValues = new float[slots][];
        tree.categoryCount = new int[slots];
        tree.pointCategory = new int[pointCount * slots];
        float[] table = new float[Long.SIZE * additive];
        for (int s = 0; s < slots; s++) {
            int count = 0;
            for (int p = 0; p < pointCount; p++) {
                if ((points.mask()[p] & 1 << s) == 0) {
                    continue;
                }
                int at = p * width + s * stride + additiveAt;
                int c = 0;
                while (c < count && !Arrays.equals(table, c * additive, (c + 1) * additive, points.values(), at, at + additive)) {
                    c++;
                }
                if (c == count) {
                    if (count == Long.SIZE) {
                        return false;
                    }
                    System.arraycopy(points.values(), at, table, c * additive, additive);
                    count++;
                }
                tree.pointCategory[p * slots + s] = c;
            }
            tree.categoryCount[s] = count;
            tree.categoryValues[s] = Arrays.copyOf(table, count * additive);
        }
        return true;
    }

    /**
     * The children of a node over buckets [first, last) (bucket b being points starts[b] to
     * starts[b + 1]): one bucket is split by its floats; several are halved at the bucket boundary
     * nearest the middle point, so buckets of every size sit under one root.
     */
    private void buckets(LowDimensionalTree tree, int[] order, int[] starts, int first, int last, int node) {
        if (last - first == 1) {
            split(tree, order, node);
            return;
        }
        int from = starts[first];
        int to = starts[last];
        int middle = first + 1;
        int differ = points.mask()[starts[first]] ^ points.mask()[starts[last - 1]];
        if (differ != 0) {
            // buckets are in order of their masks: split where the highest slot bit in which they differ turns on
            int bit = Integer.highestOneBit(differ);
            while ((points.mask()[starts[middle]] & bit) == 0) {
                middle++;
            }
        } else {
            for (int b = first + 2; b < last; b++) {
                if (Math.abs(2L * starts[b] - from - to) < Math.abs(2L * starts[middle] - from - to)) {
                    middle = b;
                }
            }
        }
        int left = children(tree, order, node, starts[middle]);
        buckets(tree, order, starts, first, middle, left);
        buckets(tree, order, starts, middle, last, left + 1);
    }

    /**
     * Two children of the node, split at point {@code middle}, made one after the other: a query
     * computes both bounds together, from one run of memory. Returns the left one.
     */
    private int children(LowDimensionalTree tree, int[] order, int node, int middle) {
        int left = node(tree, order, tree.from.get(node), middle);
        int right = node(tree, order, middle, tree.to.get(node));
        tree.left.set(node, left);
        tree.right.set(node, right);
        return left;
    }

    /**
     * A new leaf over order[from, to): which slots some and all of its points hold, their
     * classes, per slot the box of the floats and the least penalty of the points holding it,
     * the least scene index.
     */
    private int node(LowDimensionalTree tree, int[] order, int from, int to) {
        int node = tree.from.size();
        tree.from.add(from);
        tree.to.add(to);
        tree.left.add(-1);
        tree.right.add(-1);
        int slots = points.slotGroup().length;
        float[] low = new float[width];
        float[] high = new float[width];
        Arrays.fill(low, Float.POSITIVE_INFINITY);
        Arrays.fill(high, Float.NEGATIVE_INFINITY);
        double[] penalty = new double[slots];
        Arrays.fill(penalty, Double.POSITIVE_INFINITY);
        long[] categories = new long[slots];
        int least = Integer.MAX_VALUE;
        int some = 0;
        int all = -1;
        int classes = 0;
        for (int r = from; r < to; r++) {
            int p = order[r];
            some |= points.mask()[p];
            all &= points.mask()[p];
            classes |= 1 << (points.actionClass()[p] + 1);
            for (int s = 0; s < slots; s++) {
                if ((points.mask()[p] & 1 << s) == 0) {
                    continue;
                }
                for (int f = s * stride; f < (s + 1) * stride; f++) {
                    float v = points.values()[p * width + f];
                    low[f] = Math.min(low[f], v);
                    high[f] = Math.max(high[f], v);
                }
                penalty[s] = Math.min(penalty[s], metric.penalty(points.values(), p * width + s * stride));
                categories[s] |= 1L << tree.pointCategory[p * slots + s];
            }
            least = Math.min(least, points.indices()[points.indexStart()[p]]);
        }
        tree.some.add(some);
        tree.all.add(all);
        tree.classes.add(classes);
        for (int f = 0; f < width; f++) {
            tree.min.add(low[f]);
            tree.max.add(high[f]);
        }
        for (int s = 0; s < slots; s++) {
            tree.penalty.add(penalty[s]);
            tree.category.add(categories[s]);
        }
        tree.index.add(least);
        return node;
    }

    /** Below a node within one bucket and above a leaf's size, children split at the median of the widest weighted float. */
    private void split(LowDimensionalTree tree, int[] order, int node) {
        int from = tree.from.get(node);
        int to = tree.to.get(node);
        if (to - from <= LEAF) {
            return;
        }
        float[] low = new float[width];
        float[] high = new float[width];
        for (int f = 0; f < width; f++) {
            low[f] = tree.min.get(node * width + f);
            high[f] = tree.max.get(node * width + f);
        }
        int widest = -1;
        double extent = 0;
        for (int f = 0; f < width; f++) {
            int s = f / stride;
            if ((points.mask()[order[from]] & 1 << s) == 0 || f % stride == metric.penaltyIndex()) {
                continue;
            }
            double e = points.slotWeight()[s] * ((double) high[f] - low[f]);
            if (e > extent) {
                extent = e;
                widest = f;
            }
        }
        if (widest < 0) {
            return; // all pointCount alike in every compared float (cannot happen for distinct pointCount)
        }
        int middle = (from + to) >>> 1;
        // sorted as primitive keys: the float made order-preserving in the high half, the point in the low
        long[] keys = new long[to - from];
        for (int r = from; r < to; r++) {
            int bits = Float.floatToIntBits(points.values()[order[r] * width + widest]);
            int ordered = bits ^ ((bits >> 31) & 0x7fffffff);
            keys[r - from] = (long) ordered << 32 | (order[r] & 0xffffffffL);
        }
        Arrays.sort(keys);
        for (int r = from; r < to; r++) {
            order[r] = (int) keys[r - from];
        }
        middle = from + betweenValues(keys, middle - from);
        int left = children(tree, order, node, middle);
        split(tree, order, left);
        split(tree, order, left + 1);
    }

    /**
     * Where to split sorted keys (value in the high half) near position {@code middle}: the
     * nearest boundary between two values that leaves each side at least an eighth, else middle.
     * Equal values on both sides (rows, sides of the heading, repeated positions) would leave
     * both children's boxes around a query that has that value, and the search would visit both.
     */
    private static int betweenValues(long[] keys, int middle) {
        int n = keys.length;
        for (int d = 0; d <= n / 2 - n / 8; d++) {
            if (startsValue(keys, middle - d)) {
                return middle - d;
            }
            if (startsValue(keys, middle + d)) {
                return middle + d;
            }
        }
        return middle;
    }

    private static boolean startsValue(long[] keys, int r) {
        return r > 0 && r < keys.length && keys[r] >>> 32 != keys[r - 1] >>> 32;
    }
}
