package org.scenes.agent.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.Side;
import org.scenes.internal.files.Inputs;
import org.scenes.internal.proxylog.ProxyLogLine;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.simulator.server.SoccerServer;
import org.scenes.simulator.teacher.Teachers;

/**
 * The same teams and seed give the same game in process and over UDP in synchronous mode: the
 * teachers, connected with the project's live runtime ({@code agent.net}) and seeded as the
 * simulator seeds them, see and do exactly what they see and do in {@code scenes simulate}, for
 * the whole game, goals and half time included.
 */
class ServerDeterminismTest {
    private static final int PLAYERS = 3;
    private static final int CYCLES = 600;
    private static final long SEED = 11;

    @TempDir
    Path directory;

    private static List<String> lsf(Path file) throws IOException {
        try (InputStream in = Inputs.open(file)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
        }
    }

    /** The messages of a live player's traffic log, without the synchronous-mode think/done and the bye. */
    private static List<String> traffic(Path file) throws IOException {
        List<String> messages = new ArrayList<>();
        for (String line : Files.readAllLines(file)) {
            if (ProxyLogLine.isComment(line)) {
                continue;
            }
            String text = ProxyLogLine.parse(line).text();
            if (!text.equals("(think)") && !text.equals("(done)") && !text.equals("(bye)")) {
                messages.add(text);
            }
        }
        return messages;
    }

    private void serve(Path logs, Path record) throws Exception {
        ServerConfig config = ServerConfig.defaults().withPort(0).withSynch(true).withGame(CYCLES, SEED)
                .withRecordDirectory(record).withTimings(Duration.ofMillis(500), Duration.ofSeconds(3));
        ExecutorService executor = Executors.newSingleThreadExecutor();
        try (SoccerServer server = SoccerServer.open(config, line -> { })) {
            Future<ServerResult> running = executor.submit(() -> server.run(frame -> { }));
            BrainFactory krislet = Teachers.byName("krislet");
            List<Thread> threads = new ArrayList<>();
            for (String team : List.of("Teal", "Amber")) {
                Side side = team.equals("Teal") ? Side.LEFT : Side.RIGHT;
                for (int unum = 1; unum <= PLAYERS; unum++) {
                    ClientOptions options = ClientOptions.of(new ServerAddress("127.0.0.1", server.port()), team)
                            .withLogDirectory(logs).withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(10));
                    LivePlayer player = new LivePlayer(options,
                            krislet.create(team, new Random(Simulator.brainSeed(SEED, side, unum))), false, n -> { });
                    Thread thread = new Thread(player, team + "-" + unum);
                    thread.start();
                    threads.add(thread);
                    assertTrue(player.awaitAnswer(5, TimeUnit.SECONDS), team + " " + unum + " connected");
                }
            }
            ServerResult result = running.get(120, TimeUnit.SECONDS);
            assertEquals(CYCLES, result.cycles());
            assertEquals(0, result.dropped());
            for (Thread thread : threads) {
                thread.join(10_000);
            }
        } finally {
            executor.shutdownNow();
        }
    }

    @Test
    void theSameGameInProcessAndOverUdp() throws Exception {
        GameSetup setup = new GameSetup(new GameSetup.Team("Teal", PLAYERS, Teachers.byName("krislet")),
                new GameSetup.Team("Amber", PLAYERS, Teachers.byName("krislet")), CYCLES, SEED,
                directory.resolve("in-process"));
        GameResult game = new Simulator(setup).run(t -> { });
        assertTrue(game.scoreLeft() + game.scoreRight() > 0, "a goal was scored");
        serve(directory.resolve("udp"), directory.resolve("server-a"));
        serve(directory.resolve("udp-again"), directory.resolve("server-b"));
        for (String team : List.of("Teal", "Amber")) {
            for (int unum = 1; unum <= PLAYERS; unum++) {
                List<String> inProcess = lsf(directory.resolve("in-process/" + team + "_" + unum + ".lsf.gz"));
                List<String> udp = traffic(directory.resolve("udp/" + team + "_" + unum + ".log"));
                // The whole game, goals and half time included: in process the players get their
                // kick-off move again after each, as the live runtime sends it.
                assertEquals(inProcess, udp, team + " " + unum);
                // Over UDP, the same clients and seed give the same game to the end.
                assertEquals(udp, traffic(directory.resolve("udp-again/" + team + "_" + unum + ".log")),
                        team + " " + unum + " twice over UDP");
            }
        }
        try (var a = Files.list(directory.resolve("server-a")); var b = Files.list(directory.resolve("server-b"))) {
            List<Path> first = a.sorted().toList();
            List<Path> second = b.sorted().toList();
            assertEquals(first.get(0).getFileName(), second.get(0).getFileName());
            assertEquals(Files.readAllLines(first.get(0)), Files.readAllLines(second.get(0)), "the same game log");
        }
    }
}
