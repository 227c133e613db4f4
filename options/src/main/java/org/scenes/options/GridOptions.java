package org.scenes.options;

import java.util.Arrays;
import org.scenes.api.Grid;
import picocli.CommandLine.Option;

/** {@code --grid CxR} and {@code --bounds D,...}: the discretisation of the view. */
public final class GridOptions {
    @Option(names = "--grid", paramLabel = "CxR", defaultValue = "5x3",
            description = "Columns (angle slices over [-45,45] degrees) x rows (distance rings); default ${DEFAULT-VALUE}.")
    private String grid;

    @Option(names = "--bounds", paramLabel = "D", split = ",", splitSynopsisLabel = ",",
            description = "Ascending distances (m) separating the rows: rows - 1 values; default 1,5 for 3 rows.")
    private double[] bounds;

    /**
     * The grid the options describe.
     *
     * @throws OptionException naming the option, for a malformed or inconsistent grid
     */
    public Grid grid() {
        int x = grid.indexOf('x');
        int columns;
        int rows;
        try {
            columns = Integer.parseInt(grid.substring(0, x < 0 ? grid.length() : x).trim());
            rows = x < 0 ? -1 : Integer.parseInt(grid.substring(x + 1).trim());
        } catch (NumberFormatException e) {
            throw new OptionException("--grid must be COLUMNSxROWS, e.g. 5x3, not '" + grid + "'");
        }
        double[] distances = bounds;
        if (distances == null) {
            if (rows != -1 && rows != 3) {
                throw new OptionException("--grid " + grid + " has " + rows + " rows: give --bounds with "
                        + (rows - 1) + " distances");
            }
            distances = Grid.DEFAULT.bounds();
        } else if (rows != -1 && distances.length != rows - 1) {
            throw new OptionException("--grid " + grid + " has " + rows + " rows but --bounds gives "
                    + distances.length + " distances (need " + (rows - 1) + ")");
        }
        try {
            return Grid.of(columns, distances);
        } catch (IllegalArgumentException e) {
            throw new OptionException("--grid " + grid + " --bounds " + Arrays.toString(distances) + ": " + e.getMessage());
        }
    }
}
