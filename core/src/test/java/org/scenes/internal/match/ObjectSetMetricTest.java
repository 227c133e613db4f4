package org.scenes.internal.match;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

class ObjectSetMetricTest {
    private static ObjectSetMetric metric(Map<String, String> options, ObjectSetMetric.Space space) {
        return new ObjectSetMetric(ObjectSetMetric.settings(PluginConfig.DEFAULT.withOptions(options), space, 0));
    }

    /** The options with more key, value pairs. */
    private static Map<String, String> with(Map<String, String> options, String... pairs) {
        Map<String, String> all = new java.util.HashMap<>(options);
        for (int i = 0; i < pairs.length; i += 2) {
            all.put(pairs[i], pairs[i + 1]);
        }
        return all;
    }

    static void assertTrueMetric(SceneMetric metric, List<Scene> scenes) {
        assertTrue(metric.isTrueMetric());
        for (Scene a : scenes) {
            assertEquals(0, metric.distance(a, a), 1e-9, "identity");
        }
        for (int i = 0; i < scenes.size(); i++) {
            for (int j = 0; j < scenes.size(); j++) {
                double ij = metric.distance(scenes.get(i), scenes.get(j));
                assertEquals(ij, metric.distance(scenes.get(j), scenes.get(i)), 1e-9, "symmetry");
                for (int k = 0; k < scenes.size(); k += 3) {
                    double viaK = metric.distance(scenes.get(i), scenes.get(k)) + metric.distance(scenes.get(k), scenes.get(j));
                    assertTrue(ij <= viaK + 1e-9, "triangle inequality " + i + " " + j + " " + k + ": " + ij + " > " + viaK);
                }
            }
        }
    }

    @Test
    void optimalMatchingIsATrueMetricInEverySpace() {
        List<Scene> scenes = TestScenes.random(7, 36);
        assertTrueMetric(metric(Map.of("matching", "optimal"), ObjectSetMetric.Space.CARTESIAN), scenes);
        assertTrueMetric(metric(Map.of("matching", "optimal", "log-distance", "true", "penalty", "1"),
                ObjectSetMetric.Space.CARTESIAN), scenes);
        assertTrueMetric(metric(Map.of("matching", "optimal", "space", "polar", "direction-weight", "3"),
                ObjectSetMetric.Space.CARTESIAN), scenes);
        assertTrueMetric(metric(Map.of("matching", "optimal", "space", "polar", "direction-weight", "3", "side-weight", "5"),
                ObjectSetMetric.Space.CARTESIAN), scenes);
        assertTrueMetric(metric(Map.of("matching", "optimal", "penalty", "1", "penalty-scale", "1"), ObjectSetMetric.Space.CELL), scenes);
        assertTrueMetric(metric(Map.of("matching", "optimal", "memory", "0.5", "memory-action", "2"),
                ObjectSetMetric.Space.CARTESIAN), scenes);
    }

    @Test
    void greedyIsNotClaimedAndAPenaltyTooSteepIsNotEither() {
        assertFalse(metric(Map.of(), ObjectSetMetric.Space.CARTESIAN).isTrueMetric());
        assertFalse(metric(Map.of("matching", "optimal", "penalty", "50", "penalty-scale", "5"),
                ObjectSetMetric.Space.CARTESIAN).isTrueMetric());
    }

    @Test
    void greedyIsZeroOnIdenticalScenesAndSymmetric() {
        ObjectSetMetric greedy = metric(Map.of(), ObjectSetMetric.Space.CARTESIAN);
        List<Scene> scenes = TestScenes.random(3, 20);
        for (Scene a : scenes) {
            assertEquals(0, greedy.distance(a, a), 1e-12);
            for (Scene b : scenes) {
                assertEquals(greedy.distance(a, b), greedy.distance(b, a), 1e-9);
            }
        }
    }

    @Test
    void optimalPairingBeatsTheGreedyHeuristicOnConcyclicObjects() {
        // two flags at the same distance: greedy pairs them in list order, crossing over
        Scene a = TestScenes.scene(1, null, TestScenes.flag(10, -40), TestScenes.flag(10.1, 40));
        Scene b = TestScenes.scene(2, null, TestScenes.flag(10, 40), TestScenes.flag(10.1, -40));
        double greedy = metric(Map.of(), ObjectSetMetric.Space.CARTESIAN).distance(a, b);
        double optimal = metric(Map.of("matching", "optimal"), ObjectSetMetric.Space.CARTESIAN).distance(a, b);
        assertTrue(optimal < 0.5, "optimal pairs like with like: " + optimal);
        assertTrue(greedy > 10, "greedy crosses over: " + greedy);
    }

