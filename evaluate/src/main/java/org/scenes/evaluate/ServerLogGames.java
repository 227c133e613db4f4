package org.scenes.evaluate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.IntConsumer;
import java.util.stream.Stream;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.simulator.GameResult;

/**
 * Games read from the server's logs alone, for an evaluation of any team: each game log
 * ({@code .rcg} or {@code .rcg.gz}) of a directory with the command log beside it when there is
 * one ({@code .rcl}, {@code .rcl.gz}), seen from one named team's side. The games of each side
 * are taken in name order and numbered 1, 2, ... as their seeds, so the Turing figure's folds
 * pair the teacher's first game with the imitator's first.
 */
public final class ServerLogGames {
    /** One game's frames and where they were read. */
    public record Game(Path gameLog, Path commandLog, List<GameFrame> frames) {
        /** The names of the game's two teams, left first (empty names left out). */
        public Set<String> teams() {
            Set<String> teams = new LinkedHashSet<>();
            if (!frames.isEmpty()) {
                GameFrame last = frames.get(frames.size() - 1);
                if (!last.leftTeam().isEmpty()) {
                    teams.add(last.leftTeam());
                }
                if (!last.rightTeam().isEmpty()) {
                    teams.add(last.rightTeam());
                }
            }
            return teams;
        }
    }

    /** Both sides' games read, seen from {@code team}. */
    public record Read(String team, Evaluation.Results results, List<Game> teacherGames, List<Game> imitatorGames) {
    }

    private ServerLogGames() {
    }

    /**
     * Reads the game logs of both sides ({@link #gameLogs}) and sees them from {@code team}'s side
     * (null: the one team that plays in all of them); {@code gamesRead} gets the games read so far.
     *
     * @throws IllegalArgumentException for a team missing from a game, or not given where several
     *                                  could be meant
     */
    public static Read read(List<Path> teacherLogs, List<Path> imitatorLogs, String team, IntConsumer gamesRead)
            throws IOException {
        List<Game> teacherGames = new ArrayList<>();
        List<Game> imitatorGames = new ArrayList<>();
        for (Path log : teacherLogs) {
            teacherGames.add(read(log));
            gamesRead.accept(teacherGames.size());
        }
        for (Path log : imitatorLogs) {
            imitatorGames.add(read(log));
            gamesRead.accept(teacherGames.size() + imitatorGames.size());
        }
        List<Game> all = new ArrayList<>(teacherGames);
        all.addAll(imitatorGames);
        String named = team != null ? team : commonTeam(all);
        return new Read(named, new Evaluation.Results(played(PlayedGame.Role.TEACHER, teacherGames, named),
                played(PlayedGame.Role.IMITATOR, imitatorGames, named)), teacherGames, imitatorGames);
    }

    /**
     * The game logs in {@code directory}, in name order: the server's names (rcssserver's
     * {@code incomplete.rcg} of a game still running is left out).
     *
     * @throws IllegalArgumentException when it is not a directory or holds no game log
     */
    public static List<Path> gameLogs(Path directory) throws IOException {
        if (!Files.isDirectory(directory)) {
            throw new IllegalArgumentException(directory + " is not a directory");
        }
        List<Path> logs;
        try (Stream<Path> files = Files.list(directory)) {
            logs = files.filter(f -> {
                String name = f.getFileName().toString();
                return (name.endsWith(".rcg") || name.endsWith(".rcg.gz")) && !name.startsWith("incomplete")
                        && Files.isRegularFile(f);
            }).sorted().toList();
        }
        if (logs.isEmpty()) {
            throw new IllegalArgumentException(directory + " holds no game log (.rcg or .rcg.gz)");
        }
        return logs;
    }

    /** Reads one game log and finds the command log beside it (null when none). */
    public static Game read(Path gameLog) throws IOException {
        List<GameFrame> frames = GameLogReader.readAll(gameLog);
        Path commandLog;
        try {
            commandLog = GameLogs.commandLogBeside(gameLog);
        } catch (IllegalArgumentException none) {
            commandLog = null; // the executed commands come from the game log's counters
        }
        return new Game(gameLog, commandLog, frames);
    }

    /**
     * The one team that plays in every game, or an {@link IllegalArgumentException} listing the
     * teams and in how many games each played.
     */
    public static String commonTeam(List<Game> games) {
        Map<String, Integer> counts = new LinkedHashMap<>();
        for (Game game : games) {
            for (String team : game.teams()) {
                counts.merge(team, 1, Integer::sum);
            }
        }
        List<String> common = counts.entrySet().stream().filter(e -> e.getValue() == games.size())
                .map(Map.Entry::getKey).toList();
        if (common.size() == 1) {
            return common.get(0);
        }
        StringBuilder names = new StringBuilder();
        counts.forEach((team, n) -> names.append(names.length() == 0 ? "" : ", ").append(team).append(" (")
                .append(n).append(n == 1 ? " game)" : " games)"));
        throw new IllegalArgumentException((common.isEmpty() ? "no team plays in all " : "more than one team plays"
                + " in all ") + games.size() + " games: give --team NAME; the teams are " + names);
    }

    /**
     * The games seen from {@code team}'s side, numbered from 1 as their seeds.
     *
     * @throws IllegalArgumentException when a game is not one of {@code team}'s
     */
    public static List<PlayedGame> played(PlayedGame.Role role, List<Game> games, String team) throws IOException {
        List<PlayedGame> played = new ArrayList<>();
        for (Game game : games) {
            if (game.frames().isEmpty()) {
                throw new IOException(game.gameLog() + ": no frames (show lines) in this game log");
            }
            GameFrame last = game.frames().get(game.frames().size() - 1);
            Side side = last.leftTeam().equals(team) ? Side.LEFT : last.rightTeam().equals(team) ? Side.RIGHT : null;
            if (side == null) {
                throw new IllegalArgumentException(game.gameLog() + " is a game of " + last.leftTeam() + " against "
                        + last.rightTeam() + ", not of " + team);
            }
            ExecutedCommands executed = game.commandLog() == null ? ExecutedCommands.fromCounters(game.frames(), side)
                    : ExecutedCommands.fromCommandLog(game.frames(), side, team, game.commandLog());
            List<Path> logs = game.commandLog() == null ? List.of(game.gameLog())
                    : List.of(game.gameLog(), game.commandLog());
            GameResult result = new GameResult(last.scoreLeft(), last.scoreRight(), kicks(game.frames(), Side.LEFT),
                    kicks(game.frames(), Side.RIGHT), last.time(), game.frames().size(), logs);
            played.add(new PlayedGame(role, side, played.size() + 1, result, game.frames(), List.of(), executed));
        }
        return played;
    }

    /** Kicks that reached the ball: the sum of the side's players' kick counters at their last frame. */
    static int kicks(List<GameFrame> frames, Side side) {
        Map<Integer, Integer> counters = new LinkedHashMap<>();
        for (GameFrame frame : frames) {
            for (PlayerState player : frame.players()) {
                if (player.side() == side) {
                    counters.put(player.unum(), player.counts().kick());
                }
            }
        }
        return counters.values().stream().mapToInt(Integer::intValue).sum();
    }
}
