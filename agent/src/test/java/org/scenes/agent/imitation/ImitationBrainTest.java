package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.scenes.api.ActionSelector;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.simulator.Brain;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;

/** Learn from a simulated Krislet game, then play in the simulator with what was learnt. */
class ImitationBrainTest {
    @TempDir
    Path directory;

    /** Ball position difference; no ball is far from any ball. Enough to imitate chase and kick. */
    static final SceneMetric BALL = new SceneMetric() {
        @Override
        public double distance(Scene query, Scene stored) {
            SeenObject a = ball(query);
            SeenObject b = ball(stored);
            if (a == null || b == null) {
                return a == b ? 0 : 1000;
            }
            return Math.abs(a.distance() - b.distance()) + Math.abs(a.direction() - b.direction()) / 10;
        }
    };

    static final ActionSelector FIRST = (nearest, random) -> nearest.get(0).scene().primaryAction();

    /** What player {@code unum} of the left team sends at its first see (time 1) after the referee called {@code mode}. */
    static List<String> firstAnswerAfter(Brain brain, int unum, String mode, String seen) {
        List<String> sent = new ArrayList<>();
        brain.receive("(init l " + unum + " before_kick_off)", command -> { });
        brain.receive("(hear 0 referee " + mode + ")", command -> { });
        brain.receive("(see 1 " + seen + ")", sent::add);
        return sent;
    }

    private static SeenObject ball(Scene scene) {
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL && !object.name().equals("B")) {
                return object;
            }
        }
        return null;
    }

    private KnowledgeBase learn() throws IOException {
        GameResult teacherGame = new Simulator(new GameSetup(new GameSetup.Team("Teal", 2, Teachers.byName("krislet")),
                new GameSetup.Team("Amber", 2, Teachers.byName("krislet")), 600, 3, directory.resolve("teach"))).run(t -> { });
        List<Scene> scenes = new ArrayList<>();
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        for (Path log : teacherGame.logs()) {
            converter.convert(log, scenes::add);
        }
        return KnowledgeBase.of(Grid.DEFAULT, scenes);
    }

    @Test
    void answersASeeWithTheNearestScenesAction() throws IOException {
        KnowledgeBase knowledge = learn();
        ImitationBrain brain = new ImitationBrain("Teal", new Recognizer(knowledge, () -> BALL, 1), FIRST, List::of,
                new Random(1));
        List<String> sent = new ArrayList<>();
        brain.receive("(init l 1 before_kick_off)", sent::add);
        brain.receive("(player_type (id 0))", sent::add);
        assertTrue(sent.get(0).startsWith("(move -"), sent.toString());
        sent.clear();
        // Far ball straight ahead: Krislet dashed in every such scene.
        brain.receive("(see 50 ((b) 20 0) ((g r) 60 3))", sent::add);
        assertEquals(1, sent.size());
        assertTrue(sent.get(0).startsWith("(dash "), sent.toString());
        assertEquals(1, brain.decisions());
    }

    /** Remembers the scene before, like the memory plugin. */
    static final class Remember implements org.scenes.api.SceneTransform {
        private Scene last;

        @Override
        public Scene apply(Scene scene) {
            Scene remembered = scene.withPrevious(last);
            last = scene.withPrevious(null);
            return remembered;
        }
    }

    @Test
    void transformsRememberTheActionThisBrainChose() throws IOException {
        KnowledgeBase knowledge = learn();
        List<Scene> queries = new ArrayList<>();
        SceneMetric recording = (query, stored) -> {
            if (queries.isEmpty() || queries.get(queries.size() - 1) != query) {
                queries.add(query);
            }
            return BALL.distance(query, stored);
        };
        ImitationBrain brain = new ImitationBrain("Teal", new Recognizer(knowledge, () -> recording, 1), FIRST,
                () -> List.of(new Remember()), new Random(1));
        List<String> sent = new ArrayList<>();
        brain.receive("(init l 1 before_kick_off)", sent::add);
        brain.receive("(see 50 ((b) 20 0))", sent::add);
        brain.receive("(see 51 ((b) 19 0))", sent::add);
        Scene second = queries.get(queries.size() - 1);
        assertEquals(50, second.previous().cycle());
        assertEquals(sent.get(0), second.previous().primaryAction().command(), "the action sent for see 50");
    }

    @Test
    void imitatorsPlayAGameInTheSimulator() throws IOException {
        Recognizer recognizer = new Recognizer(learn(), () -> BALL, 1);
        GameResult game = new Simulator(new GameSetup(
                new GameSetup.Team("Imitator", 2, ImitationBrain.factory(recognizer, () -> FIRST, List::of)),
                new GameSetup.Team("Amber", 2, Teachers.byName("krislet")), 300, 4, directory.resolve("play")))
                .run(t -> { });
        SceneConverter converter = SceneConverter.with(Grid.DEFAULT).strict(true).build();
        long[] scenes = new long[1];
        var report = converter.convert(game.logs().get(0), scene -> scenes[0]++);
        assertEquals(0, report.malformed());
        assertTrue(scenes[0] > 100, "the imitator acted on its sees: " + scenes[0]);
    }
}
