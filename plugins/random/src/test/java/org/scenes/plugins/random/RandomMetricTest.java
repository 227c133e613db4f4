package org.scenes.plugins.random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;

class RandomMetricTest {
    private static Scene scene(int cycle) {
        return new Scene(cycle, Observer.UNKNOWN, List.of(), List.of(Action.dash(cycle)));
    }

    @Test
    void repeatsForTheSameSeedAndDiffersForAnother() {
        PluginRegistry registry = PluginRegistry.load();
        SceneMetric one = registry.metric("random", PluginConfig.DEFAULT.withSeed(1));
        SceneMetric again = registry.metric("random", PluginConfig.DEFAULT.withSeed(1));
        SceneMetric other = registry.metric("random", PluginConfig.DEFAULT.withSeed(2));
        assertFalse(one.isTrueMetric());
        int differing = 0;
        for (int i = 0; i < 50; i++) {
            double d = one.distance(scene(i), scene(i + 1));
            assertTrue(d >= 0 && d < 1);
            assertEquals(d, again.distance(scene(i), scene(i + 1)));
            if (d != other.distance(scene(i), scene(i + 1))) {
                differing++;
            }
        }
        assertTrue(differing > 45);
        assertNotEquals(one.distance(scene(1), scene(2)), one.distance(scene(1), scene(3)));
    }

    @Test
    void theHashOfAGivenSceneIsFixedAcrossRuns() {
        // a constant computed once: enum or identity hash codes would change it from run to run
        Scene scene = new Scene(7, new Observer("T", org.scenes.api.Side.LEFT, 3), List.of(), List.of(Action.turn(40)));
        assertEquals(RandomMetricProvider.RandomMetric.contentHash(scene),
                ((((7L * 31 + "T".hashCode()) * 31 + 3) * 31 + org.scenes.api.ActionType.TURN.ordinal()) * 31
                        + Double.hashCode(40)) * 31 + Double.hashCode(Double.NaN));
    }
}
