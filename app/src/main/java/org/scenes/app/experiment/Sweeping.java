package org.scenes.app.experiment;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.scenes.api.PluginRegistry;
import org.scenes.app.Progress;
import org.scenes.app.validate.Validation;
import org.scenes.internal.experiment.Configuration;
import org.scenes.internal.experiment.Experiment;
import org.scenes.internal.experiment.FoldValidation;
import org.scenes.internal.experiment.ResultTable;
import org.scenes.internal.experiment.Sweep;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.scene.SceneFile;

/**
 * {@code scenes experiment}: a sweep's configurations cross-validated on its scene files, as
 * {@code scenes validate --folds} does, into one results table; and the table's files (CSV, JSON,
 * Markdown), which {@code scenes-spark experiment} writes too.
 */
public final class Sweeping {
    /** Sweeps of fewer queries report no progress. */
    private static final long LARGE_SWEEP = 20_000;

    private Sweeping() {
    }

    /**
     * The results.
     *
     * @param table one row per configuration, its measures checked
     * @param folds the scene files, one fold each
     */
    public record Outcome(ResultTable table, int folds) {
    }

    /**
     * Validates every configuration of the sweep on its scene files.
     *
     * @param data the sweep's scene files, at least two, on one grid
     * @param workers configurations validated at once
     * @param progress told of every query answered in a large sweep
     */
    public static Outcome run(Sweep sweep, List<Path> data, PluginRegistry registry, int workers, Progress progress) {
        List<SceneFile> files = Validation.readSameGrid(data);
        List<Configuration> configurations = sweep.configurations();
        // Few configurations: each spreads its queries over the cores; many: one per core.
        boolean parallelQueries = configurations.size() < workers;
        long queries = configurations.size() * files.stream().mapToLong(f -> f.scenes().size()).sum();
        Progress shown = queries < LARGE_SWEEP ? Progress.NONE : progress;
        ResultTable table;
        shown.begin("Sweeping", queries);
        try {
            FoldValidation validation = new FoldValidation(sweep, files, registry, parallelQueries, shown::step);
            validation.check(configurations);
            table = Experiment.run(sweep, validation, parallelQueries ? 1 : workers, () -> { });
        } finally {
            shown.end();
        }
        table.checkMeasures();
        return new Outcome(table, files.size());
    }

    /**
     * Writes {@code base}.csv, .json and .md in {@code directory}, each atomically.
     *
     * @param command the command line the files name as their source
     * @param chart the chart's file name the Markdown shows, or null for none
     * @return the files written, in that order
     */
    public static List<Path> writeTables(ResultTable table, Path directory, String base, String command, String chart)
            throws IOException {
        Path csv = directory.resolve(base + ".csv");
        Path json = directory.resolve(base + ".json");
        Path markdown = directory.resolve(base + ".md");
        CsvTables.write(csv, table.csvHeader(), table.csvRows());
        table.writeJson(json, command);
        String text = table.markdownDocument(markdown.getFileName().toString(), command, chart);
        try (AtomicOutput output = AtomicOutput.create(markdown);
             Writer writer = new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8)) {
            writer.write(text);
            writer.flush();
            output.commit();
        }
        return List.of(csv, json, markdown);
    }
}
