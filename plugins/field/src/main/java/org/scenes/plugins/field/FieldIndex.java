package org.scenes.plugins.field;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.PackedMetric;
import org.scenes.api.Scene;
import org.scenes.api.TopK;

/**
 * An exact index for {@code field}: scenes are grouped by what adds a fixed cost (play mode,
 * whether the ball is known and within reach, whether the player is its team's nearest to it,
 * whether the world is located), and each group's weighted features
 * go into a k-d tree. A query visits groups in ascending fixed cost and stops once that alone
 * passes the k-th best distance; within a group it descends the nearer child first and skips any
 * box whose nearest point is farther than the k-th best. Offered distances are computed with the
 * very operations of {@link FieldMetricProvider.FieldMetric#distance}, so they are the scan's bit
 * for bit; pruning keeps a relative margin of {@link #SLACK} for the rounding of box bounds, so
 * it never skips a scene the scan would keep.
 */
final class FieldIndex implements PackedMetric.PackedScenes {
    /** Scenes per leaf: a scan of 40 costs about what the boxes above it do (bench --synthetic: 40 to 64 best). */
    private static final int LEAF = 40;
    private static final double SLACK = 1e-9;
    private static final int DIMENSIONS = FieldMetricProvider.FEATURES;

    private final FieldMetricProvider.FieldMetric metric;
    private final List<Group> groups;
    /** Scenes without a located world: at {@code missing} from every located query, 0 from another. */
    private final int[] unlocated;

    private FieldIndex(FieldMetricProvider.FieldMetric metric, List<Group> groups, int[] unlocated) {
        this.metric = metric;
        this.groups = groups;
        this.unlocated = unlocated;
    }

    static FieldIndex build(FieldMetricProvider.FieldMetric metric, List<Scene> scenes) {
        Map<String, List<Integer>> byKey = new LinkedHashMap<>();
        Map<String, FieldMetricProvider.Features> keyFeatures = new LinkedHashMap<>();
        List<Integer> unlocated = new ArrayList<>();
        FieldMetricProvider.Features[] features = new FieldMetricProvider.Features[scenes.size()];
        for (int i = 0; i < scenes.size(); i++) {
            features[i] = metric.encode(scenes.get(i));
            if (features[i].values() == null) {
                unlocated.add(i);
                continue;
            }
            String key = features[i].mode() + '\u0000' + features[i].ballKnown() + '\u0000' + features[i].kickable()
                    + '\u0000' + features[i].chaser();
            byKey.computeIfAbsent(key, unused -> new ArrayList<>()).add(i);
            keyFeatures.putIfAbsent(key, features[i]);
        }
        List<Group> groups = new ArrayList<>();
        byKey.forEach((key, members) -> groups.add(Group.of(keyFeatures.get(key), members, features)));
        return new FieldIndex(metric, groups, unlocated.stream().mapToInt(Integer::intValue).toArray());
    }

    @Override
    public void scan(Scene query, TopK top) {
        FieldMetricProvider.Features q = metric.encode(query);
        if (q.values() == null) {
            // an unlocated query is missing away from every located scene, 0 from an unlocated one
            for (int index : unlocated) {
                top.offer(0, index);
            }
            for (Group group : groups) {
                for (int index : group.members) {
                    top.offer(metric.missing(), index);
                }
            }
            return;
        }
        for (int index : unlocated) {
            top.offer(metric.missing(), index);
        }
        double[] fixed = new double[groups.size()];
        Integer[] order = new Integer[groups.size()];
        for (int g = 0; g < fixed.length; g++) {
            fixed[g] = metric.fixedCost(q, groups.get(g).key);
            order[g] = g;
        }
        java.util.Arrays.sort(order, Comparator.comparingDouble(g -> fixed[g]));
        for (int g : order) {
            if (pruned(fixed[g], top)) {
                break;
            }
            groups.get(g).search(0, q.values(), fixed[g], top);
        }
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
            double widestSpread = -1;
            for (int d = 0; d < DIMENSIONS; d++) {
                double min = Double.POSITIVE_INFINITY;
                double max = Double.NEGATIVE_INFINITY;
                for (int i = from; i < to; i++) {
                    double v = values[i * DIMENSIONS + d];
                    min = Math.min(min, v);
                    max = Math.max(max, v);
                }
                low[node * DIMENSIONS + d] = min;
                high[node * DIMENSIONS + d] = max;
                if (max - min > widestSpread) {
                    widestSpread = max - min;
                    widest = d;
                }
            }
            if (to - from > LEAF && widestSpread > 0) {
                int middle = (from + to) >>> 1;
                select(from, to, middle, widest);
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

        void search(int node, double[] q, double fixed, TopK top) {
            if (pruned(fixed + boxCost(node, q), top)) {
                return;
            }
            if (left[node] < 0) {
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
            double toLeft = boxCost(left[node], q);
            double toRight = boxCost(right[node], q);
            int first = toLeft <= toRight ? left[node] : right[node];
            int second = first == left[node] ? right[node] : left[node];
            search(first, q, fixed, top);
            search(second, q, fixed, top);
        }
    }
}
