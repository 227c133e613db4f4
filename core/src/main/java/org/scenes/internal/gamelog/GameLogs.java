package org.scenes.internal.gamelog;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The server's two logs of one game: the game log ({@code GAME.rcg}) and the command log
 * ({@code GAME.rcl}) whose commands the scenes pair with what each player saw; no command log
 * (null) when the commands are inferred from the game log alone.
 */
public record GameLogs(Path gameLog, Path commandLog) {
    /** Where a game's commands come from. */
    public enum Commands {
        /** The command log: given, or the one beside the game log (required). */
        RCL,
        /** Inferred from the game log alone, whatever lies beside it. */
        INFER,
        /** The command log when there is one, else inferred. */
        AUTO;

        /** The choice of its lower-case name ({@code rcl}, {@code infer}, {@code auto}), null for another word. */
        public static Commands named(String name) {
            for (Commands commands : values()) {
                if (commands.name().toLowerCase(Locale.ROOT).equals(name)) {
                    return commands;
                }
            }
            return null;
        }
    }

    /** The command log's names beside a game log, in the order they are tried. */
    private static final String[] COMMAND_SUFFIXES = {".rcl", ".rcl.gz"};

    /**
     * The game among {@code inputs}, told apart by content: null when none is a server log (they
     * are players' logs). A game log alone takes the command log beside it.
     *
     * @throws IllegalArgumentException for two game logs, a command log alone, or a game mixed
     *                                  with other logs
     */
    public static GameLogs among(List<Path> inputs) throws IOException {
        return among(inputs, Commands.RCL);
    }

    /**
     * The game among {@code inputs}, as {@link #among(List)}, its commands from where {@code commands}
     * says: with {@link Commands#INFER} a command log given is refused; with {@link Commands#AUTO} a
     * game log without one beside it has its commands inferred.
     */
    public static GameLogs among(List<Path> inputs, Commands commands) throws IOException {
        GameLogs logs = find(inputs, commands);
        if (logs != null && commands == Commands.INFER && logs.commandLog() != null) {
            throw new IllegalArgumentException("--commands infer takes the game log alone: leave out " + logs.commandLog());
        }
        return logs;
    }

    private static GameLogs find(List<Path> inputs, Commands choice) throws IOException {
        Path game = null;
        Path commands = null;
        for (Path log : inputs) {
            ServerLogs.Kind kind = Files.isRegularFile(log) ? ServerLogs.detect(log) : null;
            if (kind == ServerLogs.Kind.GAME) {
                if (game != null) {
                    throw new IllegalArgumentException("convert one game at a time: " + game + " and " + log
                            + " are both game logs");
                }
                game = log;
            } else if (kind == ServerLogs.Kind.COMMAND) {
                if (commands != null) {
                    throw new IllegalArgumentException(commands + " and " + log + " are both command logs");
                }
                commands = log;
            }
        }
        if (game == null && commands == null) {
            return null;
        }
        if (game == null) {
            throw new IllegalArgumentException(commands + " is a command log: give it with its game log"
                    + " (GAME.rcg GAME.rcl)");
        }
        if (inputs.size() > (commands == null ? 1 : 2)) {
            throw new IllegalArgumentException("a game log is converted with its command log only, not with other logs");
        }
        if (commands != null || choice == Commands.RCL) {
            return new GameLogs(game, commands == null ? commandLogBeside(game) : commands);
        }
        return new GameLogs(game, choice == Commands.AUTO ? commandLogBesideOrNull(game) : null);
    }

    private static Path commandLogBesideOrNull(Path gameLog) throws IOException {
        try {
            return commandLogBeside(gameLog);
        } catch (IllegalArgumentException none) {
            return null;
        }
    }

    /**
     * GAME.rcl (or .rcl.gz) beside GAME.rcg (or .rcg.gz): the scenes need the players' commands.
     *
     * @throws IllegalArgumentException when there is none
     */
    public static Path commandLogBeside(Path gameLog) throws IOException {
        String base = baseName(gameLog.getFileName().toString());
        for (String suffix : COMMAND_SUFFIXES) {
            Path candidate = gameLog.resolveSibling(base + suffix);
            if (Files.isRegularFile(candidate) && ServerLogs.detect(candidate) == ServerLogs.Kind.COMMAND) {
                return candidate;
            }
        }
        throw new IllegalArgumentException("no command log beside " + gameLog + " (" + base + ".rcl): give it after"
                + " the game log; the scenes pair what each player saw with what it sent");
    }

    /** A game log's name without {@code .rcg} and {@code .gz}: the game's name. */
    public static String baseName(String gameLogName) {
        return gameLogName.replaceFirst("(\\.rcg)?(\\.gz)?$", "");
    }

    /** Whether the commands are inferred from the game log alone. */
    public boolean inferred() {
        return commandLog == null;
    }

    /** The names of the two logs, for a scene file's header. */
    public String source() {
        return gameLog.getFileName() + (commandLog == null ? " (commands inferred)" : " + " + commandLog.getFileName());
    }
}
