package org.scenes.simulator.server;

import java.io.IOException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.scenes.internal.gamelog.GameFrame;

/**
 * Several games served one after another on the same init port, as a closed-loop evaluation
 * needs (a game per seed and side): after each game's time over the server completes its logs,
 * forgets every player and waits for new teams. Game {@code g} (from 0) is played with seed
 * {@code seed + g / gamesPerSeed}, so {@code gamesPerSeed 2} serves the teacher's and the
 * imitator's game of each seed with the same randomness. With a record directory, each game's
 * logs are written in its {@code .serving} folder and moved into it when complete, with the game's
 * number in front ({@code 001-Teal_1-vs-Amber_0.rcg}), so games with the same teams and score do
 * not overwrite one another.
 */
public final class GameSeries {
    private final ServerConfig config;
    private final int games;
    private final int gamesPerSeed;
    private final Consumer<String> events;
    private volatile boolean stopRequested;
    private volatile SoccerServer current;
    /** How long the next game may wait for the previous game's port to be free again. */
    private static final long REBIND_MILLIS = 5000;
    private static final long REBIND_PAUSE_MILLIS = 50;

    /**
     * @param config the first game's configuration; its seed is the first seed
     * @param games how many games, at least 1
     * @param gamesPerSeed how many games in a row share a seed, at least 1
     */
    public GameSeries(ServerConfig config, int games, int gamesPerSeed, Consumer<String> events) {
        if (games < 1) {
            throw new IllegalArgumentException("games must be at least 1, not " + games);
        }
        if (gamesPerSeed < 1) {
            throw new IllegalArgumentException("games per seed must be at least 1, not " + gamesPerSeed);
        }
        this.config = config;
        this.games = games;
        this.gamesPerSeed = gamesPerSeed;
        this.events = events;
    }

    /** The seed of game {@code game} (from 0). */
    public long seed(int game) {
        return config.seed() + game / gamesPerSeed;
    }

    /**
     * Serves the games in turn; {@code started} is told each game's number (from 1) and its
     * init port once it listens, {@code finished} each game's result, {@code frames} the state
     * after every cycle. A stop ends the current game (its logs completed) and serves no more.
     */
    public List<ServerResult> run(Consumer<int[]> started, Consumer<ServerResult> finished,
                                  Consumer<GameFrame> frames) throws IOException {
        List<ServerResult> results = new ArrayList<>();
        int port = config.port();
        for (int game = 0; game < games && !stopRequested; game++) {
            ServerConfig one = config.withGame(config.cycles(), seed(game)).withPort(port);
            if (games > 1 && config.recordDirectory() != null) {
                // written aside, then moved in under the numbered name: the directory only ever
                // holds complete, numbered logs
                one = one.withRecordDirectory(Files.createDirectories(config.recordDirectory().resolve(".serving")));
            }
            try (SoccerServer server = game == 0 ? SoccerServer.open(one, events) : reopen(one)) {
                current = server;
                // port 0: any free port for the first game, the same for the next ones
                port = server.port();
                if (stopRequested) {
                    break;
                }
                started.accept(new int[] {game + 1, server.port()});
                ServerResult result = server.run(frames);
                result = games > 1 && config.recordDirectory() != null ? numbered(result, game + 1) : result;
                results.add(result);
                finished.accept(result);
                if (result.stopped()) {
                    break;
                }
            } finally {
                current = null;
            }
        }
        if (games > 1 && config.recordDirectory() != null) {
            try {
                Files.deleteIfExists(config.recordDirectory().resolve(".serving"));
            } catch (DirectoryNotEmptyException e) {
                // a stopped game's incomplete logs stay for the user to see
            }
        }
        return results;
    }

    /**
     * The next game's server on the previous game's port. The previous socket's close can complete
     * a moment after {@code close} returns (seen as "Address already in use" in about every other
     * series under test), so binding is retried for up to {@link #REBIND_MILLIS}.
     */
    private SoccerServer reopen(ServerConfig one) throws IOException {
        long deadline = System.nanoTime() + REBIND_MILLIS * 1_000_000L;
        while (true) {
            try {
                return SoccerServer.open(one, events);
            } catch (IOException inUse) {
                if (System.nanoTime() > deadline || stopRequested) {
                    throw inUse;
                }
                try {
                    Thread.sleep(REBIND_PAUSE_MILLIS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw inUse;
                }
            }
        }
    }

    /** Ends the game being served (its logs are completed) and serves no more; from any thread. */
    public void stop() {
        stopRequested = true;
        SoccerServer server = current;
        if (server != null) {
            server.stop();
        }
    }

    private ServerResult numbered(ServerResult result, int game) throws IOException {
        List<Path> logs = new ArrayList<>();
        for (Path log : result.logs()) {
            Path target = config.recordDirectory().resolve(String.format(Locale.ROOT, "%03d-%s", game,
                    log.getFileName()));
            logs.add(Files.move(log, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE));
        }
        return new ServerResult(result.scoreLeft(), result.scoreRight(), result.cycles(), result.steps(),
                result.players(), result.dropped(), result.stopped(), result.latenessP50Millis(),
                result.latenessP99Millis(), result.latenessMaxMillis(), result.seconds(), logs);
    }
}
