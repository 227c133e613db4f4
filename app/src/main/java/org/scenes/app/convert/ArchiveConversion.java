package org.scenes.app.convert;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.time.Duration;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.scenes.app.Progress;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.files.CsvTables;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogs;

/**
 * {@code scenes convert ARCHIVE_DIR --out-dir DIR}: every game log in a directory tree
 * ({@code .rcg}, {@code .rcg.gz}, the command log beside it) into a scene file per player, grouped
 * by team: {@code DIR/TEAM/GAME_UNUM.json.gz} (or as the settings compress). Each game is converted on its own: its files are
 * committed together once it gave scenes, then its row is recorded in {@code DIR/.games/GAME.json};
 * a game with a record is skipped by the next run, so an interrupted run resumes where it stopped
 * (a game cut off leaves no file: {@link AtomicOutput}, and no record, so it is converted again).
 * A game that fails is recorded in the manifest with its reason and the run goes on. The manifest,
 * {@code DIR/manifest.csv}, has a row per game of the archive.
 */
public final class ArchiveConversion {
    /** The manifest of an archive's output directory. */
    public static final String MANIFEST = "manifest.csv";
    /** The directory of the games' records, the run's memory of what is done. */
    public static final String RECORDS = ".games";

    private static final Pattern GAME_LOG = Pattern.compile(".+\\.rcg(\\.gz)?");
    /** The characters rcssserver allows in a team name: safe as a directory name. */
    private static final Pattern TEAM_NAME = Pattern.compile("[A-Za-z0-9_-]+");
    private static final ObjectMapper JSON = new ObjectMapper();

    /**
     * What to convert and where.
     *
     * @param archive the directory tree of game logs
     * @param outDir where the teams' directories, the manifest and the games' records go
     */
    public record Request(Path archive, Path outDir, ConvertSettings settings, GameLogs.Commands commands) {
        /** Commands from the command log beside each game, inferred from the game log where there is none. */
        public Request(Path archive, Path outDir, ConvertSettings settings) {
            this(archive, outDir, settings, GameLogs.Commands.AUTO);
        }
    }

    /**
     * The outcome.
     *
     * @param rows a row per game, in the order of their paths
     * @param resumed games found converted by an earlier run, not converted again
     * @param manifest the manifest written
     */
    public record Result(List<ManifestRow> rows, int resumed, Path manifest, double seconds) {
        public long count(ManifestRow.Status status) {
            return rows.stream().filter(r -> r.status() == status).count();
        }
    }

    private final Request request;
    private final AtomicInteger done = new AtomicInteger();
    private volatile int games;
    private volatile boolean cancelled;
    private final CountDownLatch stopped = new CountDownLatch(1);

    public ArchiveConversion(Request request) {
        this.request = request;
    }

    /** Whether {@code input} is an archive: a directory. */
    public static boolean isArchive(Path input) {
        return Files.isDirectory(input);
    }

    /** Games done so far (converted, resumed, failed or skipped); read from any thread. */
    public int done() {
        return done.get();
    }

    /**
     * Stops the run (from any thread: a shutdown hook): no game starts and no file is opened
     * after this, the game under way is abandoned, and {@link #run} ends with a
     * {@link CancellationException}.
     */
    public void cancel() {
        cancelled = true;
    }

