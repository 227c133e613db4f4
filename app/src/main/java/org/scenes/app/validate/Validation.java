package org.scenes.app.validate;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.app.Progress;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.ValidationReport;
import org.scenes.internal.validate.Validator;

/**
 * {@code scenes validate}: each configuration's knowledge base built from training files and
 * queried with test files (or the training files themselves), or cross-validated over folds.
 */
public final class Validation {
    private Validation() {
    }

    /**
     * What to validate.
     *
     * @param train the training files, or with {@code crossValidate} the folds' files
     * @param test the test files; empty with {@code self} or {@code crossValidate}
     * @param self test against the training files themselves
     * @param crossValidate cross-validate over {@code train} instead of testing
     * @param protocol the folds' protocol, with {@code crossValidate}
     * @param configs the configurations, in order
     * @param labels their labels, or empty for their descriptions
     * @param parallel spread the queries over the cores
     */
    public record Request(List<Path> train, List<Path> test, boolean self, boolean crossValidate, Folds.Protocol protocol,
                          List<MatchConfig> configs, List<String> labels, boolean parallel) {
        public Request {
            train = List.copyOf(train);
            test = List.copyOf(test);
            configs = List.copyOf(configs);
            labels = List.copyOf(labels);
            if (!labels.isEmpty() && labels.size() != configs.size()) {
                throw new IllegalArgumentException(labels.size() + " labels for " + configs.size() + " configurations");
            }
        }

        /** The files read: training files, then test files. */
        List<Path> files() {
            List<Path> all = new ArrayList<>(train);
            all.addAll(test);
            return all;
        }
    }

    /** One test query: the file it came from (its name) and its cycle. */
    public record Query(String file, int cycle) {
    }

    /**
     * The stored scene a prediction came from: its training file as given (the files of several
     * games share names), its cycle and its distance from the query.
     */
    public record Source(String file, int cycle, double distance) {
    }

    /**
     * One configuration's result: a single run with its queries in order, or folds.
     *
     * @param label the configuration's label
     * @param config the configuration
     * @param report a single run's report, or null for folds
     * @param folds the folds, or null for a single run
     * @param queries a single run's queries, in the report's order; empty for folds
     * @param sources where each query's prediction came from, in the same order (null for a query
     *                without one); empty for folds
     */
    public record Outcome(String label, MatchConfig config, ValidationReport report, Folds folds, List<Query> queries,
                          List<Source> sources) {
        public double accuracy() {
            return report != null ? report.accuracy() : folds.mean(ValidationReport::accuracy);
        }

        public double kickRecall() {
            return report != null ? report.recall(ActionType.KICK) : folds.mean(r -> r.recall(ActionType.KICK));
        }
    }

