package org.scenes.api;

/** A cell of the discretised view: column counts from the observer's left, row from near to far. */
public record Cell(int column, int row) {
    /** @throws IllegalArgumentException for a negative column or row */
    public Cell {
        if (column < 0 || row < 0) {
            throw new IllegalArgumentException("cell (" + column + ", " + row + ") must not be negative");
        }
    }
}
