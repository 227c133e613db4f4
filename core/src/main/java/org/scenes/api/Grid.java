package org.scenes.api;

import java.util.Arrays;
import java.util.List;

/**
 * The discretisation of the view into columns (angle slices) and rows (distance rings).
 * Columns split {@code [minAngle, maxAngle]} evenly, left (negative direction) to right;
 * directions outside the range fall into the outermost column, so an object seen behind
 * the player still counts as "extreme left" or "extreme right". Rows are separated by the
 * ascending distance {@code bounds}: a distance equal to a bound belongs to the nearer row.
 */
public final class Grid {
    /** 5 x 3 over the normal 90 degree view, rows split at 1 m (kickable) and 5 m. */
    public static final Grid DEFAULT = new Grid(5, -45, 45, new double[] {1, 5});

    private final int columns;
    private final double minAngle;
    private final double maxAngle;
    private final double[] bounds;
    private final double columnWidth;
    /** Every cell, row after row, made once (decoding a knowledge base asks for millions); null for huge grids. */
    private final Cell[] cells;

    /**
     * A grid over any angle range.
     *
     * @param columns how many angle slices, at least 1
     * @param minAngle the left edge of the range, degrees relative to the head
     * @param maxAngle the right edge, degrees, above {@code minAngle}
     * @param bounds the distances in metres separating the rows, positive and ascending
     */
    public Grid(int columns, double minAngle, double maxAngle, double[] bounds) {
        if (columns < 1) {
            throw new IllegalArgumentException("a grid needs at least one column, not " + columns);
        }
        if (!Double.isFinite(minAngle) || !Double.isFinite(maxAngle)) {
            throw new IllegalArgumentException("angle range [" + minAngle + ", " + maxAngle + "] must be finite");
        }
        if (!(maxAngle > minAngle)) {
            throw new IllegalArgumentException("angle range [" + minAngle + ", " + maxAngle + "] is empty");
        }
        for (int i = 0; i < bounds.length; i++) {
            if (!(bounds[i] > 0) || !Double.isFinite(bounds[i]) || (i > 0 && !(bounds[i] > bounds[i - 1]))) {
                throw new IllegalArgumentException("distance bounds must be finite, positive and ascending: "
                        + Arrays.toString(bounds));
            }
        }
        this.columns = columns;
        this.minAngle = minAngle;
        this.maxAngle = maxAngle;
        this.bounds = bounds.clone();
        this.columnWidth = (maxAngle - minAngle) / columns;
        long count = (long) columns * (bounds.length + 1);
        cells = count <= 4096 ? new Cell[(int) count] : null;
        for (int i = 0; cells != null && i < cells.length; i++) {
            cells[i] = new Cell(i % columns, i / columns);
        }
    }

    /**
     * A grid with {@code columns} columns and {@code bounds.length + 1} rows over the default angle range.
     *
     * @param columns how many angle slices over [-45, 45] degrees
     * @param bounds the distances in metres separating the rows
     * @return the grid
     */
    public static Grid of(int columns, double... bounds) {
        return new Grid(columns, DEFAULT.minAngle, DEFAULT.maxAngle, bounds);
    }

    /** @return how many angle slices (columns) */
    public int columns() {
        return columns;
    }

    /** @return how many distance rings (rows): one more than the bounds */
    public int rows() {
        return bounds.length + 1;
    }

    /** @return the left edge of the angle range, in degrees */
    public double minAngle() {
        return minAngle;
    }

    /** @return the right edge of the angle range, in degrees */
    public double maxAngle() {
        return maxAngle;
    }

    /** @return a copy of the distances in metres separating the rows, ascending */
    public double[] bounds() {
        return bounds.clone();
    }

    /**
     * Column of a direction; directions outside the range fall into the outermost column, and an
     * object whose direction the server did not send into the middle one.
     *
     * @param direction degrees relative to the head, positive to the right
     * @return the column, from 0 (left)
     */
    public int column(double direction) {
        if (Double.isNaN(direction)) {
            return columns / 2;
        }
        int column = (int) Math.floor((direction - minAngle) / columnWidth);
        return Math.max(0, Math.min(columns - 1, column));
    }

    /**
     * Row of a distance; an object whose distance the server did not send is taken as far.
     *
     * @param distance metres
     * @return the row, from 0 (nearest)
     */
    public int row(double distance) {
        if (Double.isNaN(distance)) {
            return bounds.length;
        }
        int row = 0;
        while (row < bounds.length && distance > bounds[row]) {
            row++;
        }
        return row;
    }

    /**
     * Cell of an object seen at a distance and direction.
     *
     * @param distance metres
     * @param direction degrees relative to the head, positive to the right
     * @return the cell of {@link #column} and {@link #row}
     */
    public Cell cell(double distance, double direction) {
        int column = column(direction);
        int row = row(distance);
        return cells != null ? cells[row * columns + column] : new Cell(column, row);
    }

    /**
     * The grid that every source shares, the one check of mixed grids (matching never mixes them):
     * the first source whose grid differs is named beside the first source's.
     *
     * @param sources what the user knows each grid by (a file name), in the order of {@code grids}
     * @param grids the grids, at least one
     * @return the grid they share
     * @throws MismatchException when two grids differ: a fault of the data, not of the call
     */
    public static Grid common(List<?> sources, List<Grid> grids) {
        if (grids.isEmpty() || sources.size() != grids.size()) {
            throw new IllegalArgumentException("need one source per grid and at least one grid");
        }
        Grid first = grids.get(0);
        for (int i = 1; i < grids.size(); i++) {
            if (!grids.get(i).equals(first)) {
                throw new MismatchException(sources.get(i) + ": grid " + grids.get(i).describe() + " differs from "
                        + first.describe() + " of " + sources.get(0));
            }
        }
        return first;
    }

    /**
     * "5x3 [-45,45] bounds 1,5": the form shown in reports and errors.
     *
     * @return the description
     */
    public String describe() {
        StringBuilder text = new StringBuilder().append(columns).append('x').append(rows())
                .append(" [").append(format(minAngle)).append(',').append(format(maxAngle)).append("] bounds ");
        for (int i = 0; i < bounds.length; i++) {
            text.append(i == 0 ? "" : ",").append(format(bounds[i]));
        }
        return text.toString();
    }

    private static String format(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Grid grid && grid.columns == columns && grid.minAngle == minAngle
                && grid.maxAngle == maxAngle && Arrays.equals(grid.bounds, bounds);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * Integer.hashCode(columns) + Double.hashCode(minAngle + 7 * maxAngle)) + Arrays.hashCode(bounds);
    }

    @Override
    public String toString() {
        return "Grid " + describe();
    }

    /** Scenes made with different grids were to be matched together; the message names both sources. */
    public static final class MismatchException extends RuntimeException {
        MismatchException(String message) {
            super(message);
        }
    }
}