    /** Waits until {@link #run} has returned or thrown, at most {@code timeout}; whether it has. */
    public boolean awaitStop(Duration timeout) throws InterruptedException {
        return stopped.await(timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** Games in the archive, known once {@link #run} has walked it. */
    public int games() {
        return games;
    }

    /** Whether a file of the archive is a game log, by its name: {@code *.rcg} or {@code *.rcg.gz}. */
    public static boolean isGameLog(String fileName) {
        return GAME_LOG.matcher(fileName).matches();
    }

    /**
     * A game's name from its game log's path in the archive ({@code day1/late/A-vs-B.rcg.gz}):
     * without {@code .rcg[.gz]}, directories joined by '-' ({@code day1-late-A-vs-B}).
     */
    public static String gameName(String path) {
        return GameLogs.baseName(path).replace('/', '-');
    }

    /** A game log in the archive and its name. */
    record Game(String name, Path gameLog, String path) {
    }

    /**
     * The archive's game logs, in the order of their paths, the output directory left out.
     *
     * @throws IllegalArgumentException when two game logs would have the same name
     */
    static List<Game> games(Path archive, Path outDir) throws IOException {
        Path root = archive.toAbsolutePath().normalize();
        Path out = outDir.toAbsolutePath().normalize();
        List<Game> games = new ArrayList<>();
        Map<String, Path> names = new HashMap<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path file : files.filter(f -> !f.startsWith(out) && Files.isRegularFile(f)
                    && isGameLog(f.getFileName().toString())).sorted().toList()) {
                String path = root.relativize(file).toString().replace(file.getFileSystem().getSeparator(), "/");
                String name = gameName(path);
                Path before = names.put(name, file);
                if (before != null) {
                    throw new IllegalArgumentException(before + " and " + file + " would both be game " + name
                            + " (a game log's path in the archive, directories joined by '-', names its game)");
                }
                games.add(new Game(name, file, path));
            }
        }
        return games;
    }

    /** @throws IllegalArgumentException when the archive holds no game log, or two of one name */
    public Result run(Progress progress) throws IOException {
        try {
            return runGames(progress);
        } finally {
            stopped.countDown();
        }
    }

    private Result runGames(Progress progress) throws IOException {
        long started = System.nanoTime();
        List<Game> found = games(request.archive(), request.outDir());
        if (found.isEmpty()) {
            throw new IllegalArgumentException("no game logs (.rcg, .rcg.gz) under " + request.archive());
        }
        games = found.size();
        Path records = request.outDir().resolve(RECORDS);
        Files.createDirectories(records);
        List<ManifestRow> rows = new ArrayList<>();
        int resumed = 0;
        progress.begin("Converting", found.size());
        try {
            for (Game game : found) {
                stopIfCancelled();
                ManifestRow row = record(records, game);
                if (row != null) {
                    resumed++;
                } else {
                    Path commandLog = request.commands() == GameLogs.Commands.INFER ? null : commandLog(game.gameLog());
                    row = commandLog == null && request.commands() == GameLogs.Commands.RCL
                            ? ManifestRow.notConverted(game.name(), game.path(), ManifestRow.Status.skipped,
                                    "no command log beside it (" + GameLogs.baseName(game.gameLog().getFileName()
                                            .toString()) + ".rcl or .rcl.gz) and --commands rcl")
                            : convertGame(request.settings(), game.name(), game.path(), game.gameLog(), commandLog,
                                    request.outDir(), () -> cancelled);
                    // a game finished as the run was stopped has no record: the next run converts it again
                    stopIfCancelled();
                    if (row.status() == ManifestRow.Status.converted) {
                        writeRecord(records, row);
                    }
                }
                rows.add(row);
                done.incrementAndGet();
                progress.step();
            }
        } finally {
            progress.end();
        }
        stopIfCancelled();
        Path manifest = request.outDir().resolve(MANIFEST);
        writeManifest(manifest, rows);
        return new Result(List.copyOf(rows), resumed, manifest, (System.nanoTime() - started) / 1e9);
    }

    private void stopIfCancelled() {
        if (cancelled) {
            throw new CancellationException("stopped: " + done.get() + " of " + games + " games done");
        }
    }

    /** The game's record from an earlier run, null when it was not converted. */
    private static ManifestRow record(Path records, Game game) throws IOException {
        Path file = records.resolve(game.name() + ".json");
        if (!Files.isRegularFile(file)) {
            return null;
        }
        ManifestRow row = readRecord(file);
        return row.status() == ManifestRow.Status.converted ? row : null;
    }

    /** A game's record, {@code DIR/.games/GAME.json}: its manifest row, warnings in full. */
    public static ManifestRow readRecord(Path file) throws IOException {
        return JSON.readValue(file.toFile(), ManifestRow.class);
    }

    /** The same from the record's bytes (read from another file system). */
    public static ManifestRow readRecord(byte[] json) throws IOException {
        return JSON.readValue(json, ManifestRow.class);
    }

    /** The manifest, a row per game, written complete or not at all. */
    public static void writeManifest(Path file, List<ManifestRow> rows) throws IOException {
        CsvTables.write(file, ManifestRow.COLUMNS, rows.stream().map(ManifestRow::cells).toList());
    }

    /** Writes a game's record into {@code records} ({@code DIR/.games}), complete or not at all. */
    public static void writeRecord(Path records, ManifestRow row) throws IOException {
        try (AtomicOutput output = AtomicOutput.create(records.resolve(row.game() + ".json"))) {
            JSON.writerWithDefaultPrettyPrinter().writeValue(output.stream(), row);
            output.commit();
        }
    }

    /**
     * One game of an archive into {@code outDir/TEAM/GAME_UNUM.json.gz}, its failure a row with the
     * reason; the step {@link #run} takes for each game, and the Spark job's task (into a scratch
     * directory it then publishes). A game that fails while its files are committed (an output
     * error) has those already in place removed: a game is in the output whole or not at all.
     *
     * @param name the game's name ({@link #gameName})
     * @param path the game log's path in the archive, for the manifest
     * @param commandLog the command log beside the game log; null: the commands are inferred from
     *                   the game log alone (docs/conversion.md)
     * @param cancelled whether the run was stopped: then no scene file is opened and the game fails
     */
    public static ManifestRow convertGame(ConvertSettings settings, String name, String path, Path gameLog,
                                          Path commandLog, Path outDir, BooleanSupplier cancelled) {
        Game game = new Game(name, gameLog, path);
        List<Path> targets = new ArrayList<>();
        try {
            return convert(settings, game, new GameLogs(game.gameLog(), commandLog), outDir, targets, cancelled);
        } catch (IOException | RuntimeException e) {
            // a game log cut off, shuffled or of another game than its command log (the file and line
            // named), or an output that could not be written
            for (Path target : targets) {
                try {
                    if (Files.isRegularFile(target, LinkOption.NOFOLLOW_LINKS)) {
                        Files.delete(target);
                    }
                } catch (IOException ignored) {
                    // a file that cannot be deleted is replaced when the game is converted again
                }
            }
            return ManifestRow.notConverted(game.name(), game.path(), ManifestRow.Status.failed, reason(e));
        }
    }

    /** The command log beside the game log; null when there is none. */
    private static Path commandLog(Path gameLog) {
        try {
            return GameLogs.commandLogBeside(gameLog);
        } catch (IllegalArgumentException | IOException e) {
            return null;
        }
    }

    private static ManifestRow convert(ConvertSettings settings, Game game, GameLogs logs, Path outDir,
                                       List<Path> targets, BooleanSupplier cancelled) throws IOException {
        GameSceneFiles.Written written = GameSceneFiles.write(settings.gameLogConverter(), settings.grid(), logs,
                key -> {
                    if (cancelled.getAsBoolean()) {
                        throw new CancellationException("stopped");
                    }
                    int cut = key.lastIndexOf('_');
                    String team = key.substring(0, cut);
                    if (!TEAM_NAME.matcher(team).matches()) {
                        throw new IllegalArgumentException("team name '" + team + "' is not a directory name"
                                + " (letters, digits, '-' and '_')");
                    }
                    Path target = outDir.resolve(team).resolve(settings.compression().fileName(game.name() + "_" + key.substring(cut + 1)));
                    targets.add(target);
                    return target;
                });
        GameLogConverter.Result result = written.result();
        if (written.files().isEmpty()) {
            return ManifestRow.notConverted(game.name(), game.path(), ManifestRow.Status.failed,
                    result.players().isEmpty() ? "no player chosen" : "no scenes: no player sent a command after a see");
        }
        GameFrame last = result.last(); // the converter read every show up to where the log ends or is cut
        return new ManifestRow(game.name(), game.path(), ManifestRow.Status.converted, last == null ? "" : last.leftTeam(),
                last == null ? "" : last.rightTeam(), last == null ? -1 : last.scoreLeft(),
                last == null ? -1 : last.scoreRight(), written.files().size(), written.scenes(),
                result.warnings(), logs.inferred() ? "infer" : "rcl", "");
    }

    private static String reason(Exception e) {
        String message = e.getMessage();
        return message == null ? e.getClass().getSimpleName() : message.replace('\n', ' ');
    }
}
