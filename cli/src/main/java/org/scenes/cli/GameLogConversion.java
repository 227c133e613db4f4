package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.scenes.api.Grid;
import org.scenes.app.convert.GameConversion;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.DropReason;
import org.scenes.internal.convert.GameLogConverter;
import org.scenes.internal.gamelog.GameLogs;

/**
 * {@code scenes convert GAME.rcg [GAME.rcl]}: the options handed to the {@link GameConversion}
 * service (the server's logs of a game to scenes for its players), and its summary printed.
 */
final class GameLogConversion {
    private final GameLogs logs;

    private GameLogConversion(GameLogs logs) {
        this.logs = logs;
    }

    /** The server's logs among the inputs, null when they are players' logs. */
    static GameLogConversion of(List<Path> inputs, GameLogs.Commands source) throws IOException {
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
        GameConversion.Result result;
        try {
            result = GameConversion.run(new GameConversion.Request(logs, options.output.file,
                    options.output.directory, options.settings(grid)));
        } catch (GameConversion.OnePlayerPerFile e) {
            throw new UsageException(e.getMessage());
        }
        GameLogConverter.Result conversion = result.written().result();
        if (conversion.players().isEmpty()) {
            throw new UsageException(options.gameLogOptions.noPlayer(logs.gameLog()));
        }
        for (String warning : conversion.warnings()) {
            err.println("scenes: warning: " + warning);
        }
        if (result.written().scenes() == 0) {
            err.printf("scenes: error: no scenes from %s: no player sent a command after a see%n", logs.source());
            err.flush();
            return ExitCodes.FAILURE;
        }
        summary(out, conversion, result.written().files(), result.seconds());
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
                    r.dropped(DropReason.NO_SEE), r.dropped(DropReason.NO_ACTION),
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
