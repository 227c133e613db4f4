package org.scenes.plugins.memory;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.SeenObject;

class MemoryTransformTest {
    private static Scene scene(int cycle, Action action) {
        return new Scene(cycle, Observer.UNKNOWN, List.of(), List.of(action));
    }

    @Test
    void eachSceneRemembersTheOneBeforeOnly() {
        SceneTransform memory = PluginRegistry.load().transform("memory", PluginConfig.DEFAULT);
        Scene first = memory.apply(scene(1, Action.turn(40)));
        Scene second = memory.apply(scene(2, Action.dash(50)));
        Scene third = memory.apply(scene(3, Action.kick(100, 5)));
        assertNull(first.previous());
        assertEquals(1, second.previous().cycle());
        assertEquals(Action.turn(40), second.previous().primaryAction());
        assertEquals(2, third.previous().cycle());
        assertNull(third.previous().previous(), "one step of memory, not a chain");
        SceneTransform fresh = PluginRegistry.load().transform("memory", PluginConfig.DEFAULT);
        assertNull(fresh.apply(scene(9, Action.dash(1))).previous(), "a new sequence starts without memory");
    }

    @Test
    void longMemoryRemembersThePreviousSceneAndTheActionsBefore() {
        SceneTransform memory = PluginRegistry.load().transform("long-memory", PluginConfig.DEFAULT);
        Scene last = null;
        for (int cycle = 1; cycle <= 12; cycle++) {
            last = memory.apply(new Scene(cycle, Observer.UNKNOWN,
                    List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 5, 10, Grid.DEFAULT)),
                    List.of(Action.dash(cycle))));
        }
        assertEquals(Scene.MAX_MEMORY, last.memoryDepth(), "a chain cut at the longest memory");
        assertEquals(11, last.previous().cycle());
        assertEquals(1, last.previous().objects().size(), "the previous scene keeps its objects");
        Scene earlier = last.previous().previous();
        assertEquals(10, earlier.cycle());
        assertEquals(Action.dash(10), earlier.primaryAction());
        assertTrue(earlier.objects().isEmpty(), "earlier scenes keep their actions only");
    }
}
