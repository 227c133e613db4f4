package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

class RecognizerTest {
    /** A plain metric (no fast path): distance is the ball distance difference. */
    private static final SceneMetric BALL_DISTANCE = (a, b) -> Math.abs(a.objects().get(0).distance() - b.objects().get(0).distance());

    private static KnowledgeBase knowledge(double... ballDistances) {
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < ballDistances.length; i++) {
            scenes.add(TestScenes.scene(i, null, TestScenes.ball(ballDistances[i], 0)));
        }
        return KnowledgeBase.of(Grid.DEFAULT, scenes);
    }

    @Test
    void keepsTheKNearestNearestFirstWithTiesByIndex() {
        KnowledgeBase knowledge = knowledge(9, 5, 7, 3, 5, 3, 20);
        Recognizer recognizer = new Recognizer(knowledge, () -> BALL_DISTANCE, 4);
        List<Neighbour> nearest = recognizer.nearest(TestScenes.scene(0, null, TestScenes.ball(4, 0)));
        // distances 5,1,3,1,1,1,16: the four at 1, in index order
        assertEquals(List.of(1, 3, 4, 5), nearest.stream().map(Neighbour::index).toList());
        assertEquals(1, nearest.get(0).distance(), 1e-12);
    }

    @Test
    void looksFurtherThanKWhenAskedWithoutChangingK() {
        KnowledgeBase knowledge = knowledge(9, 5, 7, 3, 5, 3, 20);
        Recognizer recognizer = new Recognizer(knowledge, () -> BALL_DISTANCE, 1);
        Scene query = TestScenes.scene(0, null, TestScenes.ball(4, 0));
        assertEquals(List.of(1, 3, 4, 5, 2), recognizer.nearest(query, 5).stream().map(Neighbour::index).toList());
        assertEquals(List.of(1), recognizer.nearest(query).stream().map(Neighbour::index).toList());
        assertEquals(7, recognizer.nearest(query, 50).size(), "no more than it holds");
        assertThrows(IllegalArgumentException.class, () -> recognizer.nearest(query, 0));
    }

    @Test
    void agreesWithASortOfAllDistancesForEveryK() {
        List<Scene> scenes = TestScenes.random(11, 300);
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, scenes.subList(0, 250));
        ObjectSetMetric metric = new ObjectSetMetric(ObjectSetMetric.settings(
                PluginConfig.DEFAULT.withOptions(Map.of("space", "polar")), ObjectSetMetric.Space.CARTESIAN, 0));
        for (int k : new int[] {1, 2, 7, 250, 400}) {
            Recognizer recognizer = new Recognizer(knowledge, () -> metric, k);
            for (Scene query : scenes.subList(250, 300)) {
                List<Integer> expected = new ArrayList<>();
                for (int i = 0; i < knowledge.size(); i++) {
                    expected.add(i);
                }
                expected.sort(Comparator.comparingDouble((Integer i) -> metric.distance(query, knowledge.scene(i)))
                        .thenComparing(i -> i));
                List<Integer> got = recognizer.nearest(query).stream().map(Neighbour::index).toList();
                assertEquals(expected.subList(0, Math.min(k, knowledge.size())), got, "k=" + k);
            }
        }
    }

    @Test
    void aKnowledgeBaseTooLargeToKeepDecodedGivesTheStoredScenesAndReusesRecentDecodes() {
        List<Scene> scenes = TestScenes.random(12, Recognizer.KEEP_DECODED + 1 + 40);
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, scenes.subList(0, Recognizer.KEEP_DECODED + 1));
        ObjectSetMetric metric = new ObjectSetMetric(ObjectSetMetric.settings(PluginConfig.DEFAULT,
                ObjectSetMetric.Space.CARTESIAN, 0));
        Recognizer recognizer = new Recognizer(knowledge, () -> metric, 5);
        for (Scene query : scenes.subList(Recognizer.KEEP_DECODED + 1, scenes.size())) {
            List<Neighbour> first = recognizer.nearest(query);
            List<Neighbour> again = recognizer.nearest(query);
            assertEquals(first.stream().map(Neighbour::index).toList(), again.stream().map(Neighbour::index).toList());
            for (int i = 0; i < first.size(); i++) {
                assertEquals(knowledge.scene(first.get(i).index()), first.get(i).scene());
                int slot = first.get(i).index() & (Recognizer.RECENT_SLOTS - 1);
                boolean shared = first.stream().filter(n -> (n.index() & (Recognizer.RECENT_SLOTS - 1)) == slot).count() > 1;
                if (!shared) { // two neighbours of one slot evict each other
                    assertSame(first.get(i).scene(), again.get(i).scene(), "decoded once, then found in the cache");
                }
            }
        }
    }

    @Test
    void refusesMixedGridsAndEmptyKnowledge() {
        assertThrows(IllegalArgumentException.class, () -> new Recognizer(KnowledgeBase.of(Grid.DEFAULT, List.of()), () -> BALL_DISTANCE, 1));
        assertThrows(IllegalArgumentException.class, () -> new Recognizer(knowledge(1), () -> BALL_DISTANCE, 0));
        org.scenes.internal.scene.SceneFile a = new org.scenes.internal.scene.SceneFile(org.scenes.internal.scene.SceneFileHeader.of(Grid.DEFAULT,
                new org.scenes.internal.scene.SceneSource("a", TestScenes.OBSERVER)), List.of());
        org.scenes.internal.scene.SceneFile b = new org.scenes.internal.scene.SceneFile(org.scenes.internal.scene.SceneFileHeader.of(Grid.of(3, 2),
                new org.scenes.internal.scene.SceneSource("b", TestScenes.OBSERVER)), List.of());
        Grid.MismatchException error = assertThrows(Grid.MismatchException.class,
                () -> KnowledgeBase.fromFiles(List.of(a, b), List::of));
        assertEquals("b: grid 3x2 [-45,45] bounds 2 differs from 5x3 [-45,45] bounds 1,5 of a", error.getMessage());
    }
}