    @Test
    void unmatchedObjectsCostMoreWhenNear() {
        ObjectSetMetric metric = metric(Map.of(), ObjectSetMetric.Space.CARTESIAN);
        Scene empty = TestScenes.scene(1, null);
        double near = metric.distance(empty, TestScenes.scene(2, null, TestScenes.ball(1, 0)));
        double far = metric.distance(empty, TestScenes.scene(2, null, TestScenes.ball(50, 0)));
        assertEquals(10 * 10 / 11.0, near, 1e-5, "penalties are stored as 32-bit floats");
        assertTrue(near > far);
    }

    @Test
    void classesOnlyMatchTheirOwnKindAndWeightsScaleThem() {
        Scene teammate = TestScenes.scene(1, null, TestScenes.player(Relation.TEAMMATE, 5, 0));
        Scene opponent = TestScenes.scene(2, null, TestScenes.player(Relation.OPPONENT, 5, 0));
        ObjectSetMetric byTeam = metric(Map.of(), ObjectSetMetric.Space.CARTESIAN);
        assertEquals(2 * 10 * 10 / 15.0, byTeam.distance(teammate, opponent), 1e-5, "penalties are 32-bit floats");
        ObjectSetMetric allPlayers = new ObjectSetMetric(ObjectSetMetric.settings(
                PluginConfig.DEFAULT.withObjectWeights(ObjectWeights.parse("players=1")), ObjectSetMetric.Space.CARTESIAN, 0));
        assertEquals(0, allPlayers.distance(teammate, opponent), 1e-12);
    }

    @Test
    void projectionMovesObjectsByTheirChanges() {
        // changes +0.1 m and -0.5 degrees per cycle: after 10 cycles the player is at 11 m, -5 degrees
        Scene now = TestScenes.scene(1, null, TestScenes.player(Relation.OPPONENT, 10, 0));
        Scene later = TestScenes.scene(2, null, org.scenes.api.SeenObject.simple(org.scenes.api.ObjectKind.PLAYER, "p",
                Relation.OPPONENT, 11, -5, org.scenes.api.Grid.DEFAULT));
        ObjectSetMetric direct = metric(Map.of("space", "polar"), ObjectSetMetric.Space.CARTESIAN);
        ObjectSetMetric projected = new ObjectSetMetric(ObjectSetMetric.settings(
                PluginConfig.DEFAULT.withOptions(Map.of("cycles", "10", "space", "polar")), ObjectSetMetric.Space.CARTESIAN, 1));
        assertEquals(6, direct.distance(now, later), 1e-9);
        assertEquals(0, projected.distance(now, later), 1e-9);
    }

    @Test
    void memoryWeighsThePreviousSceneAndAction() {
        Scene before = TestScenes.scene(1, Action.turn(-30), TestScenes.ball(5, -30));
        Scene beforeOther = TestScenes.scene(1, Action.turn(30), TestScenes.ball(5, -30));
        Scene now = TestScenes.scene(2, Action.turn(-10), TestScenes.ball(5, -10));
        ObjectSetMetric memory = metric(Map.of("memory-action", "7"), ObjectSetMetric.Space.CARTESIAN);
        assertEquals(0, memory.distance(now.withPrevious(before), now.withPrevious(before)), 1e-12);
        assertEquals(7, memory.distance(now.withPrevious(before), now.withPrevious(beforeOther)), 1e-12);
        ObjectSetMetric objects = metric(Map.of("memory", "2"), ObjectSetMetric.Space.CARTESIAN);
        double expected = 2 * objects.distance(before, TestScenes.scene(1, null, TestScenes.ball(5, -10)));
        assertEquals(expected, objects.distance(now.withPrevious(before), now.withPrevious(now)), 1e-9);
    }

