package org.scenes.match;

import java.util.Arrays;

/**
 * Minimum-cost assignment on a square cost matrix (the Hungarian method with row and column
 * potentials, O(n^3)). Used to pair the objects of two scenes optimally.
 */
public final class Assignment {
    private Assignment() {
    }

    /**
     * @param cost n x n costs, row-major: {@code cost[row * n + column]}
     * @return the smallest total cost of a perfect matching of rows to columns
     */
    public static double minimumCost(double[] cost, int n) {
        if (n == 0) {
            return 0;
        }
        // potentials u (rows) and v (columns), 1-based with column 0 as the virtual start
        double[] u = new double[n + 1];
        double[] v = new double[n + 1];
        int[] rowOfColumn = new int[n + 1];
        int[] way = new int[n + 1];
        double[] minimum = new double[n + 1];
        boolean[] used = new boolean[n + 1];
        for (int row = 1; row <= n; row++) {
            rowOfColumn[0] = row;
            int column0 = 0;
            Arrays.fill(minimum, Double.POSITIVE_INFINITY);
            Arrays.fill(used, false);
            do {
                used[column0] = true;
                int row0 = rowOfColumn[column0];
                double delta = Double.POSITIVE_INFINITY;
                int column1 = 0;
                for (int column = 1; column <= n; column++) {
                    if (!used[column]) {
                        double reduced = cost[(row0 - 1) * n + (column - 1)] - u[row0] - v[column];
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
        }
        double total = 0;
        for (int column = 1; column <= n; column++) {
            total += cost[(rowOfColumn[column] - 1) * n + (column - 1)];
        }
        return total;
    }
}
