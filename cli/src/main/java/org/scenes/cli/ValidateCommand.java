package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileException;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.MatchConfigFile;
import org.scenes.internal.validate.ValidationReport;
import org.scenes.internal.validate.Validator;
import org.scenes.options.KeyConverters;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes validate}: how often matching picks the action the recorded player took. */
@Command(name = "validate", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Predict the action of every test scene from the training scenes and compare with the recorded one.",
                "Reports action accuracy, body, neck and body+neck accuracy, each beside the majority-class and"
                        + " repeat-previous-action baselines, kicks, per-action precision/recall/F1, parameter errors"
                        + " and decision time."})
final class ValidateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--train", arity = "1..*", paramLabel = "FILE", description = "Training scene files (the knowledge base).")
    List<Path> train = new ArrayList<>();

    @Option(names = "--test", arity = "1..*", paramLabel = "FILE", description = "Test scene files.")
    List<Path> test = new ArrayList<>();

    @Option(names = "--self", description = "Test against the training scenes themselves.")
    boolean self;

    @Option(names = "--folds", arity = "2..*", paramLabel = "FILE",
            description = "Cross-validate: each file is tested against the next one (cyclically); mean and standard deviation.")
    List<Path> folds = new ArrayList<>();

    @Option(names = "--protocol", paramLabel = "next|leave-one-out", defaultValue = "next",
            converter = KeyConverters.Protocol.class,
            description = "With --folds: train on the next file (the thesis' protocol, validate's default) or on all other"
                    + " files (tune's default).")
    Folds.Protocol foldProtocol;

    @Mixin
    MatchOptions match;

    @Option(names = "--json", description = "Print one JSON object instead of tables.")
    boolean json;

    @Option(names = "--chart", paramLabel = "FILE.png|svg", description = "Draw accuracy and kick recall per configuration.")
    Path chart;

    @Option(names = "--label", paramLabel = "TEXT", description = "Labels of the configurations in tables and the chart (repeatable, in order).")
    List<String> labels = new ArrayList<>();

    @Option(names = "--predictions", paramLabel = "FILE.csv",
            description = "With --train/--test: write one row per test scene and configuration: file, cycle, recorded and"
                    + " predicted commands, whether the type and the turn's sign were right.")
    Path predictions;

    @Option(names = "--sequential", description = "Run queries on one thread (same results, for timing comparisons).")
    boolean sequential;

    /** One configuration's result: a single run, or folds. */
    record Outcome(String label, MatchConfig config, ValidationReport report, Folds folds) {
        double accuracy() {
            return report != null ? report.accuracy() : folds.mean(ValidationReport::accuracy);
        }

        double kickRecall() {
            return report != null ? report.recall(ActionType.KICK) : folds.mean(r -> r.recall(ActionType.KICK));
        }
    }

    @Override
    public Integer call() throws Exception {
        boolean split = !train.isEmpty() || !test.isEmpty();
        if (!folds.isEmpty() && (split || self)) {
            throw new UsageException("--folds replaces --train/--test/--self; give one or the other");
        }
        if (folds.isEmpty()) {
            if (train.isEmpty()) {
                throw new UsageException("give --train FILE... with --test FILE... or --self, or --folds FILE...");
            }
            if (test.isEmpty() == !self) {
                throw new UsageException(self ? "--self tests against the training files; drop --test"
                        : "give --test FILE... or --self");
            }
        }
        if (chart != null) {
            OutputPaths.checkFile("--chart", chart, OutputPaths.inputs(train, test, folds), ".png", ".svg");
        }
        if (predictions != null) {
            if (!folds.isEmpty()) {
                throw new UsageException("--predictions lists the predictions of --train/--test or --self, not of --folds");
            }
            OutputPaths.checkFile("--predictions", predictions, OutputPaths.inputs(train, test, folds), ".csv");
        }
        List<MatchConfig> configs = match.configs();
        PluginRegistry registry = top.global.registry();
        for (MatchConfig config : configs) {
            config.check(registry);
        }
        if (!labels.isEmpty() && labels.size() != configs.size()) {
            throw new UsageException(labels.size() + " --label for " + configs.size() + " configurations");
        }
        List<Path> trainPaths = folds.isEmpty() ? train : folds;
        List<Path> testPaths = self ? List.of() : test;
        // Train and test are checked as one set: a test grid unlike the training grid matches silently wrong.
        List<Path> allPaths = concat(trainPaths, testPaths);
        List<SceneFile> all = readSameGrid(allPaths);
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).scenes().isEmpty()) {
                // an accuracy over no scene is NaN, and a knowledge base without it silently smaller
                throw new SceneFileException(allPaths.get(i), 0, 0, "holds no scenes; convert a log that has some", null);
            }
        }
        List<SceneFile> trainFiles = all.subList(0, trainPaths.size());
        List<SceneFile> testFiles = self ? trainFiles : all.subList(trainPaths.size(), all.size());
        long queries = (long) configs.size() * testFiles.stream().mapToLong(f -> f.scenes().size()).sum();
        List<Outcome> outcomes = new ArrayList<>();
        // per configuration, the file and cycle of each query, for --predictions
        List<List<String>> queryFiles = new ArrayList<>();
        List<List<Integer>> queryCycles = new ArrayList<>();
        // a bar whatever the number of queries: a slow configuration takes minutes over a few thousand
        try (TerminalProgress bar = queries == 0 ? TerminalProgress.none() : TerminalProgress.start("Validating", queries)) {
            Runnable tick = bar.shown() ? bar::step : null;
            for (int i = 0; i < configs.size(); i++) {
                MatchConfig config = configs.get(i);
                String label = labels.isEmpty() ? config.describe() : labels.get(i);
                if (!folds.isEmpty()) {
                    outcomes.add(new Outcome(label, config, null, Folds.run(trainFiles, config, registry, !sequential, tick, foldProtocol)));
                } else {
                    KnowledgeBase knowledge = KnowledgeBase.fromFiles(trainFiles, config.transformFactory(registry));
                    List<Scene> queriesOf = new ArrayList<>();
                    List<String> fileOf = new ArrayList<>();
                    List<Integer> cycleOf = new ArrayList<>();
                    queryFiles.add(fileOf);
                    queryCycles.add(cycleOf);
                    List<Path> testNames = self ? trainPaths : testPaths;
                    for (int f = 0; f < testFiles.size(); f++) {
                        List<Scene> transformed = KnowledgeBase.transform(testFiles.get(f).scenes(),
                                config.transformFactory(registry).get());
                        queriesOf.addAll(transformed);
                        for (Scene scene : transformed) {
                            fileOf.add(String.valueOf(testNames.get(f).getFileName()));
                            cycleOf.add(scene.cycle());
                        }
                    }
                    ValidationReport report = Validator.run(knowledge, queriesOf, config, registry, !sequential, tick);
                    outcomes.add(new Outcome(label, config, report, null));
                }
            }
        }
        if (predictions != null) {
            writePredictions(outcomes, queryFiles, queryCycles);
        }
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            printJson(out, outcomes);
        } else {
            ReportTables.print(out, outcomes);
        }
        if (chart != null) {
            Charts.write(chart, outcomes);
            if (!json) {
                out.println("Chart written to " + chart);
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** One row per test scene and configuration, for error analysis (pandas, a spreadsheet). */
    private void writePredictions(List<Outcome> outcomes, List<List<String>> files, List<List<Integer>> cycles)
            throws java.io.IOException {
        List<List<Object>> rows = new ArrayList<>();
        for (int o = 0; o < outcomes.size(); o++) {
            Outcome outcome = outcomes.get(o);
            ValidationReport report = outcome.report();
            for (int i = 0; i < report.testScenes(); i++) {
                rows.add(List.of(outcome.label(), files.get(o).get(i), cycles.get(o).get(i), commands(report.recorded().get(i)),
                        commands(report.predictions().get(i)), report.right(i), report.rightWithDirection(i)));
            }
        }
        CsvTables.write(predictions, List.of("configuration", "file", "cycle", "recorded", "predicted", "type_right",
                "direction_right"), rows);
    }

    private static String commands(List<org.scenes.api.Action> actions) {
        StringBuilder text = new StringBuilder();
        for (org.scenes.api.Action action : actions) {
            text.append(action.command());
        }
        return text.length() == 0 ? "none" : text.toString();
    }

    /**
     * Reads scene files that must share one grid (matching never mixes grids), on all cores:
     * reading is the part of a validation that does not spread over queries.
     */
    static List<SceneFile> readSameGrid(List<Path> paths) {
        List<SceneFile> files = paths.parallelStream().map(SceneFileReader::read).toList();
        Grid.common(paths, files.stream().map(SceneFile::grid).toList());
        return files;
    }

    private static List<Path> concat(List<Path> first, List<Path> second) {
        List<Path> all = new ArrayList<>(first);
        all.addAll(second);
        return all;
    }

    private static void printJson(PrintWriter out, List<Outcome> outcomes) throws Exception {
        List<Map<String, Object>> maps = new ArrayList<>();
        for (Outcome outcome : outcomes) {
            Map<String, Object> map = new LinkedHashMap<>();
            map.put("label", outcome.label());
            map.put("config", MatchConfigFile.toMap(outcome.config()));
            map.putAll(outcome.report() != null ? outcome.report().toMap() : outcome.folds().toMap());
            maps.add(map);
        }
        Object result = maps.size() == 1 ? maps.get(0) : Map.of("configurations", maps);
        out.println(ConfigFiles.JSON.writeValueAsString(result));
    }
}