    @Test
    void thePreviousSceneHasItsOwnDirectionWeight() {
        // the two previous scenes differ by 20 degrees of ball direction, the current ones by 4
        Scene a = TestScenes.scene(2, Action.turn(-10), TestScenes.ball(5, -10))
                .withPrevious(TestScenes.scene(1, null, TestScenes.ball(5, -30)));
        Scene b = TestScenes.scene(2, Action.turn(-10), TestScenes.ball(5, -6))
                .withPrevious(TestScenes.scene(1, null, TestScenes.ball(5, -10)));
        ObjectSetMetric same = metric(Map.of("space", "polar", "direction-weight", "100", "memory", "0.5"),
                ObjectSetMetric.Space.CARTESIAN);
        assertEquals(100 * 4 + 0.5 * 100 * 20, same.distance(a, b), 1e-6, "by default the direction weight of both");
        ObjectSetMetric own = metric(Map.of("space", "polar", "direction-weight", "100", "memory", "0.5",
                "memory-direction-weight", "3"), ObjectSetMetric.Space.CARTESIAN);
        assertEquals(100 * 4 + 0.5 * 3 * 20, own.distance(a, b), 1e-6);
        assertThrows(org.scenes.api.PluginException.class, () -> metric(Map.of("memory-direction-weight", "-1"),
                ObjectSetMetric.Space.CARTESIAN));
    }

    @Test
    void sideWeightSeparatesLeftAheadAndRight() {
        Scene ahead = TestScenes.scene(1, Action.dash(50), TestScenes.ball(8, 0));
        Scene right = TestScenes.scene(2, Action.turn(1), TestScenes.ball(8, 1));
        Scene farRight = TestScenes.scene(3, Action.turn(9), TestScenes.ball(8, 9));
        Scene left = TestScenes.scene(4, Action.turn(-1), TestScenes.ball(8, -1));
        Map<String, String> polar = Map.of("space", "polar", "direction-weight", "10");
        ObjectSetMetric plain = metric(polar, ObjectSetMetric.Space.CARTESIAN);
        ObjectSetMetric sided = metric(with(polar, "side-weight", "300"), ObjectSetMetric.Space.CARTESIAN);
        assertEquals(plain.distance(ahead, right) + 300, sided.distance(ahead, right), 1e-3, "ahead against right");
        assertEquals(plain.distance(left, right) + 300, sided.distance(left, right), 1e-3, "left against right");
        assertEquals(plain.distance(ahead, left) + 300, sided.distance(ahead, left), 1e-3, "ahead against left");
        assertEquals(plain.distance(right, farRight), sided.distance(right, farRight), 1e-3, "the same side costs nothing more");
        // 1 degree off the heading and dead ahead now differ more than 8 degrees on one side
        assertTrue(sided.distance(ahead, right) > sided.distance(right, farRight));
        assertTrue(plain.distance(ahead, right) < plain.distance(right, farRight));
        ObjectSetMetric wide = metric(with(polar, "side-weight", "300", "ahead-width", "3"), ObjectSetMetric.Space.CARTESIAN);
        assertEquals(plain.distance(ahead, right), wide.distance(ahead, right), 1e-3, "within 1.5 degrees is ahead");
        assertThrows(org.scenes.api.PluginException.class, () -> metric(Map.of("side-weight", "-1"),
                ObjectSetMetric.Space.CARTESIAN));
    }

    @Test
    void theOwnGoalHasItsShareOfTheGoalWeight() {
        Scene both = TestScenes.scene(1, Action.dash(50), TestScenes.ball(8, 0), TestScenes.goal(30, 10),
                TestScenes.ownGoal(40, -170));
        Scene opponentOnly = TestScenes.scene(2, Action.dash(50), TestScenes.ball(8, 0), TestScenes.goal(30, 12));
        Scene ownMoved = TestScenes.scene(3, Action.dash(50), TestScenes.ball(8, 0), TestScenes.goal(30, 10),
                TestScenes.ownGoal(20, -150));
        Map<String, String> options = Map.of("space", "polar", "penalty", "1000");
        ObjectSetMetric whole = metric(options, ObjectSetMetric.Space.CARTESIAN);
        ObjectSetMetric half = metric(with(options, "own-goal-weight", "0.5"), ObjectSetMetric.Space.CARTESIAN);
        ObjectSetMetric none = metric(with(options, "own-goal-weight", "0"), ObjectSetMetric.Space.CARTESIAN);
        double opponentGoal = none.distance(both, opponentOnly);
        assertEquals(2, opponentGoal, 1e-4, "the opponent goal's 2 degrees alone");
        double ownGoal = whole.distance(both, opponentOnly) - opponentGoal;
        assertTrue(ownGoal > 100, "a missing own goal costs its penalty: " + ownGoal);
        assertEquals(opponentGoal + ownGoal / 2, half.distance(both, opponentOnly), 1e-3);
        assertEquals(0, none.distance(both, ownMoved), 1e-9);
        assertTrue(whole.distance(both, ownMoved) > 20);
        assertThrows(org.scenes.api.PluginException.class, () -> metric(Map.of("own-goal-weight", "-0.5"),
                ObjectSetMetric.Space.CARTESIAN));
    }

