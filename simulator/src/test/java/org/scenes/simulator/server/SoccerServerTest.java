package org.scenes.simulator.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;

class SoccerServerTest {
    @TempDir
    Path directory;

    private final ExecutorService executor = Executors.newSingleThreadExecutor();
    private final List<String> events = Collections.synchronizedList(new ArrayList<>());
    private final List<GameFrame> frames = Collections.synchronizedList(new ArrayList<>());
    private SoccerServer server;
    private Future<ServerResult> running;

    private void start(ServerConfig config) throws IOException {
        server = SoccerServer.open(config.withPort(0), events::add);
        running = executor.submit(() -> server.run(frames::add));
    }

    private static ServerConfig synchGame(int cycles) {
        return ServerConfig.defaults().withSynch(true).withGame(cycles, 1)
                .withTimings(Duration.ofMillis(200), Duration.ofMillis(500));
    }

    private ServerResult finish() throws InterruptedException, ExecutionException, TimeoutException {
        return running.get(30, TimeUnit.SECONDS);
    }

    @AfterEach
    void stop() throws IOException {
        if (server != null) {
            server.stop();
            try {
                running.get(10, TimeUnit.SECONDS);
            } catch (InterruptedException | ExecutionException | TimeoutException e) {
                // the test has failed already
            }
            server.close();
        }
        executor.shutdownNow();
    }

    @Test
    void initIsAnsweredFromAPortOfItsOwnWithTheParametersOfTheVersion() throws Exception {
        start(synchGame(20));
        try (RawClient v7 = new RawClient(server.port()); RawClient v9 = new RawClient(server.port())) {
            List<String> seven = v7.init("(init Teal (version 7))");
            assertEquals("(init l 1 before_kick_off)", seven.get(0));
            assertNotEquals(server.port(), ((java.net.InetSocketAddress) v7.playerPort).getPort());
            // positional parameters, 103 server parameters as rcssserver 19 sends version 7
            assertTrue(seven.get(1).startsWith("(server_param 14.02 5 0.3 0.4 0.1 60 1.05 1 8000 45 "), seven.get(1));
            assertEquals(103, seven.get(1).substring(1, seven.get(1).length() - 1).split(" ").length - 1);
            assertTrue(seven.get(2).startsWith("(player_param 1 0 1 "), seven.get(2));
            assertEquals("(player_type 0 1.05 45 0.4 5 0.006 0.3 0.7 0.1 0 1 0.6)", seven.get(3));

            List<String> nine = v9.init("(init Amber (version 9) (goalie))");
            assertEquals("(init r 1 before_kick_off)", nine.get(0));
            assertTrue(nine.get(1).startsWith("(server_param (ball_accel_max 2.7)"), nine.get(1));
            assertTrue(nine.get(3).startsWith("(player_type (id 0)"), nine.get(3));

            // a connected client may not use the init port again
            v7.toInitPort("(init Teal (version 7))");
            assertEquals("(error only_init_allowed_on_init_port)", v7.receive());
        }
    }

    @Test
    void refusalsAreTheServersErrors() throws Exception {
        start(synchGame(20));
        List<RawClient> clients = new ArrayList<>();
        try {
            for (String[] asked : new String[][] {
                {"(hello)", "(error unknown_command)"},
                {"(init)", "(error unknown_command)"},
                {"(init (version 9))", "(error illegal_teamname)"},
                {"(init Team_name_far_too_long (version 9))", "(error illegal_teamname_or_too_long_teamname)"},
                {"(init Teal (version nine))", "(error illegal_command_form)"},
                {"(init Teal (colour red))", "(error illegal_command_form)"},
                {"(reconnect Nobody 3)", "(error no_such_team_or_player)"}}) {
                RawClient client = new RawClient(server.port());
                clients.add(client);
                client.toInitPort(asked[0]);
                assertEquals(asked[1], client.receive(), asked[0]);
            }
            RawClient goalie = new RawClient(server.port());
            clients.add(goalie);
            assertEquals("(init l 1 before_kick_off)", goalie.init("(init Teal (version 9) (goalie))").get(0));
            RawClient secondGoalie = new RawClient(server.port());
            clients.add(secondGoalie);
            assertEquals("(error no_more_player_or_goalie_or_illegal_client_version)",
                    secondGoalie.init("(init Teal (version 9) (goalie))").get(0));
            for (int unum = 2; unum <= 11; unum++) {
                RawClient player = new RawClient(server.port());
                clients.add(player);
                assertEquals("(init l " + unum + " before_kick_off)", player.init("(init Teal (version 9))").get(0));
            }
            RawClient twelfth = new RawClient(server.port());
            clients.add(twelfth);
            assertEquals("(error no_more_player_or_goalie_or_illegal_client_version)",
                    twelfth.init("(init Teal (version 9))").get(0));
            RawClient right = new RawClient(server.port());
            clients.add(right);
            assertEquals("(init r 1 before_kick_off)", right.init("(init Amber (version 9))").get(0));
            RawClient third = new RawClient(server.port());
            clients.add(third);
            assertEquals("(error no_more_team)", third.init("(init Cyan (version 9))").get(0));
        } finally {
            clients.forEach(RawClient::close);
        }
    }

