package org.example.scenes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginKind;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

/** The plugins are found by name through META-INF/services, as scenes finds them, and behave. */
class MyPluginsTest {
    private final PluginRegistry registry = PluginRegistry.load();

    private static Scene scene(Double ballDistance, double ballDirection, Action action) {
        List<SeenObject> objects = ballDistance == null
                ? List.of(SeenObject.simple(ObjectKind.FLAG, "f c", Relation.NONE, 20, 0, Grid.DEFAULT))
                : List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, ballDistance, ballDirection, Grid.DEFAULT));
        return new Scene(1, Observer.UNKNOWN, objects, action == null ? List.of() : List.of(action));
    }

    @Test
    void metricIsFoundByNameAndMeasuresHowFarTheBallMoved() {
        assertTrue(registry.names(PluginKind.METRIC).contains("my-metric"), registry.names(PluginKind.METRIC).toString());
        SceneMetric metric = registry.metric("my-metric", PluginConfig.DEFAULT);
        // 3 m straight ahead, and 3 m ahead and 4 m to the right (5 m away): 4 m apart
        assertEquals(4, metric.distance(scene(3.0, 0, null), scene(5.0, Math.toDegrees(Math.atan2(4, 3)), null)), 1e-9);
        assertEquals(0, metric.distance(scene(7.0, 12, null), scene(7.0, 12, null)), 1e-12);
        assertEquals(10, metric.distance(scene(7.0, 12, null), scene(null, 0, null)));
        assertEquals(0, metric.distance(scene(null, 0, null), scene(null, 0, null)));
    }

    @Test
    void missingOptionIsReadAndChecked() {
        SceneMetric metric = registry.metric("my-metric", PluginConfig.DEFAULT.withOptions(Map.of("missing", "2.5")));
        assertEquals(2.5, metric.distance(scene(7.0, 12, null), scene(null, 0, null)));
        assertThrows(PluginException.class,
                () -> registry.metric("my-metric", PluginConfig.DEFAULT.withOptions(Map.of("missing", "-1"))));
    }

    @Test
    void selectorTakesTheNearestNeighbourThatHasAnAction() {
        ActionSelector selector = registry.selector("my-selector", PluginConfig.DEFAULT);
        List<Neighbour> nearest = List.of(new Neighbour(scene(1.0, 0, null), 0, 0.5),
                new Neighbour(scene(2.0, 0, Action.turn(30)), 1, 1.0),
                new Neighbour(scene(3.0, 0, Action.dash(80)), 2, 2.0));
        assertEquals(Action.turn(30), selector.select(nearest, new Random(1)));
        assertEquals(null, selector.select(nearest.subList(0, 1), new Random(1)));
    }
}
