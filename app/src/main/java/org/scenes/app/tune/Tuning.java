package org.scenes.app.tune;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.RandomSearch;
import org.scenes.internal.validate.Tuner;

/**
 * {@code scenes tune}: the matching configuration chosen by cross-validation on training files only,
 * by coordinate descent or by random search with successive halving, with the {@code crossValidation}
 * block the configuration file carries beside it ({@code scenes-spark tune} writes the same block).
 */
public final class Tuning {
    private Tuning() {
    }

    /**
     * What to tune on.
     *
     * @param train the training files, at least two
     * @param protocol the folds' protocol
     * @param objective what to maximise
     * @param seed the seed of every random choice
     */
    public record Request(List<Path> train, Folds.Protocol protocol, Tuner.Objective objective, long seed) {
        public Request {
            train = List.copyOf(train);
        }

        /** The training files' names, as the configuration file lists them. */
        public List<String> trainNames() {
            return train.stream().map(Path::toString).toList();
        }
    }

    /**
     * A search's end.
     *
     * @param config the configuration chosen
     * @param crossValidation the block written beside it
     * @param tried every configuration scored, in order (for {@code --table})
     * @param configurations the distinct configurations tried
     * @param scores the scores computed (a random search scores a configuration once per rung)
     * @param seconds the search's wall-clock time
     * @param figures the chosen configuration's figures
     * @param score its score
     */
    public record Outcome(MatchConfig config, Map<String, Object> crossValidation, List<RandomSearch.Tried> tried,
                          long configurations, int scores, double seconds, Map<String, Double> figures, double score) {
    }

    /**
     * The coordinate descent from the built-in starts over the built-in search.
     *
     * @param sweeps passes over the dimensions, at least 1
     * @param log told one line per configuration scored; may be null
     */
    public static Outcome descent(Request request, int sweeps, PluginRegistry registry, Consumer<String> log) {
        long start = System.nanoTime();
        Tuner tuner = new Tuner(read(request.train()), registry, request.protocol(), request.objective(), log);
        Tuner.Result result = tuner.tune(Tuner.defaultStarts(MatchConfig.DEFAULT.withSeed(request.seed())),
                Tuner.defaultSearch(registry), sweeps);
        return new Outcome(result.config(), crossValidation(result, request.protocol(), request.objective(),
                request.trainNames()), tuner.tried(), result.evaluated(), result.evaluated(),
                (System.nanoTime() - start) / 1e9, result.figures(), result.score());
    }

    /**
     * The random search: one bracket of {@code configurations}, or brackets until the time is spent.
     *
     * @param timeNanos the time after which no bracket starts, counted once the files are read, or
     *                  Long.MAX_VALUE for one bracket
     * @param metrics the metrics to search, or empty for every family
     * @param progress told after each score; may be null
     */
    public static Outcome random(Request request, List<String> metrics, int configurations, long timeNanos,
                                 PluginRegistry registry, RandomSearch.Progress progress) {
        List<SceneFile> files = read(request.train());
        long start = System.nanoTime();
        RandomSearch searcher = new RandomSearch(files, registry, request.protocol(), request.objective(), metrics);
        long deadline = timeNanos == Long.MAX_VALUE ? Long.MAX_VALUE : start + timeNanos;
        RandomSearch.Result result = searcher.run(MatchConfig.DEFAULT.withSeed(request.seed()), request.seed(), configurations,
                deadline, progress);
        double seconds = (System.nanoTime() - start) / 1e9;
        long distinct = result.table().stream().map(RandomSearch.Tried::config).distinct().count();
        Map<String, Object> score = new LinkedHashMap<>();
        score.put("score", result.score());
        score.put("protocol", request.protocol().key());
        score.put("objective", request.objective().key());
        score.put("search", "random search with successive halving");
        if (!metrics.isEmpty()) {
            score.put("metrics", metrics);
        }
        score.put("figures", result.figures());
        score.put("configurationsTried", distinct);
        score.put("scores", result.table().size());
        score.put("seconds", Math.round(seconds * 10) / 10.0);
        score.put("trainFiles", request.trainNames());
        return new Outcome(result.config(), score, result.table(), distinct, result.table().size(), seconds,
                result.figures(), result.score());
    }

    /** The {@code crossValidation} block of the configuration file a descent writes (here or on Spark). */
    public static Map<String, Object> crossValidation(Tuner.Result result, Folds.Protocol protocol, Tuner.Objective objective,
                                                      List<String> trainFiles) {
        Map<String, Object> score = new LinkedHashMap<>();
        score.put("score", result.score());
        score.put("protocol", protocol.key());
        score.put("objective", objective.key());
        score.put("scoreFormula", objective == Tuner.Objective.MEAN
                ? "(accuracy + action-with-direction accuracy + macro F1) / 3 over the decisions of all folds"
                : objective.key() + " over the decisions of all folds");
        score.put("figures", result.figures());
        score.put("configurationsTried", result.evaluated());
        score.put("trainFiles", trainFiles);
        return score;
    }

    private static List<SceneFile> read(List<Path> paths) {
        List<SceneFile> files = new ArrayList<>();
        for (Path path : paths) {
            files.add(SceneFileReader.read(path));
        }
        return files;
    }
}
