package org.scenes.internal.validate;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.ToDoubleFunction;
import java.util.function.UnaryOperator;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.scene.SceneFile;

/**
 * Chooses metric, options, weights, k and selector by cross-validation on training files only
 * ({@link Folds}, by default leave-one-file-out: each file tested against all the others, which
 * is closest to using the whole training game). The search is a coordinate descent: each
 * dimension's variants are tried on the best configuration so far and the best is kept; the
 * dimensions are swept until nothing improves (at most {@code sweeps} times). The score, over
 * the decisions of all folds pooled, is by default the mean of action accuracy, "action with
 * direction" accuracy and macro F1, so rare actions (kicks) and turn directions count, not only
 * the common dash; {@link Objective} offers each of them alone.
 */
public final class Tuner {
    /** One axis of the search: variants of the current configuration. */
    public record Dimension(String name, List<UnaryOperator<MatchConfig>> variants) {
    }

    /** The chosen configuration, its cross-validation score and the figures behind it. */
    public record Result(MatchConfig config, double score, Map<String, Double> figures, int evaluated) {
        /** A descent's end, with the figures of its best configuration's pooled report. */
        public static Result of(Descent descent, ValidationReport pooled, int evaluated) {
            Map<String, Double> figures = new LinkedHashMap<>();
            Folds.figures().forEach((name, figure) -> figures.put(name, figure.applyAsDouble(pooled)));
            return new Result(descent.best(), descent.score(), figures, evaluated);
        }
    }

    /**
     * Scores configurations for {@link #descend}: the local tuner validates them one at a time; one
     * that validates on many machines may validate the variants it is told of ahead all at once.
     */
    @FunctionalInterface
    public interface Evaluation {
        double score(MatchConfig config);

        /** The configurations the descent is about to score; nothing is done ahead by default. */
        default void ahead(List<MatchConfig> configurations) {
        }
    }

    /** Where a descent ends: the best configuration and its score. */
    public record Descent(MatchConfig best, double score) {
    }

    private final List<SceneFile> files;
    private final PluginRegistry registry;
    private final Consumer<String> log;
    private final Map<MatchConfig, Double> scores = new HashMap<>();
    private final Map<MatchConfig, Folds> folds = new HashMap<>();
    private final List<RandomSearch.Tried> tried = new ArrayList<>();

    private final Folds.Protocol protocol;
    private final ToDoubleFunction<ValidationReport> objective;

    /** What the search maximises, over the decisions of all folds pooled. */
    public enum Objective {
        /** the mean of accuracy, action-with-direction accuracy and macro F1 (default) */
        MEAN("mean"),
        ACCURACY("accuracy"),
        /** action-with-direction accuracy */
        DIRECTION("direction"),
        MACRO_F1("macro-f1");

        private final String key;

        Objective(String key) {
            this.key = key;
        }

        /** The name written in results and read from options: {@code mean}, {@code macro-f1}. */
        public String key() {
            return key;
        }

        /** The objective of that key; null for none (the caller says where the bad name came from). */
        public static Objective fromKey(String key) {
            for (Objective objective : values()) {
                if (objective.key.equals(key)) {
                    return objective;
                }
            }
            return null;
        }

        public double of(ValidationReport pooled) {
            return switch (this) {
                case MEAN -> score(pooled);
                case ACCURACY -> pooled.accuracy();
                case DIRECTION -> pooled.directionAccuracy();
                case MACRO_F1 -> pooled.macroF1();
            };
        }
    }

    public Tuner(List<SceneFile> files, PluginRegistry registry, Folds.Protocol protocol, Consumer<String> log) {
        this(files, registry, protocol, Objective.MEAN, log);
    }

    public Tuner(List<SceneFile> files, PluginRegistry registry, Folds.Protocol protocol, Objective objective,
                 Consumer<String> log) {
        this.protocol = protocol;
        this.objective = objective::of;
        if (files.size() < 2) {
            throw new IllegalArgumentException("tuning needs at least two training files for cross-validation");
        }
        this.files = List.copyOf(files);
        this.registry = registry;
        this.log = log == null ? line -> { } : log;
    }

    public static double score(ValidationReport pooled) {
        return (pooled.accuracy() + pooled.directionAccuracy() + pooled.macroF1()) / 3;
    }

