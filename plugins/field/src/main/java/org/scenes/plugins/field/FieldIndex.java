package org.scenes.plugins.field;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.scenes.api.PackedMetric;
import org.scenes.api.Scene;
import org.scenes.api.TopK;

/**
 * An exact index for {@code field}: scenes are grouped by what adds a fixed cost (play mode,
 * whether the ball is known and within reach, whether the player is its team's nearest to it,
 * whether the world is located), and each group's weighted features
 * go into a k-d tree split at the median of the dimension that varies most. A query visits groups
 * in ascending fixed cost (their order kept per query state) and stops once that alone passes the
 * k-th best distance; within a group it descends the query's side first and skips any region
 * whose lower bound (updated incrementally, one dimension per node) or leaf box is farther than
 * the k-th best. Offered distances are computed with the
 * very operations of {@link FieldMetricProvider.FieldMetric#distance}, so they are the scan's bit
 * for bit; pruning keeps a relative margin of {@link #SLACK} for the rounding of box bounds, so
 * it never skips a scene the scan would keep. Of scenes at one distance only the k lowest indices
 * can enter, so scenes without a located world are offered k at most.
 */
final class FieldIndex implements PackedMetric.PackedScenes {
    /**
     * Scenes per leaf: with the incremental bound an inner node costs little, so leaves are smaller
     * than the 40 that suited full box costs (10^6 jittered HELIOS scenes, k 10: p99 106 us at 24).
     */
    private static final int LEAF = 24;
    private static final double SLACK = 1e-9;
    private static final int DIMENSIONS = FieldMetricProvider.FEATURES;

    /** Query states whose plan is kept, at most: play modes are a few dozen, times eight ball states. */
    private static final int MAX_PLANS = 1024;

    private final FieldMetricProvider.FieldMetric metric;
    private final List<Group> groups;
    /** Scenes without a located world, ascending: at {@code missing} from every located query, 0 from another. */
    private final int[] unlocated;
    /** Scenes with a located world, ascending. */
    private final int[] located;
    private final Map<String, Plan> plans = new ConcurrentHashMap<>();

    private FieldIndex(FieldMetricProvider.FieldMetric metric, List<Group> groups, int[] unlocated, int[] located) {
        this.metric = metric;
        this.groups = groups;
        this.unlocated = unlocated;
        this.located = located;
    }

    static FieldIndex build(FieldMetricProvider.FieldMetric metric, List<Scene> scenes) {
        Map<String, List<Integer>> byKey = new LinkedHashMap<>();
        Map<String, FieldMetricProvider.Features> keyFeatures = new LinkedHashMap<>();
        List<Integer> unlocated = new ArrayList<>();
        List<Integer> located = new ArrayList<>();
        FieldMetricProvider.Features[] features = new FieldMetricProvider.Features[scenes.size()];
        for (int i = 0; i < scenes.size(); i++) {
            features[i] = metric.encode(scenes.get(i));
            if (features[i].values() == null) {
                unlocated.add(i);
                continue;
            }
            located.add(i);
            String key = features[i].mode() + '\u0000' + features[i].ballKnown() + '\u0000' + features[i].kickable()
                    + '\u0000' + features[i].chaser();
            byKey.computeIfAbsent(key, unused -> new ArrayList<>()).add(i);
            keyFeatures.putIfAbsent(key, features[i]);
        }
        List<Group> groups = new ArrayList<>();
        byKey.forEach((key, members) -> groups.add(Group.of(keyFeatures.get(key), members, features)));
        return new FieldIndex(metric, groups, unlocated.stream().mapToInt(Integer::intValue).toArray(),
                located.stream().mapToInt(Integer::intValue).toArray());
    }

    @Override
    public void scan(Scene query, TopK top) {
        FieldMetricProvider.Features q = metric.encode(query);
        // Equal distances rank by index, so of scenes all at one distance only the k lowest indices can enter.
        int k = top.capacity();
        if (q.values() == null) {
            // an unlocated query is missing away from every located scene, 0 from an unlocated one
            for (int i = 0; i < Math.min(k, unlocated.length); i++) {
                top.offer(0, unlocated[i]);
            }
            for (int i = 0; i < Math.min(k, located.length); i++) {
                top.offer(metric.missing(), located[i]);
            }
            return;
        }
        for (int i = 0; i < Math.min(k, unlocated.length); i++) {
            top.offer(metric.missing(), unlocated[i]);
        }
        Plan plan = plan(q);
        for (int at = 0; at < plan.order.length; at++) {
            double fixed = plan.fixed[at];
            if (pruned(fixed, top)) {
                break;
            }
            groups.get(plan.order[at]).search(q.values(), fixed, top);
        }
    }

