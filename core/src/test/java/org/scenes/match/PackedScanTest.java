package org.scenes.match;

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
import org.scenes.plugin.PluginConfig;
import org.scenes.scene.Grid;
import org.scenes.scene.Scene;

/**
 * The packed object-set scan finds the same neighbours at the same distances as an exhaustive
 * scan through {@link SceneMetric#distance}, on real Krislet scenes, for each space and matching.
 */
class PackedScanTest {
    private static List<Scene> stored;
    private static List<Scene> queries;

    @BeforeAll
    static void load() throws IOException {
        Path game = Path.of(System.getProperty("scenes.shared"), "data", "krislet", "classic-game1");
        stored = scenes(game.resolve("Carleton_1.lsf.gz")).subList(0, 2500);
        List<Scene> test = scenes(game.resolve("Carleton_2.lsf.gz"));
        queries = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            queries.add(test.get(i * test.size() / 40));
        }
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        new SceneConverter(Grid.DEFAULT, false, null).convert(log, scenes::add);
        return scenes;
    }

    private static ObjectSetMetric metric(Map<String, String> options, ObjectSetMetric.Space space, double cycles) {
        return new ObjectSetMetric(ObjectSetMetric.settings(PluginConfig.DEFAULT.withOptions(options), space, cycles));
    }

    @Test
    void memoryTermsAreNotPacked() {
        assertNull(metric(Map.of("memory", "1"), ObjectSetMetric.Space.CARTESIAN, 0).pack(stored));
        assertNotNull(metric(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0).pack(stored));
    }

    @Test
    void greedyCartesianAsExhaustive() {
        check(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    void greedyPolarWithRowsAndLogDistanceAsExhaustive() {
        check(Map.of("space", "polar", "row-weight", "2", "log-distance", "true"), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    void cellAndProjectionAsExhaustive() {
        check(Map.of(), ObjectSetMetric.Space.CELL, 0);
        check(Map.of(), ObjectSetMetric.Space.CARTESIAN, 1);
    }

    @Test
    void optimalAsExhaustive() {
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    private static void check(Map<String, String> options, ObjectSetMetric.Space space, double cycles) {
        ObjectSetMetric metric = metric(options, space, cycles);
        for (int k : new int[] {1, 5, 15}) {
            Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), () -> metric(options, space, cycles), k);
            for (Scene query : queries) {
                List<Neighbour> expected = exhaustive(metric, query, k);
                List<Neighbour> actual = recognizer.nearest(query);
                assertEquals(k, actual.size());
                for (int i = 0; i < k; i++) {
                    assertEquals(expected.get(i).index(), actual.get(i).index(), "neighbour " + i + " with " + options + ", k=" + k);
                    assertEquals(expected.get(i).distance(), actual.get(i).distance(), 0.0);
                }
            }
        }
    }

    /** Every distance through the scene-level method (no bound), sorted by distance then index. */
    private static List<Neighbour> exhaustive(SceneMetric metric, Scene query, int k) {
        List<Neighbour> all = new ArrayList<>();
        for (int i = 0; i < stored.size(); i++) {
            all.add(new Neighbour(stored.get(i), i, metric.distance(query, stored.get(i))));
        }
        all.sort(Comparator.comparingDouble(Neighbour::distance).thenComparingInt(Neighbour::index));
        return all.subList(0, k);
    }
}
