package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.convert.LogFormat;
import org.scenes.logproxy.ClientKind;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.Route;
import org.scenes.tests.SimulatedGame;

/**
 * Issue 31.5: junk and refused clients do not hold the proxy's client slots, the proxy cannot be
 * pointed at itself, and a team name too long for a file name still gives a complete log.
 */
class ProxyLimitsTest {
    private static final long WAIT = 20_000;
    /** Few slots, so a handful of bad senders would fill them all. */
    private static final int SLOTS = 4;

    @TempDir
    Path out;

    private final List<PlayerClient> clients = new ArrayList<>();
    private final List<String> events = new CopyOnWriteArrayList<>();
    private FakeSoccerServer server;
    private LogProxy proxy;

    @AfterEach
    void stopAll() throws IOException {
        for (PlayerClient client : clients) {
            client.close();
        }
        if (proxy != null) {
            proxy.close();
        }
        if (server != null) {
            server.close();
        }
    }

    private void start() throws IOException {
        server = FakeSoccerServer.start(FakeSoccerServer.recordedSensing(SimulatedGame.log("Carleton", 1), 50));
        proxy = LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(),
                List.of(new Route(ClientKind.PLAYER, 0, server.address(FakeSoccerServer.Port.PLAYER))), out,
                LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofMillis(200), 1 << 20,
                SLOTS, events::add));
    }

    private PlayerClient client() throws IOException {
        PlayerClient client = new PlayerClient(new InetSocketAddress(InetAddress.getLoopbackAddress(),
                proxy.listenPort(ClientKind.PLAYER)));
        clients.add(client);
        return client;
    }

    @Test
    void datagramsThatAreNoInitOpenNoSession() throws Exception {
        start();
        for (int i = 0; i < 3 * SLOTS; i++) {
            client().send("(dash 100)");
        }
        for (int i = 0; i < 3 * SLOTS; i++) {
            client().send("garbage " + i);
        }
        String reply = client().init("(init Good (version 9))", WAIT);
        assertTrue(reply.startsWith("(init l 1"), reply);
        assertEquals(List.of(), server.strayOnInitPorts(), "nothing but the init reached the server");
    }

    @Test
    void aClientTheServerRefusesFreesItsSlotAtOnce() throws Exception {
        start();
        server.refuseTeams(team -> team.equals("Refused"));
        for (int i = 0; i < 3 * SLOTS; i++) {
            String reply = client().init("(init Refused (version 9))", WAIT);
            assertEquals("(error no_more_team_or_player_or_goalie)", reply, "the refusal reaches the client");
        }
        String reply = client().init("(init Good (version 9))", WAIT);
        assertTrue(reply.startsWith("(init l 1"), reply);
        assertTrue(events.stream().anyMatch(e -> e.contains("the server refused the client")), events.toString());
    }

    @Test
    void aProxyForwardingToItsOwnPortIsRefused() {
        int port = 34_567;
        IllegalArgumentException error = assertThrows(IllegalArgumentException.class, () -> new ProxyConfig(
                InetAddress.getLoopbackAddress(), List.of(new Route(ClientKind.PLAYER, port,
                        new InetSocketAddress(InetAddress.getLoopbackAddress(), port))), out, LogFormat.NATIVE,
                Duration.ofSeconds(1), Duration.ofSeconds(1), 1 << 20, SLOTS, events::add));
        assertTrue(error.getMessage().contains("forward every datagram to itself"), error.getMessage());
    }

    @Test
    void aTeamNameTooLongForAFileNameStillGivesACompleteLog() throws Exception {
        start();
        String team = "T".repeat(300);
        PlayerClient client = client();
        assertTrue(client.init("(init " + team + " (version 9))", WAIT).startsWith("(init "));
        client.send("(bye)");
        long deadline = System.currentTimeMillis() + WAIT;
        List<Path> logs;
        do {
            try (Stream<Path> files = Files.list(out)) {
                logs = files.filter(f -> f.getFileName().toString().endsWith(".log")).toList();
            }
            Thread.sleep(20); // polling the directory for the condition, not ordering by time
        } while (logs.isEmpty() && System.currentTimeMillis() < deadline);
        assertEquals(1, logs.size(), "one log; events " + events);
        assertEquals("T".repeat(64) + "_1.log", logs.get(0).getFileName().toString());
        assertTrue(Files.readString(logs.get(0)).contains("(bye)"));
        try (Stream<Path> files = Files.list(out)) {
            assertEquals(List.of(), files.filter(f -> f.getFileName().toString().endsWith(".part")).toList());
        }
    }

    /** Issue 31.7: the proxy knows when a game has been played through, so it can end with it. */
    @Test
    void aGameEndsWhenItsLastClientGoesAfterTimeOver() throws Exception {
        start();
        PlayerClient first = client();
        PlayerClient second = client();
        assertTrue(first.init("(init A (version 9))", WAIT).startsWith("(init "));
        assertTrue(second.init("(init B (version 9))", WAIT).startsWith("(init "));
        for (FakeSoccerServer.Client client : server.clients()) {
            client.send("(hear 3000 referee time_over)\0".getBytes(java.nio.charset.StandardCharsets.UTF_8));
        }
        first.send("(bye)");
        long deadline = System.currentTimeMillis() + WAIT;
        while (proxy.gamesEnded() == 0 && System.currentTimeMillis() < deadline) {
            Thread.sleep(20); // polling the condition, bounded
        }
        assertEquals(1, proxy.gamesEnded(), "events " + events);
    }
}
