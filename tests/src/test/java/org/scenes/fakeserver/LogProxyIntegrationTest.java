package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.scenes.fakeserver.ProxyLogs.assertSameDatagrams;
import static org.scenes.fakeserver.ProxyLogs.unpadded;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.LongSupplier;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.convert.LogFormat;
import org.scenes.internal.proxylog.Direction;
import org.scenes.logproxy.ClientKind;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.ProxyEnvironment;
import org.scenes.logproxy.Route;
import org.scenes.tests.SimulatedGame;

/** Clients talk to the fake soccer server through the logging proxy; the logs are checked message by message. */
class LogProxyIntegrationTest {
    private static final long WAIT = 20_000;

    @TempDir
    Path out;

    private FakeSoccerServer server;
    private LogProxy proxy;
    private final List<PlayerClient> clients = new ArrayList<>();
    private final List<String> events = new CopyOnWriteArrayList<>();

    @BeforeEach
    void startServer() throws IOException {
        // any player's sensing will do: a simulated game's, so the test needs no shared recordings
        server = FakeSoccerServer.start(FakeSoccerServer.recordedSensing(SimulatedGame.log("Carleton", 1), 400));
    }

    @AfterEach
    void stopAll() throws IOException {
        for (PlayerClient client : clients) {
            client.close();
        }
        if (proxy != null) {
            proxy.close();
        }
        server.close();
    }

    private void startProxy(LogFormat format, Duration idle, Duration endGrace) throws IOException {
        startProxy(format, idle, endGrace, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES);
    }

    private void startProxy(LogFormat format, Duration idle, Duration endGrace, int logBuffer) throws IOException {
        startProxy(format, idle, endGrace, logBuffer, System::nanoTime);
    }

