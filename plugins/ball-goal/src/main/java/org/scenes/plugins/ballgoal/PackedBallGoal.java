package org.scenes.plugins.ballgoal;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.PackedMetric;
import org.scenes.api.Scene;
import org.scenes.api.TopK;

/**
 * The knowledge base for {@code ball-goal} as small keys: per scene and object (ball, goal) one
 * byte naming its cell (or its absence) and one char naming its direction, each an index into a
 * dictionary of the distinct values the knowledge base holds (real scenes have 15 cells and a few
 * hundred integer directions). A query turns the dictionaries into cost tables, so the scan is
 * table look-ups and one addition per object: {@code min(cellCost[cell] + directionCost[dir],
 * cap[cell])}. The tables hold the very partial sums {@link BallGoalMetricProvider.BallGoalMetric}
 * computes ({@code (cw |dc| + rw |dr|) + aw |dd|}, summed in that order), so every distance is
 * identical to the exhaustive scan's; absence is folded into the tables (an infinite cell cost
 * and a cap of M or 0), so the loop has no branch but the rare offer. Unless disabled
 * ({@code index=false}), queries go through a {@link BallGoalIndex} built alongside, with the
 * same sums; the scan stays for queries the index does not cover.
 */
final class PackedBallGoal implements PackedMetric.PackedScenes {
    private static final int MAX_CELLS = 255;
    private static final int MAX_DIRECTIONS = 65536;

    private final BallGoalMetricProvider.BallGoalMetric metric;
    private final int size;
    /** per object (0 ball, 1 goal): cell key of each scene; the last key means absent */
    private final byte[][] cellKeys = new byte[2][];
    private final char[][] directionKeys = new char[2][];
    private final double[][] cellColumn = new double[2][];
    private final double[][] cellRow = new double[2][];
    private final double[][] directions = new double[2][];
    /** the exact index, or null when disabled or not applicable: then every query scans */
    private BallGoalIndex index;

    private PackedBallGoal(BallGoalMetricProvider.BallGoalMetric metric, int size) {
        this.metric = metric;
        this.size = size;
    }

    /**
     * The packed form, with the index when {@code indexed} and it applies, or null when the scenes
     * hold too many distinct cells or directions for the keys.
     */
    static PackedBallGoal pack(BallGoalMetricProvider.BallGoalMetric metric, List<Scene> scenes, boolean indexed) {
        PackedBallGoal packed = new PackedBallGoal(metric, scenes.size());
        double[][] features = new double[scenes.size()][];
        for (int i = 0; i < features.length; i++) {
            features[i] = metric.encode(scenes.get(i));
        }
        for (int object = 0; object < 2; object++) {
            int offset = 4 * object;
            Map<Long, Integer> cells = new HashMap<>();
            Map<Double, Integer> directionIndex = new HashMap<>();
            for (double[] f : features) {
                if (f[offset] != 0) {
                    cells.putIfAbsent(cellKey(f, offset), cells.size());
                    directionIndex.putIfAbsent(f[offset + 3], directionIndex.size());
                }
            }
            if (cells.size() > MAX_CELLS || directionIndex.size() > MAX_DIRECTIONS) {
                return null;
            }
            int absent = cells.size();
            packed.cellColumn[object] = new double[absent];
            packed.cellRow[object] = new double[absent];
            packed.directions[object] = new double[Math.max(1, directionIndex.size())];
            byte[] cellKey = new byte[features.length];
            char[] directionKey = new char[features.length];
            for (int i = 0; i < features.length; i++) {
                double[] f = features[i];
                if (f[offset] == 0) {
                    cellKey[i] = (byte) absent;
                    continue;
                }
                int cell = cells.get(cellKey(f, offset));
                int direction = directionIndex.get(f[offset + 3]);
                cellKey[i] = (byte) cell;
                directionKey[i] = (char) direction;
                packed.cellColumn[object][cell] = f[offset + 1];
                packed.cellRow[object][cell] = f[offset + 2];
                packed.directions[object][direction] = f[offset + 3];
            }
            packed.cellKeys[object] = cellKey;
            packed.directionKeys[object] = directionKey;
        }
        packed.index = indexed ? BallGoalIndex.build(metric, features) : null;
        return packed;
    }

    /** Column and row (small non-negative integers) in one long, one key per cell. */
    private static long cellKey(double[] features, int offset) {
        return ((long) features[offset + 1] << 32) | (long) features[offset + 2];
    }

    /** Whether queries go through the index (else every one scans). */
    boolean indexed() {
        return index != null;
    }

    /** Through the index when it covers the query, else the scan of every scene. */
    @Override
    public void scan(Scene query, TopK top) {
        double[] q = metric.encode(query);
        if (index != null && index.covers(q)) {
            index.search(q, top);
        } else {
            scanAll(q, top);
        }
    }

