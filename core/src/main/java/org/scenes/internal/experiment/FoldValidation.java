package org.scenes.internal.experiment;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.ValidationReport;

/**
 * A sweep configuration validated as {@code scenes validate --folds} validates it: the same
 * {@link Folds} run on the same scene files with the same matching configuration, so a row
 * of a sweep's table is exactly what that command prints for the configuration alone.
 */
public final class FoldValidation implements Experiment.Validation {
    /** Decision time depends on the machine and on what else runs; a sweep's numbers must not. */
    private static final String TIMING = "meanDecisionMicros";

    private final List<SceneFile> files;
    private final List<String> transforms;
    private final Folds.Protocol protocol;
    private final long seed;
    private final PluginRegistry registry;
    private final boolean parallelQueries;
    private final Runnable query;

    /**
     * @param parallelQueries whether each validation spreads its queries over the cores (worth it
     *                        when fewer configurations than cores run at once)
     * @param query called once per query validated, from any thread (progress)
     */
    public FoldValidation(Sweep sweep, List<SceneFile> files, PluginRegistry registry, boolean parallelQueries,
                          Runnable query) {
        this.files = List.copyOf(files);
        this.transforms = sweep.transforms();
        this.protocol = sweep.protocol();
        this.seed = sweep.seed();
        this.registry = registry;
        this.parallelQueries = parallelQueries;
        this.query = query;
    }

    /** The matching configuration {@code scenes validate} would run for this sweep point. */
    public static MatchConfig matchConfig(Configuration configuration, List<String> transforms, long seed) {
        return MatchConfig.DEFAULT.withMetric(configuration.metric(), Map.of()).withObjectWeights(configuration.weights())
                .withK(configuration.k()).withSelector(configuration.selector(), Map.of())
                .withActionWeights(configuration.actionWeights()).withTransforms(transforms).withSeed(seed);
    }

    /** Fails early, naming the plugin, when a configuration cannot be built (unknown name, script error). */
    public void check(List<Configuration> configurations) {
        for (Configuration configuration : configurations) {
            matchConfig(configuration, transforms, seed).check(registry);
        }
    }

    @Override
    public Map<String, Double> validate(Configuration configuration) {
        Folds folds = Folds.run(files, matchConfig(configuration, transforms, seed), registry, parallelQueries, query,
                protocol);
        return measures(folds);
    }

    /** Each figure's mean over the folds, and the accuracy's standard deviation; no timing. */
    public static Map<String, Double> measures(Folds folds) {
        return measures(folds.reports().stream().map(FoldValidation::figures).toList());
    }

    /** A fold's figures, as {@link Folds#figures()} names them: all that {@link #measures(List)} needs of it. */
    public static Map<String, Double> figures(ValidationReport fold) {
        Map<String, Double> figures = new LinkedHashMap<>();
        Folds.figures().forEach((name, figure) -> figures.put(name, figure.applyAsDouble(fold)));
        return figures;
    }

    /**
     * {@link #measures(Folds)} from each fold's {@link #figures}, in fold order, so a run that
     * computes the figures where the fold ran collects a few numbers a fold, not its decisions.
     */
    public static Map<String, Double> measures(List<Map<String, Double>> folds) {
        Map<String, Double> measures = new LinkedHashMap<>();
        for (String figure : Folds.figures().keySet()) {
            if (figure.equals(TIMING)) {
                continue;
            }
            double[] byFold = folds.stream().mapToDouble(fold -> fold.get(figure)).toArray();
            measures.put(figure, Folds.mean(byFold));
            if (figure.equals("accuracy")) {
                measures.put("accuracyStd", Folds.std(byFold));
            }
        }
        return measures;
    }
}
