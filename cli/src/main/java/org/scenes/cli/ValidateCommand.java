package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.app.validate.Validation;
import org.scenes.app.validate.Validation.Outcome;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.MatchConfigFile;
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
                    + " predicted commands, whether the type and the turn's sign were right, and the stored scene the"
                    + " prediction came from (training file, cycle, distance).")
    Path predictions;

    @Option(names = "--sequential", description = "Run queries on one thread (same results, for timing comparisons).")
    boolean sequential;

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
        if (!labels.isEmpty() && labels.size() != configs.size()) {
            throw new UsageException(labels.size() + " --label for " + configs.size() + " configurations");
        }
        boolean crossValidate = !folds.isEmpty();
        Validation.Request request = new Validation.Request(crossValidate ? folds : train, self ? List.of() : test, self,
                crossValidate, foldProtocol, configs, labels, !sequential);
        List<Outcome> outcomes = Validation.run(request, top.global.registry(), TerminalProgress.reporter());
        if (predictions != null) {
            Validation.writePredictions(predictions, outcomes);
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
        if (predictions != null && !json) {
            out.printf("%-24s %s%n", "Predictions written", predictions);
        }
        out.flush();
        return ExitCodes.OK;
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
