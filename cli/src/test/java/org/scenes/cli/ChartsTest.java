package org.scenes.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.labels.CategoryItemLabelGenerator;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.data.category.DefaultCategoryDataset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ChartsTest {
    @Test
    void closeFiguresGetAZoomedAxisThatStillShowsEveryBar() {
        DefaultCategoryDataset data = new DefaultCategoryDataset();
        data.addValue(98.4, "action %", "a");
        data.addValue(98.9, "action %", "b");
        data.addValue(99.7, "action %", "c");
        JFreeChart chart = Charts.bars("t", "", "%", data, 100);
        ValueAxis axis = ((CategoryPlot) chart.getPlot()).getRangeAxis();
        assertTrue(axis.getLowerBound() > 90 && axis.getLowerBound() < 98.4, "lower " + axis.getLowerBound());
        assertTrue(axis.getUpperBound() >= 99.7 && axis.getUpperBound() <= 100, "upper " + axis.getUpperBound());
        // the difference between the bars is a visible share of the axis, not 1% of it
        assertTrue((99.7 - 98.4) / (axis.getUpperBound() - axis.getLowerBound()) > 0.3);
        assertTrue(((CategoryPlot) chart.getPlot()).getRenderer().getDefaultItemLabelsVisible(), "value labels");
    }

    @Test
    void labelsLoseTheWordsTheyAllShare() {
        List<String> labels = List.of("ball-goal w=1/1/1/1/0/1/1/1 k=1 vote", "ball-goal w=1/1/1/1/0/1/1/1 k=5 vote",
                "continuous w=1/1/1/1/0/1/1/1 k=1 vote");
        assertEquals(List.of("ball-goal k=1", "ball-goal k=5", "continuous k=1"), Charts.shortLabels(labels));
        assertEquals("w=1/1/1/1/0/1/1/1 vote", Charts.commonPart(labels));
        assertEquals(List.of("only one"), Charts.shortLabels(List.of("only one")));
    }

    @Test
    void barLabelsCarryTheDigitsThatTellDifferentBarsApart() {
        DefaultCategoryDataset data = new DefaultCategoryDataset();
        data.addValue(0.9512, "accuracy", "a");
        data.addValue(0.9534, "accuracy", "b");
        data.addValue(0.9548, "accuracy", "c");
        data.addValue(0.9548, "accuracy", "d");
        JFreeChart chart = Charts.bars("t", "", "share", data, 1);
        CategoryItemLabelGenerator labels = ((CategoryPlot) chart.getPlot()).getRenderer().getDefaultItemLabelGenerator();
        assertEquals(List.of("0.951", "0.953", "0.955", "0.955"),
                List.of(labels.generateLabel(data, 0, 0), labels.generateLabel(data, 0, 1),
                        labels.generateLabel(data, 0, 2), labels.generateLabel(data, 0, 3)));
        // figures that differ in the first two decimals keep two
        DefaultCategoryDataset apart = new DefaultCategoryDataset();
        apart.addValue(0.91, "accuracy", "a");
        apart.addValue(0.95, "accuracy", "b");
        CategoryItemLabelGenerator two = ((CategoryPlot) Charts.bars("t", "", "share", apart, 1).getPlot()).getRenderer()
                .getDefaultItemLabelGenerator();
        assertEquals("0.91", two.generateLabel(apart, 0, 0));
    }

    @Test
    void aSweepChartOfManyBarsDrawsEveryBarsLabel(@TempDir Path directory) throws Exception {
        // 4 groups of 6 bars, as the k-selectors sweep draws: JFreeChart drops a label its bar is too thin for
        DefaultCategoryDataset data = new DefaultCategoryDataset();
        for (int row = 0; row < 4; row++) {
            for (int k = 0; k < 6; k++) {
                data.addValue(0.88 + 0.0123 * row + 0.0017 * k, "k " + k, "selector " + row);
            }
        }
        JFreeChart chart = Charts.bars("t", "rows: selector", "accuracy", data, Double.NaN);
        Path svg = directory.resolve("chart.svg");
        Charts.write(svg, chart, 900, Charts.height(4, 6));
        String text = Files.readString(svg);
        CategoryItemLabelGenerator labels = ((CategoryPlot) chart.getPlot()).getRenderer().getDefaultItemLabelGenerator();
        List<String> missing = new ArrayList<>();
        for (int series = 0; series < 6; series++) {
            for (int row = 0; row < 4; row++) {
                String label = labels.generateLabel(data, series, row);
                if (!text.contains(">" + label + "<")) {
                    missing.add(label);
                }
            }
        }
        assertEquals(List.of(), missing, "labels not drawn");
    }
}
