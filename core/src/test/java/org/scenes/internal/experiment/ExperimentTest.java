package org.scenes.internal.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;

/** The sweep runner and its result files, with a stand-in validation. */
class ExperimentTest {
    @TempDir
    Path dir;

    private static Sweep sweep() {
        Sweep sweep = new Sweep("k and selectors", List.of("a.json", "b.json"), List.of("cell", "ball-goal"),
                List.of(ObjectWeights.DEFAULT), List.of(1, 3, 5), List.of("first-valid", "vote"),
                List.of(ActionWeights.DEFAULT), null, List.of(), 7,
                new Sweep.Layout(List.of(Axis.METRIC, Axis.SELECTOR), Axis.K, "accuracy"));
        return sweep;
    }

    /** Numbers that depend only on the configuration; later configurations finish first. */
    private static Map<String, Double> fake(Configuration configuration) {
        try {
            Thread.sleep(configuration.metric().equals("cell") ? 20 : 1);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        Map<String, Double> measures = new LinkedHashMap<>();
        double base = configuration.metric().equals("cell") ? 0.5 : 0.25;
        measures.put("accuracy", base + configuration.k() / 100.0 + (configuration.selector().equals("vote") ? 0.001 : 0));
        measures.put("kick accuracy", Double.NaN);
        return measures;
    }

    @Test
    void resultsFollowSweepOrderWhateverTheThreads() {
        AtomicInteger done = new AtomicInteger();
        ResultTable parallel = Experiment.run(sweep(), ExperimentTest::fake, 4, done::incrementAndGet);
        ResultTable serial = Experiment.run(sweep(), ExperimentTest::fake, 1, () -> { });
        assertEquals(12, done.get());
        assertEquals(serial.results(), parallel.results());
        assertEquals(sweep().configurations(), parallel.results().stream().map(Result::configuration).toList());
    }

    @Test
    void pivotHasOneRowPerRowAxesCombination() {
        ResultTable table = Experiment.run(sweep(), ExperimentTest::fake, 2, () -> { });
        assertEquals(List.of("cell / first-valid", "cell / vote", "ball-goal / first-valid", "ball-goal / vote"),
                table.rowValues());
        assertEquals(List.of("1", "3", "5"), table.columnValues());
        assertEquals(0.531, table.cell("cell / vote", "3"), 1e-12);
        assertEquals("""
                | metric / selector \\ k | 1 | 3 | 5 |
                |---|---:|---:|---:|
                | cell / first-valid | 0.5100 | 0.5300 | 0.5500 |
                | cell / vote | 0.5110 | 0.5310 | 0.5510 |
                | ball-goal / first-valid | 0.2600 | 0.2800 | 0.3000 |
                | ball-goal / vote | 0.2610 | 0.2810 | 0.3010 |
                """, table.markdown());
    }

    @Test
    void columnsMayBeSeveralMeasures() {
        Sweep sweep = sweep();
        sweep = sweep.withLayout(new Sweep.Layout(List.of(Axis.METRIC, Axis.K, Axis.SELECTOR), null,
                List.of("kick accuracy", "accuracy")));
        ResultTable table = Experiment.run(sweep, ExperimentTest::fake, 2, () -> { });
        assertEquals(List.of("kick accuracy", "accuracy"), table.columnValues());
        assertEquals(0.261, table.cell("ball-goal / 1 / vote", "accuracy"), 1e-12);
        assertTrue(table.markdown().startsWith("| metric / k / selector \\ measure | kick accuracy | accuracy |\n"
                + "|---|---:|---:|\n| cell / 1 / first-valid | - | 0.5100 |\n"), table.markdown());
    }

    @Test
    void csvAndJsonHoldEveryConfiguration() throws IOException {
        ResultTable table = Experiment.run(sweep(), ExperimentTest::fake, 2, () -> { });
        assertEquals(List.of("metric", "weights", "k", "selector", "action-weights", "accuracy", "kick accuracy"), table.csvHeader());
        assertEquals(12, table.csvRows().size());
        assertEquals(List.of("cell", "1/1/1/1/0/1/1/1", "1", "first-valid", "1/1/1/1/1/1/1/1", "0.51", ""), table.csvRows().get(0));
        Path json = dir.resolve("out/results.json");
        table.writeJson(json, "scenes experiment sweep.groovy");
        String text = Files.readString(json);
        assertTrue(text.contains("\"command\" : \"scenes experiment sweep.groovy\""), text);
        assertTrue(text.contains("\"kick accuracy\" : null"), text);
        assertTrue(text.contains("\"cells\" : [ [ 0.51, 0.53, 0.55 ]"), text);
        assertTrue(text.contains("\"measures\" : [ \"accuracy\" ]"), text);
        assertFalse(Files.list(dir.resolve("out")).anyMatch(f -> f.getFileName().toString().endsWith(".tmp")));
    }

    @Test
    void failingConfigurationIsNamed() {
        ExperimentException e = assertThrows(ExperimentException.class, () -> Experiment.run(sweep(), configuration -> {
            if (configuration.k() == 5 && configuration.metric().equals("ball-goal")) {
                throw new IllegalStateException("query scene 12: boom");
            }
            return fake(configuration);
        }, 3, () -> { }));
        assertEquals("configuration metric=ball-goal weights=1/1/1/1/0/1/1/1 k=5 selector=first-valid "
                + "action-weights=1/1/1/1/1/1/1/1: query scene 12: boom", e.getMessage());
    }

    @Test
    void everyVaryingAxisMustBeInTheTable() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Sweep("", List.of("x", "y"),
                List.of("cell", "vote"), List.of(ObjectWeights.DEFAULT), List.of(1, 2), List.of("first-valid"),
                List.of(ActionWeights.DEFAULT), null, List.of(), 1, new Sweep.Layout(List.of(Axis.SELECTOR), Axis.K, "accuracy")));
        assertEquals("the table's rows are selector and its columns k, but metric takes several values too: add it to the rows",
                e.getMessage());
    }
}