    public double evaluate(MatchConfig config) {
        Double known = scores.get(config);
        if (known != null) {
            return known;
        }
        config.check(registry);
        Folds result = Folds.run(files, config, registry, true, null, protocol);
        ValidationReport pooled = result.pooled();
        double score = objective.applyAsDouble(pooled);
        scores.put(config, score);
        folds.put(config, result);
        tried.add(new RandomSearch.Tried(tried.size() + 1, config, 0, pooled.testScenes(), score, pooled.accuracy(),
                pooled.directionAccuracy(), pooled.macroF1()));
        log.accept(String.format("%.4f  acc %.4f  dir %.4f  F1 %.4f  kicks %d/%d  %s", score, pooled.accuracy(),
                pooled.directionAccuracy(), pooled.macroF1(), pooled.truePositives(ActionType.KICK),
                pooled.support(ActionType.KICK), config.describe()));
        return score;
    }

    /** Every configuration scored so far, in order, on every query of every fold. */
    public List<RandomSearch.Tried> tried() {
        return List.copyOf(tried);
    }

    public Result tune(List<MatchConfig> starts, List<Dimension> dimensions, int sweeps) {
        checkVariants(starts, dimensions);
        Descent descent = descend(starts, dimensions, sweeps, this::evaluate);
        return Result.of(descent, folds.get(descent.best()).pooled(), scores.size());
    }

    /** A descent from each start (configurations met again are not scored again); the best end, the earlier on ties. */
    public static Descent descend(List<MatchConfig> starts, List<Dimension> dimensions, int sweeps, Evaluation evaluation) {
        Descent best = null;
        for (MatchConfig start : starts) {
            Descent descent = descend(start, dimensions, sweeps, evaluation);
            if (best == null || descent.score() > best.score() + 1e-9) {
                best = descent;
            }
        }
        return best;
    }

    /**
     * The coordinate descent: each dimension's variants applied to the best configuration so far,
     * a variant kept only when strictly better; before each dimension the evaluation is told the
     * variants of the best at the dimension's start.
     */
    public static Descent descend(MatchConfig start, List<Dimension> dimensions, int sweeps, Evaluation evaluation) {
        // start from the first variant of the first dimension: the bare start may be slow and is rarely a contender
        MatchConfig best = dimensions.isEmpty() ? start : dimensions.get(0).variants().get(0).apply(start);
        if (!dimensions.isEmpty()) {
            evaluation.ahead(variants(dimensions.get(0), best));
        }
        double bestScore = evaluation.score(best);
        for (int sweep = 0; sweep < sweeps; sweep++) {
            boolean improved = false;
            for (Dimension dimension : dimensions) {
                evaluation.ahead(variants(dimension, best));
                for (UnaryOperator<MatchConfig> variant : dimension.variants()) {
                    MatchConfig candidate = variant.apply(best);
                    double score = evaluation.score(candidate);
                    // strictly better only: ties keep the earlier, simpler configuration
                    if (score > bestScore + 1e-9) {
                        best = candidate;
                        bestScore = score;
                        improved = true;
                    }
                }
            }
            if (!improved) {
                break;
            }
        }
        return new Descent(best, bestScore);
    }

    /**
     * Applies every variant to every start, scoring nothing: a variant setting a value its metric does
     * not declare ({@link DeclaredDimensions}) fails here, before the first validation.
     */
    public static void checkVariants(List<MatchConfig> starts, List<Dimension> dimensions) {
        for (MatchConfig start : starts) {
            for (Dimension dimension : dimensions) {
                variants(dimension, start);
            }
        }
    }

    private static List<MatchConfig> variants(Dimension dimension, MatchConfig config) {
        return dimension.variants().stream().map(variant -> variant.apply(config)).toList();
    }

    /**
     * Where the built-in search starts: the thesis' {@code ball-goal} on ball and goals, and
     * {@code continuous} in polar space on the ball and (lightly) the goals with log distances, the
     * distance ring weighed most (the kickable distance is a row boundary), then the direction, a
     * missing ball or goal costing more than any position difference. Each family's best needs its
     * memory and side settings, which a single descent from one of them would never try on the other.
     */
    public static List<MatchConfig> defaultStarts(MatchConfig base) {
        return List.of(base.withMetric("ball-goal", Map.of()).withObjectWeights(ObjectWeights.parse("ball=1,goal=1")),
                base.withMetric("continuous", withRows(withPenalty(polar(30, 10), 20000, 10000), 1000))
                        .withObjectWeights(ObjectWeights.parse("ball=1,goal=0.05")));
    }

