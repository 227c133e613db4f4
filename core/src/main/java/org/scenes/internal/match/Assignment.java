package org.scenes.internal.match;

import java.util.Arrays;

/**
 * Minimum-cost assignment on a square cost matrix (the Hungarian method with row and column
 * potentials, O(n^3)). Used to pair the objects of two scenes optimally. The potentials start
 * from row and column reduction and the tight pairs they give are taken greedily, so only the
 * rows left over need an augmenting path; for the small matrices of scene objects that skips
 * most of the work. The potentials are a lower bound of the answer at every step (their sum,
 * by LP duality), so a caller that only needs to know whether the cost exceeds a limit can stop
 * as soon as that bound does.
 */
public final class Assignment {
    private Assignment() {
    }

    /** Scratch arrays of one thread's assignments, reused across calls; grows as needed. */
    static final class Workspace {
        double[] cost = new double[0];
        /** Penalties of the objects of the rows and columns, for callers building costs. */
        double[] rowPenalties = new double[0];
        double[] columnPenalties = new double[0];
        private double[] u = new double[0];
        private double[] v = new double[0];
        private double[] minimum = new double[0];
        private int[] rowOfColumn = new int[0];
        private int[] columnOfRow = new int[0];
        private int[] way = new int[0];
        private boolean[] used = new boolean[0];

        /** The cost array, at least n x n long (contents undefined). */
        double[] cost(int n) {
            if (cost.length < n * n) {
                cost = new double[n * n];
            }
            if (u.length < n + 1) {
                u = new double[n + 1];
                v = new double[n + 1];
                minimum = new double[n + 1];
                rowOfColumn = new int[n + 1];
                columnOfRow = new int[n + 1];
                way = new int[n + 1];
                used = new boolean[n + 1];
                rowPenalties = new double[n + 1];
                columnPenalties = new double[n + 1];
            }
            return cost;
        }
    }

    /**
     * @param cost n x n costs, row-major: {@code cost[row * n + column]}
     * @return the smallest total cost of a perfect matching of rows to columns
     */
    public static double minimumCost(double[] cost, int n) {
        Workspace workspace = new Workspace();
        double[] copy = workspace.cost(n);
        System.arraycopy(cost, 0, copy, 0, n * n);
        return minimumCost(workspace, n, 0, 1, Double.POSITIVE_INFINITY);
    }

    /**
     * The smallest total cost of a perfect matching on {@code workspace.cost} (n x n, row-major),
     * or, once a lower bound {@code lower} of it makes {@code before + weight * lower} exceed
     * {@code limit}, that lower bound (then the exact cost exceeds the limit too). The bound is
     * shaved so that rounding in the potentials can never put it above the cost this method
     * would return without a limit.
     */
    static double minimumCost(Workspace workspace, int n, double before, double weight, double limit) {
        if (n == 0) {
            return 0;
        }
        double[] cost = workspace.cost;
        double[] u = workspace.u;
        double[] v = workspace.v;
        int[] rowOfColumn = workspace.rowOfColumn;
        int[] columnOfRow = workspace.columnOfRow;
        // potentials (1-based, column 0 the virtual start): row minima, then column minima of what is left
        for (int row = 1; row <= n; row++) {
            double min = Double.POSITIVE_INFINITY;
            int base = (row - 1) * n - 1;
            for (int column = 1; column <= n; column++) {
                min = Math.min(min, cost[base + column]);
            }
            u[row] = min;
            columnOfRow[row] = 0;
        }
        for (int column = 1; column <= n; column++) {
            double min = Double.POSITIVE_INFINITY;
            for (int row = 1; row <= n; row++) {
                min = Math.min(min, cost[(row - 1) * n + column - 1] - u[row]);
            }
            v[column] = min;
            rowOfColumn[column] = 0;
        }
        u[0] = 0;
        v[0] = 0;
        boolean bounded = limit < Double.POSITIVE_INFINITY;
        if (bounded) {
            double lower = dual(u, v, n);
            if (before + weight * lower > limit) {
                return lower;
            }
        }
        // tight pairs taken greedily: each row its first free column of reduced cost 0
        for (int row = 1; row <= n; row++) {
            int base = (row - 1) * n - 1;
            for (int column = 1; column <= n; column++) {
                if (rowOfColumn[column] == 0 && cost[base + column] - u[row] - v[column] == 0) {
                    rowOfColumn[column] = row;
                    columnOfRow[row] = column;
                    break;
                }
            }
        }
        for (int row = 1; row <= n; row++) {
            if (columnOfRow[row] != 0) {
                continue;
            }
            if (!augment(workspace, n, row)) {
                return Double.NaN; // no finite path: NaN costs
            }
            if (bounded) {
                double lower = dual(u, v, n);
                if (before + weight * lower > limit) {
                    return lower;
                }
            }
        }
        double total = 0;
        for (int column = 1; column <= n; column++) {
            total += cost[(rowOfColumn[column] - 1) * n + (column - 1)];
        }
        return total;
    }

    /** Sum of the potentials, a lower bound of the optimum, shaved against rounding. */
    private static double dual(double[] u, double[] v, int n) {
        double sum = 0;
        for (int i = 1; i <= n; i++) {
            sum += u[i] + v[i];
        }
        return sum * (1 - 1e-9) - 1e-9;
    }

    /** Matches the free row along a shortest augmenting path, updating the potentials. */
    private static boolean augment(Workspace workspace, int n, int row) {
        double[] cost = workspace.cost;
        double[] u = workspace.u;
        double[] v = workspace.v;
        double[] minimum = workspace.minimum;
        int[] rowOfColumn = workspace.rowOfColumn;
        int[] way = workspace.way;
        boolean[] used = workspace.used;
        rowOfColumn[0] = row;
        int column0 = 0;
        Arrays.fill(minimum, 0, n + 1, Double.POSITIVE_INFINITY);
        Arrays.fill(used, 0, n + 1, false);
        do {
            used[column0] = true;
            int row0 = rowOfColumn[column0];
            double delta = Double.POSITIVE_INFINITY;
            int column1 = 0;
            int base = (row0 - 1) * n - 1;
            double u0 = u[row0];
            for (int column = 1; column <= n; column++) {
                if (!used[column]) {
                    double reduced = cost[base + column] - u0 - v[column];
                    if (reduced < minimum[column]) {
                        minimum[column] = reduced;
                        way[column] = column0;
                    }
                    if (minimum[column] < delta) {
                        delta = minimum[column];
                        column1 = column;
                    }
                }
            }
            if (column1 == 0) {
                return false;
            }
            for (int column = 0; column <= n; column++) {
                if (used[column]) {
                    u[rowOfColumn[column]] += delta;
                    v[column] -= delta;
                } else {
                    minimum[column] -= delta;
                }
            }
            column0 = column1;
        } while (rowOfColumn[column0] != 0);
        do {
            int column1 = way[column0];
            rowOfColumn[column0] = rowOfColumn[column1];
            column0 = column1;
        } while (column0 != 0);
        return true; // rows matched before stay matched: a path only swaps their columns
    }
}
