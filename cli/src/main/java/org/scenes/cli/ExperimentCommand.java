package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.scenes.app.experiment.Sweeping;
import org.scenes.internal.experiment.ResultTable;
import org.scenes.internal.experiment.Sweep;
import org.scenes.internal.scene.SceneCompression;
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
        Sweeping.Outcome outcome = Sweeping.run(sweep, read(sweep.data()), top.global.registry(), workers,
                TerminalProgress.reporter());
        ResultTable table = outcome.table();
        String base = sweepOptions.baseName();
        String command = sweepOptions.command("scenes");
        Path chart = Path.of(sweepOptions.outDir()).resolve(base + ".svg");
        List<Path> written = Sweeping.writeTables(table, Path.of(sweepOptions.outDir()), base, command,
                chart.getFileName().toString());
        ExperimentChart.writeSvg(table, chart);
        PrintWriter out = spec.commandLine().getOut();
        out.printf("%s (%d configurations, %d folds, seed %d)%n%n", sweep.title().isEmpty() ? base : sweep.title(),
                sweep.configurations().size(), outcome.folds(), sweep.seed());
        out.print(table.markdown());
        out.printf("%nWritten %s, %s, %s, %s%n", written.get(0), written.get(1), written.get(2), chart);
        out.flush();
        return ExitCodes.OK;
    }

    /** The scene files, a directory standing for the scene files in it (.json, .json.gz, .json.zst), sorted. */
    private static List<Path> read(List<String> data) throws IOException {
        List<Path> paths = new ArrayList<>();
        for (String entry : data) {
            Path path = Path.of(entry);
            if (Files.isDirectory(path)) {
                paths.addAll(SceneCompression.sceneFilesIn(path));
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
        return paths;
    }
}