    /**
     * The built-in search: memory, the side of the heading, the goals and distance rings, k and
     * selector, and last the metric family (which keeps the others' settings), so each start's
     * family is tuned before families are compared. Which metrics take the side, ring and own-goal
     * variants, and whether they accept the values tried, is what each metric declares for tuning.
     *
     * @param registry the plugins, whose metrics' declared tune dimensions the variants follow
     */
    public static List<Dimension> defaultSearch(PluginRegistry registry) {
        DeclaredDimensions declared = new DeclaredDimensions(registry);
        List<Dimension> dimensions = new ArrayList<>();
        ObjectWeights ballGoal = ObjectWeights.parse("ball=1,goal=1");
        dimensions.add(new Dimension("memory", List.of(
                c -> memory(declared, c, 0, 0, 1),
                c -> memory(declared, c, 0, 10, 1),
                c -> memory(declared, c, 0, 100, 1),
                c -> memory(declared, c, 0.5, 100, 1),
                // the previous action first, then the previous scene's objects: Krislet's kicks and turn signs
                c -> memory(declared, c, 0.3, 1000, 1),
                // the previous scene's directions at a tenth or three tenths of the current one's
                c -> memory(declared, c, 0.7, 1000, 0.3),
                c -> memory(declared, c, 0.3, 1000, 0.1),
                c -> memory(declared, c, 1, 0, 1))));
        dimensions.add(new Dimension("side", List.of(
                c -> withSide(declared, c, 0),
                c -> withSide(declared, c, 100),
                c -> withSide(declared, c, 300),
                c -> withSide(declared, c, 1000))));
        dimensions.add(new Dimension("goals and rings", List.of(
                c -> withGoalsAndRings(declared, c, 1, 1000),
                c -> withGoalsAndRings(declared, c, 0, 1000),
                c -> withGoalsAndRings(declared, c, 1, 3000),
                c -> withGoalsAndRings(declared, c, 0, 3000))));
        dimensions.add(new Dimension("k and selector", List.of(
                c -> c.withK(1).withSelector("first-valid", Map.of()),
                c -> c.withK(3).withSelector("vote", Map.of()),
                c -> c.withK(5).withSelector("vote", Map.of()),
                c -> c.withK(3).withSelector("vote", Map.of("params", "average")))));
        dimensions.add(new Dimension("metric", List.of(
                c -> keepMemory(declared, c, c.withMetric("ball-goal", Map.of()).withObjectWeights(ballGoal)),
                c -> keepMemory(declared, c, c.withMetric("ball-goal", Map.of("angle-weight", "10", "row-weight", "10")).withObjectWeights(ballGoal)),
                c -> keepMemory(declared, c, c.withMetric("continuous", polar(1, 10)).withObjectWeights(ballGoal)),
                c -> keepMemory(declared, c, c.withMetric("continuous", withRows(withPenalty(polar(30, 10), 20000, 10000), 1000))
                        .withObjectWeights(ObjectWeights.parse("ball=1,goal=0.05"))),
                c -> keepMemory(declared, c, c.withMetric("continuous", withRows(withPenalty(polar(30, 10), 20000, 10000), 1000))
                        .withObjectWeights(ObjectWeights.parse("ball=1,goal=0.3"))))));
        return dimensions;
    }

    /**
     * The own goal's share of the goal weight (0: only the goal attacked counts, as for Krislet)
     * and the distance rings' weight, where an object-set metric weighs rings; otherwise unchanged.
     */
    static MatchConfig withGoalsAndRings(DeclaredDimensions declared, MatchConfig config, double ownGoal, double rows) {
        if (!declared.objectSet(config)) {
            return config;
        }
        MatchConfig with = config.withMetricOption("own-goal-weight", ownGoal == 1 ? null : format(ownGoal));
        String ring = DeclaredDimensions.ROWS;
        boolean rings = Double.parseDouble(config.metricOptions().getOrDefault(ring, "0")) > 0;
        return rings ? with.withMetricOption(ring, declared.value(config.metric(), ring, rows)) : with;
    }

