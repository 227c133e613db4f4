package org.scenes.internal.match;

import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;
import org.scenes.api.PackedMetric;
import org.scenes.api.Scene;
import org.scenes.api.TopK;

/**
 * The packed form of {@link ObjectSetMetric}: every stored object's floats, scene after scene
 * (each scene's weighted groups in group order, objects nearest first), in chunks of 256 KB that
 * no scene straddles (no huge array to find room for in a nearly full heap, no copy to grow one),
 * the start of each scene, and each scene's object count per weighted group as an unsigned byte. Scans compute
 * the same sums in the same order as {@link ObjectSetMetric#distance(ObjectSetMetric.Encoded,
 * ObjectSetMetric.Encoded, double)}, so distances are bit-identical to the exhaustive path.
 * Read-only once built: scans keep their scratch per call, so threads share one instance.
 */
final class PackedObjectSets implements PackedMetric.PackedScenes {
    private final ObjectSetMetric metric;
    private final int stride;
    private final int size;
    /** Group numbers of the weighted groups, and their weights. */
    private final int[] groups;
    private final double[] weights;
    private static final int CHUNK_BITS = 16;
    private static final int CHUNK = 1 << CHUNK_BITS;
    private static final int IN_CHUNK = CHUNK - 1;
    private final float[][] chunks;
    /** Where each scene's first float is: chunk number times {@link #CHUNK} plus the index in it. */
    private final int[] starts;
    /** Objects of scene i in weighted group g at {@code counts[i * groups.length + g]}, unsigned. */
    private final byte[] counts;
    /** With memory-action: scene i's remembered action classes at {@code actions[i * depth ..]}; else empty. */
    private final int[] actions;
    private final int depth;

    private PackedObjectSets(ObjectSetMetric metric, int[] groups, float[][] chunks, int[] starts, byte[] counts, int[] actions) {
        this.metric = metric;
        this.stride = metric.stride();
        this.size = starts.length;
        this.groups = groups;
        this.weights = Arrays.stream(groups).mapToDouble(metric::groupWeight).toArray();
        this.chunks = chunks;
        this.starts = starts;
        this.counts = counts;
        this.actions = actions;
        this.depth = metric.memoryDepth();
    }

    /**
     * Two passes, so the chunks are allocated once at their final size: counting (which only
     * reads object kinds), then encoding. Null (the caller then uses the encoded path) when a
     * scene holds more than 255 objects of one group or the floats exceed 2^31.
     */
    static PackedObjectSets pack(ObjectSetMetric metric, List<Scene> scenes) {
        int[] groups = IntStream.range(0, ObjectSetMetric.GROUPS).filter(g -> metric.groupWeight(g) != 0).toArray();
        int n = scenes.size();
        int stride = metric.stride();
        byte[] counts = new byte[n * groups.length];
        int[] starts = new int[n];
        int[] perGroup = new int[ObjectSetMetric.GROUPS];
        long position = 0;
        for (int i = 0; i < n; i++) {
            metric.count(scenes.get(i), perGroup);
            int length = 0;
            for (int g = 0; g < groups.length; g++) {
                int count = perGroup[groups[g]];
                if (count > 255) {
                    return null;
                }
                counts[i * groups.length + g] = (byte) count;
                length += count * stride; // at most 10 * 255 * 6 floats: always fits a chunk
            }
            if ((position & IN_CHUNK) + length > CHUNK) {
                position = (position | IN_CHUNK) + 1; // the next chunk
            }
            if (position + length > Integer.MAX_VALUE) {
                return null;
            }
            starts[i] = (int) position;
            position += length;
        }
        // one chunk past the last full one, maybe empty: a scene without objects may start there
        float[][] chunks = new float[(int) (position >>> CHUNK_BITS) + 1][];
        for (int c = 0; c < chunks.length; c++) {
            chunks[c] = new float[(int) Math.min(CHUNK, position - ((long) c << CHUNK_BITS))];
        }
        for (int i = 0; i < n; i++) {
            float[][] encoded = metric.encode(scenes.get(i), false).groups();
            float[] chunk = chunks[starts[i] >>> CHUNK_BITS];
            int at = starts[i] & IN_CHUNK;
            int first = i * groups.length;
            for (int g = 0; g < groups.length; g++) {
                float[] objects = encoded[groups[g]];
                if (objects.length != (counts[first + g] & 0xFF) * stride) {
                    throw new IllegalStateException("scene " + i + " changed between the packing passes");
                }
                System.arraycopy(objects, 0, chunk, at, objects.length);
                at += objects.length;
            }
        }
        int depth = metric.memoryDepth();
        int[] actions = new int[n * depth];
        for (int i = 0; depth > 0 && i < n; i++) {
            System.arraycopy(metric.rememberedActions(scenes.get(i)), 0, actions, i * depth, depth);
        }
        return new PackedObjectSets(metric, groups, chunks, starts, counts, actions);
    }

    /** Bytes of the packed arrays (the floats with the chunks' unused ends, the starts and the counts). */
    long bytes() {
        long floats = 0;
        for (float[] chunk : chunks) {
            floats += chunk.length;
        }
        return 4 * floats + 4L * starts.length + counts.length + 4L * actions.length;
    }

