package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Predicate;
import org.scenes.convert.ConversionReport;
import org.scenes.convert.GameLogConverter;
import org.scenes.gamelog.ServerLogs;
import org.scenes.scene.Grid;
import org.scenes.scene.Observer;
import org.scenes.scene.SceneFileHeader;
import org.scenes.scene.SceneFileWriter;
import org.scenes.scene.SceneSource;
import org.scenes.vision.Fading;

/** {@code scenes convert GAME.rcg [GAME.rcl]}: the server's logs of a game to scenes for its players. */
final class GameLogConversion {
    private final Path gameLog;
    private final Path commandLog;

    private GameLogConversion(Path gameLog, Path commandLog) {
        this.gameLog = gameLog;
        this.commandLog = commandLog;
    }

    /** The server's logs among the inputs, null when they are players' logs. */
    static GameLogConversion of(List<Path> logs) throws IOException {
        Path game = null;
        Path commands = null;
        for (Path log : logs) {
            ServerLogs.Kind kind = Files.isRegularFile(log) ? ServerLogs.detect(log) : null;
            if (kind == ServerLogs.Kind.GAME) {
                if (game != null) {
                    throw new UsageException("convert one game at a time: " + game + " and " + log
                            + " are both game logs");
                }
                game = log;
            } else if (kind == ServerLogs.Kind.COMMAND) {
                if (commands != null) {
                    throw new UsageException(commands + " and " + log + " are both command logs");
                }
                commands = log;
            }
        }
        if (game == null && commands == null) {
            return null;
        }
        if (game == null) {
            throw new UsageException(commands + " is a command log: give it with its game log (GAME.rcg GAME.rcl)");
        }
        if (logs.size() > (commands == null ? 1 : 2)) {
            throw new UsageException("a game log is converted with its command log only, not with other logs");
        }
        if (commands == null) {
            commands = sibling(game);
        }
        return new GameLogConversion(game, commands);
    }

    /** GAME.rcl (or .rcl.gz) beside GAME.rcg: the scenes need the players' commands. */
    private static Path sibling(Path game) throws IOException {
        String name = game.getFileName().toString();
        String base = name.replaceFirst("(\\.rcg)?(\\.gz)?$", "");
        for (String suffix : new String[] {".rcl", ".rcl.gz"}) {
            Path candidate = game.resolveSibling(base + suffix);
            if (Files.isRegularFile(candidate) && ServerLogs.detect(candidate) == ServerLogs.Kind.COMMAND) {
                return candidate;
            }
        }
        throw new UsageException("no command log beside " + game + " (" + base + ".rcl): give it after the game"
                + " log; the scenes pair what each player saw with what it sent");
    }

    int run(ConvertCommand options, Grid grid, PrintWriter out, PrintWriter err) throws IOException {
        Fading fading = Fading.named(options.fading, options.fadingSeed);
        if (fading == null) {
            throw new UsageException("--fading: expected dice or halfway, not '" + options.fading + "'");
        }
        if (options.unum < 0 || options.unum > 11) {
            throw new UsageException("--unum: a uniform number from 1 to 11, not " + options.unum);
        }
        Predicate<Observer> selected = GameLogConverter.only(options.team, options.unum);
        Map<String, SceneFileWriter> writers = new LinkedHashMap<>();
        Path single = options.output.file;
        Path directory = options.output.directory;
        if (directory != null) {
            Files.createDirectories(directory);
        }
        long started = System.nanoTime();
        GameLogConverter.Result result;
        try {
            result = new GameLogConverter(grid, options.pairing, fading, selected, options.threads)
                    .commandsBeforeSee(options.commandsFirst).convert(gameLog, commandLog, observer -> {
                String key = observer.team() + "_" + observer.uniformNumber();
                if (single != null && !writers.isEmpty()) {
                    throw new UsageException("-o takes the scenes of one player (choose it with --team and --unum);"
                            + " use --out-dir for several");
                }
                Path target = single != null ? single : directory.resolve(key + ".json.gz");
                SceneFileWriter writer = SceneFileWriter.create(target, SceneFileHeader.of(grid,
                        new SceneSource(gameLog.getFileName() + " + " + commandLog.getFileName(), observer)));
                writers.put(key, writer);
                return writer::write;
            });
            if (writers.isEmpty()) {
                throw new UsageException("no player of " + gameLog + " is " + (options.team == null ? "" : "of team "
                        + options.team + " ") + (options.unum == 0 ? "" : "number " + options.unum));
            }
            for (String warning : result.warnings()) {
                err.println("scenes: warning: " + warning);
            }
            long scenes = result.players().stream().mapToLong(p -> p.report().scenes()).sum();
            if (scenes == 0) {
                err.printf("scenes: error: no scenes from %s and %s: no player sent a command after a see%n", gameLog,
                        commandLog);
                err.flush();
                return ExitCodes.FAILURE;
            }
            List<Path> written = new ArrayList<>();
            for (Map.Entry<String, SceneFileWriter> writer : writers.entrySet()) {
                writer.getValue().commit();
                written.add(single != null ? single : directory.resolve(writer.getKey() + ".json.gz"));
            }
            summary(out, result, written, (System.nanoTime() - started) / 1e9);
            err.flush();
            return ExitCodes.OK;
        } finally {
            for (SceneFileWriter writer : writers.values()) {
                writer.close();
            }
        }
    }

    private void summary(PrintWriter out, GameLogConverter.Result result, List<Path> written, double seconds) {
        ConversionReport total = new ConversionReport();
        out.printf(Locale.ROOT, "%-22s %s and %s (%d shows)%n", "Game read", gameLog, commandLog, result.frames());
        out.printf(Locale.ROOT, "%-14s %8s %8s %8s %8s %8s%n", "Player", "sees", "scenes", "no see", "no act",
                "cycles");
        for (GameLogConverter.PlayerResult player : result.players()) {
            ConversionReport r = player.report();
            total.add(r);
            out.printf(Locale.ROOT, "%-14s %8d %8d %8d %8d %8s%n", player.key(), r.sees(), r.scenes(),
                    r.dropped(org.scenes.convert.DropReason.NO_SEE), r.dropped(org.scenes.convert.DropReason.NO_ACTION),
                    r.perCycleLogs() > 0 ? Long.toString(r.cycles()) : "-");
        }
        out.printf(Locale.ROOT, "%-22s %d for %d players%n", "Scenes written", total.scenes(), result.players().size());
        for (Path file : written) {
            out.printf(Locale.ROOT, "%-22s %s%n", "Written", file);
        }
        out.printf(Locale.ROOT, "%-22s %.2f s%n", "Time", seconds);
        out.flush();
    }
}
