package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.ServerAddress;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.server.GameSeries;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.simulator.teacher.Teachers;

/**
 * {@code scenes evaluate --server}: the evaluation's games played on the project's own server
 * (in this JVM, loopback, synchronous, a series of games) through the live runtime, compared
 * with the same evaluation in process.
 */
@Tag("slow")
class LiveEvaluationTest {
    private static final int CYCLES = 240;
    private static final List<Long> SEEDS = List.of(1L, 2L);
    private static final GameSetup.Team TEACHER = new GameSetup.Team("Teal", 3, Teachers.byName("krislet"));
    private static final GameSetup.Team OPPONENT = new GameSetup.Team("Amber", 3, Teachers.byName("krislet"));

    @TempDir
    Path directory;

    @Test
    void onTheProjectsServerTheGamesStartAsInProcessAndTheFiguresAreSane() throws Exception {
        MatchConfig config = MatchConfig.DEFAULT.withMetric("ball-goal", Map.of());
        Learner.Imitator imitator = Learner.fromTeacherGames(TEACHER, OPPONENT, 600, List.of(1001L),
                Learner.Matching.of(config, PluginRegistry.load()), done -> { });
        Evaluation.Plan plan = new Evaluation.Plan(TEACHER, PacedBrain.pace(imitator.brains(), 2), OPPONENT, CYCLES,
                SEEDS);
        Evaluation.Results inProcess = Evaluation.run(plan, Arena.embedded(), done -> { });

        Path logs = Files.createDirectories(directory.resolve("logs"));
        ServerConfig server = ServerConfig.defaults().withPort(0).withSynch(true).withGame(CYCLES, SEEDS.get(0))
                .withRecordDirectory(logs)
                // kick-off preparations only when every client's first move has surely arrived: on a busy
                // machine 300 ms was sometimes too short, and a first see then showed a player unmoved
                .withTimings(Duration.ofSeconds(2), Duration.ofSeconds(5));
        // what the server and the arena said, for a failure's message
        List<String> said = Collections.synchronizedList(new ArrayList<>());
        GameSeries series = new GameSeries(server, 2 * SEEDS.size(), 2, said::add);
        CompletableFuture<Integer> port = new CompletableFuture<>();
        ExecutorService executor = Executors.newSingleThreadExecutor();
        Evaluation.Results live;
        List<ServerResult> served;
        try {
            Future<List<ServerResult>> serving = executor.submit(
                    () -> series.run(started -> port.complete(started[1]), result -> { }, frame -> { }));
            LiveArena arena = new LiveArena(ClientOptions.of(new ServerAddress("127.0.0.1", port.get(30, TimeUnit.SECONDS)),
                    "Teal").withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(10)), logs, Duration.ofSeconds(30),
                    said::add);
            live = Evaluation.run(plan, arena, done -> { });
            served = serving.get(60, TimeUnit.SECONDS);
        } finally {
            series.stop();
            executor.shutdownNow();
        }
        assertEquals(4, served.size());
        try (var files = Files.list(logs)) {
            assertEquals(List.of("001-", "002-", "003-", "004-"), files.map(f -> f.getFileName().toString())
                    .filter(n -> n.endsWith(".rcg")).map(n -> n.substring(0, 4)).sorted().toList(),
                    "one numbered game log per game, none overwritten");
        }

