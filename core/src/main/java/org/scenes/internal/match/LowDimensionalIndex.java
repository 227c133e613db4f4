package org.scenes.internal.match;

import java.util.List;
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

    private LowDimensionalIndex(LowDimensionalPoints points, LowDimensionalTree tree) {
        ObjectSetMetric metric = points.metric();
        int[] slotGroup = points.slotGroup();
        this.metric = metric;
        this.stride = metric.stride();
        ObjectSetMetric.Settings settings = metric.settings();
        this.polar = settings.space() == ObjectSetMetric.Space.POLAR;
        this.optimal = !metric.greedy();
        this.memoryAction = settings.memoryActionWeight();
        this.slotGroup = slotGroup;
        this.slotPrevious = points.slotPrevious();
        this.slotWeight = points.slotWeight();
        this.width = slotGroup.length * stride;
        this.values = points.values();
        this.mask = points.mask();
        this.actionClass = points.actionClass();
        this.indexStart = points.indexStart();
        this.indices = points.indices();
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
        LowDimensionalPoints points = LowDimensionalPoints.of(metric, scenes);
        if (points == null) {
            return null;
        }
        LowDimensionalTree tree = new LowDimensionalTree();
        int[] order = new LowDimensionalTreeBuilder(points).grow(tree);
        return order == null ? null : new LowDimensionalIndex(points.inOrder(order), tree);
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
}