    /** Offers every scene's distance that is below the bound, in index order. */
    void scanAll(double[] q, TopK top) {
        double[] ballCell = new double[256];
        double[] ballCap = new double[256];
        double[] ballDirection = tables(q, 0, ballCell, ballCap);
        double[] goalCell = new double[256];
        double[] goalCap = new double[256];
        double[] goalDirection = tables(q, 1, goalCell, goalCap);
        if (!finiteSums(ballDirection, goalDirection)) {
            scanExactly(q, top);
            return;
        }
        double ballWeight = metric.ballWeight();
        double goalWeight = metric.goalWeight();
        byte[] ballCells = cellKeys[0];
        char[] ballDirections = directionKeys[0];
        byte[] goalCells = cellKeys[1];
        char[] goalDirections = directionKeys[1];
        double bound = top.bound();
        for (int i = 0; i < size; i++) {
            int bc = ballCells[i] & 0xff;
            int gc = goalCells[i] & 0xff;
            double ball = Math.min(ballCell[bc] + ballDirection[ballDirections[i]], ballCap[bc]);
            double goal = Math.min(goalCell[gc] + goalDirection[goalDirections[i]], goalCap[gc]);
            double distance = ballWeight * ball + goalWeight * goal;
            if (distance < bound) {
                top.offer(distance, i);
                bound = top.bound();
            }
        }
    }

    /**
     * Whether every distance of this query is finite, as the table scan needs: a NaN direction
     * cost (0 times an infinite difference) would spread to absent objects through the tables,
     * and a NaN or infinite distance is never below an infinite bound, so it would not be offered.
     */
    private boolean finiteSums(double[] ballDirection, double[] goalDirection) {
        double cap = 2 * metric.missing();
        if (!Double.isFinite(metric.ballWeight() * cap + metric.goalWeight() * cap)) {
            return false;
        }
        for (double[] costs : new double[][] {ballDirection, goalDirection}) {
            for (double cost : costs) {
                if (Double.isNaN(cost)) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * The rare queries the tables cannot serve (directions that are not finite, overflowing
     * weights): each scene's features rebuilt from the dictionaries and measured by the metric itself.
     */
    private void scanExactly(double[] q, TopK top) {
        double[] stored = new double[q.length];
        for (int i = 0; i < size; i++) {
            for (int object = 0; object < 2; object++) {
                int offset = 4 * object;
                int cell = cellKeys[object][i] & 0xff;
                boolean present = cell < cellColumn[object].length;
                stored[offset] = present ? 1 : 0;
                stored[offset + 1] = present ? cellColumn[object][cell] : 0;
                stored[offset + 2] = present ? cellRow[object][cell] : 0;
                stored[offset + 3] = present ? directions[object][directionKeys[object][i]] : 0;
            }
            top.offer(metric.distance(q, stored, Double.POSITIVE_INFINITY), i);
        }
    }

    /**
     * The cell tables of one object for a query, shared by the scan and the index: for each of
     * the {@code columns.length} known cells and then "absent", the cost before direction and
     * the cap. With the query's object present: {@code cw |dc| + rw |dr|} and cap 2M for a
     * present cell, infinite cost and cap M for absent; with it absent: infinite cost, cap M or 0.
     */
    static void cellTables(BallGoalMetricProvider.BallGoalMetric metric, double[] q, int offset,
                           double[] columns, double[] rows, double[] cellCost, double[] cap) {
        boolean present = q[offset] != 0;
        double missing = metric.missing();
        int absent = columns.length;
        for (int cell = 0; cell < absent; cell++) {
            if (present) {
                cellCost[cell] = metric.columnWeight() * Math.abs(q[offset + 1] - columns[cell])
                        + metric.rowWeight() * Math.abs(q[offset + 2] - rows[cell]);
                cap[cell] = 2 * missing;
            } else {
                cellCost[cell] = Double.POSITIVE_INFINITY;
                cap[cell] = missing;
            }
        }
        cellCost[absent] = Double.POSITIVE_INFINITY;
        cap[absent] = present ? missing : 0;
    }

    /**
     * Fills the cell tables of one object for this query and returns its direction table. With
     * the query's object present: cost {@code cw |dc| + rw |dr|} and cap 2M for a present cell,
     * infinite cost and cap M for absent; with it absent: infinite cost, cap M or 0.
     */
    private double[] tables(double[] q, int object, double[] cellCost, double[] cap) {
        int offset = 4 * object;
        boolean present = q[offset] != 0;
        cellTables(metric, q, offset, cellColumn[object], cellRow[object], cellCost, cap);
        double[] values = directions[object];
        double[] directionCost = new double[values.length];
        for (int d = 0; d < values.length; d++) {
            directionCost[d] = present ? metric.anglePerDegree() * Math.abs(q[offset + 3] - values[d]) : 0;
        }
        return directionCost;
    }
}
