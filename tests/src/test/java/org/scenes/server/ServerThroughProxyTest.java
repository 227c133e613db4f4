package org.scenes.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.LivePlayer;
import org.scenes.agent.net.ServerAddress;
import org.scenes.api.Grid;
import org.scenes.api.Side;
import org.scenes.internal.convert.ConversionReport;
import org.scenes.internal.convert.LogFormat;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.proxylog.Direction;
import org.scenes.internal.proxylog.ProxyLogLine;
import org.scenes.logproxy.ClientKind;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.Route;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.simulator.server.SoccerServer;
import org.scenes.simulator.teacher.Teachers;

/**
 * The project's agents (teachers on the live runtime, over UDP) play one full game on
 * {@code scenes server} through the logging proxy: the proxy's logs hold every message either
 * way, in order, and convert into scenes with no malformed line.
 */
class ServerThroughProxyTest {
    private static final int PLAYERS = 3;
    private static final int CYCLES = 1000;

    @TempDir
    Path directory;

    /** The messages of a proxy-format log in one direction, without padding. */
    private static List<String> messages(Path log, Direction direction) throws IOException {
        List<String> out = new ArrayList<>();
        for (String line : Files.readAllLines(log)) {
            if (!ProxyLogLine.isComment(line)) {
                ProxyLogLine parsed = ProxyLogLine.parse(line);
                if (parsed.direction() == direction) {
                    out.add(parsed.text().replace("\0", ""));
                }
            }
        }
        return out;
    }

    private static List<Path> files(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.sorted().toList();
        }
    }

    @Test
    void aFullGameThroughTheProxyIsLoggedWhole() throws Exception {
        ServerConfig config = ServerConfig.defaults().withPort(0).withSynch(true).withGame(CYCLES, 3)
                .withTimings(Duration.ofMillis(500), Duration.ofSeconds(3));
        ExecutorService executor = Executors.newSingleThreadExecutor();
        Path proxyLogs = directory.resolve("proxy");
        Path clientLogs = directory.resolve("clients");
        ServerResult result;
        try (SoccerServer server = SoccerServer.open(config, line -> { })) {
            Future<ServerResult> running = executor.submit(() -> server.run(frame -> { }));
            InetSocketAddress serverAddress = new InetSocketAddress(InetAddress.getLoopbackAddress(), server.port());
            try (LogProxy proxy = LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(),
                    List.of(new Route(ClientKind.PLAYER, 0, serverAddress)), proxyLogs, LogFormat.NATIVE,
                    Duration.ofSeconds(5), Duration.ofSeconds(2), ProxyConfig.DEFAULT_LOG_BUFFER_BYTES,
                    ProxyConfig.DEFAULT_MAX_CLIENTS, event -> { }))) {
                List<Thread> threads = new ArrayList<>();
                for (String team : List.of("Teal", "Amber")) {
                    Side side = team.equals("Teal") ? Side.LEFT : Side.RIGHT;
                    for (int unum = 1; unum <= PLAYERS; unum++) {
                        ClientOptions options = ClientOptions.of(new ServerAddress("127.0.0.1",
                                proxy.listenPort(ClientKind.PLAYER)), team).withLogDirectory(clientLogs)
                                .withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(10));
                        LivePlayer player = new LivePlayer(options, Teachers.byName("krislet").create(team,
                                new Random(Simulator.brainSeed(3, side, unum))), false, n -> { });
                        Thread thread = new Thread(player, team + "-" + unum);
                        thread.start();
                        threads.add(thread);
                        assertTrue(player.awaitAnswer(5, TimeUnit.SECONDS), team + " " + unum + " connected");
                    }
                }
                result = running.get(180, TimeUnit.SECONDS);
                for (Thread thread : threads) {
                    thread.join(15_000);
                }
                // the proxy completes a log when its client has been idle for the idle timeout
                long deadline = System.currentTimeMillis() + 30_000;
                while (files(proxyLogs).stream().filter(f -> f.toString().endsWith(".log")).count() < 2 * PLAYERS
                        && System.currentTimeMillis() < deadline) {
                    Thread.sleep(100);
                }
            }
        } finally {
            executor.shutdownNow();
        }
        assertEquals(CYCLES, result.cycles());
        assertEquals(0, result.dropped());

        // Pair each proxy log with the client's own traffic log by the init reply the client got.
        Map<String, Path> byReply = new HashMap<>();
        for (Path log : files(clientLogs)) {
            byReply.put(messages(log, Direction.SERVER_TO_CLIENT).get(0), log);
        }
        List<Path> logged = files(proxyLogs).stream().filter(f -> f.toString().endsWith(".log")).toList();
        assertEquals(2 * PLAYERS, logged.size(), logged.toString());
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        for (Path log : logged) {
            List<String> fromServer = messages(log, Direction.SERVER_TO_CLIENT);
            Path client = byReply.get(fromServer.get(0));
            assertTrue(client != null, "a client got " + fromServer.get(0));
            assertEquals(messages(client, Direction.SERVER_TO_CLIENT), fromServer, "server to client, " + log);
            assertEquals(messages(client, Direction.CLIENT_TO_SERVER), messages(log, Direction.CLIENT_TO_SERVER),
                    "client to server, " + log);
            assertTrue(fromServer.get(fromServer.size() - 1).endsWith("referee time_over)"), "to the end: " + log);
            ConversionReport report = converter.convert(log, scene -> { });
            assertEquals(0, report.malformed(), log + ": " + report.malformedLines());
            // a see on two cycles of three, three in four answered: about half a scene per cycle
            assertTrue(report.scenes() > CYCLES * 0.4, log + " gives scenes: " + report.scenes());
        }
    }
}