    /**
     * Runs the request.
     *
     * @param progress told of every query answered
     * @return one outcome per configuration, in order
     * @throws SceneFileException for a file that cannot be read or holds no scenes
     * @throws Grid.MismatchException for files of different grids
     */
    public static List<Outcome> run(Request request, PluginRegistry registry, Progress progress) {
        for (MatchConfig config : request.configs()) {
            config.check(registry);
        }
        // Train and test are checked as one set: a test grid unlike the training grid matches silently wrong.
        List<Path> allPaths = request.files();
        List<SceneFile> all = readSameGrid(allPaths);
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).scenes().isEmpty()) {
                // an accuracy over no scene is NaN, and a knowledge base without it silently smaller
                throw new SceneFileException(allPaths.get(i), 0, 0, "holds no scenes; convert a log that has some", null);
            }
        }
        int trained = request.train().size();
        List<SceneFile> trainFiles = all.subList(0, trained);
        List<SceneFile> testFiles = request.self() ? trainFiles : all.subList(trained, all.size());
        List<Path> testNames = request.self() ? request.train() : request.test();
        List<MatchConfig> configs = request.configs();
        // cross-validation tests every file once per configuration (the command before this service counted
        // no test file there, so its bar never showed)
        List<SceneFile> tested = request.crossValidate() ? trainFiles : testFiles;
        long queries = (long) configs.size() * tested.stream().mapToLong(f -> f.scenes().size()).sum();
        List<Outcome> outcomes = new ArrayList<>();
        progress.begin("Validating", queries);
        try {
            Runnable tick = progress::step;
            for (int i = 0; i < configs.size(); i++) {
                MatchConfig config = configs.get(i);
                String label = request.labels().isEmpty() ? config.describe() : request.labels().get(i);
                if (request.crossValidate()) {
                    outcomes.add(new Outcome(label, config, null,
                            Folds.run(trainFiles, config, registry, request.parallel(), tick, request.protocol()), List.of(),
                            List.of()));
                    continue;
                }
                int[] fileEnds = new int[trainFiles.size()];
                KnowledgeBase knowledge = KnowledgeBase.fromFiles(trainFiles, config.transformFactory(registry), fileEnds);
                List<Scene> queriesOf = new ArrayList<>();
                List<Query> asked = new ArrayList<>();
                for (int f = 0; f < testFiles.size(); f++) {
                    List<Scene> transformed = KnowledgeBase.transform(testFiles.get(f).scenes(),
                            config.transformFactory(registry).get());
                    queriesOf.addAll(transformed);
                    for (Scene scene : transformed) {
                        asked.add(new Query(String.valueOf(testNames.get(f).getFileName()), scene.cycle()));
                    }
                }
                Validator.Donors donors = Validator.Donors.of(queriesOf.size());
                ValidationReport report = Validator.run(knowledge, queriesOf, config, registry, request.parallel(), tick,
                        donors);
                outcomes.add(new Outcome(label, config, report, null, List.copyOf(asked),
                        sources(donors, knowledge, fileEnds, request.train())));
            }
        } finally {
            progress.end();
        }
        return outcomes;
    }

    /**
     * Reads scene files that must share one grid (matching never mixes grids), on all cores:
     * reading is the part of a validation that does not spread over queries.
     *
     * @throws Grid.MismatchException for files of different grids
     */
    public static List<SceneFile> readSameGrid(List<Path> paths) {
        List<SceneFile> files = paths.parallelStream().map(SceneFileReader::read).toList();
        Grid.common(paths, files.stream().map(SceneFile::grid).toList());
        return files;
    }

    /** Each query's donor as its training file, cycle and distance. */
    private static List<Source> sources(Validator.Donors donors, KnowledgeBase knowledge, int[] fileEnds,
                                        List<Path> trainFiles) {
        List<Source> sources = new ArrayList<>(donors.index().length);
        for (int i = 0; i < donors.index().length; i++) {
            int stored = donors.index()[i];
            if (stored < 0) {
                sources.add(null);
                continue;
            }
            // the first file whose stored scenes end after the donor holds it
            int file = 0;
            while (fileEnds[file] <= stored) {
                file++;
            }
            sources.add(new Source(String.valueOf(trainFiles.get(file)), knowledge.cycle(stored),
                    donors.distance()[i]));
        }
        return sources;
    }

    /**
     * One row per test scene and single-run outcome, for error analysis (pandas, a spreadsheet):
     * configuration, file, cycle, recorded and predicted commands, whether the type and the turn's
     * sign were right, and the stored scene the prediction came from (training file, cycle, distance).
     */
    public static void writePredictions(Path file, List<Outcome> outcomes) throws IOException {
        List<List<Object>> rows = new ArrayList<>();
        for (Outcome outcome : outcomes) {
            ValidationReport report = outcome.report();
            for (int i = 0; i < report.testScenes(); i++) {
                Query query = outcome.queries().get(i);
                Source source = outcome.sources().get(i);
                rows.add(Arrays.asList(outcome.label(), query.file(), query.cycle(), commands(report.recorded().get(i)),
                        commands(report.predictions().get(i)), report.right(i), report.rightWithDirection(i),
                        source == null ? "" : source.file(), source == null ? "" : source.cycle(),
                        source == null ? "" : source.distance()));
            }
        }
        CsvTables.write(file, List.of("configuration", "file", "cycle", "recorded", "predicted", "type_right",
                "direction_right", "neighbour_file", "neighbour_cycle", "neighbour_distance"), rows);
    }

    private static String commands(List<Action> actions) {
        StringBuilder text = new StringBuilder();
        for (Action action : actions) {
            text.append(action.command());
        }
        return text.length() == 0 ? "none" : text.toString();
    }
}
