package org.scenes.plugins.history;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;

class HistoryTransformTest {
    @Test
    void eachSceneCarriesTheEarlierActionsAndAgesWithoutTheirObjects() {
        SceneTransform history = new HistoryTransformProvider().create(PluginConfig.DEFAULT);
        List<Scene> out = new ArrayList<>();
        for (int cycle = 1; cycle <= 12; cycle++) {
            out.add(history.apply(Synthetic.scene(cycle, cycle % 2, 10, Action.dash(cycle), Action.turnNeck(cycle))));
        }
        assertNull(out.get(0).previous(), "the first scene has no past");
        Scene last = out.get(11);
        assertEquals(Scene.MAX_MEMORY, last.memoryDepth(), "the chain stops after MAX_MEMORY scenes");
        Scene back = last.previous();
        for (int step = 1; step <= Scene.MAX_MEMORY; step++, back = back.previous()) {
            int cycle = 12 - step;
            assertEquals(cycle, back.cycle());
            assertEquals(cycle % 2, back.seeAge());
            assertEquals(List.of(Action.dash(cycle), Action.turnNeck(cycle)), back.actions());
            assertTrue(back.objects().isEmpty(), "only actions and ages are remembered");
        }
        assertEquals(1, last.objects().size(), "the scene's own objects stay");
        assertNull(new HistoryTransformProvider().create(PluginConfig.DEFAULT)
                .apply(Synthetic.scene(13, 0, 10, Action.dash(1), null)).previous(), "a new sequence starts without a past");
    }

    @Test
    void aSceneKeepsABoundedChainHowEverItIsBuilt() {
        Scene chain = null;
        for (int cycle = 1; cycle <= 30; cycle++) {
            chain = Synthetic.scene(cycle, 0, 5, Action.turn(cycle), null).withHistory(chain);
        }
        assertEquals(Scene.MAX_MEMORY, chain.memoryDepth());
        assertEquals(29, chain.previous().cycle());
        assertNull(chain.withPrevious(chain.previous()).previous().previous(), "withPrevious still keeps one step");
    }
}
