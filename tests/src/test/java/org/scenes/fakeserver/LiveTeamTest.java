package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.DatagramChannel;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.PlayerReport.Outcome;
import org.scenes.agent.net.ServerAddress;
import org.scenes.agent.net.TeamRunner;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;

/** The client runtime against the fake server on loopback: init, port switch, synchronous play, failures. */
class LiveTeamTest {
    private final List<String> notices = Collections.synchronizedList(new ArrayList<>());
    private final ExecutorService executor = Executors.newCachedThreadPool();

    @AfterEach
    void shutDown() {
        executor.shutdownNow();
    }

    /** Dashes on every see; remembers nothing. */
    static final BrainFactory DASHER = (team, random) -> new Brain() {
        @Override
        public void receive(String message, Consumer<String> send) {
            if (message.startsWith("(see ")) {
                send.accept("(dash 50)");
            }
        }
    };

    static ClientOptions options(InetSocketAddress server, String team) {
        return ClientOptions.of(new ServerAddress("127.0.0.1", server.getPort()), team)
                .withTimeouts(Duration.ofMillis(700), Duration.ofMillis(700));
    }

    private Future<List<PlayerReport>> start(TeamRunner runner) {
        return executor.submit(runner::play);
    }

    private static void send(FakeSoccerServer.Client client, String message) throws IOException {
        client.send((message + '\0').getBytes(StandardCharsets.UTF_8));
    }

    /** Every datagram the server got from a client, as text without the trailing NUL. */
    private static List<String> received(FakeSoccerServer.Client client) {
        List<String> texts = new ArrayList<>();
        for (byte[] datagram : client.received()) {
            assertEquals(0, datagram[datagram.length - 1], "NUL-terminated: " + new String(datagram, StandardCharsets.UTF_8));
            texts.add(new String(datagram, 0, datagram.length - 1, StandardCharsets.UTF_8));
        }
        return texts;
    }

    private static void awaitClients(FakeSoccerServer server, int count) throws InterruptedException {
        for (int i = 0; i < 200 && server.clients().size() < count; i++) {
            Thread.sleep(10);
        }
        assertEquals(count, server.clients().size(), "clients connected");
    }

    /** A team of one player with the brain, playing on the server, and the server's side of that player. */
    private record OnePlayer(Future<List<PlayerReport>> reports, FakeSoccerServer.Client client) {
    }

    private OnePlayer onePlayer(FakeSoccerServer server, String team, BrainFactory brain) throws InterruptedException {
        Future<List<PlayerReport>> reports = start(new TeamRunner(options(server.address(FakeSoccerServer.Port.PLAYER),
                team), 1, brain, 1, notices::add));
        awaitClients(server, 1);
        return new OnePlayer(reports, server.clients().get(0));
    }

    private static void awaitReceived(FakeSoccerServer.Client client, int count) throws InterruptedException {
        for (int i = 0; i < 300 && client.receivedCount() < count; i++) {
            Thread.sleep(10);
        }
        assertTrue(client.receivedCount() >= count, "expected " + count + " datagrams from " + client);
    }

