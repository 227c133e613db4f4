package org.scenes.plugins.ballgoal;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import org.scenes.api.TopK;

/**
 * An exact index for {@code ball-goal}: the distance only depends on each scene's ball key and
 * goal key (a cell and a direction, or absent), and a knowledge base holds far fewer distinct
 * (ball key, goal key) pairs than scenes. Scenes are grouped by that pair (each group's indices
 * ascending); groups are ordered by ball cell, ball direction, goal cell, goal direction.
 *
 * <p>A query visits ball keys in ascending ball cost (per cell, outward from the query's
 * direction by binary search over the sorted directions, merged across cells) and stops once
 * {@code ballWeight * ballCost} alone exceeds the k-th best distance: the goal term is never
 * negative and {@code a + b >= a} holds in floating point for {@code b >= 0}. Within a ball key,
 * goal cells are tried in ascending order of their cheapest possible cost and each is walked
 * outward from the query's direction while the sum can still enter. Every group reached offers its
 * first k indices (they share one distance, so lower indices win). Pruning is strict ({@code >}),
 * so a scene at exactly the k-th best distance with a lower index still enters. Distances are
 * computed with the very operations of the packed scan, so they are identical bit for bit.
 *
 * <p>Components whose weight is 0 are left out of the keys at build time (a zero column weight
 * merges columns, a zero angle weight merges directions, a zero object weight or zero
 * {@code missing} drops the object), which leaves every distance unchanged ({@code 0 * x = 0}
 * for finite x) and keeps the groups few.
 */
final class BallGoalIndex {
    private static final int BALL = 0;
    private static final int GOAL = 1;
    private static final int MAX_CELLS = 256;
    private static final int MAX_DIRECTIONS = 65536;
    /** directions the index takes: far inside the finite doubles, so no difference of two overflows */
    private static final double MAX_ABS_DIRECTION = 1e6;

    private final BallGoalMetricProvider.BallGoalMetric metric;
    /** per object: whether it is left out (weight or missing 0); then its one cell costs nothing */
    private final boolean[] dropped = new boolean[2];
    /** per object and cell: column and row as keyed (0 where the weight is 0); the last cell is "absent" */
    private final int[][] cellColumn = new int[2][];
    private final int[][] cellRow = new int[2][];

    /** ball keys, ordered by cell then direction: cell c owns keys ballCellStart[c] until ballCellStart[c + 1] */
    private final int[] ballCellStart;
    private final double[] ballDirection;
    /** the groups of ball key b: from ballGroupStart[b] until ballGroupStart[b + 1] */
    private final int[] ballGroupStart;
    /** groups of ball key b in goal cell c start at goalCellStart[b * (goalCells + 1) + c] */
    private final int[] goalCellStart;
    private final int goalCells;
    /** per group: its goal key's direction, and its scenes members[groupStart[g] until groupStart[g + 1]] */
    private final double[] goalDirection;
    private final int[] groupStart;
    private final int[] members;

    private BallGoalIndex(BallGoalMetricProvider.BallGoalMetric metric, int[] ballCellStart, double[] ballDirection,
                          int[] ballGroupStart, int[] goalCellStart, int goalCells, double[] goalDirection,
                          int[] groupStart, int[] members) {
        this.metric = metric;
        this.ballCellStart = ballCellStart;
        this.ballDirection = ballDirection;
        this.ballGroupStart = ballGroupStart;
        this.goalCellStart = goalCellStart;
        this.goalCells = goalCells;
        this.goalDirection = goalDirection;
        this.groupStart = groupStart;
        this.members = members;
    }

    /** Per object, each scene's key as the index sees it, before the groups are built. */
    private static final class Keys {
        boolean dropped;
        boolean directionsKept;
        int[] cellColumn;
        int[] cellRow;
        int[] cell;
        int[] directionRank;
        double[] directionValues;
    }