        for (int i = 0; i < SEEDS.size(); i++) {
            for (PlayedGame[] pair : List.of(new PlayedGame[] {inProcess.teacher().get(i), live.teacher().get(i)},
                    new PlayedGame[] {inProcess.imitator().get(i), live.imitator().get(i)})) {
                PlayedGame expected = pair[0];
                PlayedGame got = pair[1];
                String game = got.role().label() + " seed " + got.seed();
                assertEquals(CYCLES, got.result().cycles(), game);
                assertEquals(expected.traces().size(), got.traces().size(), game);
                // The live runtime moves its players back to their spots at half time (a real server
                // does not, the embedded simulator does): up to then, every see and every answer,
                // the driver's and the shadow's, is the same as in process.
                for (int p = 0; p < got.traces().size(); p++) {
                    List<PlayerTrace.Decision> want = firstHalf(expected.traces().get(p));
                    assertTrue(want.size() > 50, game + ": the compared part is long enough");
                    assertSameDecisions(want, firstHalf(got.traces().get(p)), game + " player " + (p + 1), said);
                }
                // What the players heard agrees with the server's game log.
                assertFalse(got.frames().isEmpty(), game + ": frames from the game log");
                GameFrame last = got.frames().get(got.frames().size() - 1);
                assertEquals("Teal", last.leftTeam());
                assertEquals(last.scoreLeft(), got.result().scoreLeft(), game);
                assertEquals(last.scoreRight(), got.result().scoreRight(), game);
                assertEquals(last.players().stream().filter(s -> s.side() == Side.LEFT)
                        .mapToInt(s -> s.counts().kick()).sum(), got.kicks(), game + ": kick counters");
                // and the positions the log gives are the game in process up to half time
                List<GameFrame> wantFrames = firstHalfFrames(expected.frames());
                List<GameFrame> gotFrames = firstHalfFrames(got.frames());
                assertEquals(wantFrames.size(), gotFrames.size(), game + ": frames of the first half");
                for (int f = 0; f < wantFrames.size(); f++) {
                    GameFrame a = wantFrames.get(f);
                    GameFrame b = gotFrames.get(f);
                    assertEquals(a.time(), b.time());
                    assertEquals(a.playMode(), b.playMode(), game + " cycle " + a.time());
                    assertEquals(a.ball().x(), b.ball().x(), 1e-3, game + " ball x at " + a.time());
                    assertEquals(a.ball().y(), b.ball().y(), 1e-3, game + " ball y at " + a.time());
                }
                GameFigures figures = GameFigures.of(got);
                boolean playOn = got.frames().stream().anyMatch(f -> f.playMode().equals("play_on"));
                assertEquals(playOn, figures.ballDistance() > 0 && figures.ballDistance() < 80, game + " " + figures);
                assertTrue(figures.answered() > 0.5 && figures.answered() <= 1, game + " " + figures);
                assertTrue(figures.dashes() + figures.turns() > 100, game + " " + figures);
            }
        }
        Comparison comparison = Comparison.of(live);
        double agreement = comparison.figure("agreement").imitator().mean();
        assertTrue(agreement > 0.5 && agreement <= 1, "agreement " + agreement);
        assertEquals(TuringTest.FEATURES, comparison.turing().features());
        Path page = HtmlReport.write(directory.resolve("report"), "live", Map.of(), comparison, live);
        assertTrue(Files.readString(page).contains("replay-imitator"), "a replay from the server's game log");
    }

    @Test
    void withoutTheServersGameLogTheFiguresThatNeedPositionsAreAbsentAndSaySo() throws IOException {
        Evaluation.Plan plan = new Evaluation.Plan(TEACHER, Teachers.byName("statebased"), OPPONENT, 400, SEEDS);
        Evaluation.Results played = Evaluation.run(plan, Arena.embedded(), done -> { });
        Evaluation.Results blind = new Evaluation.Results(played.teacher().stream().map(this::withoutFrames).toList(),
                played.imitator().stream().map(this::withoutFrames).toList());
        Comparison comparison = Comparison.of(blind);
        assertTrue(Double.isNaN(comparison.figure("ballDistance").teacher().mean()));
        assertTrue(Double.isNaN(comparison.figure("firstTouch").imitator().mean()));
        assertEquals(Comparison.of(played).figure("agreement"), comparison.figure("agreement"),
                "agreement comes from the traffic alone");
        assertEquals(TuringTest.TRAFFIC_FEATURES, comparison.turing().features());
        assertTrue(comparison.turing().teacherWindows() > 10, "windows by sees: " + comparison.turing());
        assertFalse(Double.isNaN(comparison.turing().accuracy()));
        String html = Files.readString(HtmlReport.write(directory.resolve("blind"), "blind", Map.of(), comparison, blind));
        assertTrue(html.contains(HtmlReport.NO_POSITIONS.substring(0, 40)), "the page says what is absent");
        assertFalse(html.contains("class=\"replay\""), "no replay without frames");
    }

    private PlayedGame withoutFrames(PlayedGame game) {
        return new PlayedGame(game.role(), game.side(), game.seed(), game.result(), List.of(), game.traces());
    }

    /** Equal lists, or a failure that names the first decision where they part (not two lists of hundreds). */
    private static void assertSameDecisions(List<PlayerTrace.Decision> want, List<PlayerTrace.Decision> got,
                                            String what, List<String> said) {
        int same = 0;
        while (same < Math.min(want.size(), got.size()) && want.get(same).equals(got.get(same))) {
            same++;
        }
        if (same < want.size() || same < got.size()) {
            fail(what + ": " + want.size() + " decisions in process, " + got.size() + " live, the first " + same
                    + " the same; then in process " + want.subList(same, Math.min(want.size(), same + 3))
                    + ", live " + got.subList(same, Math.min(got.size(), same + 3)) + "; the server and arena said "
                    + said);
        }
    }

    private static List<GameFrame> firstHalfFrames(List<GameFrame> frames) {
        return frames.stream().filter(f -> f.time() >= 1 && f.time() < CYCLES / 2).toList();
    }

    private static List<PlayerTrace.Decision> firstHalf(PlayerTrace trace) {
        return trace.decisions().stream().filter(d -> d.time() < CYCLES / 2).toList();
    }
}
