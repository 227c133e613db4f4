package org.scenes.spark;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.apache.hadoop.fs.FileStatus;
import org.apache.spark.api.java.JavaSparkContext;
import org.scenes.convert.DropReason;
import org.scenes.convert.Pairing;
import org.scenes.scene.Grid;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes-spark convert}: player logs to scene files as a Spark job, one task per game. */
@Command(name = "convert", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Convert player logs into scene files as 'scenes convert --out-dir' does, as a Spark job with "
                + "one task per game. A game is a directory of player logs: each directory given, and each of its "
                + "subdirectories, that holds logs (.lsf, .log, .txt, gzip or not); a log given by name belongs to "
                + "the game of its directory. OUT/GAME/<log name>.json.gz appear only when complete; paths may be "
                + "any Hadoop-compatible file system (hdfs://, s3a://, file://; no scheme: the local disk).")
final class ConvertCommand implements Callable<Integer> {
    private static final String[] LOG_SUFFIXES = {".lsf", ".log", ".txt"};

    @Spec
    CommandSpec spec;

    @ParentCommand
    SparkCommand top;

    @Parameters(paramLabel = "LOG|DIR", arity = "1..*", description = "Player logs, or directories of games.")
    List<String> inputs;

    @Option(names = "--out-dir", paramLabel = "OUT", required = true,
            description = "Where each game's scene files go: OUT/GAME/<log name>.json.gz.")
    String outDir;

    @Option(names = "--grid", paramLabel = "CxR", defaultValue = "5x3",
            description = "Columns (angle slices over [-45,45] degrees) x rows (distance rings); default ${DEFAULT-VALUE}.")
    String gridText;

    @Option(names = "--bounds", paramLabel = "D", split = ",", splitSynopsisLabel = ",",
            description = "Ascending distances (m) separating the rows: rows - 1 values; default 1,5 for 3 rows.")
    double[] bounds;

    @Option(names = "--strict", description = "A malformed line fails its log instead of being skipped.")
    boolean strict;

    @Option(names = "--pairing", paramLabel = "see|cycle|auto", defaultValue = "auto",
            description = "How sees and actions become scenes, as for 'scenes convert' (default auto).")
    String pairing;

    @Override
    public Integer call() throws IOException {
        Pairing chosen = Pairing.fromKey(pairing);
        if (chosen == null) {
            throw new UsageException("--pairing must be see, cycle or auto, not '" + pairing + "'");
        }
        GameConversion.Settings settings = GameConversion.Settings.of(grid(), chosen, strict);
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        List<GameConversion.Game> games = games(hadoop);
        for (GameConversion.Game game : games) {
            GameConversion.outputNames(game); // two logs of a game with one name fail before any task runs
        }
        long started = System.nanoTime();
        List<List<GameConversion.LogResult>> results;
        try (JavaSparkContext spark = top.options.start("convert")) {
            String out = outDir;
            results = spark.parallelize(games, games.size())
                    .map(game -> GameConversion.convert(game, settings, out, GameConversion.outputNames(game))).collect();
        }
        return report(games, results, (System.nanoTime() - started) / 1e9);
    }

    private int report(List<GameConversion.Game> games, List<List<GameConversion.LogResult>> results, double seconds) {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        long logs = 0;
        long lines = 0;
        long bytes = 0;
        long sees = 0;
        long repeated = 0;
        long scenes = 0;
        long malformed = 0;
        Map<DropReason, Long> dropped = new LinkedHashMap<>();
        List<String> failures = new ArrayList<>();
        long written = 0;
        for (List<GameConversion.LogResult> game : results) {
            for (GameConversion.LogResult log : game) {
                logs++;
                lines += log.lines();
                bytes += log.bytes();
                sees += log.sees();
                repeated += log.repeatedSees();
                scenes += log.scenes();
                malformed += log.malformed();
                log.dropped().forEach((reason, count) -> dropped.merge(reason, count, Long::sum));
                log.warnings().forEach(warning -> err.println("scenes-spark: warning: " + warning));
                if (log.error() != null) {
                    failures.add(log.error());
                } else {
                    written++;
                }
            }
        }
        out.printf(Locale.ROOT, "%-22s %s (one task each)%n", "Games", games.size());
        out.printf(Locale.ROOT, "%-22s %s%n", "Logs read", logs);
        out.printf(Locale.ROOT, "%-22s %s (%.1f MB of text)%n", "Lines read", lines, bytes / 1e6);
        out.printf(Locale.ROOT, "%-22s %s (%s repeated while paused, collapsed)%n", "See messages", sees, repeated);
        out.printf(Locale.ROOT, "%-22s %s  (grid %s)%n", "Scenes written", scenes, grid().describe());
        out.printf(Locale.ROOT, "%-22s %s%n", "Scenes dropped", dropped.values().stream().mapToLong(Long::longValue).sum());
        for (DropReason reason : DropReason.values()) {
            out.printf(Locale.ROOT, "  %-20s %s%n", reason.label(), dropped.getOrDefault(reason, 0L));
        }
        out.printf(Locale.ROOT, "%-22s %s%n", "Malformed lines", malformed);
        out.printf(Locale.ROOT, "%-22s %s scene files under %s%n", "Written", written, outDir);
        out.printf(Locale.ROOT, "%-22s %.2f s%n", "Time", seconds);
        out.flush();
        for (String failure : failures) {
            err.println("scenes-spark: error: " + failure);
        }
        if (!failures.isEmpty()) {
            err.printf("scenes-spark: error: %d of %d logs gave no scenes%n", failures.size(), logs);
        }
        err.flush();
        return failures.isEmpty() ? 0 : 1;
    }

