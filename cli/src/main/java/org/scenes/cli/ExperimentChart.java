package org.scenes.cli;

import java.awt.Color;
import java.awt.Font;
import java.awt.Rectangle;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
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
import org.jfree.svg.SVGGraphics2D;
import org.scenes.experiment.Axis;
import org.scenes.experiment.ResultTable;
import org.scenes.experiment.Sweep;
import org.scenes.files.AtomicOutput;

/** The pivot of a sweep's results as a grouped bar chart: a group per row, a bar per column value. */
final class ExperimentChart {
    private ExperimentChart() {
    }

    static void writeSvg(ResultTable table, Path file) throws IOException {
        // Drawing needs no display; without this AWT looks for one on some systems.
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
        int height = 480;
        SVGGraphics2D graphics = new SVGGraphics2D(width, height);
        chart.draw(graphics, new Rectangle(0, 0, width, height));
        try (AtomicOutput output = AtomicOutput.create(file);
             Writer out = new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8)) {
            out.write(graphics.getSVGDocument());
            out.flush();
            output.commit();
        }
    }

    private static int longest(List<String> labels) {
        return labels.stream().mapToInt(String::length).max().orElse(0);
    }
}
