package org.scenes.cli;

import java.awt.Color;
import java.awt.Rectangle;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.jfree.chart.ChartFactory;
import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.CategoryLabelPositions;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.renderer.category.BarRenderer;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.data.category.DefaultCategoryDataset;
import org.jfree.svg.SVGGraphics2D;
import org.scenes.files.AtomicOutput;

/** Bar charts of accuracy and kick recall per configuration, like the thesis' figures. */
final class Charts {
    private static final int WIDTH = 900;
    private static final int HEIGHT = 560;

    private Charts() {
    }

    static void write(Path file, List<ValidateCommand.Outcome> outcomes) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!name.endsWith(".png") && !name.endsWith(".svg")) {
            throw new UsageException("--chart " + file + ": the name must end in .png or .svg");
        }
        System.setProperty("java.awt.headless", "true");
        write(file, chart(outcomes), WIDTH, HEIGHT);
    }

    /** Writes a chart as PNG or SVG by the file name's ending, atomically. */
    static void write(Path file, JFreeChart chart, int width, int height) throws IOException {
        System.setProperty("java.awt.headless", "true");
        try (AtomicOutput output = AtomicOutput.create(file)) {
            if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
                ChartUtils.writeChartAsPNG(output.stream(), chart, width, height);
            } else {
                SVGGraphics2D graphics = new SVGGraphics2D(width, height);
                // a fixed prefix instead of a time-based one, so the same chart gives the same file
                graphics.setDefsKeyPrefix("scenes");
                chart.draw(graphics, new Rectangle(width, height));
                output.stream().write(graphics.getSVGDocument().getBytes(StandardCharsets.UTF_8));
            }
            output.commit();
        }
    }

    static JFreeChart chart(List<ValidateCommand.Outcome> outcomes) {
        DefaultCategoryDataset data = new DefaultCategoryDataset();
        for (ValidateCommand.Outcome outcome : outcomes) {
            data.addValue(100 * orZero(outcome.accuracy()), "Action %", outcome.label());
            data.addValue(100 * orZero(outcome.kickRecall()), "Kick %", outcome.label());
        }
        JFreeChart chart = ChartFactory.createBarChart("Prediction accuracy per configuration", null, "%", data,
                PlotOrientation.VERTICAL, true, false, false);
        chart.setBackgroundPaint(Color.WHITE);
        CategoryPlot plot = chart.getCategoryPlot();
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(Color.GRAY);
        plot.getRangeAxis().setRange(0, 100);
        plot.getDomainAxis().setCategoryLabelPositions(CategoryLabelPositions.UP_45);
        plot.getDomainAxis().setMaximumCategoryLabelLines(3);
        BarRenderer renderer = (BarRenderer) plot.getRenderer();
        renderer.setBarPainter(new StandardBarPainter());
        renderer.setShadowVisible(false);
        renderer.setSeriesPaint(0, new Color(0x33, 0x66, 0x99));
        renderer.setSeriesPaint(1, new Color(0xcc, 0x66, 0x33));
        return chart;
    }

    private static double orZero(double value) {
        return Double.isNaN(value) ? 0 : value;
    }
}
