package org.scenes.internal.validate;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.ToDoubleFunction;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;

/**
 * Cross-validation over scene files: each file in turn is the test set. With the thesis'
 * protocol ({@link Protocol#NEXT}) the next file (cyclically) is the training set; with
 * {@link Protocol#LEAVE_ONE_OUT} all the other files are. Figures are averaged over the folds
 * with their standard deviation, and also pooled over all decisions ({@link #pooled()}).
 */
public final class Folds {
    /** Which files train each fold. */
    public enum Protocol {
        /** Each file trains the fold that tests the next one (the thesis' protocol). */
        NEXT("next"),
        /** All the other files train the fold that tests one. */
        LEAVE_ONE_OUT("leave-one-out");

        private final String key;

        Protocol(String key) {
            this.key = key;
        }

        /** The name written in results and read from options and scripts: {@code next}, {@code leave-one-out}. */
        public String key() {
            return key;
        }

        /** The protocol of that key; null for none (the caller says where the bad name came from). */
        public static Protocol fromKey(String key) {
            for (Protocol protocol : values()) {
                if (protocol.key.equals(key)) {
                    return protocol;
                }
            }
            return null;
        }

        /** The keys, for messages: {@code next or leave-one-out}. */
        public static String keys() {
            return NEXT.key + " or " + LEAVE_ONE_OUT.key;
        }
    }

    private final List<ValidationReport> reports;
    private final Protocol protocol;

    private Folds(List<ValidationReport> reports, Protocol protocol) {
        this.reports = List.copyOf(reports);
        this.protocol = protocol;
    }

    public static Folds run(List<SceneFile> files, MatchConfig config, PluginRegistry registry, boolean parallel,
                            Runnable progress) {
        return run(files, config, registry, parallel, progress, Protocol.NEXT);
    }

    public static Folds run(List<SceneFile> files, MatchConfig config, PluginRegistry registry, boolean parallel,
                            Runnable progress, Protocol protocol) {
        if (files.size() < 2) {
            throw new IllegalArgumentException("a fold validation needs at least two scene files, not " + files.size());
        }
        Grid grid = SceneFile.commonGrid(files);
        Sequences sequences = sequences(files, config, registry);
        List<ValidationReport> reports = new ArrayList<>();
        for (int i = 0; i < files.size(); i++) {
            // the sequences are held for every fold anyway: the knowledge base reads them instead of decoding
            KnowledgeBase train = KnowledgeBase.held(grid, sequences.training(i, protocol));
            reports.add(Validator.run(train, sequences.test(i), config, registry, parallel, progress));
        }
        return new Folds(reports, protocol);
    }

    /** Folds already validated one by one (e.g. as separate tasks of a distributed job), in fold order. */
    public static Folds of(List<ValidationReport> reports, Protocol protocol) {
        return new Folds(reports, protocol);
    }

    /**
     * Each file's scenes through fresh transforms of the configuration, in file order, as queries
     * and as training stores them (a mirror transform stores more scenes than it asks).
     */
    public record Sequences(List<List<Scene>> queries, List<List<Scene>> stored) {
        /** The test scenes of fold {@code fold}: the queries of file {@code fold}. */
        public List<Scene> test(int fold) {
            return queries.get(fold);
        }

        /** The training scenes of fold {@code fold}: the stored scenes of the other file(s). */
        public List<Scene> training(int fold, Protocol protocol) {
            List<Scene> trainScenes = new ArrayList<>();
            if (protocol == Protocol.NEXT) {
                trainScenes.addAll(stored.get((fold + 1) % stored.size()));
            } else {
                for (int j = 0; j < stored.size(); j++) {
                    if (j != fold) {
                        trainScenes.addAll(stored.get(j));
                    }
                }
            }
            return trainScenes;
        }
    }

    /** The queries and stored scenes of every file; all files must share one grid. */
    public static Sequences sequences(List<SceneFile> files, MatchConfig config, PluginRegistry registry) {
        SceneFile.commonGrid(files);
        List<List<Scene>> queries = new ArrayList<>();
        List<List<Scene>> stored = new ArrayList<>();
        for (SceneFile file : files) {
            queries.add(KnowledgeBase.transform(file.scenes(), config.transformFactory(registry).get()));
            stored.add(KnowledgeBase.stored(file.scenes(), config.transformFactory(registry).get()));
        }
        return new Sequences(queries, stored);
    }