    /**
     * The groups in ascending fixed cost from a query of this play mode and ball state, made once
     * per such state and kept (a game has a few dozen); the sort is stable, so equal costs keep build order.
     */
    private Plan plan(FieldMetricProvider.Features q) {
        String key = q.mode() + '\u0000' + q.ballKnown() + '\u0000' + q.kickable() + '\u0000' + q.chaser();
        Plan plan = plans.get(key);
        if (plan != null) {
            return plan;
        }
        double[] costs = new double[groups.size()];
        Integer[] order = new Integer[groups.size()];
        for (int g = 0; g < costs.length; g++) {
            costs[g] = metric.fixedCost(q, groups.get(g).key);
            order[g] = g;
        }
        Arrays.sort(order, Comparator.comparingDouble(g -> costs[g]));
        plan = new Plan(new int[order.length], new double[order.length]);
        for (int at = 0; at < order.length; at++) {
            plan.order[at] = order[at];
            plan.fixed[at] = costs[order[at]];
        }
        if (plans.size() < MAX_PLANS) {
            plans.putIfAbsent(key, plan);
        }
        return plan;
    }

    /** The groups a query visits, in order, and the fixed cost of each. */
    private record Plan(int[] order, double[] fixed) {
    }

    /** Whether a sum of squares of at least {@code lower} cannot enter {@code top}. */
    private static boolean pruned(double lower, TopK top) {
        double bound = top.bound();
        return lower > bound * bound * (1 + SLACK) + SLACK;
    }

    /** The scenes of one play mode and ball state, in a k-d tree over their weighted features. */
    private static final class Group {
        final FieldMetricProvider.Features key;
        final int[] members;
        /** the members' features, row-major in {@link #members}' order after the build's reordering */
        final double[] values;
        /** per node: first and end position in members, children (-1 for a leaf), box min and max */
        final int[] start;
        final int[] end;
        final int[] left;
        final int[] right;
        /** per inner node: the dimension it splits and the value there (left holds no more, right no less) */
        final int[] splitDimension;
        final double[] splitValue;
        final double[] low;
        final double[] high;
        int nodes;

        private Group(FieldMetricProvider.Features key, int[] members, double[] values, int capacity) {
            this.key = key;
            this.members = members;
            this.values = values;
            start = new int[capacity];
            end = new int[capacity];
            left = new int[capacity];
            right = new int[capacity];
            splitDimension = new int[capacity];
            splitValue = new double[capacity];
            low = new double[capacity * DIMENSIONS];
            high = new double[capacity * DIMENSIONS];
        }

        static Group of(FieldMetricProvider.Features key, List<Integer> indices, FieldMetricProvider.Features[] all) {
            int n = indices.size();
            int[] members = indices.stream().mapToInt(Integer::intValue).toArray();
            double[] values = new double[n * DIMENSIONS];
            for (int i = 0; i < n; i++) {
                System.arraycopy(all[members[i]].values(), 0, values, i * DIMENSIONS, DIMENSIONS);
            }
            Group group = new Group(key, members, values, Math.max(1, 4 * n / LEAF + 2));
            group.split(0, n);
            return group;
        }

        /** Builds the node of members [from, to) and returns its number. */
        private int split(int from, int to) {
            int node = nodes++;
            start[node] = from;
            end[node] = to;
            left[node] = -1;
            right[node] = -1;
            int widest = 0;
            double widestVariance = -1;
            for (int d = 0; d < DIMENSIONS; d++) {
                double min = Double.POSITIVE_INFINITY;
                double max = Double.NEGATIVE_INFINITY;
                double sum = 0;
                for (int i = from; i < to; i++) {
                    double v = values[i * DIMENSIONS + d];
                    min = Math.min(min, v);
                    max = Math.max(max, v);
                    sum += v;
                }
                low[node * DIMENSIONS + d] = min;
                high[node * DIMENSIONS + d] = max;
                if (max > min) {
                    // split where the members vary most, not where the range is widest: a few far scenes
                    // (a ball across the pitch) would otherwise choose the dimension (HELIOS: p99 143 -> 120 us)
                    double mean = sum / (to - from);
                    double variance = Double.MIN_VALUE;
                    for (int i = from; i < to; i++) {
                        double deviation = values[i * DIMENSIONS + d] - mean;
                        variance += deviation * deviation;
                    }
                    if (variance > widestVariance) {
                        widestVariance = variance;
                        widest = d;
                    }
                }
            }
            if (to - from > LEAF && widestVariance > 0) {
                int middle = (from + to) >>> 1;
                select(from, to, middle, widest);
                splitDimension[node] = widest;
                splitValue[node] = values[middle * DIMENSIONS + widest];
                left[node] = split(from, middle);
                right[node] = split(middle, to);
            }
            return node;
        }

