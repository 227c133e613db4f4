package org.scenes.plugins.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SeenObject;

class CellMetricTest {
    private static Scene ball(double distance, double direction) {
        return new Scene(1, Observer.UNKNOWN,
                List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, distance, direction, Grid.DEFAULT)), List.of());
    }

    @Test
    void comparesCellsNotPositions() {
        SceneMetric metric = PluginRegistry.load().metric("cell", PluginConfig.DEFAULT);
        assertEquals(0, metric.distance(ball(10, 1), ball(30, 8)), 1e-12, "same cell (column 2, row 2)");
        assertEquals(1, metric.distance(ball(10, 1), ball(3, 1)), 1e-12, "one row nearer");
        assertEquals(Math.sqrt(2), metric.distance(ball(10, 1), ball(3, 20)), 1e-7, "one row and one column (single precision)");
        // with the default penalty (1 at the nearest row, halving per row) optimal matching is a metric
        assertTrue(PluginRegistry.load().metric("cell", PluginConfig.DEFAULT.withOptions(Map.of("matching", "optimal")))
                .isTrueMetric());
        assertEquals(1.0 / 3, metric.distance(ball(10, 1), new Scene(1, Observer.UNKNOWN, List.of(), List.of())), 1e-7,
                "an unmatched ball in the far row costs 1 / (1 + 2), stored as a 32-bit float");
    }
}