    /**
     * The index over the encoded scenes (as {@link BallGoalMetricProvider.BallGoalMetric#encode}
     * gives them), or null when a stored direction is far out of range, {@code 2 missing} overflows or
     * there are too many distinct keys (then the scan is as good).
     */
    static BallGoalIndex build(BallGoalMetricProvider.BallGoalMetric metric, double[][] features) {
        if (!Double.isFinite(2 * metric.missing())) {
            return null; // an infinite cap times a zero weight is NaN, not the 0 a dropped object costs
        }
        Keys[] keys = new Keys[2];
        for (int object = 0; object < 2; object++) {
            keys[object] = keys(metric, features, object);
            if (keys[object] == null) {
                return null;
            }
        }
        int size = features.length;
        long[] joint = new long[size];
        for (int i = 0; i < size; i++) {
            joint[i] = ((long) keys[BALL].cell[i] << 40) | ((long) keys[BALL].directionRank[i] << 24)
                    | ((long) keys[GOAL].cell[i] << 16) | keys[GOAL].directionRank[i];
        }
        long[] distinct = distinct(joint);
        int groups = distinct.length;
        // scenes of each group in ascending index: a counting sort by group, in scene order
        int[] groupOf = new int[size];
        int[] groupStart = new int[groups + 1];
        for (int i = 0; i < size; i++) {
            groupOf[i] = Arrays.binarySearch(distinct, joint[i]);
            groupStart[groupOf[i] + 1]++;
        }
        for (int g = 0; g < groups; g++) {
            groupStart[g + 1] += groupStart[g];
        }
        int[] members = new int[size];
        int[] fill = Arrays.copyOf(groupStart, groups);
        for (int i = 0; i < size; i++) {
            members[fill[groupOf[i]]++] = i;
        }
        // ball keys: the distinct (ball cell, ball direction) prefixes of the ordered groups
        int ballCells = keys[BALL].cellColumn.length;
        int goalCells = keys[GOAL].cellColumn.length;
        int ballKeys = 0;
        for (int g = 0; g < groups; g++) {
            if (g == 0 || (distinct[g] >>> 24) != (distinct[g - 1] >>> 24)) {
                ballKeys++;
            }
        }
        if ((long) ballKeys * (goalCells + 1) > 2L * size + 65536) {
            return null; // nearly every scene its own ball key over a fine grid: the per-key cell table would outweigh the scenes
        }
        double[] ballDirection = new double[ballKeys];
        int[] ballGroupStart = new int[ballKeys + 1];
        int[] ballCellStart = new int[ballCells + 1];
        int[] goalCellStart = new int[ballKeys * (goalCells + 1)];
        double[] goalDirection = new double[groups];
        int ball = -1;
        for (int g = 0; g < groups; g++) {
            int ballCell = (int) (distinct[g] >>> 40);
            if (g == 0 || (distinct[g] >>> 24) != (distinct[g - 1] >>> 24)) {
                ball++;
                ballGroupStart[ball] = g;
                ballDirection[ball] = keys[BALL].directionValues[(int) (distinct[g] >>> 24) & 0xffff];
                for (int c = ballCell + 1; c <= ballCells; c++) {
                    ballCellStart[c] = ball + 1;
                }
            }
            goalDirection[g] = keys[GOAL].directionValues[(int) distinct[g] & 0xffff];
        }
        ballGroupStart[ballKeys] = groups;
        for (int b = 0; b < ballKeys; b++) {
            // groups of b are ordered by goal cell: each cell starts at its first group, an empty one where the next starts
            int row = b * (goalCells + 1);
            int g = ballGroupStart[b];
            for (int c = 0; c <= goalCells; c++) {
                while (g < ballGroupStart[b + 1] && ((int) (distinct[g] >>> 16) & 0xff) < c) {
                    g++;
                }
                goalCellStart[row + c] = g;
            }
        }
        BallGoalIndex index = new BallGoalIndex(metric, ballCellStart, ballDirection, ballGroupStart, goalCellStart,
                goalCells, goalDirection, groupStart, members);
        for (int object = 0; object < 2; object++) {
            index.dropped[object] = keys[object].dropped;
            index.cellColumn[object] = keys[object].cellColumn;
            index.cellRow[object] = keys[object].cellRow;
        }
        return index;
    }

