package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.scenes.simulator.server.GameSeries;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code scenes server}: the embedded simulator served over UDP to any soccer server client. */
@Command(name = "server", mixinStandardHelpOptions = true,
        description = {"Serve the embedded soccer simulator over UDP, like rcssserver, to any player client"
                + " (protocol versions 7 to 9 as the real server writes them, 18+ with synch_see)."
                + " Kick-off when both teams are connected; halves; time over; then it completes its logs and"
                + " stops, or with --games serves the next game (Ctrl-C and SIGTERM end the game and stop)."
                + " Model and differences: docs/simulator.md."})
final class ServerCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--port", paramLabel = "PORT", defaultValue = "6000",
            description = "The init port players send (init ...) to. Default: ${DEFAULT-VALUE}.")
    int port;

    @Option(names = "--host", paramLabel = "ADDRESS", defaultValue = "127.0.0.1",
            description = "The address to listen on. Default: ${DEFAULT-VALUE}.")
    String host;

    @Option(names = "--synch", description = "Synchronous mode: the next cycle starts when every player sent"
            + " (done) after (think); a player that does not answer within --think-timeout is dropped.")
    boolean synch;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "6000",
            description = "Game length in cycles; half time at half. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = {"--game-seed", "--seed"}, paramLabel = "N", defaultValue = "1",
            description = "The game's seed: the server's randomness (motion and kick noise); --seed is the older spelling."
                    + " Default: ${DEFAULT-VALUE}.")
    long seed;

    @Option(names = "--record", paramLabel = "DIR",
            description = "Write the game log (.rcg, rcssserver 19's text format) and the command log (.rcl) there.")
    Path recordDir;

    @Option(names = "--teams-wait", paramLabel = "SECONDS",
            description = "Start even with one team after that many seconds from the first connection."
                    + " Default: wait for both teams.")
    Double teamsWait;

    @Option(names = "--think-timeout", paramLabel = "MS", defaultValue = "1250",
            description = "Synchronous mode: how long a player may take to send (done). Default: ${DEFAULT-VALUE}.")
    long thinkTimeout;

    @Option(names = "--games", paramLabel = "N", defaultValue = "1",
            description = "Serve N games in a row on the same port: after each time over the logs are completed,"
                    + " the players forgotten, and new teams awaited (as 'scenes evaluate --server' needs)."
                    + " Default: ${DEFAULT-VALUE}.")
    int games;

    @Option(names = "--games-per-seed", paramLabel = "K", defaultValue = "1",
            description = "With --games: K games in a row share a seed, game g (from 0) plays seed --game-seed + g / K;"
                    + " 2 serves the teacher's and the imitator's game of each seed of 'scenes evaluate'."
                    + " Default: ${DEFAULT-VALUE}.")
    int gamesPerSeed;

    @Override
    public Integer call() throws IOException {
        if (games < 1) {
            throw new UsageException("--games: must be at least 1, not " + games);
        }
        if (gamesPerSeed < 1) {
            throw new UsageException("--games-per-seed: must be at least 1, not " + gamesPerSeed);
        }
        if (cycles < 1) {
            throw new UsageException("--cycles: must be at least 1, not " + cycles);
        }
        if (port < 0 || port > 65535) {
            throw new UsageException("--port: must be 0 to 65535, not " + port);
        }
        if (teamsWait != null && !(teamsWait >= 0)) {
            throw new UsageException("--teams-wait: must be a number of seconds, not " + teamsWait);
        }
        if (thinkTimeout < 1) {
            throw new UsageException("--think-timeout: must be at least 1 ms, not " + thinkTimeout);
        }
        ServerConfig config = ServerConfig.defaults().withHost(host).withPort(port).withSynch(synch)
                .withGame(cycles, seed).withRecordDirectory(recordDir)
                .withTeamsWait(teamsWait == null ? null : Duration.ofMillis(Math.round(teamsWait * 1000)))
                .withTimings(ServerConfig.DEFAULT_SETTLE, Duration.ofMillis(thinkTimeout));
        PrintWriter out = spec.commandLine().getOut();
        CountDownLatch finished = new CountDownLatch(1);
        GameSeries series = new GameSeries(config, games, gamesPerSeed, line -> {
            out.println(line);
            out.flush();
        });
        // Ctrl-C and SIGTERM end the game like time over: its logs are completed and the command exits 0
        try (StopSignals signals = StopSignals.install("scenes-server", series::stop, finished)) {
            series.run(started -> {
                String game = games == 1 ? "" : String.format(Locale.ROOT, "game %d of %d, ", started[0], games);
                out.printf(Locale.ROOT, "Serving on UDP %s:%d (%s%s, %d cycles, seed %d)%n", host, started[1], game,
                        synch ? "synchronous" : "real time", cycles, series.seed(started[0] - 1));
                out.flush();
            }, result -> printSummary(out, result), frame -> { });
        } finally {
            finished.countDown();
        }
        return ExitCodes.OK;
    }

    private static void printSummary(PrintWriter out, ServerResult result) {
        out.printf(Locale.ROOT, "%-14s %d : %d%n", "Score", result.scoreLeft(), result.scoreRight());
        out.printf(Locale.ROOT, "%-14s %d (%d server steps) in %.2f s%n", "Cycles", result.cycles(), result.steps(),
                result.seconds());
        out.printf(Locale.ROOT, "%-14s %d connected, %d dropped%n", "Players", result.players(), result.dropped());
        if (result.latenessP99Millis() > 0 || result.latenessMaxMillis() > 0) {
            out.printf(Locale.ROOT, "%-14s p50 %.2f ms, p99 %.2f ms, max %.2f ms%n", "Cycle lateness",
                    result.latenessP50Millis(), result.latenessP99Millis(), result.latenessMaxMillis());
        }
        for (Path log : result.logs()) {
            out.printf(Locale.ROOT, "%-14s %s%n", "Server log", log.toAbsolutePath());
        }
        out.flush();
    }
}