    /** The games of the inputs, in the order given, each named by its directory. */
    private List<GameConversion.Game> games(HadoopFiles hadoop) throws IOException {
        Map<String, GameConversion.Game> games = new LinkedHashMap<>();
        Map<String, String> directories = new LinkedHashMap<>();
        for (String input : inputs) {
            if (hadoop.isDirectory(input)) {
                String directory = input.replaceFirst("/+$", "");
                addGame(games, directories, hadoop.path(directory).toString(), logsIn(hadoop, directory));
                for (FileStatus status : hadoop.list(directory)) {
                    if (status.isDirectory() && !status.getPath().getName().startsWith(".")) {
                        String sub = directory + "/" + status.getPath().getName();
                        addGame(games, directories, hadoop.path(sub).toString(), logsIn(hadoop, sub));
                    }
                }
            } else if (hadoop.exists(input)) {
                String path = hadoop.path(input).toString();
                addGame(games, directories, path.substring(0, path.lastIndexOf('/')), List.of(input));
            } else {
                throw new UsageException("no such log or directory: " + input);
            }
        }
        if (games.isEmpty()) {
            throw new UsageException("no player logs (.lsf, .log, .txt, gzip or not) in " + String.join(", ", inputs));
        }
        return new ArrayList<>(games.values());
    }

    /** Adds logs to the game of a directory (its full path), named by the directory's name. */
    private static void addGame(Map<String, GameConversion.Game> games, Map<String, String> directories, String directory,
                                List<String> logs) {
        if (logs.isEmpty()) {
            return;
        }
        String name = gameName(directory);
        String known = directories.putIfAbsent(name, directory);
        if (known != null && !known.equals(directory)) {
            throw new UsageException("two games are named " + name + " (" + known + " and " + directory
                    + "); convert them separately, into different --out-dir");
        }
        GameConversion.Game game = games.computeIfAbsent(name, n -> new GameConversion.Game(n, new ArrayList<>()));
        for (String log : logs) {
            if (!game.logs().contains(log)) {
                game.logs().add(log);
            }
        }
    }

    private static String gameName(String directory) {
        String trimmed = directory.replaceFirst("/+$", "");
        String name = trimmed.substring(trimmed.lastIndexOf('/') + 1);
        return name.isEmpty() || name.equals(".") ? "game" : name;
    }

    private static List<String> logsIn(HadoopFiles hadoop, String directory) throws IOException {
        List<String> logs = new ArrayList<>();
        for (FileStatus status : hadoop.list(directory)) {
            String name = status.getPath().getName();
            String plain = name.endsWith(".gz") ? name.substring(0, name.length() - 3) : name;
            if (status.isFile() && !name.startsWith(".") && Arrays.stream(LOG_SUFFIXES).anyMatch(plain::endsWith)) {
                logs.add(directory + "/" + name);
            }
        }
        return logs;
    }

    private Grid grid() {
        int x = gridText.indexOf('x');
        int columns;
        int rows;
        try {
            columns = Integer.parseInt(gridText.substring(0, x < 0 ? gridText.length() : x).trim());
            rows = x < 0 ? -1 : Integer.parseInt(gridText.substring(x + 1).trim());
        } catch (NumberFormatException e) {
            throw new UsageException("--grid must be COLUMNSxROWS, e.g. 5x3, not '" + gridText + "'");
        }
        double[] distances = bounds;
        if (distances == null) {
            if (rows != -1 && rows != 3) {
                throw new UsageException("--grid " + gridText + " has " + rows + " rows: give --bounds with " + (rows - 1)
                        + " distances");
            }
            distances = Grid.DEFAULT.bounds();
        } else if (rows != -1 && distances.length != rows - 1) {
            throw new UsageException("--grid " + gridText + " has " + rows + " rows but --bounds gives " + distances.length
                    + " distances (need " + (rows - 1) + ")");
        }
        try {
            return Grid.of(columns, distances);
        } catch (IllegalArgumentException e) {
            throw new UsageException("bad grid " + gridText + " with bounds " + Arrays.toString(distances) + ": "
                    + e.getMessage());
        }
    }
}
