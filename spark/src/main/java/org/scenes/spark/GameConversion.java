package org.scenes.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import org.scenes.api.Grid;
import org.scenes.app.convert.ConvertSettings;
import org.scenes.app.convert.PlayerLogConversion;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.DropReason;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.scene.LazySceneFileWriter;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.vision.Fading;
import org.scenes.options.GameLogOptions;

/**
 * One game's conversion, the unit of a {@code convert} job: each of the game's player logs goes
 * through the project's {@link SceneConverter} into a scene file, exactly as {@code scenes convert
 * --out-dir} writes it, which is then published under {@code OUT/GAME/}; or the game's server logs
 * ({@code GAME.rcg} and {@code GAME.rcl}, every player in one file) through {@link GameSceneFiles},
 * a scene file per player, as {@code scenes convert GAME.rcg --out-dir} writes them.
 */
final class GameConversion {
    private GameConversion() {
    }

    /**
     * A game: its name (the output directory) and its logs: players' logs, or with {@code serverLogs}
     * the server's game log and command log.
     */
    record Game(String name, ArrayList<String> logs, boolean serverLogs) implements Serializable {
        static Game ofServerLogs(String name, String gameLog, String commandLog) {
            return new Game(name, new ArrayList<>(List.of(gameLog, commandLog)), true);
        }
    }

    /**
     * How logs become scenes: the grid, the pairing and strictness of {@code scenes convert}, and
     * for game logs the players chosen, the fading and the order of commands and sees; how the scene
     * files are compressed (its key: the settings travel to the executors serialized).
     */
    record Settings(int columns, double minAngle, double maxAngle, double[] bounds, String pairing, boolean strict,
                    GameLogSettings gameLogs, boolean world, String compressionKey) implements Serializable {
        static Settings of(Grid grid, Pairing pairing, boolean strict, GameLogSettings gameLogs, boolean world,
                           SceneCompression compression) {
            return new Settings(grid.columns(), grid.minAngle(), grid.maxAngle(), grid.bounds(), pairing.key(), strict,
                    gameLogs, world, compression.key());
        }

        SceneCompression compression() {
            return SceneCompression.fromKey(compressionKey);
        }

        Grid grid() {
            return new Grid(columns, minAngle, maxAngle, bounds);
        }

        /** The settings of the application layer's conversion, one thread a game (the games are the parallelism). */
        ConvertSettings convertSettings() {
            return new ConvertSettings(grid(), Pairing.fromKey(pairing), strict, world, false,
                    Fading.named(gameLogs.fading(), gameLogs.fadingSeed()),
                    GameLogConverter.only(gameLogs.team(), gameLogs.unum()), gameLogs.commandsFirst(),
                    gameLogs.seePhase(), 1, compression());
        }
    }

    /** What converting one log gave: its counts, where its scenes went, or why it failed. */
    record LogResult(String log, String written, String error, long lines, long bytes, long sees, long scenes,
                     long repeatedSees, EnumMap<DropReason, Long> dropped, long malformed, ArrayList<String> warnings)
            implements Serializable {
    }

    /** Malformed-line warnings each log reports in full; the rest are counted. */
    static final int WARNINGS_KEPT = 10;

    /** The options of {@code scenes convert} for game logs (a null team: any; unum 0: any). */
    record GameLogSettings(String team, int unum, String fading, long fadingSeed, boolean commandsFirst,
                           GameLogConverter.SeePhase seePhase)
            implements Serializable {
        GameLogConverter converter(Grid grid, Pairing pairing) {
            // one thread: the job's parallelism is its games
            return new GameLogConverter(grid, pairing, Fading.named(fading, fadingSeed),
                    GameLogConverter.only(team, unum), 1).commandsBeforeSee(commandsFirst).seePhase(seePhase);
        }
    }

    static List<LogResult> convert(Game game, Settings settings, String outDir, List<String> names) throws IOException {
        HadoopFiles hadoop = HadoopFiles.fromEnvironment();
        Grid grid = settings.grid();
        Path scratch = Files.createTempDirectory("scenes-spark-convert");
        List<LogResult> results = new ArrayList<>();
        try {
            if (game.serverLogs()) {
                return convertServerLogs(game, settings, outDir, hadoop, scratch);
            }
            for (int i = 0; i < game.logs().size(); i++) {
                String log = game.logs().get(i);
                ArrayList<String> warnings = new ArrayList<>();
                SceneConverter converter = SceneConverter.with(grid)
                        .pairing(Pairing.fromKey(settings.pairing()))
                        .strict(settings.strict())
                        .world(settings.world())
                        .warnings(line -> {
                            if (warnings.size() < WARNINGS_KEPT) {
                                warnings.add(line.describe());
                            }
                        })
                        .build();
                Path local = hadoop.local(log, scratch);
                String fileName = log.substring(log.lastIndexOf('/') + 1);
                String sceneName = settings.compression().fileName(names.get(i));
                Path sceneFile = scratch.resolve(sceneName);
                String target = outDir.replaceFirst("/+$", "") + "/" + game.name() + "/" + sceneName;
                ConversionReport report;
                String error = null;
                try (LazySceneFileWriter writer = new LazySceneFileWriter(sceneFile, grid, fileName)) {
                    report = converter.convert(local, writer::write, bytes -> { });
                    error = noScenes(log, report);
                    if (error == null) {
                        writer.commit();
                    }
                } catch (IOException | RuntimeException e) {
                    results.add(failed(log, log + ": " + e.getMessage(), warnings));
                    cleanUp(local, sceneFile, scratch);
                    continue;
                }
                if (error == null) {
                    hadoop.publish(sceneFile, target);
                }
                results.add(result(log, error == null ? target : null, error, report, warnings));
                cleanUp(local, sceneFile, scratch);
            }
        } finally {
            deleteTree(scratch);
        }
        return results;
    }

