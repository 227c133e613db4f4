package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.scenes.app.tune.Tuning;
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

    @Option(names = "--metrics", split = ",", paramLabel = "NAME",
            description = {"For --search random: only these metrics' configurations (comma-separated, e.g. field or"
                    + " field,ball-goal), each drawn as often; default: every family."})
    List<String> metrics = new ArrayList<>();

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
        if (!metrics.isEmpty() && !search.equals("random")) {
            throw new UsageException("--metrics applies to --search random");
        }
        Budget limit = Budget.parse(budget == null ? "200" : budget);
        if (table != null) {
            TriedTable.checkName(table);
            OutputPaths.checkFile("--table", table, train);
        }
        PrintWriter out = spec.commandLine().getOut();
        Tuning.Request request = new Tuning.Request(train, tuning.protocol(), tuning.objective(), tuning.seed());
        if (search.equals("random")) {
            return random(request, limit, out);
        }
        Tuning.Outcome outcome = Tuning.descent(request, sweeps, top.global.registry(), tuning.quiet() ? null : line -> {
            out.println(line);
            out.flush();
        });
        if (table != null) {
            TriedTable.write(table, outcome.tried());
        }
        ConfigFiles.write(output, outcome.config(), Map.of("crossValidation", outcome.crossValidation()));
        TuneOptions.printBest(out, outcome.configurations(), outcome.config(), outcome.score(), outcome.figures());
        out.println("Written to " + output);
        out.flush();
        return ExitCodes.OK;
    }

    /** How much --search random may try: a number of configurations, or a time. */
    record Budget(int configurations, long nanos) {
        static Budget parse(String text) {
            Matcher m = Pattern.compile("(\\d+)(s|m|h)?").matcher(text.trim());
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

    private Integer random(Tuning.Request request, Budget limit, PrintWriter out) throws IOException {
        Tuning.Outcome outcome;
        try (TerminalProgress bar = tuning.quiet() ? TerminalProgress.none()
                : TerminalProgress.start("Tuning", 1, " configurations", 1)) {
            outcome = Tuning.random(request, metrics, limit.configurations(), limit.nanos(), top.global.registry(),
                    !bar.shown() ? null : (done, planned, best) -> {
                        synchronized (bar) {
                            bar.maxHint(Math.max(planned, done));
                            bar.stepTo(done);
                            bar.message(Double.isInfinite(best) ? "" : String.format(Locale.ROOT, "best %.4f", best));
                        }
                    });
        }
        if (table != null) {
            TriedTable.write(table, outcome.tried());
        }
        ConfigFiles.write(output, outcome.config(), Map.of("crossValidation", outcome.crossValidation()));
        out.printf("Best of %d configurations (%d scores, %.1f s): %s%n", outcome.configurations(), outcome.scores(),
                outcome.seconds(), outcome.config().describe());
        out.printf("Cross-validation score %.4f (accuracy %.4f, with direction %.4f, macro F1 %.4f)%n", outcome.score(),
                outcome.figures().get("accuracy"), outcome.figures().get("directionAccuracy"), outcome.figures().get("macroF1"));
        if (table != null) {
            out.println("Tried configurations written to " + table);
        }
        out.println("Written to " + output);
        out.flush();
        return ExitCodes.OK;
    }
}
