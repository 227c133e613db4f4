package org.scenes.plugins.mirror;

import java.util.List;
import org.scenes.match.SceneTransform;
import org.scenes.match.TransformProvider;
import org.scenes.plugin.PluginConfig;
import org.scenes.scene.Scene;

/**
 * {@code mirror}: the knowledge base stores every scene and its mirror image ({@link Mirror});
 * queries are left as they are.
 */
public final class MirrorTransformProvider implements TransformProvider {
    @Override
    public String name() {
        return "mirror";
    }

    @Override
    public String description() {
        return "stores the mirror image of every scene beside it (directions, turns and kick directions negated, "
                + "left and right flags swapped); queries unchanged";
    }

    @Override
    public SceneTransform create(PluginConfig config) {
        return new SceneTransform() {
            @Override
            public Scene apply(Scene scene) {
                return scene;
            }

            @Override
            public List<Scene> stored(Scene scene) {
                return List.of(scene, Mirror.of(scene));
            }
        };
    }
}