    /** Answers (think) with (done) until time over; returns everything received. */
    private static List<String> playAlong(RawClient client, int limit) throws IOException {
        List<String> got = new ArrayList<>();
        for (int i = 0; i < limit; i++) {
            String message = client.receive();
            if (message == null) {
                break;
            }
            got.add(message);
            if (message.equals("(think)")) {
                client.send("(done)");
            }
            if (message.contains("referee time_over")) {
                break;
            }
        }
        return got;
    }

    @Test
    void commandsErrorsViewModesAndASynchronousGameToTimeOver() throws Exception {
        start(synchGame(40).withRecordDirectory(directory).withTeamsWait(Duration.ofMillis(300)));
        try (RawClient client = new RawClient(server.port())) {
            client.init("(init Teal (version 9))");
            client.send("(move -10 0)");
            client.sendWithoutNul("(turn_neck 30)");
            assertEquals("(warning message_not_null_terminated)", client.receive());
            client.send("(foo 1)");
            client.send("(dash)");
            client.send("(synch_see)");
            client.send("(score)");
            List<String> answers = List.of(client.receive(), client.receive(), client.receive(), client.receive());
            // synch_see needs version 18; score is answered at once, the commands at the step's end
            assertTrue(answers.contains("(error illegal_command_form)"), answers.toString());
            assertTrue(answers.contains("(score 0 0 0)"), answers.toString());
            // before kick-off preparations a (think) whose (done) says all sent before it is in
            List<String> beforeKickOff = client.until("(think)", 20);
            assertTrue(beforeKickOff.stream().noneMatch(m -> m.startsWith("(sense_body")), beforeKickOff.toString());
            client.send("(done)");
            List<String> first = client.until("(think)", 20);
            long illegal = answers.stream().filter(a -> a.equals("(error illegal_command_form)")).count()
                    + beforeKickOff.stream().filter(a -> a.equals("(error illegal_command_form)")).count()
                    + first.stream().filter(a -> a.equals("(error illegal_command_form)")).count();
            assertEquals(3, illegal, answers + " " + first);
            client.send("(change_view narrow high)");
            client.send("(done)");
            List<String> rest = playAlong(client, 2000);
            assertTrue(rest.stream().anyMatch(m -> m.contains("(view_mode high narrow)")));
            // narrow view: a see every 75 ms, so four sees in three cycles of 100 ms
            int thinks = 0;
            int sees = 0;
            for (String message : rest) {
                thinks += message.equals("(think)") ? 1 : 0;
                sees += message.startsWith("(see ") && thinks > 2 ? 1 : 0;
            }
            assertEquals(4.0 / 3, (double) sees / (thinks - 3), 0.05);
            assertTrue(rest.get(rest.size() - 1).equals("(hear 40 referee time_over)"), rest.get(rest.size() - 1));
            assertTrue(first.get(0).startsWith("(sense_body 0 (view_mode high normal)"), first.get(0));
            assertTrue(first.get(0).contains("(head_angle 30)"), first.get(0));
        }
        ServerResult result = finish();
        assertEquals(40, result.cycles());
        assertFalse(result.stopped());
        assertEquals(2, result.logs().size());
        List<GameFrame> frames = GameLogReader.readAll(result.logs().get(0));
        assertEquals(41, frames.size()); // cycles 0 to 40
        assertEquals(-10, frames.get(0).players().get(0).x(), 1e-9);
        assertEquals(45, frames.get(10).players().get(0).viewWidth());
        List<String> commands = Files.readAllLines(result.logs().get(1));
        assertTrue(commands.contains("0,0\tRecv Teal_1: (foo 1)"), commands.toString());
        assertTrue(commands.stream().anyMatch(l -> l.endsWith("Recv Teal_1: (done)")));
    }

