package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.scenes.api.Grid;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * The packed object-set scan finds the same neighbours at the same distances as an exhaustive
 * scan through {@link SceneMetric#distance}, on real Krislet scenes, for each space and matching.
 */
@Tag("slow")
class PackedScanTest {
    private static List<Scene> stored;
    private static List<Scene> queries;

    /** Real scenes when the shared recordings are present (tests on them say so); simulated ones: SimulatedDataTest. */
    @BeforeAll
    static void load() throws IOException {
        if (!SharedData.present()) {
            return;
        }
        Path game = SharedData.resolve("krislet/classic-game1");
        stored = scenes(game.resolve("Carleton_1.lsf.gz")).subList(0, 2500);
        List<Scene> test = scenes(game.resolve("Carleton_2.lsf.gz"));
        queries = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            queries.add(test.get(i * test.size() / 40));
        }
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
        return scenes;
    }

    private static ObjectSetMetric metric(Map<String, String> options, ObjectSetMetric.Space space, double cycles) {
        return new ObjectSetMetric(ObjectSetMetric.settings(PluginConfig.DEFAULT.withOptions(options), space, cycles));
    }

    @Test
    @RequiresSharedData
    void memoryTermsAreNotPacked() {
        assertNull(metric(Map.of("memory", "1"), ObjectSetMetric.Space.CARTESIAN, 0).pack(stored));
        assertNotNull(metric(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0).pack(stored));
    }

    @Test
    @RequiresSharedData
    void greedyCartesianAsExhaustive() {
        check(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    @RequiresSharedData
    void greedyPolarWithRowsAndLogDistanceAsExhaustive() {
        check(Map.of("space", "polar", "row-weight", "2", "log-distance", "true"), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    @RequiresSharedData
    void cellAndProjectionAsExhaustive() {
        check(Map.of(), ObjectSetMetric.Space.CELL, 0);
        check(Map.of(), ObjectSetMetric.Space.CARTESIAN, 1);
    }

    @Test
    @RequiresSharedData
    void optimalAsExhaustive() {
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    @RequiresSharedData
    void optimalInPolarSpaceWithRowsAndLogDistanceAsExhaustive() {
        check(Map.of("matching", "optimal", "space", "polar", "direction-weight", "0.3"), ObjectSetMetric.Space.CARTESIAN, 0);
        check(Map.of("matching", "optimal", "space", "polar", "row-weight", "2", "log-distance", "true"),
                ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    @RequiresSharedData
    void optimalCellProjectionAndRowWeightAsExhaustive() {
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CELL, 0);
        // cells are not projected: rows no longer follow the projected distance order
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CELL, 3);
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CARTESIAN, 1);
        check(Map.of("matching", "optimal", "row-weight", "3", "log-distance", "true"), ObjectSetMetric.Space.CARTESIAN, 0);
    }

    @Test
    @RequiresSharedData
    void optimalWithAllPlayersAndAGentlePenaltyAsExhaustive() {
        // all players as one group too (larger groups); a small penalty makes more pairs cheaper unmatched
        check(Map.of("matching", "optimal", "penalty", "2", "penalty-scale", "30"), ObjectSetMetric.Space.CARTESIAN, 0,
                ObjectWeights.parse("1/1/1/1/1/1/1/1"));
    }

    @Test
    void randomScenesAsExhaustive() {
        List<Scene> randomStored = TestScenes.random(11, 800);
        List<Scene> randomQueries = TestScenes.random(12, 30);
        ObjectWeights all = ObjectWeights.parse("1/1/1/1/1/1/1/1");
        for (Map<String, String> options : List.of(Map.<String, String>of(), Map.of("matching", "optimal"),
                Map.of("matching", "optimal", "space", "polar", "penalty", "3"))) {
            check(options, ObjectSetMetric.Space.CARTESIAN, 0, all, randomStored, randomQueries);
        }
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CELL, 2, all, randomStored, randomQueries);
    }

    @Test
    @RequiresSharedData
    void memoryTermsThroughTheEncodedPathAsExhaustive() {
        // memory is not packed: the recognizer scans the encoded forms with the k-th best as bound
        List<Scene> remembered = new ArrayList<>();
        for (int i = 0; i < 600; i++) {
            remembered.add(stored.get(i + 1).withPrevious(stored.get(i)));
        }
        List<Scene> rememberedQueries = queries.stream().map(query -> query.withPrevious(queries.get(0))).toList();
        check(Map.of("matching", "optimal", "memory", "0.5", "memory-action", "3"), ObjectSetMetric.Space.CARTESIAN, 0,
                ObjectWeights.DEFAULT, remembered, rememberedQueries);
        check(Map.of("memory", "0.5", "memory-action", "3"), ObjectSetMetric.Space.CARTESIAN, 0,
                ObjectWeights.DEFAULT, remembered, rememberedQueries);
    }

    @Test
    @RequiresSharedData
    void memoryOfActionsPackedAsExhaustive() {
        // chains of up to three earlier scenes, so that memory-depth has actions to compare
        List<Scene> remembered = new ArrayList<>();
        for (int i = 0; i < 600; i++) {
            Scene chain = null;
            for (int j = Math.max(0, i - 2); j <= i; j++) {
                chain = stored.get(j).withHistory(chain);
            }
            remembered.add(stored.get(i + 1).withHistory(chain));
        }
        List<Scene> rememberedQueries = new ArrayList<>();
        for (int q = 0; q < queries.size(); q++) {
            rememberedQueries.add(queries.get(q).withHistory(remembered.get(q * 7 % remembered.size())));
        }
        assertInstanceOf(PackedObjectSets.class,
                metric(Map.of("memory-action", "3"), ObjectSetMetric.Space.CARTESIAN, 0).pack(remembered));
        check(Map.of("memory-action", "3"), ObjectSetMetric.Space.CARTESIAN, 0, ObjectWeights.DEFAULT, remembered, rememberedQueries);
        check(Map.of("memory-action", "30", "memory-depth", "3", "memory-decay", "0.5", "space", "polar"),
                ObjectSetMetric.Space.CARTESIAN, 0, ObjectWeights.DEFAULT, remembered, rememberedQueries);
        check(Map.of("matching", "optimal", "memory-action", "3", "memory-depth", "4"), ObjectSetMetric.Space.CARTESIAN, 0,
                ObjectWeights.DEFAULT, remembered, rememberedQueries);
    }

    @Test
    @RequiresSharedData
    void packedSizePerObjectAndScene() {
        // cartesian: a and b, the penalty follows from them; polar with log-distance stores it; a row weight adds the row
        assertPackedSize(Map.of(), 8);
        assertPackedSize(Map.of("space", "polar", "log-distance", "true"), 12);
        assertPackedSize(Map.of("row-weight", "1"), 12);
    }

    private static void assertPackedSize(Map<String, String> options, int bytesPerObject) {
        ObjectSetMetric metric = metric(options, ObjectSetMetric.Space.CARTESIAN, 0);
        PackedObjectSets packed = (PackedObjectSets) metric.pack(stored);
        long floats = 0;
        for (Scene scene : stored) {
            for (float[] group : metric.encode(scene).groups()) {
                floats += group.length;
            }
        }
        assertEquals(bytesPerObject / 4, metric.stride());
        // the floats (chunks end unused where the next scene did not fit: a few hundred bytes),
        // one start and 9 weighted groups' counts per scene
        long exact = 4 * floats + 13L * stored.size();
        assertTrue(packed.bytes() >= exact && packed.bytes() < exact + 2000, packed.bytes() + " bytes, " + exact + " without gaps");
    }

    private static void check(Map<String, String> options, ObjectSetMetric.Space space, double cycles) {
        check(options, space, cycles, ObjectWeights.DEFAULT);
    }

    private static void check(Map<String, String> options, ObjectSetMetric.Space space, double cycles, ObjectWeights weights) {
        check(options, space, cycles, weights, stored, queries);
    }

    /** Every query against the recognizer at k = 1, 5, 15: same indices, bit-identical distances. */
    private static void check(Map<String, String> options, ObjectSetMetric.Space space, double cycles, ObjectWeights weights,
                              List<Scene> stored, List<Scene> queries) {
        PluginConfig config = PluginConfig.DEFAULT.withOptions(options).withObjectWeights(weights);
        ExhaustiveScan.assertRecognizerAgrees(new ObjectSetMetric(ObjectSetMetric.settings(config, space, cycles)),
                () -> new ObjectSetMetric(ObjectSetMetric.settings(config, space, cycles)), stored, queries,
                options.toString());
    }
}
