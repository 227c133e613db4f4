package org.scenes.cli;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.experiment.Configuration;
import org.scenes.internal.experiment.Experiment;
import org.scenes.internal.experiment.FoldValidation;
import org.scenes.internal.experiment.ResultTable;
import org.scenes.internal.experiment.Sweep;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.scene.SceneFile;
import org.scenes.options.SweepOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes experiment}: a parameter sweep described by a Groovy script, validated configuration by configuration. */
@Command(name = "experiment", mixinStandardHelpOptions = true, sortOptions = false,
        // one element: the main help shows a command's first description line, which must be a whole sentence
        description = {"Run the parameter sweep a Groovy script describes (metrics x object weights x k x selectors x action"
                + " weights), cross-validating each configuration on the sweep's scene files as 'scenes validate --folds' does,"
                + " and write one results table as CSV, JSON, Markdown and an SVG chart. Sweep scripts: docs/scripting.md."})
final class ExperimentCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Mixin
    SweepOptions sweepOptions;

    @Option(names = "--threads", paramLabel = "N",
            description = "Configurations validated at once (default: the number of cores).")
    Integer threads;

    @Override
    public Integer call() throws IOException {
        int workers = Limits.threads("--threads", threads == null ? Runtime.getRuntime().availableProcessors() : threads);
        Sweep sweep = sweepOptions.load();
        List<SceneFile> files = read(sweep.data());
        PluginRegistry registry = top.global.registry();
        List<Configuration> configurations = sweep.configurations();
        // Few configurations: each spreads its queries over the cores; many: one per core.
        boolean parallelQueries = configurations.size() < workers;
        long queries = configurations.size() * files.stream().mapToLong(f -> f.scenes().size()).sum();
        PrintWriter out = spec.commandLine().getOut();
        ResultTable table;
        try (ProgressBar bar = progress(queries)) {
            Runnable tick = bar == null ? () -> { } : bar::step;
            FoldValidation validation = new FoldValidation(sweep, files, registry, parallelQueries, tick);
            validation.check(configurations);
            table = Experiment.run(sweep, validation, parallelQueries ? 1 : workers, () -> { });
        }
        table.checkMeasures();
        String base = sweepOptions.baseName();
        Path directory = Path.of(sweepOptions.outDir());
        String command = sweepOptions.command("scenes");
        Path csv = directory.resolve(base + ".csv");
        Path json = directory.resolve(base + ".json");
        Path markdown = directory.resolve(base + ".md");
        Path chart = directory.resolve(base + ".svg");
        CsvTables.write(csv, table.csvHeader(), table.csvRows());
        table.writeJson(json, command);
        writeMarkdown(markdown, table, command, chart.getFileName().toString());
        ExperimentChart.writeSvg(table, chart);
        out.printf("%s (%d configurations, %d folds, seed %d)%n%n", sweep.title().isEmpty() ? base : sweep.title(),
                configurations.size(), files.size(), sweep.seed());
        out.print(table.markdown());
        out.printf("%nWritten %s, %s, %s, %s%n", csv, json, markdown, chart);
        out.flush();
        return ExitCodes.OK;
    }

    /** The scene files, a directory standing for the .json and .json.gz files in it, sorted. */
    private static List<SceneFile> read(List<String> data) throws IOException {
        List<Path> paths = new ArrayList<>();
        for (String entry : data) {
            Path path = Path.of(entry);
            if (Files.isDirectory(path)) {
                try (Stream<Path> listing = Files.list(path)) {
                    paths.addAll(listing.filter(f -> f.toString().endsWith(".json") || f.toString().endsWith(".json.gz"))
                            .sorted().toList());
                }
            } else if (Files.isRegularFile(path)) {
                paths.add(path);
            } else {
                throw new UsageException("the sweep's scene file " + entry + " does not exist (looked in "
                        + path.toAbsolutePath().normalize() + "); convert logs first with 'scenes convert'");
            }
        }
        if (paths.size() < 2) {
            throw new UsageException("the sweep's data hold " + paths.size() + " scene file(s); cross-validation needs "
                    + "at least two, one per fold");
        }
        return ValidateCommand.readSameGrid(paths);
    }

    private static void writeMarkdown(Path file, ResultTable table, String command, String chart) throws IOException {
        String text = table.markdownDocument(file.getFileName().toString(), command, chart);
        try (AtomicOutput output = AtomicOutput.create(file);
             Writer writer = new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8)) {
            writer.write(text);
            writer.flush();
            output.commit();
        }
    }

    private static ProgressBar progress(long total) {
        if (System.console() == null || total < 20_000) {
            return null;
        }
        return new ProgressBarBuilder().setTaskName("Sweeping").setInitialMax(total)
                .setConsumer(new ConsoleProgressBarConsumer(System.err)).clearDisplayOnFinish().build();
    }
}
