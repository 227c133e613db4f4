package org.scenes.plugins.mirror;

import java.util.List;
import java.util.function.UnaryOperator;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.Scene;
import org.scenes.api.SceneTransform;
import org.scenes.api.TransformProvider;

/**
 * {@code mirror}: the knowledge base stores every scene and its mirror image ({@link Mirror});
 * queries are left as they are. {@code mirror:match} stores the scenes alone and matches every
 * query as it is and as its mirror image instead, a neighbour found for the image being
 * mirrored back (its actions with it): the same neighbours, half the stored scenes.
 */
public final class MirrorTransformProvider implements TransformProvider {
    @Override
    public String name() {
        return "mirror";
    }

    @Override
    public String description() {
        return "mirror: stores the mirror image of every scene beside it (directions, turns and kick directions negated, "
                + "left and right flags swapped), queries unchanged; mirror:match stores the scenes alone and matches "
                + "each query and its mirror image, mirroring back what the image found";
    }

    @Override
    public SceneTransform create(PluginConfig config) {
        String argument = config.argument().trim();
        if (argument.equals("match")) {
            return new SceneTransform() {
                @Override
                public Scene apply(Scene scene) {
                    return scene;
                }

                @Override
                public UnaryOperator<Scene> queryImage() {
                    return Mirror::of;
                }
            };
        }
        if (!argument.isEmpty()) {
            throw new PluginException("mirror takes no argument or 'match' (mirror:match), not '" + argument + "'");
        }
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
