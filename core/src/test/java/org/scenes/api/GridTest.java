package org.scenes.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class GridTest {
    private final Grid grid = Grid.DEFAULT;

    @Test
    void defaultGridIsFiveColumnsByThreeRows() {
        assertEquals(5, grid.columns());
        assertEquals(3, grid.rows());
    }

    @Test
    void rowsSplitAtOneAndFiveMetresWithTheBoundInTheNearerRow() {
        assertEquals(0, grid.row(0.4));
        assertEquals(0, grid.row(1.0));
        assertEquals(1, grid.row(1.01));
        assertEquals(1, grid.row(5.0));
        assertEquals(2, grid.row(5.1));
        assertEquals(2, grid.row(Double.NaN), "no distance sent: far");
    }

    @Test
    void columnsSplitTheViewEvenlyLeftToRight() {
        assertEquals(0, grid.column(-45));
        assertEquals(0, grid.column(-27.1));
        assertEquals(1, grid.column(-27));
        assertEquals(2, grid.column(0));
        assertEquals(3, grid.column(9));
        assertEquals(4, grid.column(44.9));
    }

    @Test
    void directionsOutsideTheViewFallIntoTheOutermostColumns() {
        assertEquals(0, grid.column(-117));
        assertEquals(4, grid.column(90));
        assertEquals(4, grid.column(180));
    }

    @Test
    void badGridsAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> Grid.of(0, 1, 5));
        assertThrows(IllegalArgumentException.class, () -> Grid.of(5, 5, 1));
        assertThrows(IllegalArgumentException.class, () -> new Grid(5, 10, 10, new double[] {1}));
    }

    @Test
    void describeNamesShapeRangeAndBounds() {
        assertEquals("5x3 [-45,45] bounds 1,5", grid.describe());
    }
}
