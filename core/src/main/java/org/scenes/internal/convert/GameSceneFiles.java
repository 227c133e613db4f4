package org.scenes.internal.convert;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.inference.InferredCommandLog;
import org.scenes.internal.scene.SceneFileHeader;
import org.scenes.internal.scene.SceneFileWriter;
import org.scenes.internal.scene.SceneSource;

/**
 * A game's server logs into one scene file per converted player, as {@code scenes convert
 * GAME.rcg} and the Spark convert job write them, the commands from the command log or inferred
 * from the game log alone ({@link GameLogs#inferred()}). The files are committed together, and only
 * when the game gave scenes: nothing appears for a game whose players sent no command after a see.
 */
public final class GameSceneFiles {
    private GameSceneFiles() {
    }

    /**
     * @param result the conversion, a report per player
     * @param files  the scene files committed, in the order the players were first seen; empty
     *               when the game gave no scene (or no player was selected)
     */
    public record Written(GameLogConverter.Result result, List<Path> files) {
        public long scenes() {
            return result.players().stream().mapToLong(p -> p.report().scenes()).sum();
        }
    }

    /**
     * Converts the game.
     *
     * @param target where a player's scenes go, from its {@code TEAM_UNUM} key (called once per
     *               player converted; it may refuse a player by throwing)
     */
    public static Written write(GameLogConverter converter, Grid grid, GameLogs logs, Function<String, Path> target)
            throws IOException {
        Map<Path, SceneFileWriter> writers = new LinkedHashMap<>();
        try {
            InferredCommandLog inferred = logs.inferred() ? InferredCommandLog.of(logs.gameLog()) : null;
            GameLogConverter.Result result;
            try (CommandSource commands = inferred != null ? inferred : CommandLogReader.open(logs.commandLog())) {
                result = converter.convert(logs.gameLog(), commands,
                    new GameLogConverter.Output() {
                        @Override
                        public SceneConverter.SceneSink open(Observer observer) throws IOException {
                            return open(observer, false);
                        }

                        @Override
                        public SceneConverter.SceneSink open(Observer observer, boolean goalie) throws IOException {
                            Path file = target.apply(observer.team() + "_" + observer.uniformNumber());
                            SceneFileWriter writer = SceneFileWriter.create(file, SceneFileHeader.of(grid,
                                    new SceneSource(logs.source(), observer, goalie)));
                            writers.put(file, writer);
                            return writer::write;
                        }
                    });
            }
            if (inferred != null && !inferred.warnings().isEmpty()) {
                List<String> warnings = new ArrayList<>(inferred.warnings());
                warnings.addAll(result.warnings());
                result = new GameLogConverter.Result(result.frames(), result.players(), warnings, result.last());
            }
            Written written = new Written(result, List.of());
            if (written.scenes() == 0) {
                return written;
            }
            for (SceneFileWriter writer : writers.values()) {
                writer.commit();
            }
            return new Written(result, List.copyOf(new ArrayList<>(writers.keySet())));
        } finally {
            for (SceneFileWriter writer : writers.values()) {
                writer.close();
            }
        }
    }
}
