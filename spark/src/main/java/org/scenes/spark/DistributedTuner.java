package org.scenes.spark;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.scenes.api.ActionType;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.Tuner;
import org.scenes.internal.validate.ValidationReport;

/**
 * {@link Tuner#descend}, the local tuner's coordinate descent, with the folds run as Spark tasks. The search itself stays
 * sequential and takes the same steps as the local tuner (each variant applied to the best so far,
 * kept only if strictly better), so it chooses the same configuration; to keep the cluster busy,
 * every variant of a dimension is first validated at once against the best configuration at the
 * dimension's start, one job of (variants x folds) tasks. A variant that a change of the best
 * within the dimension alters is validated when the walk reaches it.
 */
final class DistributedTuner implements Tuner.Evaluation {
    private final DistributedFolds folds;
    private final Tuner.Objective objective;
    private final Consumer<String> log;
    private final Map<MatchConfig, Double> scores = new HashMap<>();
    private final Map<MatchConfig, ValidationReport> pooled = new HashMap<>();
    /** the configurations the walk asked for, as the local tuner counts them */
    private final Set<MatchConfig> asked = new LinkedHashSet<>();

    DistributedTuner(DistributedFolds folds, Tuner.Objective objective, Consumer<String> log) {
        this.folds = folds;
        this.objective = objective;
        this.log = log == null ? line -> { } : log;
    }

    /** Validates those of the configurations not validated yet, in one job. */
    @Override
    public void ahead(List<MatchConfig> configurations) {
        List<MatchConfig> fresh = new ArrayList<>();
        for (MatchConfig config : configurations) {
            if (!scores.containsKey(config) && !fresh.contains(config)) {
                fresh.add(config);
            }
        }
        if (fresh.isEmpty()) {
            return;
        }
        for (Map.Entry<MatchConfig, Folds> entry : folds.run(fresh).entrySet()) {
            ValidationReport report = entry.getValue().pooled();
            scores.put(entry.getKey(), objective.of(report));
            pooled.put(entry.getKey(), report);
        }
    }

    @Override
    public double score(MatchConfig config) {
        ahead(List.of(config));
        if (asked.add(config)) {
            ValidationReport report = pooled.get(config);
            log.accept(String.format("%.4f  acc %.4f  dir %.4f  F1 %.4f  kicks %d/%d  %s", scores.get(config),
                    report.accuracy(), report.directionAccuracy(), report.macroF1(), report.truePositives(ActionType.KICK),
                    report.support(ActionType.KICK), config.describe()));
        }
        return scores.get(config);
    }

    /** The search of {@link Tuner#tune}, step for step. */
    Tuner.Result tune(List<MatchConfig> starts, List<Tuner.Dimension> dimensions, int sweeps) {
        Tuner.checkVariants(starts, dimensions);
        Tuner.Descent descent = Tuner.descend(starts, dimensions, sweeps, this);
        return Tuner.Result.of(descent, pooled.get(descent.best()), asked.size());
    }

    /** Configurations validated, including those validated ahead and never asked for. */
    int validated() {
        return scores.size();
    }
}
