package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.testing.RequiresSharedData;
import org.scenes.testing.SharedData;

/**
 * The exact index of low-dimensional object-set configurations (ball and goals, with or without
 * memory terms) finds the same neighbours at bit-identical distances as the exhaustive scan,
 * for every space, both matchings and k = 1, 5, 15; on synthetic scenes with many ties and
 * duplicates, and on real Krislet scenes; also with the nearest player of each kind weighed
 * ({@code nearest-players}).
 */
@Tag("slow")
class LowDimensionalIndexTest {
    private static final ObjectWeights BALL_GOAL = ObjectWeights.parse("ball=1,goal=0.05");
    /** Ball, goals and the nearest teammate and opponent (with {@code nearest-players}). */
    private static final ObjectWeights NEAREST = ObjectWeights.parse("ball=1,goal=0.05,teammates=0.3,opponents=0.5");
    /** Ball and the nearest player regardless of team. */
    private static final ObjectWeights ANY_PLAYER = ObjectWeights.parse("ball=1,players=0.4");


    /** The configuration `scenes tune --objective direction` chose for Krislet (README). */
    private static final Map<String, String> TUNED = Map.of("space", "polar", "log-distance", "true",
            "distance-weight", "30", "direction-weight", "10", "row-weight", "1000", "penalty", "20000",
            "penalty-scale", "10000", "memory-action", "100");

    private static final List<Map<String, String>> CONFIGURATIONS = List.of(
            TUNED,
            Map.of(),
            Map.of("matching", "optimal"),
            Map.of("space", "polar", "row-weight", "2", "memory", "0.5"),
            Map.of("matching", "optimal", "space", "polar", "log-distance", "true", "memory", "0.3", "memory-action", "7"),
            Map.of("matching", "optimal", "penalty", "0.5", "penalty-scale", "3"),
            Map.of("memory-action", "3", "row-weight", "1"),
            Map.of("space", "polar", "direction-weight", "100", "memory-direction-weight", "10", "memory", "0.3",
                    "memory-action", "1000"),
            with(with(with(with(TUNED, "side-weight", "300"), "memory", "0.7"), "memory-direction-weight", "3"),
                    "memory-row-weight", "300"),
            Map.of("row-weight", "0", "memory-row-weight", "5", "memory", "1", "space", "polar"),
            Map.of("side-weight", "4", "row-weight", "1", "matching", "optimal", "memory", "0.5", "own-goal-weight", "0.3"));

    /** Configurations with the nearest player of each kind, with and without memory terms. */
    private static final List<Map<String, String>> NEAREST_CONFIGURATIONS = List.of(
            with(TUNED, "nearest-players", "true"),
            Map.of("nearest-players", "true"),
            Map.of("nearest-players", "true", "matching", "optimal", "memory", "0.5"),
            Map.of("nearest-players", "true", "space", "polar", "log-distance", "true", "memory", "0.3", "memory-action", "7"));

    @Test
    void syntheticScenesAsExhaustive() {
        List<Scene> stored = remembered(synthetic(21, 3000));
        List<Scene> queries = remembered(synthetic(22, 60));
        for (Map<String, String> options : CONFIGURATIONS) {
            check(options, ObjectSetMetric.Space.CARTESIAN, 0, stored, queries);
        }
        check(Map.of(), ObjectSetMetric.Space.CELL, 0, stored, queries);
        check(Map.of("matching", "optimal", "memory-action", "2"), ObjectSetMetric.Space.CELL, 0, stored, queries);
        check(Map.of(), ObjectSetMetric.Space.CARTESIAN, 1, stored, queries);
        check(Map.of("memory", "1", "matching", "optimal"), ObjectSetMetric.Space.CARTESIAN, -2, stored, queries);
    }

    @Test
    void nearestPlayersAsExhaustive() {
        List<Scene> stored = remembered(withPlayers(51, synthetic(51, 2500)));
        List<Scene> queries = remembered(withPlayers(52, synthetic(52, 50)));
        for (Map<String, String> options : NEAREST_CONFIGURATIONS) {
            check(options, ObjectSetMetric.Space.CARTESIAN, 0, NEAREST, stored, queries);
        }
        check(Map.of("nearest-players", "true", "memory-action", "2"), ObjectSetMetric.Space.CELL, 0, NEAREST, stored, queries);
        check(Map.of("nearest-players", "true", "matching", "optimal"), ObjectSetMetric.Space.CARTESIAN, 1, ANY_PLAYER,
                stored, queries);
    }

