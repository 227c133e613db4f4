package org.scenes.plugins.ballgoal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

class BallGoalMetricTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    private static Scene scene(Double ballDistance, double ballDirection, Double goalDistance, double goalDirection, Action action) {
        List<SeenObject> objects = new ArrayList<>();
        if (ballDistance != null) {
            objects.add(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, ballDistance, ballDirection, Grid.DEFAULT));
        }
        if (goalDistance != null) {
            objects.add(SeenObject.simple(ObjectKind.GOAL, "g r", Relation.OPPONENT, goalDistance, goalDirection, Grid.DEFAULT));
        }
        objects.add(SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, 20, 3, Grid.DEFAULT));
        return new Scene(1, Observer.UNKNOWN, objects, List.of(action));
    }

    private static List<Scene> randomScenes(long seed, int count) {
        Random random = new Random(seed);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            Scene scene = scene(random.nextBoolean() ? 0.3 + 40 * random.nextDouble() : null, random.nextInt(91) - 45,
                    random.nextBoolean() ? 0.3 + 60 * random.nextDouble() : null, random.nextInt(91) - 45,
                    random.nextBoolean() ? Action.turn(random.nextInt(91) - 45) : Action.dash(50));
            scenes.add(i > 0 ? scene.withPrevious(scenes.get(i - 1)) : scene);
        }
        return scenes;
    }

    @Test
    void isATrueMetricWithAndWithoutMemory() {
        for (Map<String, String> options : List.of(Map.<String, String>of(), Map.of("memory", "0.5", "memory-action", "3"))) {
            SceneMetric metric = REGISTRY.metric("ball-goal", PluginConfig.DEFAULT.withOptions(options));
            assertTrue(metric.isTrueMetric());
            List<Scene> scenes = randomScenes(5, 40);
            for (Scene a : scenes) {
                assertEquals(0, metric.distance(a, a), 1e-12);
                for (Scene b : scenes) {
                    double ab = metric.distance(a, b);
                    assertEquals(ab, metric.distance(b, a), 1e-12);
                    for (Scene c : scenes) {
                        assertTrue(ab <= metric.distance(a, c) + metric.distance(c, b) + 1e-9);
                    }
                }
            }
        }
    }

    @Test
    void rowsWeighMoreThanColumnsAndOtherObjectsDoNotCount() {
        SceneMetric metric = REGISTRY.metric("ball-goal", PluginConfig.DEFAULT.withOptions(Map.of("angle-weight", "0")));
        Scene base = scene(3.0, 0, 30.0, 0, Action.dash(30));
        // ball one row nearer (0.5 m is in the kickable row) vs one column to the right (20 degrees)
        assertEquals(3, metric.distance(base, scene(0.5, 0, 30.0, 0, Action.dash(30))), 1e-12);
        assertEquals(1, metric.distance(base, scene(3.0, 20, 30.0, 0, Action.dash(30))), 1e-12);
        assertEquals(10, metric.distance(base, scene(3.0, 0, null, 0, Action.dash(30))), 1e-12);
        SceneMetric angles = REGISTRY.metric("ball-goal", PluginConfig.DEFAULT.withOptions(Map.of("angle-weight", "2")));
        assertEquals(0.2, angles.distance(base, scene(3.0, 1, 30.0, 0, Action.dash(30))), 1e-12);
    }
}
