package org.scenes.internal.match;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.scenes.api.ActionType;
import org.scenes.api.PackedMetric;
import org.scenes.api.Scene;
import org.scenes.api.TopK;

/**
 * An exact index for {@link ObjectSetMetric} configurations whose weighted groups hold at most
 * one object in every stored scene (ball, goals; the previous scene's too with {@code memory}),
 * with or without memory terms: the low-dimensional configurations, such as the tuned Krislet
 * one. As the {@code ball-goal} index does, it groups, bounds and visits cheapest first:
 * <ul>
 * <li>scenes with the same objects and previous action class (every float equal) are one
 * <em>point</em>, which offers its k lowest indices;</li>
 * <li>points are sorted into buckets by which groups they hold and (with {@code memory-action})
 * their previous action class; one k-d tree spans them all. Its upper nodes split between
 * buckets, one held group at a time, so that a node lacking what the query holds (or holding
 * what it lacks) is bounded by the penalty at once; then between previous action classes. Its
 * lower ones split within a bucket on the widest weighted float, at the boundary between two
 * values nearest the median (rows and sides of the heading repeat a few values). A node keeps
 * which groups some and all of its points hold, their previous action classes, per group the box
 * of a and b of the points holding it, which additive tuples (weighted row, sides) they hold and
 * their least unmatched penalty, and the least scene index;</li>
 * <li>a query visits nodes in order of a lower bound of their distance (per group the least of
 * the box gap plus the cost to the nearest held additive tuple and the penalty of a missing
 * partner; the memory-action cost unless the node holds the query's class) and stops once that
 * bound exceeds the k-th best, or equals it and the node holds no lower index.</li>
 * </ul>
 * Distances offered are computed as {@link ObjectSetMetric#groupDistance} computes them, in the
 * exhaustive path's order, so they are bit-identical to it; bounds are shaved against float
 * rounding. Read-only once built: queries keep their scratch per call.
 */
final class LowDimensionalIndex implements PackedMetric.PackedScenes {
    private static final int LEAF = 16;
    /** Bounds are lowered by this share: single-precision pair costs are within 3e-7 of the exact one. */
    private static final double SHAVE = 1e-6;

    private final ObjectSetMetric metric;
    private final int stride;
    private final boolean polar;
    private final boolean optimal;
    private final double memoryAction;
    /** Per slot (a weighted group of the scene, then of its previous scene) its group and weight. */
    private final int[] slotGroup;
    private final boolean[] slotPrevious;
    private final double[] slotWeight;
    private final int width;
    /** Per point its floats (slot after slot, stride each), slot mask, previous action class, indices. */
    private final float[] values;
    private final int[] mask;
    private final int[] actionClass;
    private final int[] indexStart;
    private final int[] indices;
    // the k-d tree, packed so that a node's bound reads two short runs of memory: per node NODE_INTS
    // ints (point range, children or -1 for leaves, slots some and all of its points hold, their
    // previous action classes as bits class + 1, least index) and boxStride floats (per slot the
    // box of a and b as min, max, then the least penalty, rounded down) and per slot a long (the
    // additive tuples its points hold, as bits)
    private static final int FROM = 0;
    private static final int TO = 1;
    private static final int LEFT = 2;
    private static final int RIGHT = 3;
    private static final int SOME = 4;
    private static final int ALL = 5;
    private static final int CLASSES = 6;
    private static final int INDEX = 7;
    private static final int NODE_INTS = 8;
    private final int[] nodeInts;
    /** Floats of a slot's box: min and max of a and b, the least penalty. */
    private static final int SLOT_BOX = 5;
    private static final int LEAST_AT = 4;
    /** Per slot its distinct additive tuples (weighted row, sides), additive floats each. */
    private final float[][] categoryValues;
    /** Per node and box, which of its slot's categories its points hold (bit per category). */
    private final long[] nodeCategory;
    /** Where each box's categories start in a query's table of costs to them (one more: the end). */
    private final int[] categoryAt;
    /** Where a slot's box starts within a node's floats; slots no stored scene holds have none (-1). */
    private final int[] slotBoxAt;
    private final int boxStride;
    private final float[] nodeBox;
    /** Per box (slot with a box, in order) its slot's bit and weight. */
    private final int[] boxBit;
    private final double[] boxWeight;