    /**
     * A game's server logs: {@link GameSceneFiles} writes a scene file per player, as {@code scenes
     * convert GAME.rcg --out-dir} does, and each is published as {@code OUT/GAME/TEAM_UNUM.json.gz} (or as compressed).
     * A result per player; the game's warnings go with the first.
     */
    private static List<LogResult> convertServerLogs(Game game, Settings settings, String outDir, HadoopFiles hadoop,
                                                     Path scratch) throws IOException {
        String gameLog = game.logs().get(0);
        String commandLog = game.logs().get(1);
        Grid grid = settings.grid();
        Path files = Files.createDirectory(scratch.resolve("scenes"));
        GameSceneFiles.Written written;
        try {
            GameLogs logs = new GameLogs(hadoop.local(gameLog, scratch), hadoop.local(commandLog, scratch));
            written = GameSceneFiles.write(settings.gameLogs().converter(grid, Pairing.fromKey(settings.pairing()))
                            .world(settings.world()),
                    grid, logs, key -> files.resolve(settings.compression().fileName(key)));
        } catch (IOException | RuntimeException e) {
            return List.of(failed(gameLog, gameLog + ": " + e.getMessage(), new ArrayList<>()));
        }
        ArrayList<String> warnings = new ArrayList<>(written.result().warnings());
        if (written.result().players().isEmpty()) {
            return List.of(failed(gameLog, GameLogOptions.noPlayer(gameLog, settings.gameLogs().team(),
                    settings.gameLogs().unum()), warnings));
        }
        if (written.scenes() == 0) {
            return List.of(failed(gameLog, "no scenes from " + gameLog + " and " + commandLog
                    + ": no player sent a command after a see", warnings));
        }
        List<LogResult> results = new ArrayList<>();
        for (GameLogConverter.PlayerResult player : written.result().players()) {
            String sceneName = settings.compression().fileName(player.key());
            String target = outDir.replaceFirst("/+$", "") + "/" + game.name() + "/" + sceneName;
            hadoop.publish(files.resolve(sceneName), target);
            results.add(result(gameLog + "#" + player.key(), target, null, player.report(),
                    results.isEmpty() ? warnings : new ArrayList<>()));
        }
        return results;
    }

    private static LogResult failed(String log, String error, ArrayList<String> warnings) {
        return new LogResult(log, null, error, 0, 0, 0, 0, 0, new EnumMap<>(DropReason.class), 0, warnings);
    }

    private static LogResult result(String log, String written, String error, ConversionReport report,
                                    ArrayList<String> warnings) {
        EnumMap<DropReason, Long> dropped = new EnumMap<>(DropReason.class);
        for (DropReason reason : DropReason.values()) {
            dropped.put(reason, report.dropped(reason));
        }
        return new LogResult(log, written, error, report.lines(), report.bytes(), report.sees(), report.scenes(),
                report.repeatedSees(), dropped, report.malformed(), warnings);
    }

    private static void cleanUp(Path local, Path sceneFile, Path scratch) throws IOException {
        if (local.startsWith(scratch)) {
            Files.deleteIfExists(local);
        }
        Files.deleteIfExists(sceneFile);
    }

    private static void deleteTree(Path directory) throws IOException {
        try (var walk = Files.walk(directory)) {
            for (Path file : walk.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        }
    }

    /** A log with messages but no scene failed, as for {@code scenes convert}; null when it did not. */
    private static String noScenes(String log, ConversionReport report) {
        if (report.scenes() > 0 || (report.messages() == 0 && report.malformed() == 0)) {
            return null;
        }
        long commands = report.commands().values().stream().mapToLong(Long::longValue).sum();
        return String.format(Locale.ROOT, "%s: no scenes from %d lines (%d see, %d commands, %d malformed lines)%s",
                log, report.lines(), report.sees(), commands, report.malformed(),
                report.sees() == 0 ? ": no see at all; is this a player's log?"
                        : commands == 0 ? ": the player sent no command" : "");
    }

    /**
     * One output name per log of a game: the log's name without extensions ({@code Carleton_1.lsf.gz}
     * gives {@code Carleton_1}), as {@code scenes convert --out-dir} names it.
     */
    static List<String> outputNames(Game game) {
        List<String> names = new ArrayList<>();
        if (game.serverLogs()) {
            return names; // a file per player, named by the player
        }
        for (String log : game.logs()) {
            String name = PlayerLogConversion.baseName(Path.of(log.substring(log.lastIndexOf('/') + 1)));
            if (names.contains(name)) {
                throw new UsageException("game " + game.name() + ": two logs would both be written as scene file " + name);
            }
            names.add(name);
        }
        return names;
    }
}
