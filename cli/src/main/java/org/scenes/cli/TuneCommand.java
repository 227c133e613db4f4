package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.scene.SceneFile;
import org.scenes.scene.SceneFileReader;
import org.scenes.validate.Folds;
import org.scenes.validate.MatchConfig;
import org.scenes.validate.Tuner;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes tune}: choose the matching configuration by cross-validation on training files only. */
@Command(name = "tune", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Search metric, object weights, memory, k and selector by cross-validation on the training files only",
                "(by default each file tested against all the others) and write the best configuration for --config."})
final class TuneCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--train", arity = "2..*", paramLabel = "FILE", required = true,
            description = "Training scene files, at least two (one per player works well).")
    List<Path> train = new ArrayList<>();

    @Option(names = {"-o", "--output"}, paramLabel = "CONFIG.json", required = true, description = "Where to write the configuration.")
    Path output;

    @Option(names = "--seed", paramLabel = "S", description = "Seed of every random choice (default 1).")
    long seed = 1;

    @Option(names = "--sweeps", paramLabel = "N", description = "Passes over the search dimensions (default 2).")
    int sweeps = 2;

    @Option(names = "--protocol", paramLabel = "leave-one-out|next",
            description = "Cross-validation: each file against all others (default) or against the next one, as the thesis did.")
    String protocol = "leave-one-out";

    @Option(names = "--objective", paramLabel = "mean|accuracy|direction|macro-f1",
            description = "What to maximise: the mean of accuracy, action-with-direction accuracy and macro F1 (default), or one of them.")
    String objective = "mean";

    @Option(names = "--quiet", description = "Do not print each configuration tried.")
    boolean quiet;

    @Override
    public Integer call() throws Exception {
        if (sweeps < 1) {
            throw new UsageException("--sweeps must be at least 1");
        }
        OutputPaths.checkFile("-o", output);
        List<SceneFile> files = new ArrayList<>();
        for (Path path : train) {
            files.add(SceneFileReader.read(path));
        }
        PrintWriter out = spec.commandLine().getOut();
        Folds.Protocol chosen = Folds.Protocol.fromKey(protocol);
        if (chosen == null) {
            throw new UsageException("--protocol must be " + Folds.Protocol.keys() + ", not " + protocol);
        }
        Tuner.Objective goal = switch (objective) {
            case "mean" -> Tuner.Objective.MEAN;
            case "accuracy" -> Tuner.Objective.ACCURACY;
            case "direction" -> Tuner.Objective.DIRECTION;
            case "macro-f1" -> Tuner.Objective.MACRO_F1;
            default -> throw new UsageException("--objective must be mean, accuracy, direction or macro-f1, not " + objective);
        };
        Tuner tuner = new Tuner(files, top.global.registry(), chosen, goal, quiet ? null : line -> {
            out.println(line);
            out.flush();
        });
        Tuner.Result result = tuner.tune(MatchConfig.DEFAULT.withSeed(seed), Tuner.defaultSearch(), sweeps);
        Map<String, Object> score = new LinkedHashMap<>();
        score.put("score", result.score());
        score.put("protocol", protocol);
        score.put("objective", objective);
        score.put("scoreFormula", objective.equals("mean")
                ? "(accuracy + action-with-direction accuracy + macro F1) / 3 over the decisions of all folds"
                : objective + " over the decisions of all folds");
        score.put("figures", result.figures());
        score.put("configurationsTried", result.evaluated());
        score.put("trainFiles", train.stream().map(Path::toString).toList());
        ConfigFiles.write(output, result.config(), Map.of("crossValidation", score));
        out.printf("Best of %d configurations: %s%n", result.evaluated(), result.config().describe());
        out.printf("Cross-validation score %.4f (accuracy %.4f, with direction %.4f, macro F1 %.4f)%n", result.score(),
                result.figures().get("accuracy"), result.figures().get("directionAccuracy"), result.figures().get("macroF1"));
        out.println("Written to " + output);
        out.flush();
        return ExitCodes.OK;
    }
}
