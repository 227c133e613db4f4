package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.scenes.fakeserver.ProxyLogs.assertSameDatagrams;
import static org.scenes.fakeserver.ProxyLogs.isSubsequence;
import static org.scenes.fakeserver.ProxyLogs.unpadded;

import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.proxylog.Direction;
import org.scenes.logproxy.ClientKind;
import org.scenes.internal.convert.LogFormat;
import org.scenes.logproxy.LogProxy;
import org.scenes.logproxy.ProxyConfig;
import org.scenes.logproxy.ProxyEnvironment;
import org.scenes.logproxy.Route;
import org.scenes.tests.SimulatedGame;

/**
 * The proxy under faults, with fakes on loopback: the server vanishes and comes back, a client
 * vanishes, bursts from every side, a datagram of the largest size, a disk that stalls or fails.
 * What must hold each time: every datagram forwarded is in its client's log, in order, and the
 * other clients go on being served. Waits are bounded; no sleep decides a result.
 */
class ProxyFaultsTest {
    private static final long WAIT = 20_000;
    /** The largest UDP payload over IPv4: 65,535 minus the IP and UDP headers. */
    private static final int MAX_DATAGRAM = 65_507;

    @TempDir
    Path out;

    private final List<FakeSoccerServer> servers = new ArrayList<>();
    private final List<PlayerClient> clients = new ArrayList<>();
    private final List<String> events = new CopyOnWriteArrayList<>();
    private LogProxy proxy;

    @AfterEach
    void stopAll() throws IOException {
        for (PlayerClient client : clients) {
            client.close();
        }
        try {
            if (proxy != null) {
                proxy.close();
            }
        } catch (IOException expected) {
            // the failing-disk test's proxy reports its errors on close, as it should
        }
        for (FakeSoccerServer server : servers) {
            server.close();
        }
    }

    private static List<String> sensing() throws IOException {
        return FakeSoccerServer.recordedSensing(SimulatedGame.log("Carleton", 1), 400);
    }

    private FakeSoccerServer server(int playerPort) throws IOException {
        FakeSoccerServer server = FakeSoccerServer.start(sensing(), playerPort);
        servers.add(server);
        return server;
    }

    /** A server on fixed ports (players, then the two coach ports), so it can come back on them. */
    private FakeSoccerServer serverOnFixedPorts() throws IOException {
        Random random = new Random();
        for (int attempt = 0; ; attempt++) {
            try {
                return server(20_000 + random.nextInt(40_000));
            } catch (BindException e) {
                if (attempt == 20) {
                    throw e;
                }
            }
        }
    }

    private void startProxy(FakeSoccerServer server, int logBuffer, ProxyEnvironment environment) throws IOException {
        proxy = LogProxy.start(new ProxyConfig(InetAddress.getLoopbackAddress(),
                List.of(new Route(ClientKind.PLAYER, 0, server.address(FakeSoccerServer.Port.PLAYER))), out,
                LogFormat.NATIVE, Duration.ofMillis(1500), Duration.ofSeconds(60), logBuffer,
                ProxyConfig.DEFAULT_MAX_CLIENTS, events::add), environment);
    }

    private PlayerClient connect(String team) throws IOException {
        PlayerClient client = new PlayerClient(new InetSocketAddress(InetAddress.getLoopbackAddress(),
                proxy.listenPort(ClientKind.PLAYER)));
        clients.add(client);
        client.init("(init " + team + " (version 9))", WAIT);
        return client;
    }