    @Test
    void severalCommandsInOneDatagramAsLibrcscSendsThem() throws Exception {
        start(synchGame(12).withRecordDirectory(directory).withTeamsWait(Duration.ofMillis(300)));
        List<String> got = new ArrayList<>();
        try (RawClient client = new RawClient(server.port())) {
            client.init("(init Teal (version 9))");
            boolean first = true;
            for (int i = 0; i < 2000; i++) {
                String message = client.receive();
                if (message == null) {
                    break;
                }
                got.add(message);
                if (message.equals("(think)")) {
                    // the cycle's commands and its (done) in one datagram; the second time a malformed tail
                    client.send(first ? "(turn_neck 30)(change_view narrow high)(done)" : "(turn 0)(done)(foo");
                    first = false;
                }
                if (message.contains("referee time_over")) {
                    break;
                }
            }
        }
        ServerResult result = finish();
        assertEquals(0, result.dropped(), "each (done) after commands was seen: " + events);
        assertEquals(12, result.cycles());
        assertTrue(got.get(got.size() - 1).contains("time_over"), got.get(got.size() - 1));
        assertTrue(got.stream().anyMatch(m -> m.startsWith("(sense_body") && m.contains("(view_mode high narrow)")
                && m.contains("(head_angle 30)")), got.toString());
        assertTrue(got.contains("(error illegal_command_form)"), "the malformed tail is answered: " + got);
        List<String> commands = Files.readAllLines(result.logs().get(1));
        assertTrue(commands.stream().anyMatch(l -> l.endsWith("Recv Teal_1: (turn_neck 30)(change_view narrow high)(done)")),
                commands.toString());
    }

    @Test
    void aSilentPlayerIsDroppedAndTheGameGoesOn() throws Exception {
        start(synchGame(30));
        try (RawClient silent = new RawClient(server.port()); RawClient player = new RawClient(server.port())) {
            silent.init("(init Teal (version 9))");
            player.init("(init Amber (version 9))");
            List<String> got = playAlong(player, 2000);
            assertEquals("(hear 30 referee time_over)", got.get(got.size() - 1));
        }
        ServerResult result = finish();
        assertEquals(1, result.dropped());
        assertEquals(30, result.cycles());
        assertTrue(events.stream().anyMatch(e -> e.startsWith("Dropped Teal_1")), events.toString());
    }

    @Test
    void reconnectByeAndVersion18SynchSee() throws Exception {
        start(synchGame(30).withTimings(Duration.ofMillis(800), Duration.ofMillis(500)));
        try (RawClient first = new RawClient(server.port()); RawClient modern = new RawClient(server.port());
             RawClient again = new RawClient(server.port())) {
            first.init("(init Teal (version 9))");
            modern.init("(init Amber (version 18))");
            // synchronous sees from the init on, as rcssserver gives version 18; asking again is answered alike
            assertEquals("(ok synch_see)", modern.receive());
            modern.send("(synch_see)");
            assertEquals("(ok synch_see)", modern.receive());
            again.toInitPort("(reconnect Teal 1)");
            assertEquals("(reconnect l before_kick_off)", again.receive());
            again.playerPort = again.lastFrom;
            assertTrue(again.receive().startsWith("(server_param "));
            again.receive();
            again.receive();
            again.send("(bye)");
            List<String> got = playAlong(modern, 2000);
            assertEquals("(hear 30 referee time_over)", got.get(got.size() - 1));
            // synch_see in normal view: a see every second cycle, at the cycle's start
            long sees = got.stream().filter(m -> m.startsWith("(see ")).count();
            long senses = got.stream().filter(m -> m.startsWith("(sense_body ")).count();
            assertEquals(0.5, (double) sees / senses, 0.05);
        }
        ServerResult result = finish();
        assertEquals(0, result.dropped(), "the player said bye and left");
        // synchronous sees in normal view: a cone of 120 degrees, as on the server
        GameFrame last = frames.get(frames.size() - 1);
        assertEquals(1, last.players().size());
        assertEquals(120, last.players().get(0).viewWidth(), 1e-9);
        assertTrue(events.contains("A player (Teal 1) left."), events.toString());
    }

    /** The messages {@code client} gets until {@code enough} holds of them, at most {@code limit}. */
    private static List<String> receiveUntil(RawClient client, java.util.function.Predicate<List<String>> enough,
                                             int limit) throws IOException {
        List<String> got = new ArrayList<>();
        while (got.size() < limit && !enough.test(got)) {
            String message = client.receive();
            if (message == null) {
                break;
            }
            got.add(message);
        }
        return got;
    }

    private static long count(List<String> messages, String prefix) {
        return messages.stream().filter(m -> m.startsWith(prefix)).count();
    }

