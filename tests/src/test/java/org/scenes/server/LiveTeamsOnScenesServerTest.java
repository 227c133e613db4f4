package org.scenes.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.ServerAddress;
import org.scenes.agent.net.TeamRunner;
import org.scenes.api.ActionSelector;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.server.ServerConfig;
import org.scenes.simulator.server.ServerResult;
import org.scenes.simulator.server.SoccerServer;
import org.scenes.simulator.teacher.Teachers;

/**
 * The runtime's two kinds of team, started the one way ({@link TeamRunner}), play a whole
 * synchronous game on {@code scenes server}: imitators learnt from simulated Krislets against
 * Krislet teachers. Every player stays to time_over, none misses a cycle, each answers every think.
 */
class LiveTeamsOnScenesServerTest {
    private static final int PLAYERS = 3;
    private static final int CYCLES = 600;

    @TempDir
    Path directory;

    /** Ball distance and direction; no ball is far from any ball. */
    private static final SceneMetric BALL = (query, stored) -> {
        SeenObject a = ball(query);
        SeenObject b = ball(stored);
        if (a == null || b == null) {
            return a == b ? 0 : 1000;
        }
        return Math.abs(a.distance() - b.distance()) + Math.abs(a.direction() - b.direction()) / 10;
    };

    private static SeenObject ball(Scene scene) {
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL && !object.name().equals("B")) {
                return object;
            }
        }
        return null;
    }

    private Recognizer learn() throws Exception {
        GameResult game = new Simulator(new GameSetup(new GameSetup.Team("Teal", 2, Teachers.byName("krislet")),
                new GameSetup.Team("Amber", 2, Teachers.byName("krislet")), 600, 5, directory.resolve("teach")))
                .run(t -> { });
        List<Scene> scenes = new ArrayList<>();
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        for (Path log : game.logs()) {
            converter.convert(log, scenes::add);
        }
        return new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), () -> BALL, 1);
    }

    @Test
    void anImitationTeamAndATeacherTeamPlayAWholeSynchronousGame() throws Exception {
        Recognizer recognizer = learn();
        ActionSelector first = (nearest, random) -> nearest.get(0).scene().primaryAction();
        ServerConfig config = ServerConfig.defaults().withPort(0).withSynch(true).withGame(CYCLES, 7)
                .withTimings(Duration.ofMillis(500), Duration.ofSeconds(3));
        ExecutorService executor = Executors.newCachedThreadPool();
        List<String> notices = java.util.Collections.synchronizedList(new ArrayList<>());
        // the server's notice of each imitator's connection, which the teachers wait for
        CountDownLatch imitatorsIn = new CountDownLatch(PLAYERS);
        try (SoccerServer server = SoccerServer.open(config, line -> {
            if (line.startsWith("A new ") && line.contains(" player (Imitator ")) {
                imitatorsIn.countDown();
            }
        })) {
            Future<ServerResult> running = executor.submit(() -> server.run(frame -> { }));
            ServerAddress address = new ServerAddress("127.0.0.1", server.port());
            TeamRunner imitators = new TeamRunner(ClientOptions.of(address, "Imitator").withGoalie(true), PLAYERS,
                    ImitationBrain.factory(recognizer, () -> first, List::of, ImitationBrain.Guards.ON), 1, notices::add);
            Future<List<PlayerReport>> left = executor.submit(imitators::play);
            // the imitators connect first, so they are the left team
            assertTrue(imitatorsIn.await(60, TimeUnit.SECONDS), "the imitators connected: " + notices);
            TeamRunner teachers = new TeamRunner(ClientOptions.of(address, "Krislet"), PLAYERS,
                    Teachers.byName("krislet"), 1, notices::add);
            Future<List<PlayerReport>> right = executor.submit(teachers::play);
            ServerResult result = running.get(180, TimeUnit.SECONDS);
            List<PlayerReport> reports = new ArrayList<>(left.get(30, TimeUnit.SECONDS));
            reports.addAll(right.get(30, TimeUnit.SECONDS));
            assertEquals(CYCLES, result.cycles());
            assertEquals(0, result.dropped(), "no player was too slow for the server");
            assertEquals(2 * PLAYERS, reports.size());
            assertEquals(0, TeamRunner.exitCode(reports), reports + " " + notices);
            for (PlayerReport report : reports) {
                assertEquals(PlayerReport.Outcome.GAME_OVER, report.outcome(), report.toString());
                assertTrue(report.cycles() >= CYCLES, report.toString());
                assertEquals(0, report.missed(), report.toString());
                // a think every cycle but the last (time over), each answered with a done
                assertTrue(report.thinks() >= report.cycles() - 1, "a done for every think: " + report);
                assertTrue(report.due() > CYCLES / 3, report.toString());
                assertEquals(java.util.Map.of(), report.malformed(), report.toString());
            }
            PlayerReport goalie = reports.get(0);
            assertEquals("l", goalie.side());
            assertTrue(goalie.brainCounters().containsKey("guard.stuck"), goalie.brainCounters().toString());
        } finally {
            executor.shutdownNow();
        }
    }
}
