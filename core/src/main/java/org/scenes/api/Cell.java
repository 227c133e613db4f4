package org.scenes.api;

/**
 * A cell of the discretised view: column counts from the observer's left, row from near to far.
 *
 * @param column the angle slice, from 0 (leftmost)
 * @param row the distance ring, from 0 (nearest)
 */
public record Cell(int column, int row) {
    /**
     * Checks the cell.
     *
     * @param column the angle slice, from 0
     * @param row the distance ring, from 0
     * @throws IllegalArgumentException for a negative column or row
     */
    public Cell {
        if (column < 0 || row < 0) {
            throw new IllegalArgumentException("cell (" + column + ", " + row + ") must not be negative");
        }
    }
}
