package org.scenes.simulator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import org.scenes.internal.gamelog.CommandLogWriter;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogWriter;

/**
 * The server's logs of one game in a directory: the game log ({@code .rcg}) and the command log
 * ({@code .rcl}), named like rcssserver names them once the game is over,
 * {@code LEFT_SCORE-vs-RIGHT_SCORE.rcg} (without the date, so a game repeats to the byte), a side no
 * player joined as {@code null} ({@code Teal_0-vs-null.rcg}).
 * Nothing appears before {@link #commit}.
 */
public final class GameRecorder implements AutoCloseable {
    private final Path directory;
    private final GameLogWriter gameLog;
    private final CommandLogWriter commandLog;
    private final Engine engine;

    private GameRecorder(Path directory, Engine engine) throws IOException {
        List<String> parameterMessages = engine.parameterMessages();
        this.engine = engine;
        this.directory = directory;
        this.gameLog = GameLogWriter.create(directory.resolve("incomplete.rcg"), parameterMessages);
        CommandLogWriter commands;
        try {
            commands = CommandLogWriter.create(directory.resolve("incomplete.rcl"));
        } catch (IOException e) {
            gameLog.close();
            throw e;
        }
        this.commandLog = commands;
    }

    /** Starts recording into {@code directory} with the engine's parameter messages. */
    public static GameRecorder open(Path directory, Engine engine) throws IOException {
        return new GameRecorder(directory, engine);
    }

    void frame(GameFrame frame) {
        try {
            gameLog.write(frame);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    void received(int time, int stoppage, String team, int unum, String message) throws IOException {
        commandLog.received(time, stoppage, team, unum, message);
    }

    void referee(int time, int stoppage, String word) throws IOException {
        commandLog.referee(time, stoppage, word);
    }

    /** Completes both logs and gives them their final names; returns the game log and the command log. */
    public List<Path> commit() throws IOException {
        // Named by the teams and the score at the end, also when the game was stopped before kick-off;
        // a side no player joined is "null" without a score, as rcssserver names it (Teal_0-vs-null).
        GameFrame last = engine.frame();
        String name = side(last.leftTeam(), last.scoreLeft()) + "-vs-" + side(last.rightTeam(), last.scoreRight());
        Path game = rename(gameLog.commit(), directory.resolve(name + ".rcg"));
        Path commands = rename(commandLog.commit(), directory.resolve(name + ".rcl"));
        return List.of(game, commands);
    }

    private static String side(String team, int score) {
        return team.isEmpty() ? "null" : team + "_" + score;
    }

    private static Path rename(Path from, Path to) throws IOException {
        try {
            return Files.move(from, to, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            return Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** Abandons whatever was not committed. */
    @Override
    public void close() throws IOException {
        try {
            gameLog.close();
        } finally {
            commandLog.close();
        }
    }
}
