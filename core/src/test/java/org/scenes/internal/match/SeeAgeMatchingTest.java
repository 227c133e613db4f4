package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

/** A player acting every cycle shows one view in two cycles: the see age tells them apart. */
class SeeAgeMatchingTest {
    private static final Supplier<SceneMetric> METRIC = () -> new ObjectSetMetric(ObjectSetMetric.settings(
            PluginConfig.DEFAULT.withOptions(Map.of("space", "polar")), ObjectSetMetric.Space.CARTESIAN, 0));

    private static Scene aged(int cycle, int age, Action action, double ballDistance) {
        List<SeenObject> objects = List.of(TestScenes.ball(ballDistance, 0), TestScenes.goal(30, 5));
        return new Scene(cycle, TestScenes.OBSERVER, objects, List.of(action), null, age);
    }

    @Test
    void theKnowledgeBaseKeepsTheAgeAndMatchingSearchesTheQuerysAge() {
        List<Scene> scenes = List.of(aged(1, 0, Action.turn(0), 5), aged(2, 1, Action.dash(80), 5),
                aged(3, 0, Action.turn(0), 20), aged(4, 1, Action.dash(30), 20));
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, scenes);
        assertEquals(scenes, knowledge.scenes(), "the compact store keeps the see age");
        Recognizer recognizer = new Recognizer(knowledge, METRIC, 1);
        Neighbour fresh = recognizer.nearest(aged(9, 0, Action.turn(5), 5)).get(0);
        assertEquals(0, fresh.index());
        Neighbour stale = recognizer.nearest(aged(9, 1, Action.turn(5), 5)).get(0);
        assertEquals(1, stale.index(), "index in the whole knowledge base");
        assertEquals(Action.dash(80), stale.scene().primaryAction());
        assertEquals(3, recognizer.nearest(aged(9, 2, Action.turn(5), 19)).get(0).index(),
                "an age not stored searches the nearest one");
        assertEquals(2, new Recognizer(knowledge, METRIC, 4).nearest(aged(9, 1, Action.turn(5), 5)).size(),
                "only the scenes of that age");
    }

    @Test
    void oneAgeSearchesEverything() {
        List<Scene> scenes = List.of(aged(1, 0, Action.turn(0), 5), aged(2, 0, Action.dash(80), 6));
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), METRIC, 2);
        assertEquals(2, recognizer.nearest(aged(9, 1, Action.turn(5), 5)).size());
    }

    @Test
    void theSplitByAgeIsMadeOncePerKnowledgeBaseAndAHeldOneMatchesAlike() {
        List<Scene> scenes = List.of(aged(1, 0, Action.turn(0), 5), aged(2, 1, Action.dash(80), 5),
                aged(3, 0, Action.turn(0), 20), aged(4, 1, Action.dash(30), 20), aged(5, 2, Action.kick(50, 0), 9));
        KnowledgeBase compact = KnowledgeBase.of(Grid.DEFAULT, scenes);
        KnowledgeBase held = KnowledgeBase.held(Grid.DEFAULT, scenes);
        assertSame(compact.byAge(), compact.byAge(), "recognizers built on one knowledge base share its split");
        assertEquals(List.of(0, 1, 2), List.copyOf(held.byAge().keySet()));
        assertArrayEquals(new int[] {1, 3}, held.byAge().get(1).indices());
        assertSame(scenes.get(3), held.byAge().get(1).knowledge().scene(1), "a held part gives the objects it was given");
        assertEquals(scenes, compact.scenes());
        assertSame(scenes.get(4), held.scene(4));
        assertTrue(KnowledgeBase.of(Grid.DEFAULT, scenes.subList(0, 1)).byAge().isEmpty(), "one age: no split");
        for (int k = 1; k <= 3; k++) {
            Recognizer fromCompact = new Recognizer(compact, METRIC, k);
            Recognizer fromHeld = new Recognizer(held, METRIC, k);
            for (int age = 0; age <= 3; age++) {
                for (double ball : new double[] {4, 12, 30}) {
                    Scene query = aged(9, age, Action.turn(5), ball);
                    assertEquals(fromCompact.nearest(query), fromHeld.nearest(query), "age " + age + ", ball " + ball);
                }
            }
        }
    }
}
