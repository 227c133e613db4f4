package org.scenes.spark;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.apache.spark.api.java.JavaSparkContext;
import org.scenes.app.tune.Tuning;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.MatchConfigFile;
import org.scenes.internal.validate.Tuner;
import org.scenes.options.TuneOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes-spark tune}: {@code scenes tune} with every (configuration, fold) a Spark task. */
@Command(name = "tune", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Search metric, object weights, memory, k and selector by cross-validation on the training "
                + "files, as 'scenes tune' does and with the same result, each (configuration, fold) a Spark task; "
                + "writes the best configuration for --config.")
final class TuneCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    SparkCommand top;

    @Option(names = "--train", arity = "2..*", paramLabel = "FILE", required = true,
            description = "Training scene files, at least two (one per player works well); any Hadoop-compatible path.")
    List<String> train = new ArrayList<>();

    @Option(names = {"-o", "--output"}, paramLabel = "CONFIG.json", required = true, description = "Where to write the configuration.")
    String output;

    @Mixin
    TuneOptions tuning;

    @Override
    public Integer call() throws IOException {
        int sweeps = tuning.sweeps();
        Folds.Protocol chosen = tuning.protocol();
        Tuner.Objective goal = tuning.objective();
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        SceneData data = SceneData.read(train, hadoop);
        List<SceneFile> files = SweepInputs.decodeOnDriver(train, data, hadoop);
        PrintWriter out = spec.commandLine().getOut();
        Tuner.Result result;
        int validated;
        try (JavaSparkContext spark = top.options.start("tune");
             DistributedFolds folds = new DistributedFolds(spark, files, data, chosen, top.options.registry(),
                     top.options.pluginDirectories())) {
            DistributedTuner tuner = new DistributedTuner(folds, goal, tuning.quiet() ? null : line -> {
                out.println(line);
                out.flush();
            });
            result = tuner.tune(Tuner.defaultStarts(MatchConfig.DEFAULT.withSeed(tuning.seed())),
                    Tuner.defaultSearch(top.options.registry()), sweeps);
            validated = tuner.validated();
        }
        write(hadoop, result.config(), Tuning.crossValidation(result, chosen, goal, train));
        TuneOptions.printBest(out, result);
        out.printf("Validated %d configurations in all (%d ahead of the search, to keep the executors busy)%n", validated,
                validated - result.evaluated());
        out.println("Written to " + output);
        out.flush();
        return 0;
    }

    /** The configuration file of {@code scenes tune}, written locally and published to {@code --output}. */
    private void write(HadoopFiles hadoop, MatchConfig config, Map<String, Object> crossValidation) throws IOException {
        Path scratch = Files.createTempFile("scenes-spark-tune", ".json");
        try {
            MatchConfigFile.write(Files.newOutputStream(scratch), config, Map.of("crossValidation", crossValidation));
            hadoop.publish(scratch, output);
        } finally {
            Files.deleteIfExists(scratch);
        }
    }
}
