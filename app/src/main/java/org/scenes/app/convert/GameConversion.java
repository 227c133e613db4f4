package org.scenes.app.convert;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Function;
import org.scenes.internal.convert.GameSceneFiles;
import org.scenes.internal.gamelog.GameLogs;

/**
 * {@code scenes convert GAME.rcg [GAME.rcl]}: a game's server logs into a scene file per player,
 * {@code DIR/TEAM_UNUM.json.gz} (or as the settings compress), or the one chosen player's into one file. The files are committed
 * together, and only when the game gave scenes (core's {@link GameSceneFiles}).
 */
public final class GameConversion {
    private GameConversion() {
    }

    /**
     * What to convert and where.
     *
     * @param logs the game's two logs
     * @param file the scene file of the one player chosen, or null
     * @param directory a scene file per player in this directory, or null
     */
    public record Request(GameLogs logs, Path file, Path directory, ConvertSettings settings) {
        public Request {
            if ((file == null) == (directory == null)) {
                throw new IllegalArgumentException("one scene file or one directory, not both or neither");
            }
        }
    }

    /**
     * The outcome: the conversion and its files (none when the game gave no scene or no player was chosen).
     *
     * @param seconds the time taken
     */
    public record Result(GameSceneFiles.Written written, double seconds) {
    }

    /** One scene file was asked for and the game has more than one player chosen. */
    public static final class OnePlayerPerFile extends RuntimeException {
        OnePlayerPerFile() {
            super("-o takes the scenes of one player (choose it with --team and --unum); use --out-dir for several");
        }
    }

    /** @throws OnePlayerPerFile when one file is asked for and more than one player is chosen */
    public static Result run(Request request) throws IOException {
        if (request.directory() != null) {
            Files.createDirectories(request.directory());
        }
        int[] players = {0};
        Function<String, Path> target = key -> {
            if (request.file() != null && players[0]++ > 0) {
                throw new OnePlayerPerFile();
            }
            return request.file() != null ? request.file() : request.directory().resolve(request.settings().compression().fileName(key));
        };
        long started = System.nanoTime();
        GameSceneFiles.Written written = GameSceneFiles.write(request.settings().gameLogConverter(),
                request.settings().grid(), request.logs(), target);
        return new Result(written, (System.nanoTime() - started) / 1e9);
    }
}