    /** Issue 31.6: rcssserver's cycles run before kick-off; a lone player got nothing for 2 s and no see. */
    @Test
    void aLonePlayerInRealTimeGetsSenseBodyAndSeesFromItsConnection() throws Exception {
        start(ServerConfig.defaults().withGame(6000, 1).withRecordDirectory(directory));
        try (RawClient modern = new RawClient(server.port()); RawClient classic = new RawClient(server.port())) {
            long began = System.nanoTime();
            modern.init("(init Teal (version 18))");
            assertEquals("(ok synch_see)", modern.receive());
            List<String> first = modern.until("(sense_body", 20);
            double firstMillis = (System.nanoTime() - began) / 1e6;
            assertTrue(first.get(first.size() - 1).startsWith("(sense_body 0 "), first.toString());
            // a cycle is 100 ms; before, the first came 2 s after the last connection
            assertTrue(firstMillis < 1500, "first sense_body after " + firstMillis + " ms");
            // synchronous sees in normal view: one at the start of every second cycle, time 0
            List<String> got = receiveUntil(modern, m -> count(m, "(see ") == 3, 40);
            assertEquals(3, count(got, "(see 0 "), got.toString());
            List<String> fromFirstSee = got.subList(got.indexOf(got.stream().filter(m -> m.startsWith("(see "))
                    .findFirst().orElseThrow()), got.size());
            assertEquals(List.of("(see", "(sense_body", "(sense_body", "(see", "(sense_body", "(sense_body", "(see"),
                    fromFirstSee.stream().map(m -> m.substring(0, m.indexOf(' '))).toList(), fromFirstSee.toString());

            // version 9 sees every 150 ms, sent at the cycles' starts: two in every three cycles
            classic.init("(init Teal (version 9))");
            List<String> cycles = receiveUntil(classic, m -> count(m, "(sense_body 0 ") == 10, 60);
            List<String> nine = cycles.subList(cycles.indexOf(cycles.stream().filter(m -> m.startsWith("(sense_body"))
                    .findFirst().orElseThrow()), cycles.size() - 1);
            assertEquals(9, count(nine, "(sense_body 0 "), nine.toString());
            assertEquals(6, count(nine, "(see 0 "), nine.toString());
        }
        server.stop();
        ServerResult result = finish();
        assertEquals(0, result.steps(), "waiting is no step of the game");
        // rcssserver's name for a side no player joined: null, without a score
        assertEquals(List.of("Teal_0-vs-null.rcg", "Teal_0-vs-null.rcl"),
                result.logs().stream().map(p -> p.getFileName().toString()).toList());
    }

    /** Issue 31.6: body commands count while waiting, one a cycle as on rcssserver (only the first move did). */
    @Test
    void bodyCommandsAreExecutedWhileWaitingInRealTime() throws Exception {
        start(ServerConfig.defaults().withGame(6000, 1));
        try (RawClient client = new RawClient(server.port())) {
            client.init("(init Teal (version 9))");
            client.send("(move -10 5)");
            List<String> moved = receiveUntil(client, m -> senseBodyWith(m, "(move 1)"), 50);
            assertTrue(last(moved).contains("(move 1)"), moved.toString());
            client.send("(turn 60)");
            List<String> turned = receiveUntil(client, m -> senseBodyWith(m, "(turn 1)"), 50);
            assertTrue(last(turned).contains("(turn 1)"), "the turn after the move counts: " + turned);
            client.send("(move -20 -5)");
            List<String> got = receiveUntil(client, m -> senseBodyWith(m, "(move 2)"), 50);
            assertTrue(last(got).contains("(move 2)") && last(got).contains("(turn 1)"), got.toString());
            assertTrue(last(got).startsWith("(sense_body 0 "), last(got));
        }
    }

    private static String last(List<String> messages) {
        return messages.isEmpty() ? "" : messages.get(messages.size() - 1);
    }

    private static boolean senseBodyWith(List<String> messages, String count) {
        return last(messages).startsWith("(sense_body") && last(messages).contains(count);
    }

    @Test
    void aStopEndsTheGameAndCompletesTheLogs() throws Exception {
        start(ServerConfig.defaults().withGame(6000, 1).withRecordDirectory(directory)
                .withTimings(Duration.ofMillis(100), Duration.ofMillis(500)).withTeamsWait(Duration.ofMillis(100)));
        try (RawClient client = new RawClient(server.port())) {
            client.init("(init Teal (version 9))");
            List<String> got = client.until("(sense_body 0", 50);
            assertTrue(got.get(got.size() - 1).startsWith("(sense_body 0"));
            // real time: a few cycles at 100 ms
            long began = System.nanoTime();
            client.until("(sense_body", 50);
            client.until("(sense_body", 50);
            assertTrue(System.nanoTime() - began > 150_000_000L, "cycles of 100 ms");
        }
        server.stop();
        ServerResult result = finish();
        assertTrue(result.stopped());
        assertEquals(2, result.logs().size());
        assertTrue(Files.exists(result.logs().get(1)));
        assertEquals("Teal_0-vs-null.rcg", result.logs().get(0).getFileName().toString());
    }
}
