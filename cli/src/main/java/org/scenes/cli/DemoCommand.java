package org.scenes.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.scenes.internal.files.AtomicOutput;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/**
 * {@code scenes demo}: the whole loop on the bundled default, the embedded simulator with Krislet
 * teachers: simulate, convert, validate, play, evaluate. It only runs the other commands in
 * order, exactly as a user would type them, so it shows the commands it runs and holds no logic
 * of its own.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = {"Run the whole loop on built-in data: simulate two games between Krislet teachers, convert"
                + " every player's log to scenes, validate (learn from the first game, predict the second's actions),"
                + " play a game with imitators learnt from the first game, and evaluate teacher against imitator"
                + " (HTML report). Prints each command it runs and where its results are."})
final class DemoCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--out-dir", paramLabel = "DIR", defaultValue = "scenes-demo",
            description = "Where logs, scene files and reports go. Default: ${DEFAULT-VALUE}.")
    Path outDir;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "3000",
            description = "Length of each simulated and played game in cycles. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = "--evaluate-cycles", paramLabel = "N", defaultValue = "1500",
            description = "Length of each evaluation game (2 seeds per side). Default: ${DEFAULT-VALUE}.")
    int evaluateCycles;

    @Option(names = "--metric", paramLabel = "NAME", defaultValue = "ball-goal",
            description = "Metric to validate, play and evaluate with. Default: ${DEFAULT-VALUE}.")
    String metric;

    @Override
    public Integer call() throws IOException {
        Path train = outDir.resolve("game1");
        Path test = outDir.resolve("game2");
        String length = Integer.toString(cycles);
        for (String[] step : List.of(
                new String[] {"simulate", "--seed", "1", "--cycles", length, "--out-dir", train + "/logs"},
                new String[] {"simulate", "--seed", "2", "--cycles", length, "--out-dir", test + "/logs"})) {
            int status = run(null, step);
            if (status != ExitCodes.OK) {
                return status;
            }
        }
        for (Path game : List.of(train, test)) {
            List<String> convert = new ArrayList<>(List.of("convert"));
            convert.addAll(files(game.resolve("logs"), ".lsf.gz"));
            convert.addAll(List.of("--out-dir", game.resolve("scenes").toString()));
            int status = run(null, convert.toArray(String[]::new));
            if (status != ExitCodes.OK) {
                return status;
            }
        }
        List<String> trainScenes = files(train.resolve("scenes"), ".json.gz");
        Path validationText = outDir.resolve("validation.txt");
        Path validationChart = outDir.resolve("validation.svg");
        List<String> validate = new ArrayList<>(List.of("validate", "--metric", metric, "--train"));
        validate.addAll(trainScenes);
        validate.add("--test");
        validate.addAll(files(test.resolve("scenes"), ".json.gz"));
        validate.addAll(List.of("--chart", validationChart.toString()));
        int status = run(validationText, validate.toArray(String[]::new));
        if (status != ExitCodes.OK) {
            return status;
        }
        Path played = outDir.resolve("play");
        List<String> play = new ArrayList<>(List.of("play"));
        play.addAll(trainScenes);
        play.addAll(List.of("--metric", metric, "--cycles", length, "--out-dir", played.toString()));
        status = run(null, play.toArray(String[]::new));
        if (status != ExitCodes.OK) {
            return status;
        }
        Path report = outDir.resolve("evaluation");
        List<String> evaluate = new ArrayList<>(List.of("evaluate"));
        evaluate.addAll(trainScenes);
        evaluate.addAll(List.of("--metric", metric, "--think-steps", "2", "--seeds", "2", "--cycles",
                Integer.toString(evaluateCycles), "--report", report.toString()));
        status = run(null, evaluate.toArray(String[]::new));
        if (status != ExitCodes.OK) {
            return status;
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println();
        out.printf(Locale.ROOT, "%-22s %s%n", "Scene files", train.resolve("scenes").toAbsolutePath() + ", "
                + test.resolve("scenes").toAbsolutePath());
        out.printf(Locale.ROOT, "%-22s %s (chart %s)%n", "Validation report", validationText.toAbsolutePath(),
                validationChart.toAbsolutePath());
        out.printf(Locale.ROOT, "%-22s %s%n", "Imitators' game logs", played.toAbsolutePath());
        out.printf(Locale.ROOT, "%-22s %s%n", "Evaluation report", report.resolve("index.html").toAbsolutePath());
        out.flush();
        return ExitCodes.OK;
    }

    /** Runs one command as typed, its output also kept in {@code copy} (whole or not at all) when given. */
    private int run(Path copy, String... args) throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        out.println();
        out.println("$ scenes " + String.join(" ", args));
        out.flush();
        CommandLine root = spec.root().commandLine();
        if (copy == null) {
            return root.execute(args);
        }
        PrintWriter before = root.getOut();
        StringBuilder kept = new StringBuilder();
        root.setOut(new PrintWriter(new Writer() {
            @Override
            public void write(char[] buffer, int offset, int length) {
                out.write(buffer, offset, length);
                kept.append(buffer, offset, length);
            }

            @Override
            public void flush() {
                out.flush();
            }

            @Override
            public void close() {
                flush();
            }
        }, true));
        try {
            int status = root.execute(args);
            try (AtomicOutput output = AtomicOutput.create(copy)) {
                OutputStream stream = output.stream();
                stream.write(kept.toString().getBytes(StandardCharsets.UTF_8));
                output.commit();
            }
            return status;
        } finally {
            root.setOut(before);
        }
    }

    private static List<String> files(Path directory, String suffix) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.filter(f -> f.getFileName().toString().endsWith(suffix)).sorted().map(Path::toString).toList();
        }
    }
}
