package org.scenes.plugins.memory;

import java.util.List;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.TransformProvider;

/**
 * {@code memory}: each scene also carries the scene before it (its objects and the action taken
 * then), so metrics can weigh what the player saw and did a moment ago. Recorded agents often
 * act on the {@code see} before the latest one, which makes this matter even for stateless agents.
 */
public final class MemoryTransformProvider implements TransformProvider {
    @Override
    public String name() {
        return "memory";
    }

    @Override
    public String description() {
        return "each scene remembers the previous scene and action of the same player";
    }

    @Override
    public SceneTransform create(PluginConfig config) {
        return new Memory(false);
    }

    /**
     * Remembers the last scene it saw, and with {@code chain} the actions of the scenes before
     * that (objects dropped); a new instance for each player's sequence.
     */
    static final class Memory implements SceneTransform {
        private final boolean chain;
        private Scene last;
        /** the scenes before {@code last}, actions and see ages only */
        private Scene earlier;

        Memory(boolean chain) {
            this.chain = chain;
        }

        @Override
        public Scene apply(Scene scene) {
            if (!chain) {
                Scene remembered = scene.withPrevious(last);
                last = scene.withPrevious(null);
                return remembered;
            }
            Scene remembered = scene.withHistory(last);
            // the constructor cuts each chain after Scene.MAX_MEMORY scenes
            last = scene.withHistory(earlier);
            earlier = new Scene(scene.cycle(), scene.observer(), List.of(), scene.actions(), earlier, scene.seeAge());
            return remembered;
        }
    }
}
