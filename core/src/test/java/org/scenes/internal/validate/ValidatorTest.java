package org.scenes.internal.validate;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.ObjectSetMetric;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.match.TestScenes;
import org.scenes.internal.target.Replay;

class ValidatorTest {
    private static final Supplier<SceneMetric> POLAR = () -> new ObjectSetMetric(ObjectSetMetric.settings(
            PluginConfig.DEFAULT.withOptions(Map.of("space", "polar", "direction-weight", "10")),
            ObjectSetMetric.Space.CARTESIAN, 0));
    private static final Supplier<ActionSelector> FIRST = () -> (nearest, random) -> nearest.get(0).scene().primaryAction();
    /** Picks a neighbour at random: exercises the per-query random streams. */
    private static final Supplier<ActionSelector> RANDOM = () -> (List<Neighbour> nearest, java.util.random.RandomGenerator random)
            -> nearest.get(random.nextInt(nearest.size())).scene().primaryAction();

    static List<Scene> krislet(long seed, int count) {
        java.util.Random random = new java.util.Random(seed);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            double distance = random.nextInt(10) == 0 ? 0.5 : 2 + random.nextInt(40);
            double direction = random.nextInt(3) == 0 ? 0 : random.nextInt(61) - 30;
            scenes.add(TestScenes.krislet(i, distance, direction, random.nextInt(41) - 20));
        }
        return scenes;
    }

    @Test
    void selfValidationOfADeterministicMetricAtKOneIsPerfect() {
        List<Scene> scenes = krislet(1, 400);
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), POLAR, 1);
        ValidationReport report = Validator.run(recognizer, FIRST, scenes, 1, true, null);
        assertEquals(1.0, report.accuracy());
        assertEquals(1.0, report.directionAccuracy());
        assertEquals(report.support(ActionType.KICK), report.truePositives(ActionType.KICK));
        assertEquals(0, report.turnMomentError());
    }

    @Test
    void scenesWithoutActionAreAClassOfTheirOwn() {
        // unanswered sees kept by convert: every fourth scene holds no action
        List<Scene> scenes = new ArrayList<>();
        for (Scene scene : krislet(4, 400)) {
            scenes.add(scene.cycle() % 4 == 3 ? new Scene(scene.cycle(), scene.observer(), scene.objects(), List.of())
                    : scene);
        }
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), POLAR, 1);
        ValidationReport report = Validator.run(recognizer, FIRST, scenes, 1, true, null);
        assertEquals(100, report.support(ActionType.NONE));
        // the nearest scene is itself, unless an earlier twin (the same view) holds an action
        assertTrue(report.truePositives(ActionType.NONE) >= 95, report.truePositives(ActionType.NONE) + " of 100");
        assertTrue(report.accuracy() >= 0.98, "accuracy " + report.accuracy());
        ValidationReport answering = Validator.run(recognizer, () -> (nearest, random) -> org.scenes.api.Action.dash(1),
                scenes, 1, true, null);
        assertEquals(0, answering.truePositives(ActionType.NONE));
        assertEquals(0.0, answering.recall(ActionType.NONE));
    }

    @Test
    void aQueryWithoutUsableActionHasNoDonor() {
        // the selector finds no usable action when the nearest scene's cycle is even, as body-vote among neck-only neighbours
        List<Scene> scenes = krislet(5, 200);
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), POLAR, 1);
        Validator.Donors donors = Validator.Donors.of(scenes.size());
        ValidationReport report = Validator.run(recognizer, () -> (nearest, random) -> nearest.get(0).scene().cycle() % 2 == 0
                ? null : nearest.get(0).scene().primaryAction(), scenes, 1, Replay.RAW, true, null, donors);
        assertEquals(scenes.size(), report.testScenes());
        int without = 0;
        for (int i = 0; i < scenes.size(); i++) {
            int donor = donors.index()[i];
            // scene i is cycle i: a donor is the nearest scene, always of an odd cycle
            assertTrue(donor == -1 || donor % 2 == 1, "query " + i + ": donor " + donor);
            without += donor == -1 ? 1 : 0;
        }
        assertTrue(without > 50 && without < 150, without + " queries without a donor");
    }

    @Test
    void parallelRunsGiveExactlyTheSequentialResults() {
        List<Scene> train = krislet(2, 500);
        List<Scene> test = krislet(3, 300);
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, train), POLAR, 5);
        ValidationReport sequential = Validator.run(recognizer, RANDOM, test, 42, false, null);
        ValidationReport parallel = Validator.run(recognizer, RANDOM, test, 42, true, null);
        ValidationReport otherSeed = Validator.run(recognizer, RANDOM, test, 43, true, null);
        for (ActionType truth : ActionType.values()) {
            for (ActionType predicted : ActionType.values()) {
                assertEquals(sequential.confusion(truth, predicted), parallel.confusion(truth, predicted));
            }
        }
        assertEquals(sequential.turnMomentError(), parallel.turnMomentError());
        assertEquals(sequential.dashPowerError(), parallel.dashPowerError());
        assertTrue(sequential.correct() != otherSeed.correct() || sequential.turnMomentError() != otherSeed.turnMomentError(),
                "the seed matters");
    }

    @Test
    void reportCountsPerActionFiguresAndParameterErrors() {
        Action[] truth = {Action.dash(50), Action.dash(30), Action.turn(20), Action.turn(-10), Action.kick(100, 10), Action.kick(100, 0)};
        Action[] predicted = {Action.dash(40), Action.turn(5), Action.turn(30), Action.turn(10), Action.kick(80, 20), Action.dash(10)};
        ValidationReport report = ValidationReport.of(100, truth, predicted, new long[] {1000, 2000, 3000, 4000, 5000, 100_000});
        assertEquals(4 / 6.0, report.accuracy(), 1e-12);
        assertEquals(3 / 6.0, report.directionAccuracy(), 1e-12, "the turn to the wrong side does not count");
        assertEquals(0.5, report.recall(ActionType.KICK), 1e-12);
        assertEquals(1.0, report.precision(ActionType.KICK), 1e-12);
        assertEquals(2 / 3.0, report.precision(ActionType.TURN), 1e-12);
        assertEquals(0.5, report.turnSignAgreement(), 1e-12);
        assertEquals(15, report.turnMomentError(), 1e-12);
        assertEquals(10, report.dashPowerError(), 1e-12);
        assertEquals(20, report.kickPowerError(), 1e-12);
        assertEquals(10, report.kickDirectionError(), 1e-12);
        double f1Dash = 2 * 0.5 * 0.5 / 1.0;
        double f1Turn = 2 * (2 / 3.0) * 1.0 / (2 / 3.0 + 1.0);
        double f1Kick = 2 * 1.0 * 0.5 / 1.5;
        assertEquals((f1Dash + f1Turn + f1Kick) / 3, report.macroF1(), 1e-12);
        assertEquals(1, report.confusion(ActionType.KICK, ActionType.DASH));
        assertEquals(100_000 / 1000.0, report.p99DecisionMicros(), 1e-9);
        assertEquals((long) (100 * 100_000.0 / report.meanDecisionMicros()), report.scenesPer100ms());
        Map<String, Object> json = report.toMap();
        for (String key : List.of("accuracy", "macroF1", "kick", "perAction", "confusion", "decisionMicros", "scenesPer100ms")) {
            assertTrue(json.containsKey(key), key);
        }
        ValidationReport twice = ValidationReport.pooled(List.of(report, report));
        assertEquals(12, twice.testScenes());
        assertEquals(report.accuracy(), twice.accuracy(), 1e-12);
        assertArrayEquals(new int[] {2, 2}, new int[] {twice.truePositives(ActionType.KICK), twice.support(ActionType.KICK) / 2});
    }
}
