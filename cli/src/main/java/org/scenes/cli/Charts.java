package org.scenes.cli;

import java.awt.Color;
import java.awt.Font;
import java.awt.Rectangle;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.text.DecimalFormat;
import java.text.DecimalFormatSymbols;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.ToDoubleFunction;
import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.labels.ItemLabelAnchor;
import org.jfree.chart.labels.ItemLabelPosition;
import org.jfree.chart.labels.StandardCategoryItemLabelGenerator;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.renderer.category.BarRenderer;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.chart.title.TextTitle;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.category.DefaultCategoryDataset;
import org.jfree.svg.SVGGraphics2D;
import org.scenes.app.validate.Validation;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.validate.ValidationReport;

/**
 * Bar charts of validation figures per configuration: horizontal bars (labels on one line, never
 * rotated or broken), each bar labelled with its value, on an axis zoomed to the data so that
 * 98.4, 98.9 and 99.7 look different (a subtitle says where the axis starts).
 */
final class Charts {
    private static final int WIDTH = 900;
    static final Color[] SERIES = {new Color(0x33, 0x66, 0x99), new Color(0xcc, 0x66, 0x33),
        new Color(0x55, 0x99, 0x55), new Color(0x88, 0x66, 0xaa), new Color(0xaa, 0x99, 0x33)};

    private Charts() {
    }

