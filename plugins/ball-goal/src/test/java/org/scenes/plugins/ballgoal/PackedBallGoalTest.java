package org.scenes.plugins.ballgoal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.scenes.convert.SceneConverter;
import org.scenes.match.KnowledgeBase;
import org.scenes.match.Neighbour;
import org.scenes.match.PackedMetric;
import org.scenes.match.Recognizer;
import org.scenes.match.SceneMetric;
import org.scenes.plugin.PluginConfig;
import org.scenes.plugin.PluginRegistry;
import org.scenes.scene.Grid;
import org.scenes.scene.Scene;

/** The packed scan finds the same neighbours at the same distances as an exhaustive scan, on real Krislet scenes. */
class PackedBallGoalTest {
    private static List<Scene> stored;
    private static List<Scene> queries;

    @BeforeAll
    static void load() throws IOException {
        Path game = Path.of(System.getProperty("scenes.shared"), "data", "krislet", "classic-game1");
        stored = scenes(game.resolve("Carleton_1.lsf.gz"));
        List<Scene> test = scenes(game.resolve("Carleton_2.lsf.gz"));
        queries = new ArrayList<>();
        for (int i = 0; i < 150; i++) {
            queries.add(test.get(i * test.size() / 150));
        }
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        new SceneConverter(Grid.DEFAULT, false, null).convert(log, scenes::add);
        return scenes;
    }

    private static SceneMetric metric(Map<String, String> options) {
        return PluginRegistry.load().metric("ball-goal", PluginConfig.DEFAULT.withOptions(options));
    }

    @Test
    void realScenesArePacked() {
        assertNotNull(((PackedMetric) metric(Map.of())).pack(stored));
    }

    @Test
    void memoryTermsAreNotPacked() {
        assertNull(((PackedMetric) metric(Map.of("memory", "0.5"))).pack(stored));
    }

    @Test
    void sameNeighboursAsExhaustiveScan() {
        for (Map<String, String> options : List.of(Map.<String, String>of(), Map.of("missing", "3", "angle-weight", "2"))) {
            SceneMetric metric = metric(options);
            for (int k : new int[] {1, 5, 15}) {
                Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), () -> metric(options), k);
                for (Scene query : queries) {
                    List<Neighbour> expected = exhaustive(metric, query, k);
                    List<Neighbour> actual = recognizer.nearest(query);
                    assertEquals(expected.size(), actual.size());
                    for (int i = 0; i < k; i++) {
                        assertEquals(expected.get(i).index(), actual.get(i).index(), "neighbour " + i + " with " + options + ", k=" + k);
                        assertEquals(expected.get(i).distance(), actual.get(i).distance(), 0.0);
                    }
                }
            }
        }
    }

    /** Every distance through the scene-level method, sorted by distance then index. */
    private static List<Neighbour> exhaustive(SceneMetric metric, Scene query, int k) {
        List<Neighbour> all = new ArrayList<>();
        for (int i = 0; i < stored.size(); i++) {
            all.add(new Neighbour(stored.get(i), i, metric.distance(query, stored.get(i))));
        }
        all.sort(Comparator.comparingDouble(Neighbour::distance).thenComparingInt(Neighbour::index));
        return all.subList(0, k);
    }
}
