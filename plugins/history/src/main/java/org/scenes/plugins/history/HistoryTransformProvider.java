package org.scenes.plugins.history;

import java.util.List;
import org.scenes.api.PluginConfig;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.TransformProvider;

/**
 * {@code history}: each scene carries the actions and see ages of the same player's scenes before
 * it, up to {@link Scene#MAX_MEMORY} of them, without their objects. A player that acts every
 * cycle (librcsc's HELIOS base) runs plans over several cycles, so the last few actions say more
 * about the next one than the last alone: turn, turn, dash rarely breaks off after one dash.
 */
public final class HistoryTransformProvider implements TransformProvider {
    @Override
    public String name() {
        return "history";
    }

    @Override
    public String description() {
        return "each scene remembers the actions and see ages of the player's last " + Scene.MAX_MEMORY + " scenes";
    }

    @Override
    public SceneTransform create(PluginConfig config) {
        return new History();
    }

    /** The chain of the last scenes, objects dropped (only actions and ages are kept); one per sequence. */
    static final class History implements SceneTransform {
        private Scene last;

        @Override
        public Scene apply(Scene scene) {
            Scene remembered = scene.withHistory(last);
            // the constructor cuts the chain after MAX_MEMORY scenes
            last = new Scene(scene.cycle(), scene.observer(), List.of(), scene.actions(), last, scene.seeAge());
            return remembered;
        }
    }
}
