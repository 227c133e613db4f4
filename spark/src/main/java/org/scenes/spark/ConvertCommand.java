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
import java.util.stream.IntStream;
import org.apache.hadoop.fs.FileStatus;
import org.apache.spark.api.java.JavaSparkContext;
import org.scenes.internal.convert.DropReason;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.gamelog.ServerLogs;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.options.GameLogOptions;
import org.scenes.options.WorldOptions;
import org.scenes.options.GridOptions;
import org.scenes.options.KeyConverters;
import org.scenes.options.PairingOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes-spark convert}: player logs to scene files as a Spark job, one task per game. */
@Command(name = "convert", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Convert player logs or the server's game logs into scene files as 'scenes convert --out-dir'"
                + " does, as a Spark job with one task per game. A game is a directory of player logs (each directory"
                + " given, and each of its subdirectories, that holds logs: .lsf, .log, .txt, gzip or not; a log given"
                + " by name belongs to the game of its directory), written as OUT/GAME/<log name>.json.gz;"
                + " or a game log (GAME.rcg, in those directories or given by name, told by content) with the"
                + " command log beside it (GAME.rcl; .gz or not), written as OUT/GAME/TEAM_UNUM.json.gz.",
                "One directory with game logs at any depth is an archive, as for 'scenes convert ARCHIVE_DIR': a task"
                        + " per game, OUT/TEAM/GAME_UNUM.json.gz and OUT/manifest.csv, games converted by an earlier"
                        + " run skipped.",
                "Scene files appear only when complete; paths may be any Hadoop-compatible file system (hdfs://,"
                        + " s3a://, file://; no scheme: the local disk)."})
final class ConvertCommand implements Callable<Integer> {
    private static final String[] LOG_SUFFIXES = {".lsf", ".log", ".txt"};
    private static final String[] COMMAND_LOG_SUFFIXES = {".rcl", ".rcl.gz"};

    @Spec
    CommandSpec spec;

    @ParentCommand
    SparkCommand top;

    @Parameters(paramLabel = "LOG|DIR", arity = "1..*",
            description = "Player logs, game logs (GAME.rcg beside GAME.rcl), or directories of games.")
    List<String> inputs;

    @Option(names = "--out-dir", paramLabel = "OUT", required = true,
            description = "Where each game's scene files go: OUT/GAME/<log name>.json.gz.")
    String outDir;

    @Option(names = "--compression", paramLabel = "gzip|zstd|none", defaultValue = "gzip",
            converter = KeyConverters.Compression.class,
            description = {"How the scene files are compressed, as scenes convert --compression: zstd (.json.zst)"
                    + " costs a third less CPU a game, and every scenes command reads both. Default: ${DEFAULT-VALUE}."})
    SceneCompression compression;

    @Mixin
    GridOptions gridOptions;

    @Mixin
    PairingOptions pairingOptions;

    @Mixin
    GameLogOptions gameLogOptions;

    @Mixin
    WorldOptions worldOptions;

    @Override
    public Integer call() throws IOException {
        GameLogOptions g = gameLogOptions;
        g.check();
        GameConversion.Settings settings = GameConversion.Settings.of(gridOptions.grid(), pairingOptions.pairing(), pairingOptions.strict(),
                new GameConversion.GameLogSettings(g.team(), g.unum(), g.fadingName(), g.fadingSeed(), g.commandsFirst(),
                        g.seePhase()), worldOptions.world(), compression);
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        if (ArchiveJob.isArchive(hadoop, inputs)) {
            return ArchiveJob.run(this, settings, spec.commandLine().getOut(), spec.commandLine().getErr());
        }
        List<GameConversion.Game> games = games(hadoop);
        for (GameConversion.Game game : games) {
            GameConversion.outputNames(game); // two logs of a game with one name fail before any task runs
        }
        long started = System.nanoTime();
        ConvertSummary summary;
        try (JavaSparkContext spark = top.options.start("convert")) {
            String out = outDir;
            ArrayList<GameConversion.Game> all = new ArrayList<>(games);
            List<Integer> indices = IntStream.range(0, all.size()).boxed().toList();
            // each task sums its game; the sums are reduced on the executors, the driver gets one summary
            summary = spark.parallelize(indices, all.size()).map(i -> {
                GameConversion.Game game = all.get(i);
                return ConvertSummary.of(i, GameConversion.convert(game, settings, out, GameConversion.outputNames(game)));
            }).treeReduce(ConvertSummary::merge);
        }
        return report(games.size(), summary, (System.nanoTime() - started) / 1e9);
    }