    private void startProxy(LogFormat format, Duration idle, Duration endGrace, int logBuffer, LongSupplier clock)
            throws IOException {
        List<Route> routes = List.of(
                new Route(ClientKind.PLAYER, 0, server.address(FakeSoccerServer.Port.PLAYER)),
                new Route(ClientKind.COACH, 0, server.address(FakeSoccerServer.Port.COACH)),
                new Route(ClientKind.ONLINE_COACH, 0, server.address(FakeSoccerServer.Port.ONLINE_COACH)));
        proxy = LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(), routes, out, format, idle, endGrace,
                logBuffer, ProxyConfig.DEFAULT_MAX_CLIENTS, events::add), ProxyEnvironment.system().withClock(clock));
    }

    private PlayerClient connect(ClientKind kind, String init) throws IOException {
        PlayerClient client = new PlayerClient(new InetSocketAddress(InetAddress.getLoopbackAddress(), proxy.listenPort(kind)));
        clients.add(client);
        client.init(init, WAIT);
        return client;
    }

    private static void awaitTrue(String what, java.util.function.BooleanSupplier condition) {
        long deadline = System.currentTimeMillis() + WAIT;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("timed out waiting for " + what);
            }
            PlayerClient.sleep(5);
        }
    }

    /** Waits until the condition holds, or WAIT has passed: for what may be lost and need not fail the test. */
    private static void awaitAtMost(java.util.function.BooleanSupplier condition) {
        long deadline = System.currentTimeMillis() + WAIT;
        while (!condition.getAsBoolean() && System.currentTimeMillis() <= deadline) {
            PlayerClient.sleep(5);
        }
    }

    /** Waits until server and clients have received everything the other side sent. */
    private void awaitDelivery() {
        List<FakeSoccerServer.Client> known = server.clients();
        for (int i = 0; i < clients.size(); i++) {
            PlayerClient client = clients.get(i);
            FakeSoccerServer.Client seen = known.get(i);
            awaitTrue("delivery to and from " + seen, () -> seen.received().size() == client.sent().size()
                    && client.received().size() == seen.sent().size());
        }
    }

    private List<Path> logFiles() throws IOException {
        try (Stream<Path> files = Files.list(out)) {
            return files.sorted().toList();
        }
    }

    @Test
    void severalClientsAtOnceAreForwardedAndLoggedMessageByMessage() throws Exception {
        startProxy(LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofSeconds(60));
        String[] teams = {"Carleton", "University"};
        for (int i = 0; i < 8; i++) {
            connect(ClientKind.PLAYER, "(init " + teams[i % 2] + " (version 9))\0");
        }
        Random random = new Random(6);
        List<Thread> players = new ArrayList<>();
        for (PlayerClient client : clients) {
            // Each client sends commands from its own thread while the server replays sensing to all.
            long seed = random.nextLong();
            Thread thread = new Thread(() -> {
                Random commands = new Random(seed);
                try {
                    for (int cycle = 0; cycle < 30; cycle++) {
                        client.send(commands.nextBoolean() ? "(dash " + commands.nextInt(100) + ")"
                                : "(turn " + (commands.nextInt(360) - 180) + ")");
                        PlayerClient.sleep(1);
                    }
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            });
            players.add(thread);
            thread.start();
        }
        for (int cycle = 0; cycle < 30; cycle++) {
            server.replay(2);
            PlayerClient.sleep(1);
        }
        for (Thread thread : players) {
            thread.join();
        }
        awaitDelivery();
        proxy.close();

        assertTrue(server.strayOnInitPorts().isEmpty(), "the proxy kept sending to the init port");
        Set<InetSocketAddress> addresses = new HashSet<>();
        for (int i = 0; i < clients.size(); i++) {
            PlayerClient client = clients.get(i);
            FakeSoccerServer.Client seen = server.clients().get(i);
            addresses.add(seen.address);
            assertSameDatagrams(client.sent(), seen.received(), "forwarded to the server unchanged");
            assertSameDatagrams(seen.sent(), client.received(), "forwarded to the client unchanged");

            ProxyLogs log = ProxyLogs.read(out.resolve(seen.team + "_" + seen.unum + ".log"));
            assertSameDatagrams(unpadded(client.sent()), log.messages(Direction.CLIENT_TO_SERVER), "logged c2s");
            assertSameDatagrams(unpadded(seen.sent()), log.messages(Direction.SERVER_TO_CLIENT), "logged s2c");
            log.assertTimesNeverGoBack();
            assertTrue(log.comments().contains("# team " + seen.team + " unum " + seen.unum + " side " + seen.side),
                    log.comments().toString());
            assertEquals("# end proxy stopped", log.lastComment());
        }
        assertEquals(clients.size(), addresses.size(), "the server must see one address per client");
        assertEquals(clients.size(), logFiles().size(), "one complete log per client, no temporary left: " + logFiles());
        assertEquals(0, proxy.stats().notForwarded());
        assertEquals(clients.size(), proxy.stats().sessionsClosed());
    }

    @Test
    void lsfLogsHoldOneMessagePerLineInArrivalOrder() throws Exception {
        startProxy(LogFormat.LSF, Duration.ofSeconds(60), Duration.ofSeconds(60));
        PlayerClient client = connect(ClientKind.PLAYER, "(init Carleton (version 9))\0");
        FakeSoccerServer.Client seen = server.clients().get(0);
        List<String> expected = new ArrayList<>(List.of("(init Carleton (version 9))", "(init l 1 before_kick_off)"));
        for (int cycle = 0; cycle < 5; cycle++) {
            server.replay(2);
            int count = seen.sent().size();
            client.awaitReceived(count, WAIT);
            expected.add(new String(unpadded(seen.sent().get(count - 2)), StandardCharsets.UTF_8));
            expected.add(new String(unpadded(seen.sent().get(count - 1)), StandardCharsets.UTF_8));
            client.send("(dash " + cycle + ")");
            expected.add("(dash " + cycle + ")");
            awaitTrue("dash at the server", () -> seen.received().size() == client.sent().size());
        }
        proxy.close();
        assertEquals(expected, Files.readAllLines(out.resolve("Carleton_1.lsf"), StandardCharsets.UTF_8));
    }

    @Test
    void badDatagramsAreForwardedUnchangedAndLoggedEscaped() throws Exception {
        startProxy(LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofSeconds(60));
        PlayerClient client = connect(ClientKind.PLAYER, "(init Carleton (version 9))");
        FakeSoccerServer.Client seen = server.clients().get(0);
        byte[] large = new byte[9000];
        new Random(9000).nextBytes(large);
        List<byte[]> bad = List.of(new byte[0], large, new byte[] {'(', 's', 'a', 'y', ' ', (byte) 0xFF, (byte) 0xFE, ')'},
                "(say \"two\nlines\\\r\t\")".getBytes(StandardCharsets.UTF_8), new byte[] {0, 0, 0},
                new byte[] {'(', 0, 'x', 0, 0});
        for (byte[] datagram : bad) {
            client.send(datagram);
            seen.send(datagram);
        }
        awaitDelivery();
        proxy.close();

        assertSameDatagrams(client.sent(), seen.received(), "bad datagrams reach the server byte for byte");
        assertSameDatagrams(seen.sent(), client.received(), "bad datagrams reach the client byte for byte");
        Path file = out.resolve("Carleton_1.log");
        ProxyLogs log = ProxyLogs.read(file);
        assertSameDatagrams(unpadded(client.sent()), log.messages(Direction.CLIENT_TO_SERVER), "logged c2s");
        assertSameDatagrams(unpadded(seen.sent()), log.messages(Direction.SERVER_TO_CLIENT), "logged s2c");
        String text = Files.readString(file, StandardCharsets.UTF_8);
        assertTrue(text.contains(" c2s (say \\xFF\\xFE)\n"), text);
        assertTrue(text.contains(" c2s (say \"two\\nlines\\\\\\r\\t\")\n"));
        assertTrue(text.contains(" c2s (\\0x\n"));
    }

    @Test
    void closingWhileTrafficFlowsLosesNothingThatWasForwarded() throws Exception {
        startProxy(LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofSeconds(60));
        for (int i = 0; i < 4; i++) {
            connect(ClientKind.PLAYER, "(init Carleton (version 9))\0");
        }
        List<Thread> senders = new ArrayList<>();
        for (PlayerClient client : clients) {
            Thread thread = new Thread(() -> {
                try {
                    for (int i = 0; i < 3000; i++) {
                        client.send("(turn " + i + ")");
                        if (i % 50 == 0) {
                            PlayerClient.sleep(1);
                        }
                    }
                } catch (IOException e) {
                    // the test closes everything at some point; that is the point
                }
            });
            senders.add(thread);
            thread.start();
        }
        // every client's traffic under way, not only the first's: the checks below need some from each
        awaitTrue("traffic under way", () -> server.clients().size() == clients.size()
                && server.clients().stream().allMatch(seen -> seen.received().size() > 200));
        proxy.close(); // what the shutdown hook does on SIGINT/SIGTERM
        for (Thread thread : senders) {
            thread.join();
        }
        // what the proxy forwarded before it closed may still be on its way to the server: wait for it (at most
        // WAIT, since UDP may drop a datagram under this load; the checks below hold for what did arrive)
        long forwardedByProxy = proxy.stats().toServer();
        awaitAtMost(() -> server.clients().stream().mapToLong(seen -> seen.received().size()).sum() >= forwardedByProxy);

        for (FakeSoccerServer.Client seen : server.clients()) {
            ProxyLogs log = ProxyLogs.read(out.resolve("Carleton_" + seen.unum + ".log"));
            List<byte[]> logged = log.messages(Direction.CLIENT_TO_SERVER);
            List<byte[]> forwarded = unpadded(seen.received());
            assertTrue(forwarded.size() > 1);
            assertTrue(ProxyLogs.isSubsequence(forwarded, logged),
                    "every datagram the server received is in the log: " + forwarded.size() + " vs " + logged.size());
            assertEquals("# end proxy stopped", log.lastComment());
        }
        assertEquals(4, logFiles().size(), logFiles().toString());
    }

    @Test
    void theSmallestLogBufferStillLogsEverything() throws Exception {
        int buffer = 1 << 18;
        startProxy(LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofSeconds(60), buffer);
        for (int i = 0; i < 3; i++) {
            connect(ClientKind.PLAYER, "(init University (version 9))\0");
        }
        Random random = new Random(18);
        for (int round = 0; round < 100; round++) {
            for (int i = 0; i < clients.size(); i++) {
                byte[] datagram = new byte[4000 + random.nextInt(4000)];
                random.nextBytes(datagram);
                clients.get(i).send(datagram);
                server.clients().get(i).send(datagram);
            }
            PlayerClient.sleep(2); // gentle enough for default socket buffers: UDP drops would stall the test
        }
        awaitDelivery();
        proxy.close();
        for (int i = 0; i < clients.size(); i++) {
            FakeSoccerServer.Client seen = server.clients().get(i);
            ProxyLogs log = ProxyLogs.read(out.resolve("University_" + seen.unum + ".log"));
            assertSameDatagrams(unpadded(clients.get(i).sent()), log.messages(Direction.CLIENT_TO_SERVER), "logged c2s");
            assertSameDatagrams(unpadded(seen.sent()), log.messages(Direction.SERVER_TO_CLIENT), "logged s2c");
        }
        assertTrue(proxy.stats().logBufferHighWater() <= buffer, "memory between forwarding and writing stays bounded");
    }

    /**
     * The proxy's clock is the test's: the idle timeout elapses exactly when the test advances it,
     * never between two of a client's sends because the machine is loaded (this test flaked once
     * with the real clock). A second client, silent from the start, shows when a check has run.
     */
    @Test
    void aVanishedClientIsClosedAfterTheIdleTimeoutWithItsLogComplete() throws Exception {
        ManualClock clock = new ManualClock();
        Duration idle = Duration.ofMillis(1500);
        startProxy(LogFormat.NATIVE, idle, Duration.ofSeconds(60), ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, clock);
        PlayerClient client = connect(ClientKind.PLAYER, "(init University (version 9))\0");
        connect(ClientKind.PLAYER, "(init Carleton (version 9))\0");
        FakeSoccerServer.Client seen = server.clients().get(0);
        for (int i = 0; i < 5; i++) {
            client.send("(dash 100)");
            server.replay(1);
        }
        awaitDelivery();
        // The proxy looks for silent clients at most every 250 ms of its clock, so steps are larger.
        clock.advance(Duration.ofMillis(1000));
        client.send("(turn 10)"); // the client talks in time
        awaitTrue("the turn at the server", () -> seen.received().size() == client.sent().size());
        clock.advance(Duration.ofMillis(501)); // the witness has been silent 1501 ms, the client 501 ms
        Path witness = out.resolve("Carleton_1.log");
        awaitTrue("the silent witness closed", () -> Files.exists(witness));
        assertFalse(Files.exists(out.resolve("University_1.log")), "a client that talked within the timeout stays open");
        assertTrue(ProxyLogs.read(witness).lastComment().startsWith("# end client silent"));

        client.close(); // vanishes; the server goes on sending
        List<byte[]> sentBeforeTimeout = seen.sent();
        clock.advance(idle);
        Path file = out.resolve("University_1.log");
        awaitTrue("the log of the silent client", () -> Files.exists(file));
        server.replay(3); // after the timeout: nobody is listening for this client any more

        ProxyLogs log = ProxyLogs.read(file);
        assertTrue(log.lastComment().startsWith("# end client silent"), log.lastComment());
        assertSameDatagrams(unpadded(client.sent()), log.messages(Direction.CLIENT_TO_SERVER), "logged c2s");
        assertSameDatagrams(unpadded(sentBeforeTimeout), log.messages(Direction.SERVER_TO_CLIENT), "logged s2c");
        // the writer counts a log after renaming it, so the count may trail the file by a moment
        awaitTrue("both sessions counted", () -> proxy.stats().sessionsClosed() == 2);
    }

    @Test
    void aClientIsClosedShortlyAfterTimeOver() throws Exception {
        startProxy(LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofMillis(300));
        PlayerClient client = connect(ClientKind.PLAYER, "(init Carleton (version 9))\0");
        FakeSoccerServer.Client seen = server.clients().get(0);
        client.send("(move -10 0)");
        seen.send("(hear 6000 referee time_over)\0".getBytes(StandardCharsets.UTF_8));
        awaitDelivery();
        Path file = out.resolve("Carleton_1.log");
        awaitTrue("the log after time_over", () -> Files.exists(file));
        ProxyLogs log = ProxyLogs.read(file);
        assertEquals("# end game over", log.lastComment());
        assertEquals(2, log.messages(Direction.SERVER_TO_CLIENT).size());
    }

    @Test
    void coachesAreProxiedAndLogsNeverOverwriteExistingFiles() throws Exception {
        Files.writeString(out.resolve("Carleton_1.log"), "older recording\n");
        startProxy(LogFormat.NATIVE, Duration.ofSeconds(60), Duration.ofSeconds(60));
        PlayerClient player = connect(ClientKind.PLAYER, "(init Carleton (version 9))\0");
        PlayerClient trainer = connect(ClientKind.COACH, "(init (version 9))\0");
        PlayerClient coach = connect(ClientKind.ONLINE_COACH, "(init Carleton (version 9))\0");
        trainer.send("(change_mode play_on)");
        coach.send("(say (freeform \"go\"))");
        player.send("(kick 100 0)");
        awaitDelivery();
        assertEquals("(init ok)", new String(unpadded(trainer.received().get(0)), StandardCharsets.UTF_8));
        assertEquals("(init l ok)", new String(unpadded(coach.received().get(0)), StandardCharsets.UTF_8));
        proxy.close();

        assertEquals("older recording\n", Files.readString(out.resolve("Carleton_1.log")));
        assertSameDatagrams(unpadded(player.sent()),
                ProxyLogs.read(out.resolve("Carleton_1-1.log")).messages(Direction.CLIENT_TO_SERVER), "player");
        assertSameDatagrams(unpadded(trainer.sent()),
                ProxyLogs.read(out.resolve("trainer.log")).messages(Direction.CLIENT_TO_SERVER), "trainer");
        ProxyLogs coachLog = ProxyLogs.read(out.resolve("Carleton_coach.log"));
        assertSameDatagrams(unpadded(coach.sent()), coachLog.messages(Direction.CLIENT_TO_SERVER), "coach");
        assertTrue(coachLog.comments().contains("# team Carleton coach side l"), coachLog.comments().toString());
        assertFalse(server.strayOnInitPorts().size() > 0);
    }
}
