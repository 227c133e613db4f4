package org.scenes.coverage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.ObjectSetMetric;
import org.scenes.internal.match.Recognizer;

class CoverageTest {
    private static final Grid GRID = Grid.DEFAULT;
    /** Distance of the balls' directions: a one-dimensional world where the action follows the ball. */
    private static final Supplier<SceneMetric> METRIC = () -> (a, b) ->
            Math.abs(a.objects().get(0).direction() - b.objects().get(0).direction());

    private static Scene scene(int cycle, double ballDirection, Action action) {
        return new Scene(cycle, Observer.UNKNOWN,
                List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 5, ballDirection, GRID)), List.of(action));
    }

    /** Ball to the left: turn left; ahead: dash; right: turn right; one mislabelled scene. */
    private static List<Scene> world() {
        Random random = new Random(3);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            double direction = random.nextDouble() * 90 - 45;
            Action action = direction < -10 ? Action.turn(-30) : direction > 10 ? Action.turn(30) : Action.dash(80);
            scenes.add(scene(i, direction, action));
        }
        scenes.add(scene(300, 30, Action.turn(-30)));
        return scenes;
    }

    @Test
    void condensingKeepsFewScenesThatStillPredictEveryDroppedOne() {
        List<Scene> all = world();
        Condenser.Result result = new Condenser(METRIC, 3).condense(GRID, all);
        assertTrue(result.edited() >= 1 && result.edited() <= 5, "edited " + result.edited());
        assertTrue(result.scenes().stream().noneMatch(s -> s.cycle() == 300), "the mislabelled scene is edited away");
        assertTrue(result.scenes().size() < all.size() / 10, "kept " + result.scenes().size());
        Recognizer kept = new Recognizer(KnowledgeBase.of(GRID, result.scenes()), METRIC, 1);
        int right = 0;
        for (Scene scene : all.subList(0, 300)) {
            right += ObjectSetMetric.actionClass(scene) == ObjectSetMetric.actionClass(kept.nearest(scene).get(0).scene())
                    ? 1 : 0;
        }
        // only scenes edited away at the borders may be predicted otherwise
        assertTrue(right >= 300 - result.edited(), right + " of 300");
        Condenser.Result unedited = new Condenser(METRIC, 0).condense(GRID, all);
        assertEquals(0, unedited.edited());
        assertTrue(unedited.scenes().stream().anyMatch(s -> s.cycle() == 300), "without editing the odd scene stays");
    }

    @Test
    void keyScenesAreTheOnesAtTheBordersBetweenActions() {
        List<Scene> all = world().subList(0, 300);
        List<KeyScenes.Ranked> top = KeyScenes.rank(GRID, all, METRIC, 5);
        assertTrue(top.size() >= 2 && top.size() <= 5, "both borders hold key scenes: " + top.size());
        for (KeyScenes.Ranked ranked : top) {
            double direction = Math.abs(ranked.scene().objects().get(0).direction());
            assertTrue(Math.abs(direction - 10) < 3, "a key scene lies near a border: " + direction);
        }
        assertTrue(top.get(0).influence() >= top.get(top.size() - 1).influence());
    }

    @Test
    void eventsAreKicksMovesAndTheBallChangingHands() {
        SeenObject nearBall = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 0.8, 0, GRID);
        SeenObject farBall = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 20, 0, GRID);
        SeenObject opponent = new SeenObject(ObjectKind.PLAYER, "p", "University", 4, false, Relation.OPPONENT, 19, 2,
                Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK, GRID.cell(19, 2));
        List<Scene> game = List.of(
                new Scene(1, Observer.UNKNOWN, List.of(nearBall), List.of(Action.dash(50))),
                new Scene(2, Observer.UNKNOWN, List.of(nearBall), List.of(Action.kick(100, 0))),
                new Scene(3, Observer.UNKNOWN, List.of(farBall, opponent), List.of(Action.dash(50))),
                new Scene(4, Observer.UNKNOWN, List.of(farBall, opponent), List.of(Action.dash(50))),
                new Scene(5, Observer.UNKNOWN, List.of(), List.of(Action.move(-10, 0))));
        List<KeyScenes.Ranked> events = KeyScenes.events(game, 10);
        assertEquals(List.of(1, 2, 4), events.stream().map(KeyScenes.Ranked::index).toList(),
                "the kick, the opponent taking the ball, the move");
        assertEquals(List.of(1), KeyScenes.events(game, 1).stream().map(KeyScenes.Ranked::index).toList());
    }
}
