package org.scenes.spark;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.apache.hadoop.fs.FileStatus;
import org.apache.spark.api.java.JavaSparkContext;
import org.scenes.app.experiment.Sweeping;
import org.scenes.internal.experiment.Configuration;
import org.scenes.internal.experiment.FoldValidation;
import org.scenes.internal.experiment.Result;
import org.scenes.internal.experiment.ResultTable;
import org.scenes.internal.experiment.Sweep;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.options.SweepOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes-spark experiment}: {@code scenes experiment} as a Spark job, one task per (configuration, fold). */
@Command(name = "experiment", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Run the parameter sweep a Groovy script describes, as 'scenes experiment' does, as a Spark job: "
                + "one task per (configuration, fold), each fold's knowledge base built once per executor. Writes "
                + "the same results table as CSV, JSON and Markdown (no chart: 'scenes experiment' draws it).")
final class ExperimentCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    SparkCommand top;

    @Mixin
    SweepOptions sweepOptions;

    @Override
    public Integer call() throws IOException {
        Sweep sweep = sweepOptions.load();
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        List<String> paths = dataPaths(sweep.data(), hadoop);
        SceneData data = SceneData.read(paths, hadoop);
        List<SceneFile> files = SweepInputs.decodeOnDriver(paths, data, hadoop);
        List<Configuration> configurations = sweep.configurations();
        List<MatchConfig> configs = new ArrayList<>();
        for (Configuration configuration : configurations) {
            configs.add(FoldValidation.matchConfig(configuration, sweep.transforms(), sweep.seed()));
        }
        ResultTable table;
        try (JavaSparkContext spark = top.options.start("experiment " + sweepOptions.sweepFile().getFileName());
             DistributedFolds folds = new DistributedFolds(spark, files, data, sweep.protocol(), top.options.registry(),
                     top.options.pluginDirectories())) {
            Map<MatchConfig, List<Map<String, Double>>> validated = folds.figures(configs);
            List<Result> results = new ArrayList<>();
            for (int i = 0; i < configurations.size(); i++) {
                results.add(new Result(configurations.get(i), FoldValidation.measures(validated.get(configs.get(i)))));
            }
            table = new ResultTable(sweep, results);
        }
        table.checkMeasures();
        String base = sweepOptions.baseName();
        String directory = sweepOptions.outDir();
        String command = sweepOptions.command("scenes-spark");
        List<String> written = write(table, hadoop, directory, base, command);
        PrintWriter out = spec.commandLine().getOut();
        out.printf("%s (%d configurations, %d folds, seed %d)%n%n", sweep.title().isEmpty() ? base : sweep.title(),
                configurations.size(), files.size(), sweep.seed());
        out.print(table.markdown());
        out.printf("%nWritten %s%n", String.join(", ", written));
        out.flush();
        return 0;
    }

    /** The table's files, written locally as the local command writes them, then published to the directory. */
    private static List<String> write(ResultTable table, HadoopFiles hadoop, String directory, String base, String command)
            throws IOException {
        Path scratch = Files.createTempDirectory("scenes-spark-results");
        List<String> written = new ArrayList<>();
        try {
            for (Path file : Sweeping.writeTables(table, scratch, base, command, null)) {
                String target = directory.replaceFirst("/+$", "") + "/" + file.getFileName();
                hadoop.publish(file, target);
                written.add(target);
            }
        } finally {
            try (var listing = Files.list(scratch)) {
                for (Path file : listing.toList()) {
                    Files.deleteIfExists(file);
                }
            }
            Files.deleteIfExists(scratch);
        }
        return written;
    }

    /** The sweep's scene files, a directory standing for the scene files in it (.json, .json.gz, .json.zst), sorted (as the local command). */
    static List<String> dataPaths(List<String> data, HadoopFiles hadoop) throws IOException {
        List<String> paths = new ArrayList<>();
        for (String entry : data) {
            if (hadoop.isDirectory(entry)) {
                for (FileStatus status : hadoop.list(entry)) {
                    String file = status.getPath().getName();
                    if (status.isFile() && SceneCompression.isSceneFile(Path.of(file))) {
                        paths.add(entry.replaceFirst("/+$", "") + "/" + file);
                    }
                }
            } else if (hadoop.exists(entry)) {
                paths.add(entry);
            } else {
                throw new UsageException("the sweep's scene file " + entry + " does not exist (looked in "
                        + hadoop.path(entry) + "); convert logs first with 'scenes-spark convert' or 'scenes convert'");
            }
        }
        if (paths.size() < 2) {
            throw new UsageException("the sweep's data hold " + paths.size() + " scene file(s); cross-validation needs "
                    + "at least two, one per fold");
        }
        return paths;
    }
}
