package org.scenes.plugins.ballgoal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.ObjectWeights;
import org.scenes.api.Observer;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * The packed scan and the index find the same neighbours at the same distances as an exhaustive
 * scan, on real Krislet scenes (when the shared recordings are present) and on synthetic ones with many ties.
 */
@Tag("slow")
class PackedBallGoalTest {
    private static List<Scene> stored;
    private static List<Scene> queries;

    /** Real scenes when the shared recordings are present (tests on them say so); simulated ones: SimulatedDataTest. */
    @BeforeAll
    static void load() throws IOException {
        if (!SharedData.present()) {
            return;
        }
        Path game = SharedData.resolve("krislet/classic-game1");
        stored = scenes(game.resolve("Carleton_1.lsf.gz"));
        List<Scene> test = scenes(game.resolve("Carleton_2.lsf.gz"));
        queries = new ArrayList<>();
        for (int i = 0; i < 150; i++) {
            queries.add(test.get(i * test.size() / 150));
        }
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
        return scenes;
    }

    private static SceneMetric metric(Map<String, String> options) {
        return PluginRegistry.load().metric("ball-goal", PluginConfig.DEFAULT.withOptions(options));
    }

    @Test
    @RequiresSharedData
    void realScenesArePacked() {
        assertNotNull(((PackedMetric) metric(Map.of())).pack(stored));
    }

    @Test
    @RequiresSharedData
    void memoryTermsAreNotPacked() {
        assertNull(((PackedMetric) metric(Map.of("memory", "0.5"))).pack(stored));
    }

    @Test
    @RequiresSharedData
    void indexIsOptional() {
        assertTrue(((PackedBallGoal) ((PackedMetric) metric(Map.of())).pack(stored)).indexed());
        assertFalse(((PackedBallGoal) ((PackedMetric) metric(Map.of("index", "false"))).pack(stored)).indexed());
        PluginException error = assertThrows(PluginException.class, () -> metric(Map.of("index", "yes")));
        assertTrue(error.getMessage().contains("index"), error.getMessage());
    }

    @Test
    @RequiresSharedData
    void sameNeighboursAsExhaustiveScan() {
        for (PluginConfig config : configs()) {
            assertSameNeighbours(stored, queries, config);
            assertSameNeighbours(stored, queries, config.withOptions(with(config.options(), "index", "false")));
        }
    }