    private LowDimensionalIndex(ObjectSetMetric metric, int[] slotGroup, boolean[] slotPrevious, double[] slotWeight,
                                float[] values, int[] mask, int[] actionClass, int[] indexStart, int[] indices, Tree tree) {
        this.metric = metric;
        this.stride = metric.stride();
        ObjectSetMetric.Settings settings = metric.settings();
        this.polar = settings.space() == ObjectSetMetric.Space.POLAR;
        this.optimal = !metric.greedy();
        this.memoryAction = settings.memoryActionWeight();
        this.slotGroup = slotGroup;
        this.slotPrevious = slotPrevious;
        this.slotWeight = slotWeight;
        this.width = slotGroup.length * stride;
        this.values = values;
        this.mask = mask;
        this.actionClass = actionClass;
        this.indexStart = indexStart;
        this.indices = indices;
        this.categoryValues = tree.categoryValues;
        int nodes = tree.from.size();
        int anywhere = nodes == 0 ? 0 : tree.some.get(0);
        this.slotBoxAt = new int[slotGroup.length];
        int boxes = 0;
        for (int s = 0; s < slotGroup.length; s++) {
            slotBoxAt[s] = (anywhere & 1 << s) != 0 ? SLOT_BOX * boxes++ : -1;
        }
        this.boxStride = boxes * SLOT_BOX;
        this.boxBit = new int[boxes];
        this.boxWeight = new double[boxes];
        this.categoryAt = new int[boxes + 1];
        for (int s = 0; s < slotGroup.length; s++) {
            if (slotBoxAt[s] >= 0) {
                int b = slotBoxAt[s] / SLOT_BOX;
                boxWeight[b] = slotWeight[s];
                boxBit[b] = 1 << s;
                categoryAt[b + 1] = categoryAt[b] + tree.categoryCount[s];
            }
        }
        this.nodeInts = new int[nodes * NODE_INTS];
        this.nodeBox = new float[nodes * boxStride];
        this.nodeCategory = new long[nodes * boxes];
        for (int node = 0; node < nodes; node++) {
            int at = node * NODE_INTS;
            nodeInts[at + FROM] = tree.from.get(node);
            nodeInts[at + TO] = tree.to.get(node);
            nodeInts[at + LEFT] = tree.left.get(node);
            nodeInts[at + RIGHT] = tree.right.get(node);
            nodeInts[at + SOME] = tree.some.get(node);
            nodeInts[at + ALL] = tree.all.get(node);
            nodeInts[at + CLASSES] = tree.classes.get(node);
            nodeInts[at + INDEX] = tree.index.get(node);
            for (int s = 0; s < slotGroup.length; s++) {
                if (slotBoxAt[s] < 0) {
                    continue;
                }
                int box = node * boxStride + slotBoxAt[s];
                for (int c = 0; c < 2; c++) {
                    nodeBox[box + 2 * c] = tree.min.get(node * width + s * stride + c);
                    nodeBox[box + 2 * c + 1] = tree.max.get(node * width + s * stride + c);
                }
                nodeCategory[node * boxes + slotBoxAt[s] / SLOT_BOX] = tree.category.get(node * slotGroup.length + s);
                double least = tree.penalty.get(node * slotGroup.length + s);
                float rounded = (float) least;
                nodeBox[box + LEAST_AT] = rounded > least ? Math.nextDown(rounded) : rounded;
            }
        }
    }

    /** Points: how many in this index (distinct scenes as compared), for tests and docs. */
    int points() {
        return mask.length;
    }

