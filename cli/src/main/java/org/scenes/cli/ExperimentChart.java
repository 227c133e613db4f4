package org.scenes.cli;

import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.jfree.chart.ChartFactory;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.CategoryLabelPositions;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.renderer.category.BarRenderer;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.data.category.DefaultCategoryDataset;
import org.scenes.experiment.Axis;
import org.scenes.experiment.ResultTable;
import org.scenes.experiment.Sweep;

/** The pivot of a sweep's results as a grouped bar chart: a group per row, a bar per column. */
final class ExperimentChart {
    private ExperimentChart() {
    }

    static void writeSvg(ResultTable table, Path file) throws IOException {
        System.setProperty("java.awt.headless", "true");
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
        JFreeChart chart = ChartFactory.createBarChart(table.sweep().title().isEmpty() ? valueAxis : table.sweep().title(),
                rowAxis, valueAxis, dataset, PlotOrientation.VERTICAL, true, false, false);
        chart.setBackgroundPaint(Color.WHITE);
        chart.getTitle().setFont(new Font(Font.SANS_SERIF, Font.BOLD, 16));
        CategoryPlot plot = chart.getCategoryPlot();
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        BarRenderer renderer = (BarRenderer) plot.getRenderer();
        renderer.setBarPainter(new StandardBarPainter());
        renderer.setShadowVisible(false);
        renderer.setItemMargin(0.02);
        CategoryAxis categories = plot.getDomainAxis();
        if (longest(table.rowValues()) > 12) {
            categories.setCategoryLabelPositions(CategoryLabelPositions.UP_45);
        }
        int width = Math.max(640, 60 + table.rowValues().size() * (24 + 14 * table.columnValues().size()));
        Charts.write(file, chart, width, 480);
    }

    private static int longest(List<String> labels) {
        return labels.stream().mapToInt(String::length).max().orElse(0);
    }
}