    /** Random keys from few values, so many scenes share a key and many distances tie. */
    @Test
    void sameNeighboursOnSyntheticScenesWithManyTies() {
        Random random = new Random(7);
        List<Scene> synthetic = new ArrayList<>();
        for (int i = 0; i < 40_000; i++) {
            synthetic.add(randomScene(random));
        }
        List<Scene> syntheticQueries = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            syntheticQueries.add(randomScene(random));
        }
        if (SharedData.present()) {
            syntheticQueries.addAll(queries.subList(0, 20));
        }
        for (PluginConfig config : configs()) {
            assertSameNeighbours(synthetic, syntheticQueries, config);
        }
    }

    /** A knowledge base where no scene holds a ball, and one where every scene holds both. */
    @Test
    void sameNeighboursWhenAnObjectIsNeverOrAlwaysSeen() {
        Random random = new Random(11);
        List<Scene> noBall = new ArrayList<>();
        List<Scene> both = new ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            noBall.add(scene(null, 0, random.nextBoolean() ? 20.0 : null, random.nextInt(11) - 5));
            both.add(scene(0.5 + random.nextInt(3) * 4, random.nextInt(21) - 10, 30.0, random.nextInt(21) - 10));
        }
        List<Scene> someQueries = List.of(scene(null, 0, null, 0), scene(4.5, 3, null, 0), scene(null, 0, 20.0, 2),
                scene(8.5, -4, 30.0, 7), scene(0.5, 100, 30.0, -100));
        for (PluginConfig config : configs()) {
            assertSameNeighbours(noBall, someQueries, config);
            assertSameNeighbours(both, someQueries, config);
        }
    }

    /**
     * Directions so large that a difference could overflow: a stored one leaves the knowledge base
     * to the scan, a query's sends that query to the scan; and distances that overflow. All stay exact.
     */
    @Test
    void sameNeighboursWhereTheIndexDoesNotApply() {
        Random random = new Random(13);
        List<Scene> ordinary = new ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            ordinary.add(randomScene(random));
        }
        List<Scene> farQueries = List.of(scene(3.0, 2e300, 12.0, 4), scene(3.0, 4, 12.0, -1e9), scene(null, 0, 40.0, 5e6),
                scene(3.0, Double.POSITIVE_INFINITY, 12.0, Double.NEGATIVE_INFINITY));
        List<Scene> withFarScene = new ArrayList<>(ordinary);
        withFarScene.add(scene(0.5, -3e6, 12.0, 0));
        for (PluginConfig config : List.of(PluginConfig.DEFAULT, PluginConfig.DEFAULT.withOptions(Map.of("angle-weight", "0")))) {
            assertSameNeighbours(ordinary, farQueries, config, true);
            assertSameNeighbours(withFarScene, ordinary.subList(0, 30), config, false);
        }
        // distances that overflow: 2M itself (no index), or weight times cost (the index keeps infinite distances in order)
        assertSameNeighbours(ordinary, ordinary.subList(0, 30), PluginConfig.DEFAULT.withOptions(Map.of("missing", "1e308")), false);
        assertSameNeighbours(ordinary, ordinary.subList(0, 30), PluginConfig.DEFAULT.withObjectWeights(
                withBallGoal(PluginConfig.DEFAULT.objectWeights(), 1e300, 1e300)).withOptions(Map.of("missing", "1e10")), true);
        assertSameNeighbours(ordinary, ordinary.subList(0, 30), PluginConfig.DEFAULT.withObjectWeights(
                withBallGoal(PluginConfig.DEFAULT.objectWeights(), 1e300, 1e300)).withOptions(Map.of("missing", "1e10", "index", "false")), false);
    }

    /** Nearly every scene its own ball key, over a grid of many cells: not worth an index, the scan answers. */
    @Test
    void sameNeighboursWithoutIndexWhenKeysAreAlmostAllDistinct() {
        Grid fine = new Grid(40, -45, 45, new double[] {1, 3, 6, 10, 20});
        Random random = new Random(17);
        List<Scene> distinct = new ArrayList<>();
        for (int i = 0; i < 4000; i++) {
            distinct.add(scene(fine, 0.5 + 30 * random.nextDouble(), 90 * random.nextDouble() - 45,
                    0.5 + 50 * random.nextDouble(), 90 * random.nextDouble() - 45));
        }
        assertSameNeighbours(distinct, distinct.subList(0, 40), PluginConfig.DEFAULT, false);
    }

    /** Default, each option changed, zero weights, both objects left out, and uneven weights. */
    private static List<PluginConfig> configs() {
        PluginConfig base = PluginConfig.DEFAULT;
        ObjectWeights weights = base.objectWeights();
        return List.of(base,
                base.withOptions(Map.of("row-weight", "7")),
                base.withOptions(Map.of("column-weight", "2.5")),
                base.withOptions(Map.of("angle-weight", "3")),
                base.withOptions(Map.of("missing", "3")),
                base.withOptions(Map.of("missing", "3", "angle-weight", "2")),
                base.withOptions(Map.of("angle-weight", "0")),
                base.withOptions(Map.of("column-weight", "0", "row-weight", "0")),
                base.withOptions(Map.of("missing", "0")),
                base.withObjectWeights(withBallGoal(weights, 0, 1)),
                base.withObjectWeights(withBallGoal(weights, 1, 0)),
                base.withObjectWeights(withBallGoal(weights, 0, 0)),
                base.withObjectWeights(withBallGoal(weights, 0.3, 1.7)).withOptions(Map.of("missing", "0.7", "angle-weight", "0.13")));
    }

    private static ObjectWeights withBallGoal(ObjectWeights weights, double ball, double goal) {
        double[] values = weights.toArray();
        values[0] = ball;
        values[1] = goal;
        return ObjectWeights.of(values);
    }

    private static Map<String, String> with(Map<String, String> options, String name, String value) {
        Map<String, String> changed = new HashMap<>(options);
        changed.put(name, value);
        return changed;
    }

    /** Ball and goal each absent, or at one of few distances and integer (some fractional, some signed-zero) directions. */
    private static Scene randomScene(Random random) {
        double[] distances = {0.5, 3, 12, 40};
        double[] odd = {-0.0, 0.0, 7.5, -45.25, 60, Double.NaN};
        Double ball = random.nextInt(5) == 0 ? null : distances[random.nextInt(distances.length)];
        Double goal = random.nextInt(3) == 0 ? null : distances[random.nextInt(distances.length)];
        double ballDirection = random.nextInt(10) == 0 ? odd[random.nextInt(odd.length)] : random.nextInt(61) - 30;
        double goalDirection = random.nextInt(10) == 0 ? odd[random.nextInt(odd.length)] : random.nextInt(41) - 20;
        return scene(ball, ballDirection, goal, goalDirection);
    }

    /** A scene with the given ball and opponent goal (null: not seen), an own goal and a flag, which ball-goal ignores. */
    private static Scene scene(Double ballDistance, double ballDirection, Double goalDistance, double goalDirection) {
        return scene(Grid.DEFAULT, ballDistance, ballDirection, goalDistance, goalDirection);
    }

    private static Scene scene(Grid grid, Double ballDistance, double ballDirection, Double goalDistance, double goalDirection) {
        List<SeenObject> objects = new ArrayList<>();
        objects.add(SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, 20, 3, grid));
        if (ballDistance != null) {
            objects.add(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, ballDistance, ballDirection, grid));
        }
        objects.add(SeenObject.simple(ObjectKind.GOAL, "g l", Relation.OWN, 50, -10, grid));
        if (goalDistance != null) {
            objects.add(SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, goalDistance, goalDirection, grid));
        }
        return new Scene(1, Observer.UNKNOWN, objects, List.of(Action.dash(50)));
    }

    /**
     * The recognizer (through the index, or the scan with index=false) finds the neighbours of an
     * exhaustive scan at k = 1, 5, 15: same indices, same distances bit for bit.
     */
    private static void assertSameNeighbours(List<Scene> base, List<Scene> someQueries, PluginConfig config) {
        assertSameNeighbours(base, someQueries, config, !"false".equals(config.option("index", "true")));
    }

    private static void assertSameNeighbours(List<Scene> base, List<Scene> someQueries, PluginConfig config, boolean indexed) {
        BallGoalMetricProvider.BallGoalMetric metric = (BallGoalMetricProvider.BallGoalMetric) PluginRegistry.load().metric("ball-goal", config);
        assertEquals(indexed, ((PackedBallGoal) metric.pack(base)).indexed(), "index built for " + config);
        List<double[]> encoded = base.stream().map(metric::encode).toList();
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, base);
        int[] ks = {1, 5, 15};
        List<Recognizer> recognizers = new ArrayList<>();
        for (int k : ks) {
            recognizers.add(new Recognizer(knowledge, () -> PluginRegistry.load().metric("ball-goal", config), k));
        }
        for (Scene query : someQueries) {
            List<Neighbour> all = exhaustive(metric, encoded, query);
            for (int r = 0; r < ks.length; r++) {
                int k = ks[r];
                List<Neighbour> expected = all.subList(0, Math.min(k, all.size()));
                List<Neighbour> actual = recognizers.get(r).nearest(query);
                assertEquals(expected.size(), actual.size());
                for (int i = 0; i < expected.size(); i++) {
                    String where = "neighbour " + i + " with " + config.objectWeights() + " " + config.options() + ", k=" + k + ", query " + query.objects();
                    assertEquals(expected.get(i).index(), actual.get(i).index(), where);
                    assertEquals(Double.doubleToLongBits(expected.get(i).distance()), Double.doubleToLongBits(actual.get(i).distance()), where);
                }
            }
        }
    }

    /** Every distance through the metric's encoded distance, sorted by distance then index. */
    private static List<Neighbour> exhaustive(BallGoalMetricProvider.BallGoalMetric metric, List<double[]> encoded, Scene query) {
        double[] q = metric.encode(query);
        List<Neighbour> all = new ArrayList<>();
        for (int i = 0; i < encoded.size(); i++) {
            all.add(new Neighbour(null, i, metric.distance(q, encoded.get(i), Double.POSITIVE_INFINITY)));
        }
        all.sort(Comparator.comparingDouble(Neighbour::distance).thenComparingInt(Neighbour::index));
        return all;
    }
}
