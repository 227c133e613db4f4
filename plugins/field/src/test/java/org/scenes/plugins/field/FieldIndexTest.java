package org.scenes.plugins.field;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

class FieldIndexTest {
    private static final List<String> MODES = List.of("play_on", "kick_off_l", "kick_off_r", "goal_kick_l", "goal_l",
            "before_kick_off");

    /** Random scenes: several play modes and sides, unknown balls, unlocated worlds, and exact duplicates (ties). */
    private static List<Scene> scenes(Random random, int n) {
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (i > 0 && random.nextInt(10) == 0) {
                scenes.add(scenes.get(random.nextInt(i)));
                continue;
            }
            boolean located = random.nextInt(30) != 0;
            boolean ballKnown = random.nextInt(8) != 0;
            double x = located ? random.nextDouble() * 105 - 52.5 : Double.NaN;
            // coarse positions, so many scenes share coordinates and distances tie
            double y = Math.round(random.nextDouble() * 68 - 34);
            World world = new World(x, y, random.nextInt(8) * 45, 0, random.nextGaussian() * 0.2, 0,
                    random.nextInt(3) * 4000, 1, 0, ballKnown ? x + random.nextGaussian() * 10 : Double.NaN,
                    ballKnown ? y + random.nextGaussian() * 10 : Double.NaN, random.nextGaussian(), random.nextGaussian(),
                    0, players(random), MODES.get(random.nextInt(MODES.size())), 0, 0);
            Side side = random.nextBoolean() ? Side.LEFT : Side.RIGHT;
            scenes.add(new Scene(i, new Observer("T", side, 1 + random.nextInt(11)), List.of(), List.of(Action.dash(50)),
                    null, 0, world));
        }
        return scenes;
    }

    /**
     * Half the scenes know a teammate somewhere on the pitch (it is nearer the ball than the player
     * in some), half an opponent (within 10 m of the ball in some).
     */
    private static List<World.Player> players(Random random) {
        List<World.Player> players = new ArrayList<>();
        if (random.nextBoolean()) {
            players.add(new World.Player(Relation.TEAMMATE, 5, random.nextDouble() * 105 - 52.5,
                    random.nextDouble() * 68 - 34, 0));
        }
        if (random.nextBoolean()) {
            players.add(new World.Player(Relation.OPPONENT, 7, random.nextDouble() * 105 - 52.5,
                    random.nextDouble() * 68 - 34, 0));
        }
        return players;
    }

    @Test
    void theIndexFindsTheScansNeighboursBitForBit() {
        Random random = new Random(7);
        List<Scene> stored = scenes(random, 3000);
        List<Scene> queries = new ArrayList<>(scenes(random, 150));
        queries.addAll(stored.subList(0, 50));
        for (Map<String, String> options : List.of(Map.<String, String>of(), Map.of("ball-frame", "body"),
                Map.of("position-weight", "0", "play-mode-penalty", "0.5"), Map.of("opponent-weight", "3"),
                Map.of("placement-penalty", "100"))) {
            assertSameAsScan(stored, queries, options, 1, 5, 15);
        }
    }

    /** Deeper trees, neighbours decoded from the compact store (above 4096 scenes), k of a HELIOS imitator. */
    @Test
    void theIndexFindsTheScansNeighboursInALargerKnowledgeBase() {
        Random random = new Random(11);
        List<Scene> stored = scenes(random, 12_000);
        assertSameAsScan(stored, scenes(random, 120), Map.of(), 1, 10);
    }

    /** One group (play on, ball known and out of reach), so its tree is deep and splits a dimension again and again. */
    @Test
    void theIndexFindsTheScansNeighboursInOneDeepTree() {
        Random random = new Random(13);
        List<Scene> stored = new ArrayList<>();
        for (int i = 0; i < 20_000 + 100; i++) {
            double x = random.nextGaussian() * 15;
            double y = random.nextGaussian() * 10;
            World world = new World(x, y, random.nextDouble() * 360 - 180, 0, 0, 0, 8000 - random.nextInt(3000), 1, 0,
                    x + 2 + Math.abs(random.nextGaussian() * 8), y + random.nextGaussian() * 8, random.nextGaussian() * 0.5,
                    random.nextGaussian() * 0.5, 0, List.of(), "play_on", 0, 0);
            stored.add(new Scene(i, new Observer("T", Side.LEFT, 7), List.of(), List.of(Action.dash(50)), null, 0, world));
        }
        List<Scene> queries = new ArrayList<>(stored.subList(20_000, stored.size()));
        assertSameAsScan(stored.subList(0, 20_000), queries, Map.of(), 1, 10);
    }

    /** Fewer unlocated scenes than k: an unlocated query then gets located ones at {@code missing}, lowest index first. */
    @Test
    void fewerUnlocatedScenesThanKStillRankByIndex() {
        Random random = new Random(5);
        List<Scene> stored = scenes(random, 60);
        List<Scene> queries = scenes(random, 300);
        assertTrue(queries.stream().anyMatch(q -> !q.world().located()), "some queries are unlocated");
        assertTrue(stored.stream().filter(s -> !s.world().located()).count() < 15);
        assertSameAsScan(stored, queries, Map.of(), 1, 15, 60);
    }

    private static void assertSameAsScan(List<Scene> stored, List<Scene> queries, Map<String, String> options, int... ks) {
        PluginConfig config = PluginConfig.DEFAULT.withOptions(options);
        FieldMetricProvider.FieldMetric metric = (FieldMetricProvider.FieldMetric) PluginRegistry.load()
                .metric("field", config);
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, stored);
        for (int k : ks) {
            Recognizer recognizer = new Recognizer(knowledge, () -> PluginRegistry.load().metric("field", config), k);
            for (Scene query : queries) {
                List<Neighbour> expected = exhaustive(metric, stored, query).subList(0, k);
                List<Neighbour> actual = recognizer.nearest(query);
                assertEquals(k, actual.size());
                for (int i = 0; i < k; i++) {
                    String where = "neighbour " + i + ", k=" + k + ", options " + options + ", query " + query.world();
                    assertEquals(expected.get(i).index(), actual.get(i).index(), where);
                    assertEquals(Double.doubleToLongBits(expected.get(i).distance()),
                            Double.doubleToLongBits(actual.get(i).distance()), where);
                }
            }
        }
    }

    @Test
    void theIndexIsUsedUnlessTurnedOff() {
        List<Scene> stored = scenes(new Random(3), 50);
        PluginRegistry registry = PluginRegistry.load();
        assertEquals(FieldIndex.class, ((FieldMetricProvider.FieldMetric) registry.metric("field", PluginConfig.DEFAULT))
                .pack(stored).getClass());
        assertEquals(null, ((FieldMetricProvider.FieldMetric) registry.metric("field",
                PluginConfig.DEFAULT.withOptions(Map.of("index", "false")))).pack(stored));
    }

    private static List<Neighbour> exhaustive(FieldMetricProvider.FieldMetric metric, List<Scene> stored, Scene query) {
        FieldMetricProvider.Features q = metric.encode(query);
        List<Neighbour> all = new ArrayList<>();
        for (int i = 0; i < stored.size(); i++) {
            all.add(new Neighbour(null, i, metric.distance(q, metric.encode(stored.get(i)), Double.POSITIVE_INFINITY)));
        }
        all.sort(Comparator.comparingDouble(Neighbour::distance).thenComparingInt(Neighbour::index));
        return all;
    }
}