    private static Keys keys(BallGoalMetricProvider.BallGoalMetric metric, double[][] features, int object) {
        int offset = 4 * object;
        double weight = object == BALL ? metric.ballWeight() : metric.goalWeight();
        Keys keys = new Keys();
        keys.dropped = weight == 0 || metric.missing() == 0;
        keys.directionsKept = !keys.dropped && metric.anglePerDegree() != 0;
        boolean columnsKept = metric.columnWeight() != 0;
        boolean rowsKept = metric.rowWeight() != 0;
        keys.cell = new int[features.length];
        keys.directionRank = new int[features.length];
        if (keys.dropped) {
            keys.cellColumn = new int[1];
            keys.cellRow = new int[1];
            keys.directionValues = new double[1];
            return keys;
        }
        Map<Long, Integer> cells = new HashMap<>();
        double[] directions = new double[features.length];
        int present = 0;
        for (double[] f : features) {
            if (f[offset] == 0) {
                continue;
            }
            if (!(Math.abs(f[offset + 3]) <= MAX_ABS_DIRECTION)) {
                return null; // 0 * infinity is not 0: leave such knowledge bases to the scan
            }
            long column = columnsKept ? (long) f[offset + 1] : 0;
            long row = rowsKept ? (long) f[offset + 2] : 0;
            cells.putIfAbsent((column << 32) | row, cells.size());
            directions[present++] = keys.directionsKept ? f[offset + 3] : 0;
        }
        double[] values = distinct(Arrays.copyOf(directions, Math.max(1, present)));
        if (cells.size() >= MAX_CELLS || values.length > MAX_DIRECTIONS) {
            return null;
        }
        int absent = cells.size();
        keys.cellColumn = new int[absent + 1];
        keys.cellRow = new int[absent + 1];
        for (Map.Entry<Long, Integer> cell : cells.entrySet()) {
            keys.cellColumn[cell.getValue()] = (int) (cell.getKey() >>> 32);
            keys.cellRow[cell.getValue()] = (int) (long) cell.getKey();
        }
        keys.directionValues = values;
        for (int i = 0; i < features.length; i++) {
            double[] f = features[i];
            if (f[offset] == 0) {
                keys.cell[i] = absent;
                continue;
            }
            long column = columnsKept ? (long) f[offset + 1] : 0;
            long row = rowsKept ? (long) f[offset + 2] : 0;
            keys.cell[i] = cells.get((column << 32) | row);
            keys.directionRank[i] = Arrays.binarySearch(values, keys.directionsKept ? f[offset + 3] : 0);
        }
        return keys;
    }

    private static long[] distinct(long[] values) {
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        int count = 0;
        for (int i = 0; i < sorted.length; i++) {
            if (i == 0 || sorted[i] != sorted[i - 1]) {
                sorted[count++] = sorted[i];
            }
        }
        return Arrays.copyOf(sorted, count);
    }

    /** Distinct values in {@link Double#compare} order (so -0.0 and 0.0 stay apart, as the dictionaries keep them). */
    private static double[] distinct(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int count = 0;
        for (int i = 0; i < sorted.length; i++) {
            if (i == 0 || Double.compare(sorted[i], sorted[i - 1]) != 0) {
                sorted[count++] = sorted[i];
            }
        }
        return Arrays.copyOf(sorted, count);
    }

    /** Whether the index answers this encoded query (a query direction far out of range goes to the scan). */
    boolean covers(double[] q) {
        return Math.abs(q[3]) <= MAX_ABS_DIRECTION && Math.abs(q[7]) <= MAX_ABS_DIRECTION;
    }

    /**
     * Per-query costs of one object: a key of cell c and direction x costs
     * {@code min(base[c] + aw |q - x|, cap[c])}, the packed scan's very sum; a cell whose cost does
     * not depend on the direction has an infinite base and its constant as cap.
     */
    private final class Costs {
        final double[] base;
        final double[] cap;
        final double query;
        final double angle;

        Costs(double[] q, int object) {
            int offset = 4 * object;
            int cells = cellColumn[object].length;
            base = new double[cells];
            cap = new double[cells];
            query = q[offset + 3];
            angle = metric.anglePerDegree();
            if (dropped[object]) {
                base[0] = Double.POSITIVE_INFINITY;
                return;
            }
            PackedBallGoal.cellTables(metric, q, offset, known(cellColumn[object]), known(cellRow[object]), base, cap);
        }

        /** The coordinates of the known cells, without the last slot, which stands for absent. */
        private static double[] known(int[] coordinates) {
            double[] values = new double[coordinates.length - 1];
            for (int i = 0; i < values.length; i++) {
                values[i] = coordinates[i];
            }
            return values;
        }

        double cost(int cell, double direction) {
            return Math.min(base[cell] + angle * Math.abs(query - direction), cap[cell]);
        }

        /** The least cost any key of the cell can have. */
        double least(int cell) {
            return Math.min(base[cell], cap[cell]);
        }
    }

