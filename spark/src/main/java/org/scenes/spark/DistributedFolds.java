package org.scenes.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import org.scenes.api.PluginRegistry;
import org.scenes.internal.experiment.ExperimentException;
import org.scenes.internal.experiment.FoldValidation;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.ValidationReport;
import org.scenes.internal.validate.Validator;

/**
 * Cross-validation of many matching configurations as one Spark job each call: one task per
 * (configuration, fold). The scene files go to every executor once (a broadcast); each executor
 * builds a fold's knowledge base once and shares it between that fold's tasks. A task runs the
 * project's recognizer and validator on its fold, as {@code scenes validate --folds} does. For a
 * sweep it sends back its fold's figures (a few numbers), computed by the validator's own code; for
 * the tuner, which scores the decisions of all folds pooled, its decisions, from which the driver
 * rebuilds the fold's report. Either way every number equals the local run's.
 */
final class DistributedFolds implements AutoCloseable {
    private final JavaSparkContext spark;
    private final List<SceneFile> files;
    private final Folds.Protocol protocol;
    private final PluginRegistry registry;
    private final ArrayList<String> pluginPath;
    private final Broadcast<SceneData> data;
    private final String job = UUID.randomUUID().toString();
    /** the driver's transformed sequences, by transform key */
    private final Map<String, Folds.Sequences> sequences = new HashMap<>();

    /**
     * @param files the decoded scene files (the driver's copy, for rebuilding reports)
     * @param data the same files as bytes, for the executors
     */
    DistributedFolds(JavaSparkContext spark, List<SceneFile> files, SceneData data, Folds.Protocol protocol,
                     PluginRegistry registry, List<String> pluginPath) {
        if (files.size() < 2) {
            throw new IllegalArgumentException("cross-validation needs at least two scene files, one per fold, not "
                    + files.size());
        }
        this.spark = spark;
        this.files = List.copyOf(files);
        this.protocol = protocol;
        this.registry = registry;
        this.pluginPath = new ArrayList<>(pluginPath);
        this.data = spark.broadcast(data);
    }

    int folds() {
        return files.size();
    }

    /** One (configuration, fold) task's input. */
    private record Task(int index, ConfigSpec config, int fold) implements Serializable {
    }

    /** What a task sends back instead of its decisions: its fold's figures, in the order of {@link Folds#figures()}. */
    private record FoldFigures(int task, double[] values) implements Serializable {
    }

    /**
     * Every configuration's figures by fold, in the order given, as {@link FoldValidation#measures(List)}
     * takes them: one Spark task per (configuration, fold), each computing its fold's figures where it
     * ran, so the driver collects a few numbers a task.
     */
    Map<MatchConfig, List<Map<String, Double>>> figures(List<MatchConfig> configurations) {
        List<Task> tasks = tasks(configurations);
        Map<MatchConfig, List<Map<String, Double>>> results = new LinkedHashMap<>();
        if (tasks.isEmpty()) {
            return results;
        }
        List<FoldFigures> collected = collect(tasks, (task, report) -> new FoldFigures(task.index(),
                FoldValidation.figures(report).values().stream().mapToDouble(Double::doubleValue).toArray()));
        FoldFigures[] byTask = new FoldFigures[tasks.size()];
        for (FoldFigures f : collected) {
            byTask[f.task()] = f;
        }
        List<String> names = new ArrayList<>(Folds.figures().keySet());
        for (int c = 0; c < configurations.size(); c++) {
            List<Map<String, Double>> byFold = new ArrayList<>();
            for (int fold = 0; fold < files.size(); fold++) {
                double[] values = byTask[c * files.size() + fold].values();
                Map<String, Double> figures = new LinkedHashMap<>();
                for (int i = 0; i < names.size(); i++) {
                    figures.put(names.get(i), values[i]);
                }
                byFold.add(figures);
            }
            results.put(configurations.get(c), byFold);
        }
        return results;
    }

    /**
     * Every configuration's folds, in the order given; one Spark task per (configuration, fold),
     * each sending back its decisions, from which the driver rebuilds the fold's report (the tuner
     * scores the decisions of all folds pooled).
     */
    Map<MatchConfig, Folds> run(List<MatchConfig> configurations) {
        List<Task> tasks = tasks(configurations);
        Map<MatchConfig, Folds> results = new LinkedHashMap<>();
        if (tasks.isEmpty()) {
            return results;
        }
        List<Predictions> predictions = collect(tasks, (task, report) -> Predictions.of(task.index(), report));
        Predictions[] byTask = new Predictions[tasks.size()];
        for (Predictions p : predictions) {
            byTask[p.task] = p;
        }
        for (int c = 0; c < configurations.size(); c++) {
            MatchConfig config = configurations.get(c);
            Folds.Sequences transformed = sequences.computeIfAbsent(ConfigSpec.transformKey(config),
                    key -> Folds.sequences(files, config, registry));
            List<ValidationReport> reports = new ArrayList<>();
            for (int fold = 0; fold < files.size(); fold++) {
                Predictions p = byTask[c * files.size() + fold];
                reports.add(ValidationReport.of(transformed.training(fold, protocol), transformed.test(fold),
                        p.actions(), p.nanos()));
            }
            results.put(config, Folds.of(reports, protocol));
        }
        return results;
    }

    /** What a task sends back of its fold's report. */
    private interface TaskResult<T> extends Serializable {
        T of(Task task, ValidationReport report);
    }

    /** Runs the tasks as one job, each validating its fold and sending back {@code result} of the report. */
    private <T> List<T> collect(List<Task> tasks, TaskResult<T> result) {
        Broadcast<SceneData> scenes = data;
        String jobId = job;
        Folds.Protocol folds = protocol;
        ArrayList<String> plugins = pluginPath;
        return spark.parallelize(tasks, tasks.size())
                .map(task -> result.of(task, validate(task, scenes, jobId, folds, plugins))).collect();
    }

    /** A task per (configuration, fold), configurations checked first. */
    private List<Task> tasks(List<MatchConfig> configurations) {
        for (MatchConfig config : configurations) {
            config.check(registry);
        }
        List<Task> tasks = new ArrayList<>();
        for (MatchConfig config : configurations) {
            for (int fold = 0; fold < files.size(); fold++) {
                tasks.add(new Task(tasks.size(), ConfigSpec.of(config), fold));
            }
        }
        return tasks;
    }

    /** On an executor: one fold of one configuration, its queries one after another (the task is the unit of parallelism). */
    private static ValidationReport validate(Task task, Broadcast<SceneData> scenes, String job, Folds.Protocol protocol,
                                             List<String> pluginPath) {
        PluginRegistry registry = ExecutorState.registry(pluginPath);
        ExecutorState state = ExecutorState.forJob(job, scenes::value);
        MatchConfig config = task.config().config();
        ExecutorState.Fold fold = state.fold(config, registry, task.fold(), protocol);
        try {
            return Validator.run(fold.train(), fold.test(), config, registry, false, null);
        } catch (RuntimeException e) {
            // named as the local sweep names it, with the fold
            String message = "configuration " + config.describe() + ", fold " + (task.fold() + 1) + ": " + e.getMessage();
            if (e.getClass() == IllegalArgumentException.class) {
                throw new IllegalArgumentException(message, e);
            }
            throw new ExperimentException(message, e);
        }
    }

    /** Drops the executors' copies of the scene files, waiting for it (the driver's goes with the context). */
    @Override
    public void close() {
        data.unpersist(true);
    }
}