    @Test
    void playsASynchronousGameOnTheClientsOwnPortAndSaysByeAtTimeOver() throws Exception {
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            TeamRunner runner = new TeamRunner(options(server.address(FakeSoccerServer.Port.PLAYER), "Live")
                    .withGoalie(true), 2, DASHER, 1, notices::add);
            Future<List<PlayerReport>> reports = start(runner);
            awaitClients(server, 2);
            for (int cycle = 1; cycle <= 5; cycle++) {
                for (FakeSoccerServer.Client client : server.clients()) {
                    int before = client.receivedCount();
                    send(client, "(sense_body " + cycle + " (view_mode high normal) (stamina 8000 1 130600))");
                    send(client, "(see " + cycle + " ((b) 10 0) ((g r) 50 3))");
                    send(client, "(think)");
                    awaitReceived(client, before + 2);
                }
            }
            for (FakeSoccerServer.Client client : server.clients()) {
                send(client, "(hear 6 referee time_over)");
            }
            List<PlayerReport> result = reports.get(10, TimeUnit.SECONDS);
            assertEquals(2, result.size());
            assertEquals(0, TeamRunner.exitCode(result), result.toString());
            assertTrue(server.strayOnInitPorts().isEmpty(), "nothing after the init went to the init port");
            FakeSoccerServer.Client first = server.clients().get(0);
            // init, a move, 5 x (dash, done), bye: the server may still be reading the last ones
            awaitReceived(first, 13);
            List<String> sent = received(first);
            assertEquals("(init Live (version 9)(goalie))", sent.get(0));
            assertEquals("(init Live (version 9))", received(server.clients().get(1)).get(0));
            // a formation move at the first cycle (the brain never moves), then per cycle: the see's dash, then done
            assertEquals("(move -50 0)", sent.get(1));
            for (int cycle = 0; cycle < 5; cycle++) {
                int at = 2 + 2 * cycle;
                assertEquals("(dash 50)", sent.get(at), sent.toString());
                assertEquals("(done)", sent.get(at + 1), sent.toString());
            }
            assertEquals("(bye)", sent.get(sent.size() - 1));
            PlayerReport report = result.get(0);
            assertEquals(Outcome.GAME_OVER, report.outcome());
            assertEquals(1, report.unum());
            assertEquals("l", report.side());
            assertEquals(5, report.cycles());
            assertEquals(5, report.due());
            assertEquals(0, report.missed());
            assertEquals(5, report.decisions());
            assertEquals(5, report.thinks());
            assertTrue(report.decisionP99Millis() >= 0 && report.decisionP99Millis() <= report.decisionMaxMillis());
        }
    }

    @Test
    void noServerIsOneClearLineAfterTheTimeout() throws Exception {
        int port;
        try (DatagramChannel probe = DatagramChannel.open()) {
            probe.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            port = ((InetSocketAddress) probe.getLocalAddress()).getPort();
        }
        TeamRunner runner = new TeamRunner(options(new InetSocketAddress("127.0.0.1", port), "Alone"), 3, DASHER, 1,
                notices::add);
        List<PlayerReport> result = start(runner).get(10, TimeUnit.SECONDS);
        assertEquals(1, result.size(), "no further player is started once the first found no server");
        assertEquals(Outcome.NO_SERVER, result.get(0).outcome());
        assertEquals(1, TeamRunner.exitCode(result));
        assertEquals(1, notices.size(), notices.toString());
        assertTrue(notices.get(0).contains("no answer from a soccer server at 127.0.0.1:" + port), notices.get(0));
    }

    @Test
    void aRefusedInitSaysWhatTheServerAnswered() throws Exception {
        {
            // a server that answers the init with an error, as rcssserver does when the team is full
            try (DatagramChannel refusing = DatagramChannel.open()) {
                refusing.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
                Future<?> answer = executor.submit(() -> {
                    java.nio.ByteBuffer buffer = java.nio.ByteBuffer.allocate(4096);
                    java.net.SocketAddress from = refusing.receive(buffer);
                    refusing.send(java.nio.ByteBuffer.wrap("(error no_more_team_or_player_or_goalie)\0"
                            .getBytes(StandardCharsets.UTF_8)), from);
                    return null;
                });
                TeamRunner runner = new TeamRunner(options((InetSocketAddress) refusing.getLocalAddress(), "Late"), 1,
                        DASHER, 1, notices::add);
                List<PlayerReport> result = start(runner).get(10, TimeUnit.SECONDS);
                answer.get(5, TimeUnit.SECONDS);
                assertEquals(Outcome.NO_SERVER, result.get(0).outcome());
                assertTrue(result.get(0).reason().contains("(error no_more_team_or_player_or_goalie)"),
                        result.get(0).reason());
            }
        }
    }

    @Test
    void aServerThatVanishesMidGameEndsThePlayersAfterTheTimeout() throws Exception {
        TeamRunner runner;
        Future<List<PlayerReport>> reports;
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            runner = new TeamRunner(options(server.address(FakeSoccerServer.Port.PLAYER), "Orphan"), 2, DASHER, 1,
                    notices::add);
            reports = start(runner);
            awaitClients(server, 2);
            for (FakeSoccerServer.Client client : server.clients()) {
                send(client, "(sense_body 1 (view_mode high normal))");
                send(client, "(see 1 ((b) 10 0))");
                awaitReceived(client, 3);
            }
        }
        List<PlayerReport> result = reports.get(10, TimeUnit.SECONDS);
        assertEquals(2, result.size());
        for (PlayerReport report : result) {
            assertEquals(Outcome.SERVER_LOST, report.outcome(), report.toString());
            assertEquals(1, report.cycles());
        }
        assertEquals(1, TeamRunner.exitCode(result));
    }

    @Test
    void garbageIsCountedLoggedOnceAndSkipped() throws Exception {
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            OnePlayer one = onePlayer(server, "Sturdy", DASHER);
            Future<List<PlayerReport>> reports = one.reports();
            FakeSoccerServer.Client client = one.client();
            send(client, "(see 1 ((b) 10 0)");
            send(client, "(see abc)");
            send(client, "garbage");
            client.send(new byte[] {0, 0, 0});
            send(client, "(see 2 ((b) 10 0)))");
            send(client, "(error unknown_command)");
            send(client, "(error unknown_command)");
            send(client, "(error illegal_command_form)");
            // padded to 4096 bytes with NULs, as Krislet pads
            byte[] padded = new byte[4096];
            byte[] see = "(see 3 ((b) 10 0))".getBytes(StandardCharsets.UTF_8);
            System.arraycopy(see, 0, padded, 0, see.length);
            client.send(padded);
            send(client, "(hear 4 referee time_over)");
            PlayerReport report = reports.get(10, TimeUnit.SECONDS).get(0);
            assertEquals(Outcome.GAME_OVER, report.outcome());
            assertEquals(3L, report.malformed().get("see"), report.malformed().toString());
            assertEquals(1L, report.malformed().get("unbracketed"));
            assertEquals(1L, report.malformed().get("empty"));
            assertEquals(5, report.malformed().values().stream().mapToLong(Long::longValue).sum(),
                    report.malformed().toString());
            assertEquals(2L, report.errors().get("unknown_command"));
            assertEquals(1L, report.errors().get("illegal_command_form"));
            // one notice per kind: see, unbracketed, empty... and the last (see ...))) is a see too
            assertEquals(3, notices.size(), notices.toString());
            awaitReceived(client, 3);
            List<String> sent = received(client);
            assertEquals(1, sent.stream().filter("(dash 50)"::equals).count(), "only the padded see was acted on: " + sent);
        }
    }

    @Test
    void aServerThatSendsOnlyGarbageEndsThePlayerWithAClearReason() throws Exception {
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            OnePlayer one = onePlayer(server, "Puzzled", DASHER);
            Future<List<PlayerReport>> reports = one.reports();
            FakeSoccerServer.Client client = one.client();
            // garbage every 20 ms, never silent: without a parseable message the player must still end
            for (int i = 0; i < 500 && !reports.isDone(); i++) {
                send(client, "(see " + i + " ((b) 10 0)");
                Thread.sleep(20);
            }
            PlayerReport report = reports.get(10, TimeUnit.SECONDS).get(0);
            assertEquals(Outcome.SERVER_LOST, report.outcome(), report.toString());
            assertTrue(report.reason().contains("no message from the server could be parsed for 0.7 s"), report.reason());
            assertTrue(report.malformed().get("see") > 10, report.malformed().toString());
            assertEquals(1, TeamRunner.exitCode(List.of(report)));
        }
    }

    @Test
    void aFloodFromAnotherPortDoesNotHideThatTheServerIsGone() throws Exception {
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of());
                DatagramChannel flood = DatagramChannel.open()) {
            OnePlayer one = onePlayer(server, "Flooded", DASHER);
            Future<List<PlayerReport>> reports = one.reports();
            InetSocketAddress player = one.client().address;
            flood.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            java.nio.ByteBuffer junk = java.nio.ByteBuffer.wrap("(see 1 ((b) 10 0))\0".getBytes(StandardCharsets.UTF_8));
            // bounded: at most 5 million datagrams, or until the player gives up
            for (int i = 0; i < 5_000_000 && !reports.isDone(); i++) {
                flood.send(junk.rewind(), player);
            }
            PlayerReport report = reports.get(10, TimeUnit.SECONDS).get(0);
            assertEquals(Outcome.SERVER_LOST, report.outcome(), report.toString());
            assertTrue(report.reason().contains("the server is gone"), report.reason());
        }
    }

    @Test
    void stopSaysByeAndEndsCleanly() throws Exception {
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            TeamRunner runner = new TeamRunner(options(server.address(FakeSoccerServer.Port.PLAYER), "Polite")
                    .withTimeouts(Duration.ofSeconds(2), Duration.ofSeconds(30)), 3, DASHER, 1, notices::add);
            Future<List<PlayerReport>> reports = start(runner);
            awaitClients(server, 3);
            runner.stopAndAwait();
            List<PlayerReport> result = reports.get(10, TimeUnit.SECONDS);
            assertEquals(0, TeamRunner.exitCode(result), result.toString());
            for (FakeSoccerServer.Client client : server.clients()) {
                awaitReceived(client, 2);
                List<String> sent = received(client);
                assertEquals("(bye)", sent.get(sent.size() - 1));
            }
        }
    }

    @Test
    void aPlayerWhoseBrainThrowsIsReportedAndTheOthersPlayOn() throws Exception {
        BrainFactory thirdFails = new BrainFactory() {
            int made;

            @Override
            public Brain create(String team, java.util.Random random) {
                boolean faulty = ++made == 2;
                Brain dasher = DASHER.create(team, random);
                return (message, send) -> {
                    if (faulty && message.startsWith("(see ")) {
                        throw new IllegalStateException("brain broke");
                    }
                    dasher.receive(message, send);
                };
            }
        };
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            TeamRunner runner = new TeamRunner(options(server.address(FakeSoccerServer.Port.PLAYER), "Mixed"), 2,
                    thirdFails, 1, notices::add);
            Future<List<PlayerReport>> reports = start(runner);
            awaitClients(server, 2);
            for (FakeSoccerServer.Client client : server.clients()) {
                send(client, "(see 1 ((b) 10 0))");
            }
            FakeSoccerServer.Client healthy = server.clients().get(0);
            awaitReceived(healthy, 2);
            send(healthy, "(see 2 ((b) 10 0))");
            send(healthy, "(hear 3 referee time_over)");
            List<PlayerReport> result = reports.get(10, TimeUnit.SECONDS);
            assertEquals(Outcome.GAME_OVER, result.get(0).outcome());
            assertEquals(Outcome.FAILED, result.get(1).outcome());
            assertTrue(result.get(1).reason().contains("brain broke"), result.get(1).reason());
            assertTrue(notices.stream().anyMatch(n -> n.contains("player 2") && n.contains("brain broke")), notices.toString());
            assertEquals(1, TeamRunner.exitCode(result));
            assertFalse(received(healthy).isEmpty());
        }
    }

    /**
     * The brain is held in its decision on the see of cycle 5 while the test sends {@code next};
     * the report says whether that made the decision late.
     */
    private PlayerReport decideWhile(String before, String... next) throws Exception {
        java.util.concurrent.CountDownLatch deciding = new java.util.concurrent.CountDownLatch(1);
        java.util.concurrent.CountDownLatch release = new java.util.concurrent.CountDownLatch(1);
        BrainFactory held = (team, random) -> (message, send) -> {
            if (message.startsWith("(see 5")) {
                deciding.countDown();
                try {
                    release.await(5, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                send.accept("(dash 80)");
            }
        };
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            OnePlayer one = onePlayer(server, "Held", held);
            Future<List<PlayerReport>> reports = one.reports();
            FakeSoccerServer.Client client = one.client();
            send(client, before);
            send(client, "(sense_body 5 (view_mode high normal))");
            send(client, "(see 5 ((b) 10 0))");
            assertTrue(deciding.await(5, TimeUnit.SECONDS));
            for (String message : next) {
                send(client, message);
            }
            // loopback delivers in microseconds; the wait only makes sure it is in the socket
            Thread.sleep(200);
            release.countDown();
            awaitReceived(client, 3);
            send(client, "(hear 6 referee time_over)");
            return reports.get(10, TimeUnit.SECONDS).get(0);
        }
    }

    @Test
    void aDecisionIsLateWhenTheNextCyclesSenseBodyCameFirst() throws Exception {
        PlayerReport report = decideWhile("(hear 0 referee play_on)", "(sense_body 6 (view_mode high normal))");
        assertEquals(1, report.due());
        assertEquals(1, report.missed());
    }

    @Test
    void aCyclesOwnSenseBodyAfterItsSeeDoesNotMakeTheDecisionLate() throws Exception {
        PlayerReport report = decideWhile("(hear 0 referee play_on)", "(sense_body 5 (view_mode high normal))");
        assertEquals(1, report.due());
        assertEquals(0, report.missed());
    }

    @Test
    void inSynchronousModeAThinkWaitingMeansTheDecisionStillCounts() throws Exception {
        // the server executes what came before the (done), which follows the dash; a see it sent after
        // its think (as rcssserver does before version 18) is answered in the next cycle, as intended
        PlayerReport report = decideWhile("(think)", "(think)", "(sense_body 6 (view_mode high normal))");
        assertEquals(1, report.due());
        assertEquals(0, report.missed());
        assertEquals(2, report.thinks());
    }

    @Test
    void whileTheClockStandsStillASecondSenseBodyOfTheSameTimeMakesTheDecisionLate() throws Exception {
        PlayerReport once = decideWhile("(hear 0 referee goal_l_1)", "(sense_body 5 (view_mode high normal))");
        assertEquals(0, once.missed());
        PlayerReport twice = decideWhile("(hear 0 referee goal_l_1)", "(sense_body 5 (view_mode high normal))",
                "(sense_body 5 (view_mode high normal))");
        assertEquals(1, twice.missed());
    }

    @Test
    void afterAGoalThePlayerGoesBackToItsKickOffSpot() throws Exception {
        BrainFactory placed = (team, random) -> (message, send) -> {
            if (message.startsWith("(player_type")) {
                send.accept("(move -10 5)");
            } else if (message.startsWith("(see ")) {
                send.accept("(dash 50)");
            }
        };
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            OnePlayer one = onePlayer(server, "Home", placed);
            Future<List<PlayerReport>> reports = one.reports();
            FakeSoccerServer.Client client = one.client();
            send(client, "(player_type (id 0))");
            send(client, "(sense_body 1 (view_mode high normal))");
            send(client, "(see 1 ((b) 10 0))");
            send(client, "(hear 1 referee goal_l_1)");
            for (int cycle = 2; cycle <= 4; cycle++) {
                send(client, "(sense_body " + cycle + " (view_mode high normal))");
                send(client, "(see " + cycle + " ((b) 10 0))");
            }
            send(client, "(hear 5 referee time_over)");
            assertEquals(Outcome.GAME_OVER, reports.get(10, TimeUnit.SECONDS).get(0).outcome());
            awaitReceived(client, 9);
            assertEquals(List.of("(init Home (version 9))", "(move -10 5)", "(dash 50)", "(move -10 5)", "(dash 50)",
                    "(move -10 5)", "(dash 50)", "(dash 50)", "(bye)"), received(client));
        }
    }

    @Test
    void aBrainWhoseTeacherNeverMovedAfterAGoalIsNotMovedByTheRuntime() throws Exception {
        // an imitator of a teacher whose scenes hold no move; it asks to be the goalie (its counterpart was)
        BrainFactory stays = new BrainFactory() {
            @Override
            public org.scenes.simulator.Brain create(String team, java.util.Random random) {
                return new org.scenes.simulator.Brain() {
                    @Override
                    public void receive(String message, java.util.function.Consumer<String> send) {
                        if (message.startsWith("(player_type")) {
                            send.accept("(move -10 5)");
                        } else if (message.startsWith("(see ")) {
                            send.accept("(dash 50)");
                        }
                    }

                    @Override
                    public boolean repeatsKickOffMove() {
                        return false;
                    }
                };
            }

            @Override
            public boolean goalie(int unum) {
                return unum == 1;
            }
        };
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            OnePlayer one = onePlayer(server, "Home", stays);
            Future<List<PlayerReport>> reports = one.reports();
            FakeSoccerServer.Client client = one.client();
            send(client, "(player_type (id 0))");
            send(client, "(sense_body 1 (view_mode high normal))");
            send(client, "(see 1 ((b) 10 0))");
            send(client, "(hear 1 referee goal_l_1)");
            for (int cycle = 2; cycle <= 4; cycle++) {
                send(client, "(sense_body " + cycle + " (view_mode high normal))");
                send(client, "(see " + cycle + " ((b) 10 0))");
            }
            send(client, "(hear 5 referee time_over)");
            assertEquals(Outcome.GAME_OVER, reports.get(10, TimeUnit.SECONDS).get(0).outcome());
            awaitReceived(client, 7);
            assertEquals(List.of("(init Home (version 9)(goalie))", "(move -10 5)", "(dash 50)", "(dash 50)",
                    "(dash 50)", "(dash 50)", "(bye)"), received(client));
        }
    }

    @Test
    void aReconnectTakesThePlayersPlaceWithItsNumber() throws Exception {
        try (DatagramChannel initPort = DatagramChannel.open(); DatagramChannel ownPort = DatagramChannel.open()) {
            initPort.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            ownPort.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            // a server that answers the reconnect from a port of its own, as rcssserver does
            Future<String> hello = executor.submit(() -> {
                java.nio.ByteBuffer buffer = java.nio.ByteBuffer.allocate(4096);
                java.net.SocketAddress from = initPort.receive(buffer);
                buffer.flip();
                String text = StandardCharsets.UTF_8.decode(buffer).toString();
                for (String message : List.of("(reconnect r play_on)", "(sense_body 100 (view_mode high normal))",
                        "(hear 101 referee time_over)")) {
                    ownPort.send(java.nio.ByteBuffer.wrap((message + "\0").getBytes(StandardCharsets.UTF_8)), from);
                }
                return text;
            });
            TeamRunner runner = new TeamRunner(options((InetSocketAddress) initPort.getLocalAddress(), "Back")
                    .withReconnect(3), 1, DASHER, 1, notices::add);
            PlayerReport report = start(runner).get(10, TimeUnit.SECONDS).get(0);
            assertEquals("(reconnect Back 3)\0", hello.get(5, TimeUnit.SECONDS));
            assertEquals(Outcome.GAME_OVER, report.outcome(), report.toString());
            assertEquals(3, report.unum());
            assertEquals("r", report.side());
            assertEquals(1, report.cycles());
        }
    }

    @Test
    void messagesThatCameWhileTheBrainWasThinkingCountAsHeard() throws Exception {
        // a brain that thinks longer than the silence timeout while the server goes on talking: what came in
        // meanwhile is taken in after its answer, and the server was not silent, so the player plays on
        java.util.concurrent.CountDownLatch talked = new java.util.concurrent.CountDownLatch(1);
        BrainFactory slow = (team, random) -> (message, send) -> {
            if (message.startsWith("(see 1 ")) {
                try {
                    talked.await(10, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                send.accept("(dash 50)");
            }
        };
        try (FakeSoccerServer server = FakeSoccerServer.start(List.of())) {
            Future<List<PlayerReport>> reports = start(new TeamRunner(
                    ClientOptions.of(new ServerAddress("127.0.0.1", server.address(FakeSoccerServer.Port.PLAYER)
                            .getPort()), "Slow").withTimeouts(Duration.ofMillis(700), Duration.ofMillis(1000)),
                    1, slow, 1, notices::add));
            awaitClients(server, 1);
            FakeSoccerServer.Client client = server.clients().get(0);
            send(client, "(sense_body 1 (view_mode high normal))");
            send(client, "(see 1 ((b) 10 0))");
            // 1.5 s of a sense_body every 100 ms while the brain thinks: longer than the silence timeout
            for (int cycle = 2; cycle <= 16; cycle++) {
                Thread.sleep(100);
                send(client, "(sense_body " + cycle + " (view_mode high normal))");
            }
            talked.countDown();
            // a pause shorter than the silence timeout, counted from the last message sent
            Thread.sleep(400);
            send(client, "(hear 17 referee time_over)");
            PlayerReport report = reports.get(10, TimeUnit.SECONDS).get(0);
            assertEquals(Outcome.GAME_OVER, report.outcome(), report.toString() + " " + notices);
            assertEquals(16, report.cycles());
        }
    }
}