    /** Offers every scene that may enter {@code top} for the encoded query. */
    void search(double[] q, TopK top) {
        Costs ball = new Costs(q, BALL);
        Costs goal = new Costs(q, GOAL);
        int[] goalOrder = cheapestFirst(goal);
        double ballWeight = metric.ballWeight();
        double goalWeight = metric.goalWeight();
        double ballQuery = ball.query;
        // per ball cell two cursors, walking down and up from the query's direction
        int cells = ballCellStart.length - 1;
        int[] down = new int[cells];
        int[] up = new int[cells];
        double[] downCost = new double[cells];
        double[] upCost = new double[cells];
        for (int c = 0; c < cells; c++) {
            int from = ballCellStart[c];
            int to = ballCellStart[c + 1];
            int at = firstNotBelow(ballDirection, from, to, ballQuery);
            down[c] = at - 1;
            up[c] = at;
            downCost[c] = at - 1 >= from ? ball.cost(c, ballDirection[at - 1]) : Double.NaN;
            upCost[c] = at < to ? ball.cost(c, ballDirection[at]) : Double.NaN;
        }
        while (true) {
            int bestCell = -1;
            boolean bestUp = false;
            double best = Double.POSITIVE_INFINITY;
            for (int c = 0; c < cells; c++) {
                // NaN marks an exhausted cursor: it never compares below
                if (downCost[c] <= best && (bestCell < 0 || downCost[c] < best)) {
                    bestCell = c;
                    bestUp = false;
                    best = downCost[c];
                }
                if (upCost[c] <= best && (bestCell < 0 || upCost[c] < best)) {
                    bestCell = c;
                    bestUp = true;
                    best = upCost[c];
                }
            }
            if (bestCell < 0) {
                return;
            }
            double partial = ballWeight * best;
            if (partial > top.bound()) {
                return;
            }
            int key;
            if (bestUp) {
                key = up[bestCell]++;
                upCost[bestCell] = up[bestCell] < ballCellStart[bestCell + 1]
                        ? ball.cost(bestCell, ballDirection[up[bestCell]]) : Double.NaN;
            } else {
                key = down[bestCell]--;
                downCost[bestCell] = down[bestCell] >= ballCellStart[bestCell]
                        ? ball.cost(bestCell, ballDirection[down[bestCell]]) : Double.NaN;
            }
            searchGoals(key, partial, goal, goalOrder, goalWeight, top);
        }
    }

    /** Offers the groups of one ball key whose sum may enter, goal cells cheapest first. */
    private void searchGoals(int ballKey, double partial, Costs goal, int[] goalOrder, double goalWeight, TopK top) {
        int row = ballKey * (goalCells + 1);
        for (int cell : goalOrder) {
            if (partial + goalWeight * goal.least(cell) > top.bound()) {
                return; // the cells after it cost at least as much
            }
            int from = goalCellStart[row + cell];
            int to = goalCellStart[row + cell + 1];
            if (from == to) {
                continue;
            }
            int at = firstNotBelow(goalDirection, from, to, goal.query);
            int down = at - 1;
            int up = at;
            while (down >= from || up < to) {
                double downCost = down >= from ? goal.cost(cell, goalDirection[down]) : 0;
                double upCost = up < to ? goal.cost(cell, goalDirection[up]) : 0;
                int group;
                double distance;
                if (down >= from && (up >= to || downCost <= upCost)) {
                    group = down--;
                    distance = partial + goalWeight * downCost;
                } else {
                    group = up++;
                    distance = partial + goalWeight * upCost;
                }
                if (distance > top.bound()) {
                    break; // both walks only get dearer
                }
                offer(group, distance, top);
            }
        }
    }

    /** The group's first k scenes: they share one distance, so no later one can enter. */
    private void offer(int group, double distance, TopK top) {
        int end = groupStart[group + 1];
        int offered = 0;
        for (int i = groupStart[group]; i < end; i++) {
            if (distance > top.bound()) {
                return;
            }
            top.offer(distance, members[i]);
            offered++;
            // once full, size() is k: the group's first k indices are all it can place
            if (top.bound() != Double.POSITIVE_INFINITY && offered >= top.size()) {
                return;
            }
        }
    }

    /** The goal cells in ascending order of their least cost for this query. */
    private static int[] cheapestFirst(Costs goal) {
        int cells = goal.base.length;
        int[] order = new int[cells];
        for (int c = 0; c < cells; c++) {
            int at = c;
            double least = goal.least(c);
            while (at > 0 && goal.least(order[at - 1]) > least) {
                order[at] = order[at - 1];
                at--;
            }
            order[at] = c;
        }
        return order;
    }

    /** The first position in [from, to) whose value is not below {@code value} ({@code to} if none). */
    private static int firstNotBelow(double[] values, int from, int to, double value) {
        int low = from;
        int high = to;
        while (low < high) {
            int middle = (low + high) >>> 1;
            if (values[middle] < value) {
                low = middle + 1;
            } else {
                high = middle;
            }
        }
        return low;
    }
}