    @Override
    public void scan(Scene query, TopK top) {
        float[][] encoded = metric.encode(query, false).groups();
        int[] remembered = depth > 0 ? metric.rememberedActions(query) : null;
        float[][] q = new float[groups.length][];
        int[] qn = new int[groups.length];
        for (int g = 0; g < groups.length; g++) {
            q[g] = encoded[groups[g]];
            qn[g] = q[g].length / stride;
        }
        Assignment.Workspace scratch = new Assignment.Workspace();
        // with every object weight 0 there is no group to lead: the general path sums what is left
        if (metric.greedy() && groups.length > 0) {
            int lead = 0;
            for (int g = 1; g < groups.length; g++) {
                if (qn[g] > qn[lead]) {
                    lead = g;
                }
            }
            for (int i = 0; i < size; i++) {
                offerGreedy(q, qn, remembered, i, top, lead);
            }
            return;
        }
        // optimal: scenes in order of a cheap lower bound, stopping once it exceeds the k-th best
        // a heap rather than a full sort: only the few scenes before the stop are taken out
        long[] heap = lowerBounds(q, qn);
        int left = heap.length;
        for (int parent = left / 2 - 1; parent >= 0; parent--) {
            siftDown(heap, parent, left);
        }
        while (left > 0) {
            long key = heap[0];
            if (Float.intBitsToFloat((int) (key >>> 32)) > top.bound()) {
                return;
            }
            heap[0] = heap[--left];
            siftDown(heap, 0, left);
            offer(q, qn, remembered, (int) key, top, scratch);
        }
    }

    /** Restores the min-heap order below {@code parent} in heap[0, size). */
    private static void siftDown(long[] heap, int parent, int size) {
        long key = heap[parent];
        while (true) {
            int child = 2 * parent + 1;
            if (child >= size) {
                break;
            }
            if (child + 1 < size && heap[child + 1] < heap[child]) {
                child++;
            }
            if (heap[child] >= key) {
                break;
            }
            heap[parent] = heap[child];
            parent = child;
        }
        heap[parent] = key;
    }

    /**
     * As {@link #offer}, but the lead group (the query's largest, where most scenes turn out too
     * far) is computed first: its weighted distance alone cannot exceed the total, which adds
     * only terms that are not negative (rounding is monotone), so most scenes are dropped
     * without computing the small groups before it. A kept scene's total is summed in group
     * order from the same group distances, as the exhaustive path sums them.
     */
    private void offerGreedy(float[][] q, int[] qn, int[] remembered, int i, TopK top, int lead) {
        double bound = top.bound();
        int first = i * groups.length;
        float[] data = chunks[starts[i] >>> CHUNK_BITS];
        int at = starts[i] & IN_CHUNK;
        int leadAt = at;
        for (int g = 0; g < lead; g++) {
            leadAt += (counts[first + g] & 0xFF) * stride;
        }
        double leadWeight = weights[lead];
        double leadDistance = metric.groupDistance(q[lead], 0, qn[lead], data, leadAt, counts[first + lead] & 0xFF,
                0, leadWeight, bound, null);
        if (leadWeight * leadDistance > bound) {
            return;
        }
        double total = remembered == null ? 0 : metric.actionsDistance(remembered, actions, i * depth);
        for (int g = 0; g < groups.length; g++) {
            int m = counts[first + g] & 0xFF;
            double weight = weights[g];
            double distance = g == lead ? leadDistance : metric.groupDistance(q[g], 0, qn[g], data, at, m, total, weight, bound, null);
            total += weight * distance;
            if (total > bound) {
                return;
            }
            at += m * stride;
        }
        top.offer(total, i);
    }

    /** The exact distance of scene i, offered unless it is found to exceed the bound on the way. */
    private void offer(float[][] q, int[] qn, int[] remembered, int i, TopK top, Assignment.Workspace scratch) {
        double bound = top.bound();
        // the lower bounds leave the action cost out: still bounds, as it is not negative
        double total = remembered == null ? 0 : metric.actionsDistance(remembered, actions, i * depth);
        float[] data = chunks[starts[i] >>> CHUNK_BITS];
        int at = starts[i] & IN_CHUNK;
        int first = i * groups.length;
        for (int g = 0; g < groups.length; g++) {
            int m = counts[first + g] & 0xFF;
            double weight = weights[g];
            total += weight * metric.groupDistance(q[g], 0, qn[g], data, at, m, total, weight, bound, scratch);
            if (total > bound) {
                return;
            }
            at += m * stride;
        }
        top.offer(total, i); // NaN too, which the heap ranks farthest
    }