    /**
     * A metric variant keeps the memory and side settings already chosen (the previous scene's
     * direction weight as a share of the direction weight), so the dimensions stay independent. The
     * variant's own options are checked against what its metric declares for tuning.
     */
    static MatchConfig keepMemory(DeclaredDimensions declared, MatchConfig old, MatchConfig changed) {
        Map<String, String> options = old.metricOptions();
        MatchConfig kept = withMemory(declared.checked(changed), Double.parseDouble(options.getOrDefault("memory", "0")),
                Double.parseDouble(options.getOrDefault("memory-action", "0")));
        if (options.containsKey("memory-direction-weight")) {
            kept = withPreviousDirection(declared, kept, Double.parseDouble(options.get("memory-direction-weight"))
                    / Double.parseDouble(options.getOrDefault("direction-weight", "1")));
        }
        kept = withSide(declared, kept, Double.parseDouble(options.getOrDefault(DeclaredDimensions.SIDE, "0")));
        if (options.containsKey("own-goal-weight") && declared.objectSet(kept)) {
            kept = kept.withMetricOption("own-goal-weight", options.get("own-goal-weight"));
        }
        return kept;
    }

    /**
     * A memory variant: the previous scene at {@code weight}, its directions at {@code share} of the
     * current one's (1: the same, the metric's default), the previous action at {@code actionWeight}.
     */
    private static MatchConfig memory(DeclaredDimensions declared, MatchConfig config, double weight, double actionWeight,
                                      double share) {
        MatchConfig with = withMemory(config, weight, actionWeight);
        return share != 1 ? withPreviousDirection(declared, with, share) : with.withMetricOption("memory-direction-weight", null);
    }

    /** The side weight of an object-set metric (0: none, else a value it declares); other metrics unchanged. */
    static MatchConfig withSide(DeclaredDimensions declared, MatchConfig config, double weight) {
        if (!declared.objectSet(config)) {
            return config;
        }
        String side = DeclaredDimensions.SIDE;
        return config.withMetricOption(side, weight > 0 ? declared.value(config.metric(), side, weight) : null);
    }

    /**
     * The previous scene's direction weight as {@code share} of the current one's, where an
     * object-set metric in polar space remembers the previous scene; otherwise unchanged.
     */
    static MatchConfig withPreviousDirection(DeclaredDimensions declared, MatchConfig config, double share) {
        Map<String, String> options = config.metricOptions();
        if (!declared.objectSet(config) || !"polar".equals(options.get("space")) || !options.containsKey("memory")) {
            return config;
        }
        return config.withMetricOption("memory-direction-weight",
                format(share * Double.parseDouble(options.getOrDefault("direction-weight", "1"))));
    }

    private static Map<String, String> withRows(Map<String, String> options, double rowWeight) {
        Map<String, String> with = new HashMap<>(options);
        with.put(DeclaredDimensions.ROWS, format(rowWeight));
        return with;
    }

    private static Map<String, String> withPenalty(Map<String, String> options, double penalty, double scale) {
        Map<String, String> with = new HashMap<>(options);
        with.put("penalty", format(penalty));
        with.put("penalty-scale", format(scale));
        return with;
    }

    private static Map<String, String> polar(double distanceWeight, double directionWeight) {
        return Map.of("space", "polar", "log-distance", "true", "distance-weight", format(distanceWeight),
                "direction-weight", format(directionWeight));
    }

    /** Memory needs the memory transform and a metric that reads it (the object-set metrics and ball-goal do). */
    static MatchConfig withMemory(MatchConfig config, double weight, double actionWeight) {
        Map<String, String> options = new HashMap<>(config.metricOptions());
        options.remove("memory");
        options.remove("memory-action");
        if (weight == 0) {
            options.remove("memory-direction-weight"); // nothing remembered to weigh
        }
        if (config.metric().equals("random") || weight == 0 && actionWeight == 0) {
            return config.withMetric(config.metric(), options).withTransforms(List.of());
        }
        if (weight > 0) {
            options.put("memory", format(weight));
        }
        if (actionWeight > 0) {
            options.put("memory-action", format(actionWeight));
        }
        return config.withMetric(config.metric(), options).withTransforms(List.of("memory"));
    }

    static String format(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
    }
}
