package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import org.scenes.api.Grid;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.options.GameLogOptions;

/**
 * {@code scenes convert GAME.rcg [GAME.rcl]}: the options handed to core's {@link GameSceneFiles}
 * (the server's logs of a game to scenes for its players), and its summary printed.
 */
final class GameLogConversion {
    private final GameLogs logs;

    private GameLogConversion(GameLogs logs) {
        this.logs = logs;
    }

    /** The server's logs among the inputs, null when they are players' logs. */
    static GameLogConversion of(List<Path> inputs, String commands) throws IOException {
        GameLogs.Commands source = GameLogs.Commands.named(commands);
        if (source == null) {
            throw new UsageException("--commands: expected rcl, infer or auto, not '" + commands + "'");
        }
        GameLogs logs;
        try {
            logs = GameLogs.among(inputs, source);
        } catch (IllegalArgumentException e) {
            // the inputs named on the command line do not make one game (a game log and its command log)
            throw new UsageException(e.getMessage());
        }
        return logs == null ? null : new GameLogConversion(logs);
    }

    int run(ConvertCommand options, Grid grid, PrintWriter out, PrintWriter err) throws IOException {
        GameLogOptions choice = options.gameLogOptions;
        choice.check();
        Path single = options.output.file;
        Path directory = options.output.directory;
        if (directory != null) {
            Files.createDirectories(directory);
        }
        int[] players = {0};
        Function<String, Path> target = key -> {
            if (single != null && players[0]++ > 0) {
                throw new UsageException("-o takes the scenes of one player (choose it with --team and --unum);"
                        + " use --out-dir for several");
            }
            return single != null ? single : directory.resolve(key + ".json.gz");
        };
        long started = System.nanoTime();
        GameSceneFiles.Written written = GameSceneFiles.write(new GameLogConverter(grid, options.pairingOptions.pairing(),
                choice.fading(), choice.selected(), options.threads).commandsBeforeSee(choice.commandsFirst())
                        .seePhase(choice.seePhase()).world(options.worldOptions.world())
                        .keepUnanswered(options.unanswered == ConvertCommand.Unanswered.KEEP), grid,
                logs, target);
        if (written.result().players().isEmpty()) {
            throw new UsageException(choice.noPlayer(logs.gameLog()));
        }
        for (String warning : written.result().warnings()) {
            err.println("scenes: warning: " + warning);
        }
        if (written.scenes() == 0) {
            err.printf("scenes: error: no scenes from %s: no player sent a command after a see%n", logs.source());
            err.flush();
            return ExitCodes.FAILURE;
        }
        summary(out, written.result(), written.files(), (System.nanoTime() - started) / 1e9);
        err.flush();
        return ExitCodes.OK;
    }

    private void summary(PrintWriter out, GameLogConverter.Result result, List<Path> written, double seconds) {
        ConversionReport total = new ConversionReport();
        out.printf(Locale.ROOT, "%-22s %s (%d shows)%n", "Game read", logs.inferred() ? logs.gameLog()
                + ", commands inferred from it" : logs.gameLog() + " and " + logs.commandLog(), result.frames());
        out.printf(Locale.ROOT, "%-14s %8s %8s %8s %8s %8s%n", "Player", "sees", "scenes", "no see", "no act",
                "cycles");
        for (GameLogConverter.PlayerResult player : result.players()) {
            ConversionReport r = player.report();
            total.add(r);
            out.printf(Locale.ROOT, "%-14s %8d %8d %8d %8d %8s%n", player.key(), r.sees(), r.scenes(),
                    r.dropped(org.scenes.internal.convert.DropReason.NO_SEE), r.dropped(org.scenes.internal.convert.DropReason.NO_ACTION),
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
