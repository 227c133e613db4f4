package org.scenes.cli;

import java.io.IOException;
import java.nio.file.Path;
import org.jfree.chart.JFreeChart;
import org.jfree.data.category.DefaultCategoryDataset;
import org.scenes.internal.experiment.Axis;
import org.scenes.internal.experiment.ResultTable;
import org.scenes.internal.experiment.Sweep;

/**
 * The pivot of a sweep's results as grouped bars: a group per row, a bar per column, drawn like
 * the validation chart (horizontal, value labels, axis zoomed to the data).
 */
final class ExperimentChart {
    private ExperimentChart() {
    }

    static void writeSvg(ResultTable table, Path file) throws IOException {
        Sweep.Layout layout = table.sweep().layout();
        DefaultCategoryDataset dataset = new DefaultCategoryDataset();
        for (String row : table.rowValues()) {
            for (String column : table.columnValues()) {
                double value = table.cell(row, column);
                dataset.addValue(Double.isNaN(value) ? null : value,
                        layout.columnsAreMeasures() ? column : layout.columns().key() + " " + column, row);
            }
        }
        String rowAxis = String.join(" / ", layout.rows().stream().map(Axis::key).toList());
        String valueAxis = String.join(", ", layout.measures());
        String title = table.sweep().title().isEmpty() ? valueAxis : table.sweep().title();
        JFreeChart chart = Charts.bars(title, "rows: " + rowAxis, valueAxis, dataset, Double.NaN);
        Charts.write(file, chart, 900, Charts.height(table.rowValues().size(), table.columnValues().size()));
    }
}