    /**
     * The index, or null when some weighted group holds more than one object in a stored scene
     * (or there are more than 30 slots, or more than 64 distinct additive tuples in a slot),
     * where the other paths serve.
     */
    static LowDimensionalIndex build(ObjectSetMetric metric, List<Scene> scenes) {
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
        LowDimensionalIndex shape = new LowDimensionalIndex(metric, slotGroup, slotPrevious, slotWeight, values, mask,
                actionClass, indexStart, indices, new Tree());
        return shape.withTree();
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

    /** The tree under construction, in growable lists. */
    private static final class Tree {
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
    }

    private static final class FloatList {
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

    /**
     * Numbers each slot's distinct additive tuples (weighted row, sides: a few values each) into
     * the tree: a node then keeps which of them its points hold as bits, which bounds their cost
     * more tightly and more cheaply than a box. False beyond 64 in some slot.
     */
    private boolean categorize(Tree tree) {
        int slots = slotGroup.length;
        int additiveAt = metric.additiveAt();
        int additive = stride - additiveAt;
        int points = mask.length;
        tree.categoryValues = new float[slots][];
        tree.categoryCount = new int[slots];
        tree.pointCategory = new int[points * slots];
        float[] table = new float[Long.SIZE * additive];
        for (int s = 0; s < slots; s++) {
            int count = 0;
            for (int p = 0; p < points; p++) {
                if ((mask[p] & 1 << s) == 0) {
                    continue;
                }
                int at = p * width + s * stride + additiveAt;
                int c = 0;
                while (c < count && !Arrays.equals(table, c * additive, (c + 1) * additive, values, at, at + additive)) {
                    c++;
                }
                if (c == count) {
                    if (count == Long.SIZE) {
                        return false;
                    }
                    System.arraycopy(values, at, table, c * additive, additive);
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
     * This index with its k-d tree: the points reordered within each bucket so that every
     * node is a contiguous range.
     */
    private LowDimensionalIndex withTree() {
        int points = mask.length;
        int[] order = new int[points];
        for (int p = 0; p < points; p++) {
            order[p] = p;
        }
        List<Integer> bucketStarts = new ArrayList<>();
        for (int p = 0; p <= points; p++) {
            if (p == 0 || p == points || mask[p] != mask[p - 1] || actionClass[p] != actionClass[p - 1]) {
                bucketStarts.add(p);
            }
        }
        Tree tree = new Tree();
        if (!categorize(tree)) {
            return null;
        }
        int root = node(tree, order, 0, points);
        buckets(tree, order, bucketStarts.stream().mapToInt(Integer::intValue).toArray(), 0, bucketStarts.size() - 1, root);
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
        return new LowDimensionalIndex(metric, slotGroup, slotPrevious, slotWeight, sortedValues, sortedMask, sortedClass,
                sortedStart, sortedIndices, tree);
    }

    /**
     * The children of a node over buckets [first, last) (bucket b being points starts[b] to
     * starts[b + 1]): one bucket is split by its floats; several are halved at the bucket boundary
     * nearest the middle point, so buckets of every size sit under one root.
     */
    private void buckets(Tree tree, int[] order, int[] starts, int first, int last, int node) {
        if (last - first == 1) {
            split(tree, order, node);
            return;
        }
        int from = starts[first];
        int to = starts[last];
        int middle = first + 1;
        int differ = mask[starts[first]] ^ mask[starts[last - 1]];
        if (differ != 0) {
            // buckets are in order of their masks: split where the highest slot bit in which they differ turns on
            int bit = Integer.highestOneBit(differ);
            while ((mask[starts[middle]] & bit) == 0) {
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
    private int children(Tree tree, int[] order, int node, int middle) {
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
    private int node(Tree tree, int[] order, int from, int to) {
        int node = tree.from.size();
        tree.from.add(from);
        tree.to.add(to);
        tree.left.add(-1);
        tree.right.add(-1);
        int slots = slotGroup.length;
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
            some |= mask[p];
            all &= mask[p];
            classes |= 1 << (actionClass[p] + 1);
            for (int s = 0; s < slots; s++) {
                if ((mask[p] & 1 << s) == 0) {
                    continue;
                }
                for (int f = s * stride; f < (s + 1) * stride; f++) {
                    float v = values[p * width + f];
                    low[f] = Math.min(low[f], v);
                    high[f] = Math.max(high[f], v);
                }
                penalty[s] = Math.min(penalty[s], metric.penalty(values, p * width + s * stride));
                categories[s] |= 1L << tree.pointCategory[p * slots + s];
            }
            least = Math.min(least, indices[indexStart[p]]);
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
    private void split(Tree tree, int[] order, int node) {
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
            if ((mask[order[from]] & 1 << s) == 0 || f % stride == metric.penaltyIndex()) {
                continue;
            }
            double e = slotWeight[s] * ((double) high[f] - low[f]);
            if (e > extent) {
                extent = e;
                widest = f;
            }
        }
        if (widest < 0) {
            return; // all points alike in every compared float (cannot happen for distinct points)
        }
        int middle = (from + to) >>> 1;
        // sorted as primitive keys: the float made order-preserving in the high half, the point in the low
        long[] keys = new long[to - from];
        for (int r = from; r < to; r++) {
            int bits = Float.floatToIntBits(values[order[r] * width + widest]);
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

    /**
     * A query as every node bound reads it, with the heap of its search. Per box: what
     * the query holds in its slot, its a and b, its object's penalty, its additive cost to each
     * of the slot's categories and which of them cost nothing. Slots without a box (no stored
     * scene holds their object) add the same to every bound.
     */
    private final class Query {
        static final int LACKS = 0;
        static final int HOLDS = 1;
        static final int SEVERAL = 2;
        final float[][] objects = new float[slotGroup.length][];
        final int[] counts = new int[slotGroup.length];
        final int[] mode = new int[boxWeight.length];
        final double[] boxPenalty = new double[boxWeight.length];
        final float[] position = new float[2 * boxWeight.length];
        final double[] categoryGap = new double[categoryAt[boxWeight.length]];
        final long[] free = new long[boxWeight.length];
        final NodeHeap heap = new NodeHeap();
        /** For the exact distance where the query holds several objects in a slot; made when first needed. */
        Assignment.Workspace workspace;
        final int actionClass;
        final int classBit;
        final double constant;

        Query(Scene query) {
            int slots = slotGroup.length;
            float[][] current = metric.encode(query, false).groups();
            float[][] previous = slotPrevious[slots - 1] ? metric.encodePrevious(query.previous()).groups() : null;
            int additiveAt = metric.additiveAt();
            int additive = stride - additiveAt;
            double unmatched = 0;
            for (int s = 0; s < slots; s++) {
                float[] x = (slotPrevious[s] ? previous : current)[slotGroup[s]];
                objects[s] = x;
                counts[s] = x.length / stride;
                double own = counts[s] == 1 ? metric.penalty(x, 0) : 0;
                if (slotBoxAt[s] < 0) {
                    unmatched += slotWeight[s] * own; // the query's object, if single, is unmatched
                    continue;
                }
                int b = slotBoxAt[s] / SLOT_BOX;
                mode[b] = counts[s] == 0 ? LACKS : counts[s] == 1 ? HOLDS : SEVERAL;
                boxPenalty[b] = own;
                if (counts[s] != 1) {
                    continue;
                }
                position[2 * b] = x[0];
                position[2 * b + 1] = x[1];
                float[] table = categoryValues[s];
                for (int c = 0; c < categoryAt[b + 1] - categoryAt[b]; c++) {
                    double gap = 0; // summed as the pair cost sums the additive differences
                    for (int f = 0; f < additive; f++) {
                        gap += Math.abs((double) x[additiveAt + f] - table[c * additive + f]);
                    }
                    categoryGap[categoryAt[b] + c] = gap;
                    if (gap == 0) {
                        free[b] |= 1L << c;
                    }
                }
            }
            constant = unmatched;
            actionClass = memoryAction > 0 && query.previous() != null ? ObjectSetMetric.actionClass(query.previous()) : -1;
            classBit = 1 << (actionClass + 1);
        }

        /** The least additive cost to the categories of box b that {@code held} names. */
        double nearestCategory(int b, long held) {
            double least = Double.POSITIVE_INFINITY;
            for (long rest = held; rest != 0; rest &= rest - 1) {
                least = Math.min(least, categoryGap[categoryAt[b] + Long.numberOfTrailingZeros(rest)]);
            }
            return least;
        }

        Assignment.Workspace workspace() {
            if (workspace == null) {
                workspace = new Assignment.Workspace();
            }
            return workspace;
        }
    }

    @Override
    public void scan(Scene query, TopK top) {
        Query q = new Query(query);
        NodeHeap heap = q.heap;
        heap.push(bound(0, q), 0);
        while (heap.size > 0) {
            double lower = heap.topBound();
            int node = heap.topNode();
            heap.pop();
            double worst = top.bound();
            if (lower > worst) {
                return; // every node left is bounded at least as far
            }
            int at = node * NODE_INTS;
            if (lower == worst && nodeInts[at + INDEX] > top.worstIndex()) {
                continue;
            }
            int left = nodeInts[at + LEFT];
            if (left < 0) {
                for (int p = nodeInts[at + FROM]; p < nodeInts[at + TO]; p++) {
                    offer(p, q, top);
                }
                continue;
            }
            int right = nodeInts[at + RIGHT];
            heap.push(bound(left, q), left);
            heap.push(bound(right, q), right);
        }
    }

    /**
     * A lower bound of the distance of every point under the node, shaved: the memory-action
     * cost unless some point has the query's previous action class, plus per slot the least of
     * what its points can cost: for those holding the slot's object the gap from the query's
     * object to their box of a and b plus its cost to the nearest additive tuple they hold
     * (capped by both penalties for optimal matching) or their least
     * penalty when the query lacks it; for those lacking it the query object's penalty.
     */
    private double bound(int node, Query q) {
        int at = node * NODE_INTS;
        double lower = q.constant;
        if (memoryAction > 0 && (nodeInts[at + CLASSES] & q.classBit) == 0) {
            lower += memoryAction;
        }
        int some = nodeInts[at + SOME];
        int all = nodeInts[at + ALL];
        int box = node * boxStride;
        for (int b = 0; b < boxWeight.length; b++, box += SLOT_BOX) {
            int bit = boxBit[b];
            boolean lacked = (all & bit) == 0;
            double gap;
            switch (q.mode[b]) {
                case Query.LACKS -> gap = lacked ? 0 : nodeBox[box + LEAST_AT];
                case Query.HOLDS -> {
                    gap = lacked ? q.boxPenalty[b] : Double.POSITIVE_INFINITY;
                    if ((some & bit) != 0) {
                        float[] x = q.position;
                        double da = outside(x[2 * b], nodeBox[box], nodeBox[box + 1]);
                        double db = outside(x[2 * b + 1], nodeBox[box + 2], nodeBox[box + 3]);
                        double pair = polar ? da + db : Math.sqrt(da * da + db * db);
                        long held = nodeCategory[node * boxWeight.length + b];
                        if ((held & q.free[b]) == 0) {
                            pair += q.nearestCategory(b, held);
                        }
                        if (optimal) {
                            pair = Math.min(pair, q.boxPenalty[b] + nodeBox[box + LEAST_AT]);
                        }
                        gap = Math.min(gap, pair);
                    }
                }
                default -> gap = 0; // several objects on the query's side: no bound taken
            }
            lower += boxWeight[b] * gap;
        }
        return lower * (1 - SHAVE);
    }

    private static double outside(float value, float low, float high) {
        return value < low ? (double) low - value : value > high ? (double) value - high : 0;
    }

    /** The point's exact distance, summed as the exhaustive path sums it; its k lowest indices offered unless beyond the bound. */
    private void offer(int p, Query q, TopK top) {
        double bound = top.bound();
        double total = 0;
        if (memoryAction > 0 && q.actionClass != actionClass[p]) {
            total += memoryAction;
        }
        int slots = slotGroup.length;
        for (int s = 0; s < slots; s++) {
            double weight = slotWeight[s];
            int m = (mask[p] & 1 << s) != 0 ? 1 : 0;
            int n = q.counts[s];
            // one object on each side needs no workspace: made for a query holding several only
            total += weight * metric.groupDistance(q.objects[s], 0, n, values, p * width + s * stride, m, total, weight,
                    bound, n > 1 ? q.workspace() : null);
            if (total > bound) {
                return;
            }
        }
        int last = Math.min(indexStart[p + 1], indexStart[p] + top.capacity());
        for (int i = indexStart[p]; i < last; i++) {
            top.offer(total, indices[i]);
        }
    }

    /** A min-heap of nodes by lower bound. */
    private static final class NodeHeap {
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
}