    private void awaitTrue(String what, BooleanSupplier condition) {
        long deadline = System.currentTimeMillis() + WAIT;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("timed out waiting for " + what + "; proxy events " + events);
            }
            PlayerClient.sleep(2);
        }
    }

    private void awaitDelivery(PlayerClient client, FakeSoccerServer.Client seen) {
        awaitTrue("delivery to and from " + seen, () -> seen.receivedCount() == client.sentCount()
                && client.receivedCount() == seen.sentCount());
    }

    /** One cycle: the server sends each client a see and a sense_body, each client answers with a dash. */
    private void playCycles(FakeSoccerServer server, List<PlayerClient> players, int cycles) throws IOException {
        for (int cycle = 0; cycle < cycles; cycle++) {
            server.replay(2);
            for (PlayerClient client : players) {
                client.send("(dash " + cycle + ")");
            }
        }
    }

    private ProxyLogs log(String name) throws IOException {
        return ProxyLogs.read(out.resolve(name + ".log"));
    }

    @Test
    void whenTheServerVanishesAndComesBackTheClientsInitAgainAndEverythingIsLogged() throws Exception {
        FakeSoccerServer first = serverOnFixedPorts();
        int port = first.address(FakeSoccerServer.Port.PLAYER).getPort();
        startProxy(first, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyEnvironment.system());
        List<PlayerClient> players = List.of(connect("University"), connect("Carleton"));
        playCycles(first, players, 5);
        for (int i = 0; i < players.size(); i++) {
            awaitDelivery(players.get(i), first.clients().get(i));
        }
        first.close();
        long forwarded = proxy.stats().toServer();
        for (int i = 0; i < 10; i++) {
            for (PlayerClient client : players) {
                client.send("(turn " + i + ")"); // into the void: nobody listens on the server's ports
            }
        }
        awaitTrue("the sends into the void forwarded", () -> proxy.stats().toServer() == forwarded + 20);

        FakeSoccerServer second = server(port);
        for (PlayerClient client : players) {
            int before = client.receivedCount();
            client.send("(init " + (client == players.get(0) ? "University" : "Carleton") + " (version 9))");
            awaitTrue("the new server's init answer", () -> client.receivedCount() == before + 1);
        }
        playCycles(second, players, 5);
        for (int i = 0; i < players.size(); i++) {
            PlayerClient client = players.get(i);
            FakeSoccerServer.Client before = first.clients().get(i);
            FakeSoccerServer.Client now = second.clients().get(i);
            awaitTrue("delivery to and from " + now, () -> now.receivedCount() == 6
                    && client.receivedCount() == before.sentCount() + now.sentCount());
        }
        proxy.close();

        assertTrue(second.strayOnInitPorts().isEmpty(), "after the restart the proxy must not talk to a dead port");
        String[] names = {"University_1", "Carleton_1"};
        for (int i = 0; i < players.size(); i++) {
            PlayerClient client = players.get(i);
            ProxyLogs log = log(names[i]);
            assertSameDatagrams(unpadded(client.sent()), log.messages(Direction.CLIENT_TO_SERVER), "every c2s logged");
            List<byte[]> fromServers = new ArrayList<>(first.clients().get(i).sent());
            fromServers.addAll(second.clients().get(i).sent());
            assertSameDatagrams(unpadded(fromServers), log.messages(Direction.SERVER_TO_CLIENT), "both servers' s2c");
            assertSameDatagrams(client.received(), fromServers, "the client heard both servers");
        }
        assertEquals(0, proxy.stats().notForwarded());
    }

    @Test
    void aClientThatVanishesIsLoggedToTheEndAndTheOthersAreStillServed() throws Exception {
        FakeSoccerServer server = server(0);
        ManualClock clock = new ManualClock();
        startProxy(server, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyEnvironment.system().withClock(clock));
        PlayerClient gone = connect("University");
        List<PlayerClient> staying = List.of(connect("Carleton"), connect("Carleton"));
        playCycles(server, clients, 3);
        for (int i = 0; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        gone.close();
        FakeSoccerServer.Client goneSeen = server.clients().get(0);
        // The server goes on sending to all three (as rcssserver does until the timeout).
        playCycles(server, staying, 20);
        for (int i = 1; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        awaitTrue("the vanished client's datagrams forwarded", () -> proxy.stats().toClients()
                == server.clients().stream().mapToLong(FakeSoccerServer.Client::sentCount).sum());
        clock.advance(Duration.ofMillis(1000));
        playCycles(server, staying, 1);
        for (int i = 1; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        List<byte[]> sentToGone = goneSeen.sent();
        clock.advance(Duration.ofMillis(600)); // the vanished client silent 1.6 s, the others 0.6 s
        awaitTrue("the vanished client's log", () -> Files.exists(out.resolve("University_1.log")));
        playCycles(server, staying, 5);
        for (int i = 1; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        proxy.close();

        ProxyLogs goneLog = log("University_1");
        assertTrue(goneLog.lastComment().startsWith("# end client silent"), goneLog.lastComment());
        assertSameDatagrams(unpadded(gone.sent()), goneLog.messages(Direction.CLIENT_TO_SERVER), "vanished c2s");
        assertSameDatagrams(unpadded(sentToGone), goneLog.messages(Direction.SERVER_TO_CLIENT),
                "everything forwarded to the vanished client is logged");
        for (int i = 0; i < staying.size(); i++) {
            ProxyLogs log = log("Carleton_" + (i + 1));
            assertEquals("# end proxy stopped", log.lastComment());
            assertSameDatagrams(unpadded(staying.get(i).sent()), log.messages(Direction.CLIENT_TO_SERVER), "c2s");
            assertSameDatagrams(unpadded(server.clients().get(i + 1).sent()), log.messages(Direction.SERVER_TO_CLIENT), "s2c");
        }
        assertTrue(events.stream().noneMatch(e -> e.contains("failed")), events.toString());
    }

    /**
     * Six clients and the server all send as fast as they can. The kernel may drop datagrams
     * (socket buffers are finite); the proxy must still log every datagram it received, in order,
     * before or after forwarding it, and serve everyone afterwards.
     */
    @Test
    void burstsFromEverySideAreLoggedAsReceivedAndEveryoneIsServedAfterwards() throws Exception {
        FakeSoccerServer server = server(0);
        startProxy(server, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyEnvironment.system());
        int count = 6;
        int burst = 3000;
        for (int i = 0; i < count; i++) {
            connect("Burst");
        }
        byte[] padding = "x".repeat(150).getBytes(StandardCharsets.US_ASCII);
        List<Thread> senders = new ArrayList<>();
        for (PlayerClient client : clients) {
            Thread thread = new Thread(() -> {
                try {
                    for (int n = 0; n < burst; n++) {
                        client.send("(say " + n + " " + new String(padding, StandardCharsets.US_ASCII) + ")");
                    }
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            });
            senders.add(thread);
            thread.start();
        }
        for (int n = 0; n < burst; n++) {
            for (FakeSoccerServer.Client seen : server.clients()) {
                seen.send(("(hear " + n + " referee " + new String(padding, StandardCharsets.US_ASCII) + ")\0")
                        .getBytes(StandardCharsets.US_ASCII));
            }
        }
        for (Thread thread : senders) {
            thread.join();
        }
        // A marker each way, repeated until it arrives: whatever the proxy got before it is then handled.
        for (int i = 0; i < count; i++) {
            PlayerClient client = clients.get(i);
            FakeSoccerServer.Client seen = server.clients().get(i);
            long deadline = System.currentTimeMillis() + WAIT;
            while (!lastIs(seen.received(), "(marker)") || !lastIs(client.received(), "(marker)")) {
                assertTrue(System.currentTimeMillis() < deadline, "markers never arrived: " + seen);
                client.send("(marker)");
                seen.send("(marker)\0".getBytes(StandardCharsets.US_ASCII));
                PlayerClient.sleep(20);
            }
        }
        playCycles(server, clients, 3); // everyone is served after the burst
        for (int i = 0; i < count; i++) {
            PlayerClient client = clients.get(i);
            FakeSoccerServer.Client seen = server.clients().get(i);
            awaitTrue("the last cycle's dash at the server", () -> lastIs(seen.received(), "(dash 2)"));
            awaitTrue("the last cycle's sensing at the client", () -> client.receivedCount() >= 6
                    && lastIsSameAs(client.received(), seen.sent()));
        }
        proxy.close();

        long logged = 0;
        for (int i = 0; i < count; i++) {
            PlayerClient client = clients.get(i);
            FakeSoccerServer.Client seen = server.clients().get(i);
            ProxyLogs log = log("Burst_" + seen.unum);
            List<byte[]> c2s = log.messages(Direction.CLIENT_TO_SERVER);
            List<byte[]> s2c = log.messages(Direction.SERVER_TO_CLIENT);
            assertTrue(isSubsequence(c2s, unpadded(client.sent())), "c2s logged in order, nothing invented");
            assertTrue(isSubsequence(unpadded(seen.received()), c2s), "every datagram the server got is logged");
            assertTrue(isSubsequence(s2c, unpadded(seen.sent())), "s2c logged in order, nothing invented");
            assertTrue(isSubsequence(unpadded(client.received()), s2c), "every datagram the client got is logged");
            logged += c2s.size() + s2c.size();
        }
        var stats = proxy.stats();
        assertEquals(logged, stats.logged());
        assertEquals(logged, stats.toServer() + stats.toClients() + stats.notForwarded(),
                "each datagram received was forwarded or counted as not forwarded");
    }

    private static boolean lastIs(List<byte[]> datagrams, String text) {
        return !datagrams.isEmpty() && new String(unpadded(datagrams.get(datagrams.size() - 1)),
                StandardCharsets.US_ASCII).equals(text);
    }

    private static boolean lastIsSameAs(List<byte[]> received, List<byte[]> sent) {
        return !received.isEmpty() && java.util.Arrays.equals(received.get(received.size() - 1), sent.get(sent.size() - 1));
    }

    @Test
    void aDatagramOfTheLargestSizeGoesBothWaysAndIsLoggedWhole() throws Exception {
        FakeSoccerServer server = server(0);
        startProxy(server, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyEnvironment.system());
        PlayerClient client = connect("Carleton");
        FakeSoccerServer.Client seen = server.clients().get(0);
        Random random = new Random(65_507);
        for (int i = 0; i < 3; i++) {
            byte[] largest = new byte[MAX_DATAGRAM];
            random.nextBytes(largest);
            largest[largest.length - 1] = ')'; // no trailing NUL, which the log leaves out as padding
            client.send(largest);
            seen.send(largest);
        }
        awaitDelivery(client, seen);
        proxy.close();

        assertSameDatagrams(client.sent(), seen.received(), "forwarded whole to the server");
        assertSameDatagrams(seen.sent(), client.received(), "forwarded whole to the client");
        ProxyLogs log = log("Carleton_1");
        assertSameDatagrams(unpadded(client.sent()), log.messages(Direction.CLIENT_TO_SERVER), "logged c2s");
        assertSameDatagrams(unpadded(seen.sent()), log.messages(Direction.SERVER_TO_CLIENT), "logged s2c");
    }

    /** Log files whose writes block while the disk is stalled, or fail once it is dead. */
    private static final class SickDisk implements ProxyEnvironment.LogFiles {
        private final CountDownLatch resumed = new CountDownLatch(1);
        private final AtomicInteger blocked = new AtomicInteger();
        private volatile boolean stalled;
        private volatile boolean dead;

        @Override
        public OutputStream create(Path file) throws IOException {
            return new FilterOutputStream(Files.newOutputStream(file)) {
                @Override
                public void write(byte[] bytes, int offset, int length) throws IOException {
                    sicken();
                    out.write(bytes, offset, length);
                }

                @Override
                public void write(int b) throws IOException {
                    sicken();
                    out.write(b);
                }

                @Override
                public void flush() throws IOException {
                    sicken();
                    out.flush();
                }
            };
        }

        private void sicken() throws IOException {
            if (dead) {
                throw new IOException("No space left on device");
            }
            if (stalled) {
                blocked.incrementAndGet();
                try {
                    resumed.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }

        void resume() {
            stalled = false;
            resumed.countDown();
        }
    }

    @Test
    void whileTheDiskStallsEveryoneIsServedAndAfterwardsEverythingIsLogged() throws Exception {
        FakeSoccerServer server = server(0);
        SickDisk disk = new SickDisk();
        startProxy(server, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyEnvironment.system().withLogFiles(disk));
        for (int i = 0; i < 3; i++) {
            connect("University");
        }
        disk.stalled = true;
        // The writer flushes twice a second: play until it is stuck in the disk.
        for (int round = 0; disk.blocked.get() == 0; round++) {
            assertTrue(round < WAIT / 5, "the log writer never touched the disk");
            playCycles(server, clients, 1);
            PlayerClient.sleep(5);
        }
        long loggedWhenStuck = proxy.stats().logged();
        playCycles(server, clients, 100);
        for (int i = 0; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        assertEquals(loggedWhenStuck, proxy.stats().logged(), "the writer was stuck all along");
        assertEquals(1, disk.blocked.get());
        disk.resume();
        proxy.close();

        for (int i = 0; i < clients.size(); i++) {
            ProxyLogs log = log("University_" + (i + 1));
            assertSameDatagrams(unpadded(clients.get(i).sent()), log.messages(Direction.CLIENT_TO_SERVER), "c2s");
            assertSameDatagrams(unpadded(server.clients().get(i).sent()), log.messages(Direction.SERVER_TO_CLIENT), "s2c");
        }
        assertEquals(0, proxy.stats().logBufferWaits());
    }

    /**
     * A stall longer than the log buffer holds: forwarding waits for the disk rather than forward
     * what it could not log (the ring's documented choice), and resumes when the disk does.
     */
    @Test
    void aStallLongerThanTheLogBufferPausesForwardingAndNothingForwardedIsUnlogged() throws Exception {
        FakeSoccerServer server = server(0);
        SickDisk disk = new SickDisk();
        startProxy(server, 1 << 18, ProxyEnvironment.system().withLogFiles(disk));
        PlayerClient client = connect("University");
        FakeSoccerServer.Client seen = server.clients().get(0);
        disk.stalled = true;
        byte[] large = new byte[8000];
        new Random(8000).nextBytes(large);
        large[large.length - 1] = ')';
        for (int n = 0; proxy.stats().logBufferWaits() == 0; n++) {
            assertTrue(n < 2000, "the log buffer never filled");
            client.send(large);
            PlayerClient.sleep(1);
        }
        int forwardedWhileStalled = seen.receivedCount();
        disk.resume();
        long deadline = System.currentTimeMillis() + WAIT;
        while (!lastIs(seen.received(), "(marker)")) {
            assertTrue(System.currentTimeMillis() < deadline, "forwarding never resumed");
            client.send("(marker)");
            PlayerClient.sleep(20);
        }
        proxy.close();

        List<byte[]> c2s = log("University_1").messages(Direction.CLIENT_TO_SERVER);
        assertTrue(isSubsequence(c2s, unpadded(client.sent())), "logged in order, nothing invented");
        assertSameDatagrams(unpadded(seen.received()), c2s, "everything forwarded is logged, and only that");
        assertTrue(forwardedWhileStalled * 8000L > (1 << 17), "the stall held a buffer's worth: " + forwardedWhileStalled);
        assertTrue(proxy.stats().logBufferHighWater() <= 1 << 18);
    }

    @Test
    void aDeadDiskIsReportedOnCloseAndTheGameGoesOn() throws Exception {
        FakeSoccerServer server = server(0);
        SickDisk disk = new SickDisk();
        startProxy(server, ProxyConfig.DEFAULT_LOG_BUFFER_BYTES, ProxyEnvironment.system().withLogFiles(disk));
        connect("Carleton");
        connect("Carleton");
        disk.dead = true;
        playCycles(server, clients, 30);
        for (int i = 0; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        awaitTrue("the writer met the dead disk", () -> proxy.stats().logErrors() > 0);
        playCycles(server, clients, 30);
        for (int i = 0; i < clients.size(); i++) {
            awaitDelivery(clients.get(i), server.clients().get(i));
        }
        IOException error = assertThrows(IOException.class, proxy::close);
        assertTrue(error.getMessage().contains("No space left on device"), error.getMessage());
        assertTrue(events.stream().anyMatch(e -> e.startsWith("log error for client player 127.0.0.1:")), events.toString());
        assertFalse(Files.exists(out.resolve("Carleton_1.log")), "no log is passed off as complete");
    }
}
