package org.scenes.plugins.projection;

import static org.junit.jupiter.api.Assertions.assertEquals;

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

class ProjectionMetricTest {
    private static Scene ball(double distance, double direction, double distanceChange, double directionChange) {
        SeenObject ball = new SeenObject(ObjectKind.BALL, "b", "", 0, false, Relation.NONE, distance, direction,
                distanceChange, directionChange, Double.NaN, Double.NaN, Double.NaN, SeenObject.NO_MARK,
                Grid.DEFAULT.cell(distance, direction));
        return new Scene(1, Observer.UNKNOWN, List.of(ball), List.of());
    }

    @Test
    void movingBallsMatchWhereTheyWillBe() {
        PluginRegistry registry = PluginRegistry.load();
        SceneMetric forward = registry.metric("projection", PluginConfig.DEFAULT.withOptions(Map.of("cycles", "3", "space", "polar")));
        // approaching 1 m per cycle from 8 m, and standing at 5 m: alike three cycles on
        assertEquals(0, forward.distance(ball(8, 10, -1, 0), ball(5, 10, 0, 0)), 1e-12);
        SceneMetric back = registry.metric("projection", PluginConfig.DEFAULT.withOptions(Map.of("cycles", "-2", "space", "polar")));
        // turning 2 degrees per cycle: two cycles ago it was at 6 degrees
        assertEquals(0, back.distance(ball(5, 10, 0, 2), ball(5, 6, 0, 0)), 1e-12);
        SceneMetric plain = registry.metric("projection", PluginConfig.DEFAULT.withOptions(Map.of("cycles", "0", "space", "polar")));
        assertEquals(3, plain.distance(ball(8, 10, -1, 0), ball(5, 10, 0, 0)), 1e-12);
    }
}