    static void write(Path file, List<Validation.Outcome> outcomes) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!name.endsWith(".png") && !name.endsWith(".svg")) {
            throw new UsageException("--chart " + file + ": the name must end in .png or .svg");
        }
        System.setProperty("java.awt.headless", "true");
        write(file, chart(outcomes), WIDTH, height(outcomes.size(), 3));
    }

    /** Room for every bar: rows of categories times series, plus titles and legend. */
    static int height(int categories, int series) {
        // bars thick enough for their value label inside (JFreeChart drops a label that does not fit)
        return Math.max(320, 170 + categories * (22 * series + 14));
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

    static JFreeChart chart(List<Validation.Outcome> outcomes) {
        DefaultCategoryDataset data = new DefaultCategoryDataset();
        List<String> labels = shortLabels(outcomes.stream().map(Validation.Outcome::label).toList());
        for (int i = 0; i < outcomes.size(); i++) {
            Validation.Outcome outcome = outcomes.get(i);
            add(data, 100 * figure(outcome, ValidationReport::accuracy), "action %", labels.get(i));
            add(data, 100 * figure(outcome, ValidationReport::directionAccuracy), "action with direction %", labels.get(i));
            add(data, 100 * figure(outcome, ValidationReport::macroF1), "macro F1 %", labels.get(i));
        }
        String common = commonPart(outcomes.stream().map(Validation.Outcome::label).toList());
        return bars("Prediction per configuration", common, "%", data, 100);
    }

    private static double figure(Validation.Outcome outcome, ToDoubleFunction<ValidationReport> figure) {
        return outcome.report() != null ? figure.applyAsDouble(outcome.report()) : outcome.folds().mean(figure);
    }

    private static void add(DefaultCategoryDataset data, double value, String series, String category) {
        data.addValue(Double.isNaN(value) ? null : value, series, category);
    }

    /**
     * Horizontal bars with value labels on a value axis zoomed to the data ({@code ceiling} the
     * most the figure can be, e.g. 100 for %); {@code subtitle} may be empty.
     */
    static JFreeChart bars(String title, String subtitle, String unit, DefaultCategoryDataset data, double ceiling) {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int r = 0; r < data.getRowCount(); r++) {
            for (int c = 0; c < data.getColumnCount(); c++) {
                Number value = data.getValue(r, c);
                if (value != null) {
                    min = Math.min(min, value.doubleValue());
                    max = Math.max(max, value.doubleValue());
                }
            }
        }
        double lower = 0;
        double upper = 1;
        if (min <= max) {
            double span = Math.max(max - min, Math.abs(max) * 0.01 + 1e-9);
            lower = Math.max(0, niceFloor(min - 0.6 * span, span));
            if (lower >= min) {
                lower = Math.max(0, min - span * 0.1);
            }
            upper = max + 0.04 * (max - lower);
            if (!Double.isNaN(ceiling) && max <= ceiling) {
                upper = Math.min(upper, ceiling);
            }
            if (upper <= max) {
                upper = max + 1e-9;
            }
        }
        CategoryAxis categories = new CategoryAxis(null);
        categories.setMaximumCategoryLabelWidthRatio(0.45f);
        categories.setMaximumCategoryLabelLines(1);
        categories.setTickLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        NumberAxis values = new NumberAxis(unit + (lower > 0 ? " (axis from " + format(lower) + ")" : ""));
        values.setRange(lower, upper);
        BarRenderer renderer = new BarRenderer();
        renderer.setBarPainter(new StandardBarPainter());
        renderer.setShadowVisible(false);
        renderer.setItemMargin(0.05);
        for (int i = 0; i < SERIES.length; i++) {
            renderer.setSeriesPaint(i, SERIES[i]);
        }
        renderer.setDefaultItemLabelGenerator(new StandardCategoryItemLabelGenerator("{2}",
                labelFormat(data, max - min < 10 ? 2 : 1)));
        renderer.setDefaultItemLabelsVisible(true);
        renderer.setDefaultItemLabelFont(new Font(Font.SANS_SERIF, Font.BOLD, 11));
        // inside the bar's end: the zoomed axis leaves no room beyond the longest bar
        renderer.setDefaultItemLabelPaint(Color.WHITE);
        renderer.setDefaultPositiveItemLabelPosition(new ItemLabelPosition(ItemLabelAnchor.INSIDE3, TextAnchor.CENTER_RIGHT));
        CategoryPlot plot = new CategoryPlot(data, categories, values, renderer);
        plot.setOrientation(PlotOrientation.HORIZONTAL);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        JFreeChart chart = new JFreeChart(title, new Font(Font.SANS_SERIF, Font.BOLD, 16), plot, true);
        if (!subtitle.isEmpty()) {
            chart.addSubtitle(new TextTitle(subtitle, new Font(Font.SANS_SERIF, Font.PLAIN, 12)));
        }
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /** Most decimals a bar label gets: figures closer than this are equal for the chart. */
    static final int MAX_LABEL_DECIMALS = 6;

    /**
     * The format of the bar labels: at least {@code decimals} decimals, more until bars of different
     * values read differently (0.9512 and 0.9548 are 0.951 and 0.955, not both 0.95).
     */
    static DecimalFormat labelFormat(DefaultCategoryDataset data, int decimals) {
        Set<Double> values = new TreeSet<>();
        for (int r = 0; r < data.getRowCount(); r++) {
            for (int c = 0; c < data.getColumnCount(); c++) {
                Number value = data.getValue(r, c);
                if (value != null) {
                    values.add(value.doubleValue());
                }
            }
        }
        for (int d = decimals; ; d++) {
            DecimalFormat format = new DecimalFormat("0." + "0".repeat(d),
                    DecimalFormatSymbols.getInstance(Locale.ROOT));
            Set<String> labels = new HashSet<>();
            values.forEach(v -> labels.add(format.format(v)));
            if (labels.size() == values.size() || d >= MAX_LABEL_DECIMALS) {
                return format;
            }
        }
    }

    private static double niceFloor(double value, double span) {
        double step = Math.pow(10, Math.floor(Math.log10(Math.max(span, 1e-9))));
        return Math.floor(value / step) * step;
    }

    private static String format(double value) {
        return new DecimalFormat("0.###").format(value);
    }

    /** Labels without the words every label shares (they go to the subtitle), so bars are told apart at a glance. */
    static List<String> shortLabels(List<String> labels) {
        if (labels.size() < 2) {
            return labels;
        }
        Set<String> common = commonWords(labels);
        List<String> shortened = new ArrayList<>();
        for (String label : labels) {
            String rest = String.join(" ", Arrays.stream(label.split(" ")).filter(w -> !common.contains(w)).toList());
            shortened.add(rest.isEmpty() ? label : rest);
        }
        return new ArrayList<>(new LinkedHashSet<>(shortened)).size() == labels.size() ? shortened : labels;
    }

    static String commonPart(List<String> labels) {
        if (labels.size() < 2) {
            return "";
        }
        Set<String> common = commonWords(labels);
        return String.join(" ", Arrays.stream(labels.get(0).split(" ")).filter(common::contains).toList());
    }

    private static Set<String> commonWords(List<String> labels) {
        Set<String> common = new LinkedHashSet<>(Arrays.asList(labels.get(0).split(" ")));
        for (String label : labels) {
            common.retainAll(Arrays.asList(label.split(" ")));
        }
        return common;
    }
}