    @Test
    void thePreviousSceneHasItsOwnRowWeight() {
        // the balls are 1 row apart now (4.5 and 5.5 m across the 5 m ring) and one row apart before
        Scene a = TestScenes.scene(2, Action.turn(1), TestScenes.ball(4.5, 1))
                .withPrevious(TestScenes.scene(1, null, TestScenes.ball(5.5, 1)));
        Scene b = TestScenes.scene(2, Action.turn(1), TestScenes.ball(5.5, 1))
                .withPrevious(TestScenes.scene(1, null, TestScenes.ball(4.5, 1)));
        Map<String, String> polar = Map.of("space", "polar", "distance-weight", "0", "row-weight", "100", "memory", "0.5");
        assertEquals(100 + 0.5 * 100, metric(polar, ObjectSetMetric.Space.CARTESIAN).distance(a, b), 1e-6,
                "by default the row weight of both");
        assertEquals(100 + 0.5 * 10, metric(with(polar, "memory-row-weight", "10"), ObjectSetMetric.Space.CARTESIAN)
                .distance(a, b), 1e-6);
        Map<String, String> memoryRowsOnly = with(polar, "row-weight", "0", "memory-row-weight", "10");
        assertEquals(0.5 * 10, metric(memoryRowsOnly, ObjectSetMetric.Space.CARTESIAN).distance(a, b), 1e-6);
    }

    @Test
    void deeperMemoryWeighsEarlierActionsWithDecay() {
        Scene third = TestScenes.scene(1, Action.dash(50), TestScenes.ball(5, 0));
        Scene thirdOther = TestScenes.scene(1, Action.kick(50, 0), TestScenes.ball(5, 0));
        Scene second = TestScenes.scene(2, Action.turn(-30), TestScenes.ball(5, -30));
        Scene now = TestScenes.scene(3, Action.turn(-10), TestScenes.ball(5, -10));
        Scene a = now.withHistory(second.withHistory(third));
        Scene b = now.withHistory(second.withHistory(thirdOther));
        ObjectSetMetric oneBack = metric(Map.of("memory-action", "8"), ObjectSetMetric.Space.CARTESIAN);
        assertEquals(0, oneBack.distance(a, b), 1e-12, "depth 1 compares the previous action only");
        ObjectSetMetric twoBack = metric(Map.of("memory-action", "8", "memory-depth", "2", "memory-decay", "0.25"),
                ObjectSetMetric.Space.CARTESIAN);
        assertEquals(2, twoBack.distance(a, b), 1e-12, "the action two back costs 8 · 0.25");
        assertEquals(2, twoBack.distance(a, now.withHistory(second)), 1e-12, "a chain that ends differs from any action");
        assertThrows(org.scenes.api.PluginException.class,
                () -> metric(Map.of("memory-depth", "0"), ObjectSetMetric.Space.CARTESIAN));
        // the exact index compares one action back only, so deeper memory scans: same neighbours as the plain scan
        List<Scene> stored = List.of(b, a, now.withHistory(second));
        List<Neighbour> nearest = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), () -> twoBack, 3).nearest(a);
        assertEquals(List.of(1, 0, 2), nearest.stream().map(Neighbour::index).toList());
        assertEquals(2, nearest.get(1).distance(), 1e-12);
    }

    @Test
    void assignmentFindsTheCheapestPerfectMatching() {
        double[] cost = {4, 1, 3, 2, 0, 5, 3, 2, 2};
        assertEquals(5, Assignment.minimumCost(cost, 3), 1e-12);
        assertEquals(0, Assignment.minimumCost(new double[0], 0));
    }
}
