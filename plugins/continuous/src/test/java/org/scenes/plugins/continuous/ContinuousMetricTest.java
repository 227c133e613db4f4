package org.scenes.plugins.continuous;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

class ContinuousMetricTest {
    private static final PluginRegistry REGISTRY = PluginRegistry.load();

    private static Scene ball(double distance, double direction) {
        return new Scene(1, Observer.UNKNOWN,
                List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT)), List.of());
    }

    @Test
    void comparesCartesianPositionsByDefault() {
        SceneMetric metric = REGISTRY.metric("continuous", PluginConfig.DEFAULT);
        assertFalse(metric.isTrueMetric(), "greedy by default");
        // 10 m ahead vs 10 m at 90 degrees: the straight line between them is 10 * sqrt(2)
        assertEquals(10 * Math.sqrt(2), metric.distance(ball(10, 0), ball(10, 90)), 1e-5, "single precision");
        assertEquals(0, metric.distance(ball(10, 0), ball(10, 0)));
    }

    @Test
    void polarLogDistancesAndDirectionWeight() {
        Map<String, String> options = Map.of("space", "polar", "log-distance", "true", "direction-weight", "10", "matching", "optimal");
        SceneMetric metric = REGISTRY.metric("continuous", PluginConfig.DEFAULT.withOptions(options));
        // the default penalty changes faster with ln(1 + r) than the pair cost does: not claimed
        assertFalse(metric.isTrueMetric());
        java.util.Map<String, String> gentle = new java.util.HashMap<>(options);
        gentle.put("penalty", "1");
        assertTrue(REGISTRY.metric("continuous", PluginConfig.DEFAULT.withOptions(gentle)).isTrueMetric());
        // optimal pairing never pays more for a pair than leaving both unmatched: 10*10/12 + 10*10/20
        // (penalties and positions are stored as 32-bit floats)
        assertEquals(100 / 12.0 + 5, metric.distance(ball(2, 0), ball(10, 5)), 1e-5);
        SceneMetric greedy = REGISTRY.metric("continuous", PluginConfig.DEFAULT.withOptions(
                Map.of("space", "polar", "log-distance", "true", "direction-weight", "10")));
        assertEquals(Math.log(11) - Math.log(3) + 10 * 5, greedy.distance(ball(2, 0), ball(10, 5)), 1e-5);
    }

    @Test
    void rejectsUnknownOptionValues() {
        assertThrows(PluginException.class, () -> REGISTRY.metric("continuous",
                PluginConfig.DEFAULT.withOptions(Map.of("matching", "best"))));
        assertThrows(PluginException.class, () -> REGISTRY.metric("continuous",
                PluginConfig.DEFAULT.withOptions(Map.of("space", "spherical"))));
        assertThrows(PluginException.class, () -> REGISTRY.metric("continuous",
                PluginConfig.DEFAULT.withOptions(Map.of("cycles", "2"))), "cycles belongs to projection");
    }
}
