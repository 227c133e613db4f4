package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code scenes demo}: the whole pipeline on the bundled default, the embedded simulator with
 * Krislet teachers. It only runs the other commands in order, exactly as a user would type them,
 * so it shows the commands it runs and holds no logic of its own.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = {"Run the whole pipeline on built-in data: simulate two games between Krislet teachers,"
                + " convert every player's log to scenes, then validate: learn from the first game's players,"
                + " predict the second game's actions. Prints each command it runs."})
final class DemoCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--out-dir", paramLabel = "DIR", defaultValue = "scenes-demo",
            description = "Where logs and scene files go. Default: ${DEFAULT-VALUE}.")
    Path outDir;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "3000",
            description = "Length of each simulated game in cycles. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = "--metric", paramLabel = "NAME", defaultValue = "ball-goal",
            description = "Metric to validate with. Default: ${DEFAULT-VALUE}.")
    String metric;

    @Override
    public Integer call() throws IOException {
        Path train = outDir.resolve("game1");
        Path test = outDir.resolve("game2");
        List<String[]> steps = List.of(
                new String[] {"simulate", "--seed", "1", "--cycles", Integer.toString(cycles), "--out-dir", train + "/logs"},
                new String[] {"simulate", "--seed", "2", "--cycles", Integer.toString(cycles), "--out-dir", test + "/logs"});
        for (String[] step : steps) {
            int status = run(step);
            if (status != ExitCodes.OK) {
                return status;
            }
        }
        for (Path game : List.of(train, test)) {
            List<String> convert = new ArrayList<>(List.of("convert"));
            convert.addAll(files(game.resolve("logs"), ".lsf.gz"));
            convert.addAll(List.of("--out-dir", game.resolve("scenes").toString()));
            int status = run(convert.toArray(String[]::new));
            if (status != ExitCodes.OK) {
                return status;
            }
        }
        List<String> validate = new ArrayList<>(List.of("validate", "--metric", metric, "--train"));
        validate.addAll(files(train.resolve("scenes"), ".json.gz"));
        validate.add("--test");
        validate.addAll(files(test.resolve("scenes"), ".json.gz"));
        return run(validate.toArray(String[]::new));
    }

    private int run(String... args) {
        PrintWriter out = spec.commandLine().getOut();
        out.println();
        out.println("$ scenes " + String.join(" ", args));
        out.flush();
        CommandLine root = spec.root().commandLine();
        return root.execute(args);
    }

    private static List<String> files(Path directory, String suffix) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.filter(f -> f.getFileName().toString().endsWith(suffix)).sorted().map(Path::toString).toList();
        }
    }
}