    private int report(int games, ConvertSummary summary, double seconds) {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        summary.warnings.forEach(warning -> err.println("scenes-spark: warning: " + warning.text()));
        if (summary.warningCount > summary.warnings.size()) {
            err.printf("scenes-spark: warning: %d more warnings not shown%n", summary.warningCount - summary.warnings.size());
        }
        out.printf(Locale.ROOT, "%-22s %s (one task each)%n", "Games", games);
        out.printf(Locale.ROOT, "%-22s %s%n", "Logs read", summary.logs);
        out.printf(Locale.ROOT, "%-22s %s (%.1f MB of text)%n", "Lines read", summary.lines, summary.bytes / 1e6);
        out.printf(Locale.ROOT, "%-22s %s (%s repeated while paused, collapsed)%n", "See messages", summary.sees,
                summary.repeatedSees);
        out.printf(Locale.ROOT, "%-22s %s  (grid %s)%n", "Scenes written", summary.scenes, gridOptions.grid().describe());
        out.printf(Locale.ROOT, "%-22s %s%n", "Scenes dropped", summary.dropped());
        for (DropReason reason : DropReason.values()) {
            out.printf(Locale.ROOT, "  %-20s %s%n", reason.label(), summary.dropped(reason));
        }
        out.printf(Locale.ROOT, "%-22s %s%n", "Malformed lines", summary.malformed);
        out.printf(Locale.ROOT, "%-22s %s scene files under %s%n", "Written", summary.written, outDir);
        out.printf(Locale.ROOT, "%-22s %.2f s%n", "Time", seconds);
        out.flush();
        summary.failures.forEach(failure -> err.println("scenes-spark: error: " + failure.text()));
        if (summary.failureCount > 0) {
            err.printf("scenes-spark: error: %d of %d logs gave no scenes%s%n", summary.failureCount, summary.logs,
                    summary.failureCount > summary.failures.size() ? " (the first " + summary.failures.size() + " named)"
                            : "");
        }
        err.flush();
        return summary.failureCount == 0 ? 0 : 1;
    }

    /**
     * The games of the inputs, in the order given: the player logs of a directory, named by the
     * directory, and each game log, named by its file without {@code .rcg} and {@code .gz}.
     */
    private List<GameConversion.Game> games(HadoopFiles hadoop) throws IOException {
        Map<String, GameConversion.Game> games = new LinkedHashMap<>();
        Map<String, String> sources = new LinkedHashMap<>();
        List<String> commandLogs = new ArrayList<>();
        for (String input : inputs) {
            if (hadoop.isDirectory(input)) {
                String directory = input.replaceFirst("/+$", "");
                addDirectory(hadoop, games, sources, directory);
                for (FileStatus status : hadoop.list(directory)) {
                    if (status.isDirectory() && !status.getPath().getName().startsWith(".")) {
                        addDirectory(hadoop, games, sources, directory + "/" + status.getPath().getName());
                    }
                }
            } else if (hadoop.exists(input)) {
                ServerLogs.Kind kind = hadoop.serverLogKind(input);
                if (kind == ServerLogs.Kind.GAME) {
                    addServerGame(games, sources, input, commandLogBeside(hadoop, input));
                } else if (kind == ServerLogs.Kind.COMMAND) {
                    commandLogs.add(input);
                } else {
                    String path = hadoop.path(input).toString();
                    addGame(games, sources, path.substring(0, path.lastIndexOf('/')), List.of(input));
                }
            } else {
                throw new UsageException("no such log or directory: " + input);
            }
        }
        for (String commandLog : commandLogs) {
            boolean paired = false;
            for (GameConversion.Game game : games.values()) {
                paired |= game.serverLogs() && hadoop.path(game.logs().get(1)).equals(hadoop.path(commandLog));
            }
            if (!paired) {
                throw new UsageException(commandLog + " is a command log: give its game log (GAME.rcg beside"
                        + " GAME.rcl)");
            }
        }
        if (games.isEmpty()) {
            throw new UsageException("no player logs (.lsf, .log, .txt, gzip or not) or game logs (.rcg) in "
                    + String.join(", ", inputs));
        }
        return new ArrayList<>(games.values());
    }

