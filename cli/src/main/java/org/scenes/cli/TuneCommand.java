package org.scenes.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.internal.scene.SceneFile;
import org.scenes.internal.scene.SceneFileReader;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.RandomSearch;
import org.scenes.internal.validate.Tuner;
import org.scenes.options.TuneOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes tune}: choose the matching configuration by cross-validation on training files only. */
@Command(name = "tune", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Search metric, object weights, memory, k and selector by cross-validation on the training files only",
                "(by default each file tested against all the others) and write the best configuration for --config."})
final class TuneCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--train", arity = "2..*", paramLabel = "FILE", required = true,
            description = "Training scene files, at least two (one per player works well).")
    List<Path> train = new ArrayList<>();

    @Option(names = {"-o", "--output"}, paramLabel = "CONFIG.json", required = true, description = "Where to write the configuration.")
    Path output;

    @Mixin
    TuneOptions tuning;

    @Option(names = "--search", paramLabel = "descent|random",
            description = {"descent (default): coordinate descent over a few families;",
                    "random: seeded random configurations over every object class, both matchings, memory, k and"
                            + " selectors, narrowed by successive halving on all cores (docs/validation.md)."})
    String search = "descent";

    @Option(names = "--budget", paramLabel = "N|TIME",
            description = "For --search random: configurations to try (default 200), or a time such as 90s or 3m"
                    + " (brackets of 90 until it is spent).")
    String budget;

    @Option(names = "--table", paramLabel = "FILE.csv|FILE.json",
            description = "Also write every configuration tried, with its rung, queries and figures, as CSV or JSON.")
    Path table;

    @Override
    public Integer call() throws Exception {
        int sweeps = tuning.sweeps();
        OutputPaths.checkFile("-o", output, train);
        if (!search.equals("descent") && !search.equals("random")) {
            throw new UsageException("--search must be descent or random, not " + search);
        }
        if (budget != null && !search.equals("random")) {
            throw new UsageException("--budget applies to --search random");
        }
        Budget limit = Budget.parse(budget == null ? "200" : budget);
        if (table != null) {
            TriedTable.checkName(table);
            OutputPaths.checkFile("--table", table, train);
        }
        List<SceneFile> files = new ArrayList<>();
        for (Path path : train) {
            files.add(SceneFileReader.read(path));
        }
        PrintWriter out = spec.commandLine().getOut();
        Folds.Protocol chosen = tuning.protocol();
        Tuner.Objective goal = tuning.objective();
        if (search.equals("random")) {
            return random(files, chosen, goal, limit, out);
        }
        Tuner tuner = new Tuner(files, top.global.registry(), chosen, goal, tuning.quiet() ? null : line -> {
            out.println(line);
            out.flush();
        });
        Tuner.Result result = tuner.tune(Tuner.defaultStarts(MatchConfig.DEFAULT.withSeed(tuning.seed())), Tuner.defaultSearch(), sweeps);
        if (table != null) {
            TriedTable.write(table, tuner.tried());
        }
        Map<String, Object> score = tuning.crossValidation(result, train.stream().map(Path::toString).toList());
        ConfigFiles.write(output, result.config(), Map.of("crossValidation", score));
        TuneOptions.printBest(out, result);
        out.println("Written to " + output);
        out.flush();
        return ExitCodes.OK;
    }

    /** How much --search random may try: a number of configurations, or a time. */
    record Budget(int configurations, long nanos) {
        static Budget parse(String text) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("(\\d+)(s|m|h)?").matcher(text.trim());
            if (!m.matches()) {
                throw new UsageException("--budget must be a number of configurations (200) or a time (90s, 3m, 1h), not " + text);
            }
            long value = Long.parseLong(m.group(1));
            if (value < 1) {
                throw new UsageException("--budget must be at least 1, not " + text);
            }
            if (m.group(2) == null) {
                if (value > 100_000) {
                    throw new UsageException("--budget of more than 100000 configurations: give a time instead");
                }
                return new Budget((int) value, Long.MAX_VALUE);
            }
            long seconds = value * switch (m.group(2)) {
                case "h" -> 3600;
                case "m" -> 60;
                default -> 1;
            };
            return new Budget(100_000, seconds * 1_000_000_000L);
        }
    }

    private Integer random(List<SceneFile> files, Folds.Protocol chosen, Tuner.Objective goal, Budget limit, PrintWriter out)
            throws java.io.IOException {
        RandomSearch searcher = new RandomSearch(files, top.global.registry(), chosen, goal);
        long startNanos = System.nanoTime();
        long deadline = limit.nanos() == Long.MAX_VALUE ? Long.MAX_VALUE : startNanos + limit.nanos();
        RandomSearch.Result result;
        try (TerminalProgress bar = tuning.quiet() ? TerminalProgress.none()
                : TerminalProgress.start("Tuning", 1, " configurations", 1)) {
            result = searcher.run(MatchConfig.DEFAULT.withSeed(tuning.seed()), tuning.seed(), limit.configurations(), deadline,
                    !bar.shown() ? null : (done, planned, best) -> {
                        synchronized (bar) {
                            bar.maxHint(Math.max(planned, done));
                            bar.stepTo(done);
                            bar.message(Double.isInfinite(best) ? "" : String.format(java.util.Locale.ROOT, "best %.4f", best));
                        }
                    });
        }
        double seconds = (System.nanoTime() - startNanos) / 1e9;
        if (table != null) {
            TriedTable.write(table, result.table());
        }
        long distinct = result.table().stream().map(RandomSearch.Tried::config).distinct().count();
        Map<String, Object> score = new LinkedHashMap<>();
        score.put("score", result.score());
        score.put("protocol", tuning.protocol().key());
        score.put("objective", tuning.objective().key());
        score.put("search", "random search with successive halving");
        score.put("figures", result.figures());
        score.put("configurationsTried", distinct);
        score.put("scores", result.table().size());
        score.put("seconds", Math.round(seconds * 10) / 10.0);
        score.put("trainFiles", train.stream().map(Path::toString).toList());
        ConfigFiles.write(output, result.config(), Map.of("crossValidation", score));
        out.printf("Best of %d configurations (%d scores, %.1f s): %s%n", distinct, result.table().size(), seconds,
                result.config().describe());
        out.printf("Cross-validation score %.4f (accuracy %.4f, with direction %.4f, macro F1 %.4f)%n", result.score(),
                result.figures().get("accuracy"), result.figures().get("directionAccuracy"), result.figures().get("macroF1"));
        if (table != null) {
            out.println("Tried configurations written to " + table);
        }
        out.println("Written to " + output);
        out.flush();
        return ExitCodes.OK;
    }
}
