package org.scenes.fakeserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.PlayerReport;
import org.scenes.agent.net.PlayerReport.Outcome;
import org.scenes.agent.net.ServerAddress;
import org.scenes.agent.net.TeamRunner;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.Pairing;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.teacher.Teachers;

/**
 * What one player received from a real rcssserver 19 (protocol 5, 7, 9, 15, 19), replayed by the
 * fake server through the client runtime: every message parses, the health counts match the
 * capture, and the scenes the imitation brain built live equal what the converter builds from
 * the runtime's log of the same traffic.
 */
class RealServerReplayTest {
    private final ExecutorService executor = Executors.newCachedThreadPool();
    private final List<String> notices = Collections.synchronizedList(new ArrayList<>());

    @TempDir
    Path directory;

    @AfterEach
    void shutDown() {
        executor.shutdownNow();
    }

    private static List<String> capture(int version) throws IOException {
        Path file = Path.of(System.getProperty("scenes.shared", "../shared"), "data/rcssserver19/received-v" + version + ".txt");
        assumeTrue(Files.isRegularFile(file), "no capture at " + file);
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        assertEquals("(init l 1 before_kick_off)", lines.get(0), "the fake server answers the init itself");
        return lines.subList(1, lines.size());
    }

    /** Plays one player against the fake server replaying the capture, then time_over. */
    private PlayerReport replay(List<String> capture, BrainFactory brains, int version) throws Exception {
        try (FakeSoccerServer server = FakeSoccerServer.start(capture)) {
            ClientOptions options = ClientOptions.of(new ServerAddress("127.0.0.1",
                            server.address(FakeSoccerServer.Port.PLAYER).getPort()), "TestTeam")
                    .withVersion(Math.max(ClientOptions.MIN_VERSION, version))
                    .withTimeouts(Duration.ofSeconds(2), Duration.ofSeconds(2)).withLogDirectory(directory);
            TeamRunner runner = new TeamRunner(options, 1, brains, 1, notices::add);
            Future<List<PlayerReport>> reports = executor.submit(runner::play);
            for (int i = 0; i < 200 && server.clients().isEmpty(); i++) {
                Thread.sleep(10);
            }
            FakeSoccerServer.Client client = server.clients().get(0);
            // a few datagrams at a time, each batch closed by a (think) whose (done) says the client
            // has taken it in: its socket buffer never overflows, whatever the machine's load
            int batches = 0;
            for (int sent = 0; sent < capture.size(); sent += 10) {
                server.replay(Math.min(10, capture.size() - sent));
                client.send("(think)\0".getBytes(StandardCharsets.UTF_8));
                batches++;
                for (int wait = 0; wait < 1000 && dones(client) < batches; wait++) {
                    Thread.sleep(5);
                }
                assertEquals(batches, dones(client), () -> "the client answered each (think): " + notices + " " + client);
            }
            client.send("(hear 40 referee time_over)\0".getBytes(StandardCharsets.UTF_8));
            return reports.get(20, TimeUnit.SECONDS).get(0);
        }
    }

    private static long dones(FakeSoccerServer.Client client) {
        return client.received().stream().filter(datagram -> new String(datagram, StandardCharsets.UTF_8)
                .startsWith("(done)")).count();
    }

    @ParameterizedTest
    @ValueSource(ints = {5, 7, 9, 15, 19})
    void everyMessageOfARealServerParsesAndIsCounted(int version) throws Exception {
        List<String> capture = capture(version);
        PlayerReport report = replay(capture, Teachers.byName("krislet"), version);
        assertEquals(Outcome.GAME_OVER, report.outcome(), report.toString());
        assertEquals(Map.of(), report.malformed(), "nothing malformed: " + notices);
        assertEquals(capture.stream().filter(line -> line.startsWith("(sense_body ")).count(), report.cycles());
        Map<String, Long> errors = new TreeMap<>();
        for (String line : capture) {
            if (line.startsWith("(error ")) {
                errors.merge(line.substring(7, line.length() - 1), 1L, Long::sum);
            }
        }
        assertEquals(errors, new TreeMap<>(report.errors()));
        assertTrue(report.decisions() > 0, "Krislet acted: " + report);
    }

    /** Nearest by ball distance; no ball is far from any ball. */
    private static final SceneMetric BALL = (query, stored) -> {
        double a = ball(query);
        double b = ball(stored);
        return Double.isNaN(a) || Double.isNaN(b) ? (Double.isNaN(a) == Double.isNaN(b) ? 0 : 1000) : Math.abs(a - b);
    };

    private static double ball(Scene scene) {
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL) {
                return object.distance();
            }
        }
        return Double.NaN;
    }

    private static Scene stored(double ball, Action action) {
        List<SeenObject> objects = Double.isNaN(ball) ? List.of()
                : List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, ball, 0, Grid.DEFAULT));
        return new Scene(1, Observer.UNKNOWN, objects, List.of(action));
    }

    @ParameterizedTest
    @ValueSource(ints = {9, 19})
    void scenesBuiltLiveEqualTheConvertedLogOfTheSameTraffic(int version) throws Exception {
        List<String> capture = capture(version);
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, List.of(stored(1, Action.kick(100, 0)),
                stored(10, Action.dash(60)), stored(30, Action.turn(20)), stored(Double.NaN, Action.turn(40))));
        Recognizer recognizer = new Recognizer(knowledge, () -> BALL, 1);
        List<Scene> live = Collections.synchronizedList(new ArrayList<>());
        BrainFactory imitators = (team, random) -> {
            ImitationBrain brain = new ImitationBrain(team, recognizer, (nearest, r) -> nearest.get(0).scene().primaryAction(),
                    List::of, random);
            brain.onScene(live::add);
            return brain;
        };
        PlayerReport report = replay(capture, imitators, version);
        assertEquals(Outcome.GAME_OVER, report.outcome(), report.toString());
        Path log = directory.resolve("TestTeam_1.log");
        List<Scene> converted = new ArrayList<>();
        // This knowledge base has one see age, so the brain answers each see (per-see play) even where
        // the server offers synchronous vision (v19's (ok synch_see)): the log converts alike per see.
        SceneConverter.with(Grid.DEFAULT).pairing(Pairing.SEE).strict(true).build().convert(log, converted::add);

        // identical repeated sees (play paused) are one scene in a converted log
        List<Scene> collapsed = new ArrayList<>();
        for (Scene scene : live) {
            Scene last = collapsed.isEmpty() ? null : collapsed.get(collapsed.size() - 1);
            if (last == null || last.cycle() != scene.cycle() || !last.objects().equals(scene.objects())) {
                collapsed.add(scene);
            }
        }
        assertEquals(capture.stream().filter(line -> line.startsWith("(see ")).count(), live.size(), "a scene per see");
        assertEquals(collapsed.size(), converted.size());
        for (int i = 0; i < converted.size(); i++) {
            Scene expected = collapsed.get(i);
            Scene actual = converted.get(i);
            assertEquals(new Observer("TestTeam", org.scenes.api.Side.LEFT, 1), actual.observer());
            assertEquals(expected.observer(), actual.observer(), "scene " + i);
            assertEquals(expected.cycle(), actual.cycle(), "scene " + i);
            assertEquals(expected.objects(), actual.objects(), "scene " + i);
            assertEquals(expected.primaryAction(), actual.primaryAction(), "scene " + i);
        }
    }
}