    /** A directory's player logs (a game named by the directory) and its game logs (a game each). */
    private static void addDirectory(HadoopFiles hadoop, Map<String, GameConversion.Game> games,
                                     Map<String, String> sources, String directory) throws IOException {
        List<String> logs = new ArrayList<>();
        for (FileStatus status : hadoop.list(directory)) {
            String name = status.getPath().getName();
            String plain = name.endsWith(".gz") ? name.substring(0, name.length() - 3) : name;
            if (!status.isFile() || name.startsWith(".")) {
                continue;
            }
            if (plain.endsWith(".rcg")) {
                String gameLog = directory + "/" + name;
                addServerGame(games, sources, gameLog, commandLogBeside(hadoop, gameLog));
            } else if (Arrays.stream(LOG_SUFFIXES).anyMatch(plain::endsWith)) {
                logs.add(directory + "/" + name);
            }
        }
        addGame(games, sources, hadoop.path(directory).toString(), logs);
    }

    /** GAME.rcl or GAME.rcl.gz beside GAME.rcg, as for {@code scenes convert GAME.rcg}. */
    private static String commandLogBeside(HadoopFiles hadoop, String gameLog) throws IOException {
        String directory = gameLog.contains("/") ? gameLog.substring(0, gameLog.lastIndexOf('/') + 1) : "";
        String base = GameLogs.baseName(gameLog.substring(directory.length()));
        for (String suffix : COMMAND_LOG_SUFFIXES) {
            String candidate = directory + base + suffix;
            if (hadoop.exists(candidate) && hadoop.serverLogKind(candidate) == ServerLogs.Kind.COMMAND) {
                return candidate;
            }
        }
        throw new UsageException("no command log beside " + gameLog + " (" + base + ".rcl): the scenes pair what"
                + " each player saw with what it sent");
    }

    private static void addServerGame(Map<String, GameConversion.Game> games, Map<String, String> sources,
                                      String gameLog, String commandLog) {
        String name = GameLogs.baseName(gameLog.substring(gameLog.lastIndexOf('/') + 1));
        String known = sources.putIfAbsent(name, gameLog);
        if (known != null && !known.equals(gameLog)) {
            throw new UsageException("two games are named " + name + " (" + known + " and " + gameLog
                    + "); convert them separately, into different --out-dir");
        }
        games.putIfAbsent(name, GameConversion.Game.ofServerLogs(name, gameLog, commandLog));
    }

    /** Adds logs to the game of a directory (its full path), named by the directory's name. */
    private static void addGame(Map<String, GameConversion.Game> games, Map<String, String> sources, String directory,
                                List<String> logs) {
        if (logs.isEmpty()) {
            return;
        }
        String name = gameName(directory);
        String known = sources.putIfAbsent(name, directory);
        if (known != null && !known.equals(directory)) {
            throw new UsageException("two games are named " + name + " (" + known + " and " + directory
                    + "); convert them separately, into different --out-dir");
        }
        GameConversion.Game game = games.computeIfAbsent(name, n -> new GameConversion.Game(n, new ArrayList<>(), false));
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
}