        /** Reorders [from, to) so position {@code nth} holds its value along {@code d} in sorted order (quickselect). */
        private void select(int from, int to, int nth, int d) {
            int lo = from;
            int hi = to - 1;
            while (lo < hi) {
                double pivot = values[((lo + hi) >>> 1) * DIMENSIONS + d];
                int i = lo;
                int j = hi;
                while (i <= j) {
                    while (values[i * DIMENSIONS + d] < pivot) {
                        i++;
                    }
                    while (values[j * DIMENSIONS + d] > pivot) {
                        j--;
                    }
                    if (i <= j) {
                        swap(i++, j--);
                    }
                }
                if (nth <= j) {
                    hi = j;
                } else if (nth >= i) {
                    lo = i;
                } else {
                    return;
                }
            }
        }

        private void swap(int a, int b) {
            int member = members[a];
            members[a] = members[b];
            members[b] = member;
            for (int d = 0; d < DIMENSIONS; d++) {
                double v = values[a * DIMENSIONS + d];
                values[a * DIMENSIONS + d] = values[b * DIMENSIONS + d];
                values[b * DIMENSIONS + d] = v;
            }
        }

        /** The smallest sum of squares from {@code q} to the box of {@code node}. */
        private double boxCost(int node, double[] q) {
            double sum = 0;
            for (int d = 0; d < DIMENSIONS; d++) {
                double v = q[d];
                double gap = v < low[node * DIMENSIONS + d] ? low[node * DIMENSIONS + d] - v
                        : v > high[node * DIMENSIONS + d] ? v - high[node * DIMENSIONS + d] : 0;
                sum += gap * gap;
            }
            return sum;
        }

        /** Offers the members that can enter, descending from the root. */
        void search(double[] q, double fixed, TopK top) {
            double[] offsets = new double[DIMENSIONS];
            double cost = 0;
            for (int d = 0; d < DIMENSIONS; d++) {
                double v = q[d];
                offsets[d] = v < low[d] ? low[d] - v : v > high[d] ? v - high[d] : 0;
                cost += offsets[d] * offsets[d];
            }
            search(0, cost, offsets, q, fixed, top);
        }

        /**
         * Offers the members of {@code node}'s subtree that can enter. {@code cost} is the sum of
         * {@code offsets}' squares, the query's distance along each dimension from the node's
         * region as its ancestors' splits bound it: a lower bound updated in one dimension per
         * node (Arya and Mount's incremental distance), where recomputing the box would take all
         * nine; a leaf checks its tight box before its scenes.
         */
        private void search(int node, double cost, double[] offsets, double[] q, double fixed, TopK top) {
            if (pruned(fixed + cost, top)) {
                return;
            }
            if (left[node] < 0) {
                if (pruned(fixed + boxCost(node, q), top)) {
                    return;
                }
                for (int i = start[node]; i < end[node]; i++) {
                    // the operations of FieldMetric.distance, in its order; a sum past the bound cannot enter
                    double bound = top.bound();
                    double limit = bound * bound * (1 + SLACK) + SLACK;
                    double sum = fixed;
                    for (int d = 0; d < DIMENSIONS && sum <= limit; d++) {
                        double gap = q[d] - values[i * DIMENSIONS + d];
                        sum += gap * gap;
                    }
                    if (sum <= limit) {
                        top.offer(Math.sqrt(sum), members[i]);
                    }
                }
                return;
            }
            int d = splitDimension[node];
            double gap = q[d] - splitValue[node];
            // the query's side first; the other side lies at least |gap| away along d
            search(gap < 0 ? left[node] : right[node], cost, offsets, q, fixed, top);
            double before = offsets[d];
            offsets[d] = gap;
            search(gap < 0 ? right[node] : left[node], cost - before * before + gap * gap, offsets, q, fixed, top);
            offsets[d] = before;
        }
    }
}