    public Protocol protocol() {
        return protocol;
    }

    /** One report over the decisions of every fold. */
    public ValidationReport pooled() {
        return ValidationReport.pooled(reports);
    }

    public List<ValidationReport> reports() {
        return reports;
    }

    public double mean(ToDoubleFunction<ValidationReport> figure) {
        return mean(reports.stream().mapToDouble(figure).toArray());
    }

    /** Sample standard deviation over the folds where the figure is defined. */
    public double std(ToDoubleFunction<ValidationReport> figure) {
        return std(reports.stream().mapToDouble(figure).toArray());
    }

    /** The mean of a figure's values over the folds (in fold order) where it is defined. */
    public static double mean(double[] byFold) {
        return Arrays.stream(byFold).filter(v -> !Double.isNaN(v)).average().orElse(Double.NaN);
    }

    /** The sample standard deviation of a figure's values over the folds (in fold order) where it is defined. */
    public static double std(double[] byFold) {
        double[] values = Arrays.stream(byFold).filter(v -> !Double.isNaN(v)).toArray();
        if (values.length < 2) {
            return 0;
        }
        double mean = Arrays.stream(values).average().orElse(0);
        double squares = Arrays.stream(values).map(v -> (v - mean) * (v - mean)).sum();
        return Math.sqrt(squares / (values.length - 1));
    }

    /** The figures the tables and the tuner use, by name. */
    public static Map<String, ToDoubleFunction<ValidationReport>> figures() {
        Map<String, ToDoubleFunction<ValidationReport>> figures = new LinkedHashMap<>();
        figures.put("accuracy", ValidationReport::accuracy);
        figures.put("directionAccuracy", ValidationReport::directionAccuracy);
        figures.put("macroF1", ValidationReport::macroF1);
        figures.put("kickRecall", r -> r.recall(ActionType.KICK));
        figures.put("turnSignAgreement", ValidationReport::turnSignAgreement);
        figures.put("meanDecisionMicros", ValidationReport::meanDecisionMicros);
        return figures;
    }

    /**
     * The figures of {@link #figures()} with every label's accuracy (body, neck, both) and, right
     * after each accuracy, its majority and repeat-previous baselines: what the fold table prints.
     */
    public static Map<String, ToDoubleFunction<ValidationReport>> figuresWithBaselines() {
        Map<String, ToDoubleFunction<ValidationReport>> figures = new LinkedHashMap<>();
        for (Map.Entry<String, ToDoubleFunction<ValidationReport>> figure : figures().entrySet()) {
            figures.put(figure.getKey(), figure.getValue());
            if (figure.getKey().equals("accuracy")) {
                baselines(figures, ActionLabel.PRIMARY);
            }
        }
        for (ActionLabel label : List.of(ActionLabel.BODY, ActionLabel.NECK, ActionLabel.BOTH)) {
            figures.put(label.figure(), r -> r.accuracy(label));
            baselines(figures, label);
        }
        return figures;
    }

    private static void baselines(Map<String, ToDoubleFunction<ValidationReport>> figures, ActionLabel label) {
        figures.put(label.figure() + "Majority", r -> r.majorityBaseline(label));
        figures.put(label.figure() + "RepeatPrevious", r -> r.repeatPreviousBaseline(label));
    }

    public Map<String, Object> toMap() {
        Map<String, Object> map = new LinkedHashMap<>();
        map.put("folds", reports.size());
        map.put("protocol", protocol.key());
        // the single-run keys, as means over the folds, so scripts read --folds output like a plain run
        map.put("accuracy", ValidationReport.number(mean(ValidationReport::accuracy)));
        map.put("macroF1", ValidationReport.number(mean(ValidationReport::macroF1)));
        Map<String, Object> all = new LinkedHashMap<>();
        for (Map.Entry<String, ToDoubleFunction<ValidationReport>> figure : figuresWithBaselines().entrySet()) {
            Map<String, Object> entry = new LinkedHashMap<>();
            entry.put("mean", ValidationReport.number(mean(figure.getValue())));
            entry.put("std", ValidationReport.number(std(figure.getValue())));
            all.put(figure.getKey(), entry);
        }
        map.put("figures", all);
        map.put("pooled", pooled().toMap());
        map.put("runs", reports.stream().map(ValidationReport::toMap).toList());
        return map;
    }
}