    /**
     * Per scene a lower bound of its optimal-matching distance in O(objects): exact for groups
     * of at most one object per side, else {@link #mergeBound}. Returned as sort keys: the bound
     * rounded down to a float in the high half (non-negative floats order as their bits), the
     * scene's index in the low half, so sorting the keys orders scenes by bound, then index.
     */
    private long[] lowerBounds(float[][] q, int[] qn) {
        double[][] qs = new double[groups.length][];
        double[][] qp = new double[groups.length][];
        double[] qd = new double[groups.length];
        double[] lonePenalty = new double[groups.length];
        for (int g = 0; g < groups.length; g++) {
            lonePenalty[g] = qn[g] == 1 ? metric.penalty(q[g], 0) : 0;
            qs[g] = new double[qn[g]];
            qp[g] = new double[qn[g]];
            qd[g] = monotone(q[g], 0, qn[g], qs[g], qp[g]);
        }
        double[] ys = new double[256];
        double[] yp = new double[256];
        long[] keys = new long[size];
        for (int i = 0; i < size; i++) {
            double lower = 0;
            float[] data = chunks[starts[i] >>> CHUNK_BITS];
            int at = starts[i] & IN_CHUNK;
            int first = i * groups.length;
            for (int g = 0; g < groups.length; g++) {
                int m = counts[first + g] & 0xFF;
                int n = qn[g];
                if (n <= 1 && m <= 1) {
                    // as singleDistance, with the query's penalty computed once
                    double exact = n == 1 && m == 1 ? Math.min(metric.pairCost(q[g], 0, data, at), lonePenalty[g] + metric.penalty(data, at))
                            : n == 1 ? lonePenalty[g] : m == 1 ? metric.penalty(data, at) : 0;
                    lower += weights[g] * exact;
                } else {
                    double dy = monotone(data, at, m, ys, yp);
                    lower += weights[g] * mergeBound(qs[g], qp[g], n, qd[g], ys, yp, m, dy);
                }
                at += m * stride;
            }
            // shaved: the exact distance sums other terms, which round differently
            double shaved = lower * (1 - 1e-9);
            if (!(shaved >= 0)) {
                shaved = 0;
            }
            float key = (float) shaved;
            if (key > shaved) {
                key = Math.nextDown(key);
            }
            keys[i] = (long) Float.floatToRawIntBits(Math.max(key, 0f)) << 32 | i;
        }
        return keys;
    }

    /**
     * The radial coordinates ({@link ObjectSetMetric#radial}) of n objects made non-decreasing
     * (each the running maximum) into s, their penalties into p; returns the most any object's
     * coordinate was raised (0 when already sorted), so bounds can allow for it.
     */
    private double monotone(float[] x, int at, int n, double[] s, double[] p) {
        double running = Double.NEGATIVE_INFINITY;
        double raised = 0;
        boolean derived = metric.penaltyFollowsRadial();
        for (int k = 0; k < n; k++) {
            int object = at + k * stride;
            double radial = metric.radial(x, object);
            if (radial >= running) {
                running = radial;
            } else {
                raised = Math.max(raised, running - radial);
            }
            s[k] = running;
            p[k] = derived ? metric.penaltyAt(radial) : metric.penalty(x, object);
        }
        return raised;
    }

    /**
     * A lower bound of a group's optimal matching cost from the radial coordinates alone (pair
     * cost >= |s(x) - s(y)|), by one merge of the two sorted sides. With m(x) the smallest
     * radial gap from x to the other side (less the slack for raised coordinates and rounding):
     * every object of a side is paired (at cost >= m) or unmatched (at its penalty p), so the sum
     * over a side of min(p, m) is a bound; and since a pair costs at most both penalties, a pair
     * costs at least min(p(x), m(x)/2) + min(p(y), m(y)/2), so the sum over both sides of
     * min(p, m/2) is one too. The largest of the three is returned.
     */
    private static double mergeBound(double[] xs, double[] xp, int n, double dx, double[] ys, double[] yp, int m, double dy) {
        double scale = (n > 0 ? Math.abs(xs[0]) + Math.abs(xs[n - 1]) : 0) + (m > 0 ? Math.abs(ys[0]) + Math.abs(ys[m - 1]) : 0);
        // single-precision pair costs are within 3 float roundings (< 2.4e-7) of the exact distance
        double slack = dx + dy + 1e-6 * (scale + 1);
        double sumX = 0;
        double halfX = 0;
        for (int i = 0, j = 0; i < n; i++) {
            double v = xs[i];
            while (j < m && ys[j] < v) {
                j++;
            }
            double near = j < m ? ys[j] - v : Double.POSITIVE_INFINITY;
            if (j > 0) {
                near = Math.min(near, v - ys[j - 1]);
            }
            double reach = Math.max(0, near - slack);
            sumX += Math.min(xp[i], reach);
            halfX += Math.min(xp[i], 0.5 * reach);
        }
        double sumY = 0;
        double halfY = 0;
        for (int j = 0, i = 0; j < m; j++) {
            double v = ys[j];
            while (i < n && xs[i] < v) {
                i++;
            }
            double near = i < n ? xs[i] - v : Double.POSITIVE_INFINITY;
            if (i > 0) {
                near = Math.min(near, v - xs[i - 1]);
            }
            double reach = Math.max(0, near - slack);
            sumY += Math.min(yp[j], reach);
            halfY += Math.min(yp[j], 0.5 * reach);
        }
        return Math.max(Math.max(sumX, sumY), halfX + halfY);
    }
}
