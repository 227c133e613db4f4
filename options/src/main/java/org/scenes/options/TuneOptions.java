package org.scenes.options;

import java.io.PrintWriter;
import java.util.Map;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.Tuner;
import picocli.CommandLine.Option;

/** The options of {@code tune}'s cross-validated search, and how its descent's result is reported. */
public final class TuneOptions {
    @Option(names = "--seed", paramLabel = "S", description = "Seed of every random choice (default 1).")
    private long seed = 1;

    @Option(names = "--sweeps", paramLabel = "N", description = "Passes over the search dimensions (default 2).")
    private int sweeps = 2;

    @Option(names = "--protocol", paramLabel = "leave-one-out|next", defaultValue = "leave-one-out",
            converter = KeyConverters.Protocol.class,
            description = "Cross-validation: each file against all others (tune's default) or against the next one, as the"
                    + " thesis did (validate --folds' default).")
    private Folds.Protocol protocol;

    @Option(names = "--objective", paramLabel = "mean|accuracy|direction|macro-f1", defaultValue = "mean",
            converter = KeyConverters.Objective.class,
            description = "What to maximise: the mean of accuracy, action-with-direction accuracy and macro F1 (default), or one of them.")
    private Tuner.Objective objective;

    @Option(names = "--quiet", description = "Do not print each configuration tried.")
    private boolean quiet;

    public long seed() {
        return seed;
    }

    public boolean quiet() {
        return quiet;
    }

    /**
     * The passes over the dimensions.
     *
     * @throws OptionException for fewer than one
     */
    public int sweeps() {
        if (sweeps < 1) {
            throw new OptionException("--sweeps must be at least 1");
        }
        return sweeps;
    }

    public Folds.Protocol protocol() {
        return protocol;
    }

    public Tuner.Objective objective() {
        return objective;
    }

    /** The two lines naming the configuration a descent chose and its score. */
    public static void printBest(PrintWriter out, Tuner.Result result) {
        printBest(out, result.evaluated(), result.config(), result.score(), result.figures());
    }

    /** The two lines naming the configuration a descent chose, of {@code tried}, and its score and figures. */
    public static void printBest(PrintWriter out, long tried, MatchConfig config, double score, Map<String, Double> figures) {
        out.printf("Best of %d configurations: %s%n", tried, config.describe());
        out.printf("Cross-validation score %.4f (accuracy %.4f, with direction %.4f, macro F1 %.4f)%n", score,
                figures.get("accuracy"), figures.get("directionAccuracy"), figures.get("macroF1"));
    }
}