    @Test
    void nearestPlayersKeepOnlyTheNearestOfEachKind() {
        Scene far = TestScenes.scene(1, Action.dash(50), TestScenes.ball(5, 0),
                TestScenes.player(Relation.TEAMMATE, 3, 10), TestScenes.player(Relation.TEAMMATE, 30, -40));
        Scene near = TestScenes.scene(2, Action.dash(50), TestScenes.ball(5, 0), TestScenes.player(Relation.TEAMMATE, 3, 10));
        ObjectWeights teammates = ObjectWeights.parse("ball=1,teammates=1");
        ObjectSetMetric nearest = metric(Map.of("nearest-players", "true"), ObjectSetMetric.Space.CARTESIAN, 0, teammates, true);
        ObjectSetMetric every = metric(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0, teammates, true);
        assertEquals(0.0, nearest.distance(far, near), 0.0); // the far teammate is not compared
        assertTrue(every.distance(far, near) > 0);
        assertInstanceOf(LowDimensionalIndex.class, nearest.pack(List.of(far, near)));
        assertInstanceOf(PackedObjectSets.class, every.pack(List.of(far, near)));
    }

    @Test
    void queriesWithSeveralObjectsOfAGroupAreStillExact() {
        // the index covers the stored scenes; a query seeing two balls has no bound there, yet the same result
        List<Scene> stored = remembered(synthetic(31, 1500));
        List<Scene> queries = new ArrayList<>();
        for (Scene query : synthetic(32, 20)) {
            List<SeenObject> objects = new ArrayList<>(query.objects());
            objects.add(TestScenes.ball(3, 10));
            objects.add(TestScenes.goal(30, -20));
            queries.add(new Scene(query.cycle(), query.observer(), objects, query.actions()).withPrevious(stored.get(7)));
        }
        check(TUNED, ObjectSetMetric.Space.CARTESIAN, 0, stored, queries);
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CARTESIAN, 0, stored, queries);
    }

    @Test
    void builtOnlyForGroupsOfOneObjectAndUnlessTurnedOff() {
        List<Scene> stored = synthetic(41, 200);
        ObjectSetMetric indexed = metric(TUNED, ObjectSetMetric.Space.CARTESIAN, 0, BALL_GOAL, true);
        assertInstanceOf(LowDimensionalIndex.class, indexed.pack(stored));
        ObjectSetMetric scanned = metric(TUNED, ObjectSetMetric.Space.CARTESIAN, 0, BALL_GOAL, false);
        assertInstanceOf(PackedObjectSets.class, scanned.pack(stored)); // memory of actions packs too
        assertInstanceOf(PackedObjectSets.class, metric(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0, BALL_GOAL, false).pack(stored));
        // flags weighed: several per scene, no index
        ObjectSetMetric flags = metric(Map.of(), ObjectSetMetric.Space.CARTESIAN, 0, ObjectWeights.parse("ball=1,flag=1"), true);
        List<Scene> withFlags = TestScenes.random(5, 200);
        assertInstanceOf(PackedObjectSets.class, flags.pack(withFlags));
        // duplicates are one point: far fewer points than scenes
        LowDimensionalIndex index = (LowDimensionalIndex) indexed.pack(stored);
        assertTrue(index.points() < stored.size(), index.points() + " points");
    }

    @Test
    void manyRowsAndSidesKeepTheIndexExactOrFallBack() {
        // 30 distance rows: 30 row values alone fit a node's 64 bits, with the three sides (90) they do not
        double[] bounds = new double[29];
        for (int i = 0; i < bounds.length; i++) {
            bounds[i] = 1 + i;
        }
        Grid fine = Grid.of(5, bounds);
        Random random = new Random(61);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < 1600; i++) {
            SeenObject ball = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 0.5 + random.nextInt(70) / 2.0,
                    random.nextInt(61) - 30, fine);
            Action action = random.nextBoolean() ? Action.dash(random.nextInt(100)) : Action.turn(random.nextInt(61) - 30);
            scenes.add(new Scene(i, TestScenes.OBSERVER, List.of(ball), List.of(action)));
        }
        List<Scene> stored = remembered(scenes.subList(0, 1500));
        List<Scene> queries = remembered(scenes.subList(1500, 1600));
        Map<String, String> rows = Map.of("space", "polar", "row-weight", "3", "memory", "0.3", "memory-action", "5");
        check(rows, ObjectSetMetric.Space.CARTESIAN, 0, stored, queries);
        Map<String, String> sides = with(rows, "side-weight", "7");
        assertInstanceOf(PackedObjectSets.class, metric(with(sides, "memory", "0"), ObjectSetMetric.Space.CARTESIAN, 0,
                BALL_GOAL, true).pack(stored), "90 tuples: the scan serves");
        ExhaustiveScan.assertRecognizerAgrees(metric(sides, ObjectSetMetric.Space.CARTESIAN, 0, BALL_GOAL, false),
                () -> metric(sides, ObjectSetMetric.Space.CARTESIAN, 0, BALL_GOAL, true), stored, queries, "90 tuples");
    }

    @Test
    @RequiresSharedData
    void krisletScenesAsExhaustive() throws IOException {
        Path game = SharedData.resolve("krislet/classic-game1");
        List<Scene> stored = remembered(scenes(game.resolve("Carleton_1.lsf.gz")));
        List<Scene> test = remembered(scenes(game.resolve("Carleton_2.lsf.gz")));
        List<Scene> queries = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            queries.add(test.get(i * test.size() / 60));
        }
        for (Map<String, String> options : CONFIGURATIONS) {
            check(options, ObjectSetMetric.Space.CARTESIAN, 0, stored, queries);
        }
        check(Map.of("matching", "optimal"), ObjectSetMetric.Space.CELL, 0, stored, queries);
        check(Map.of(), ObjectSetMetric.Space.CARTESIAN, 1, stored, queries);
        for (Map<String, String> options : NEAREST_CONFIGURATIONS) {
            check(options, ObjectSetMetric.Space.CARTESIAN, 0, NEAREST, stored, queries);
        }
    }

    private static Map<String, String> with(Map<String, String> options, String key, String value) {
        Map<String, String> all = new HashMap<>(options);
        all.put(key, value);
        return Map.copyOf(all);
    }

    /** The scenes with zero to three teammates and opponents each, at quantised places (so nearest ones tie and repeat). */
    private static List<Scene> withPlayers(long seed, List<Scene> scenes) {
        Random random = new Random(seed);
        List<Scene> result = new ArrayList<>();
        for (Scene scene : scenes) {
            List<SeenObject> objects = new ArrayList<>(scene.objects());
            for (Relation relation : new Relation[] {Relation.TEAMMATE, Relation.OPPONENT}) {
                int count = random.nextInt(4);
                for (int i = 0; i < count; i++) {
                    objects.add(TestScenes.player(relation, 1 + random.nextInt(30), 10 * (random.nextInt(9) - 4)));
                }
            }
            result.add(new Scene(scene.cycle(), scene.observer(), objects, scene.actions()));
        }
        return result;
    }

    private static List<Scene> scenes(Path log) throws IOException {
        List<Scene> scenes = new ArrayList<>();
        SceneConverter.with(Grid.DEFAULT).build().convert(log, scenes::add);
        return scenes;
    }

    /** Each scene with the one before it remembered, as the memory transform does. */
    private static List<Scene> remembered(List<Scene> scenes) {
        List<Scene> result = new ArrayList<>();
        for (int i = 0; i < scenes.size(); i++) {
            result.add(i == 0 ? scenes.get(i) : scenes.get(i).withPrevious(scenes.get(i - 1)));
        }
        return result;
    }

    /**
     * Krislet-like scenes: a ball, own and opponent goals each sometimes missing, positions
     * quantised as the server does (so many scenes repeat), flags that are never weighed.
     */
    private static List<Scene> synthetic(long seed, int count) {
        Random random = new Random(seed);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            List<SeenObject> objects = new ArrayList<>();
            if (random.nextInt(5) > 0) {
                objects.add(TestScenes.ball(Math.round((0.2 + random.nextDouble() * 20) * 2) / 2.0, random.nextInt(31) - 15));
            }
            if (random.nextInt(3) > 0) {
                objects.add(TestScenes.goal(Math.round(5 + random.nextDouble() * 60), 5 * (random.nextInt(13) - 6)));
            }
            if (random.nextInt(4) == 0) {
                objects.add(SeenObject.simple(ObjectKind.GOAL, "g l", Relation.OWN, Math.round(10 + random.nextDouble() * 50),
                        5 * (random.nextInt(13) - 6), Grid.DEFAULT));
            }
            objects.add(TestScenes.flag(1 + random.nextInt(40), random.nextInt(91) - 45));
            Action action = switch (random.nextInt(4)) {
                case 0, 1 -> Action.dash(random.nextInt(100));
                case 2 -> Action.turn(random.nextInt(3) * 30 - 30);
                default -> Action.kick(100, random.nextInt(91) - 45);
            };
            scenes.add(new Scene(i, TestScenes.OBSERVER, objects, List.of(action)));
        }
        return scenes;
    }

    private static ObjectSetMetric metric(Map<String, String> options, ObjectSetMetric.Space space, double cycles,
                                          ObjectWeights weights, boolean indexed) {
        Map<String, String> all = new HashMap<>(options);
        all.put("index", Boolean.toString(indexed));
        return ObjectSetMetric.create(PluginConfig.DEFAULT.withOptions(all).withObjectWeights(weights), space, cycles);
    }

    private static void check(Map<String, String> options, ObjectSetMetric.Space space, double cycles,
                              List<Scene> stored, List<Scene> queries) {
        check(options, space, cycles, BALL_GOAL, stored, queries);
    }

    /** Every query against the recognizer at k = 1, 5, 15: same indices, bit-identical distances. */
    private static void check(Map<String, String> options, ObjectSetMetric.Space space, double cycles, ObjectWeights weights,
                              List<Scene> stored, List<Scene> queries) {
        assertInstanceOf(LowDimensionalIndex.class, metric(options, space, cycles, weights, true).pack(stored),
                "the index serves " + options + " " + weights);
        ExhaustiveScan.assertRecognizerAgrees(metric(options, space, cycles, weights, false),
                () -> metric(options, space, cycles, weights, true), stored, queries,
                options + ", space " + space + ", cycles " + cycles);
    }
}
