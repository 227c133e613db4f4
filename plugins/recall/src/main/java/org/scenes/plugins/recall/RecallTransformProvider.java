package org.scenes.plugins.recall;

import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.SceneTransform;
import org.scenes.api.TransformProvider;

/**
 * {@code recall[:HORIZON]}: objects seen in the last HORIZON cycles (default 10) but not in the
 * current scene are carried into it as remembered objects, at the place their last reported
 * changes and the player's own turns and dashes take them, with a confidence that falls with
 * their age. See {@link ObjectMemory}.
 */
public final class RecallTransformProvider implements TransformProvider {
    static final int DEFAULT_HORIZON = 10;

    @Override
    public String name() {
        return "recall";
    }

    @Override
    public String description() {
        return "recall[:HORIZON]: objects out of sight for at most HORIZON cycles (default " + DEFAULT_HORIZON
                + ") stay in the scene as remembered objects, moved by their last changes and the player's own "
                + "motion, confidence falling with age";
    }

    @Override
    public SceneTransform create(PluginConfig config) {
        return new ObjectMemory(horizon(config.argument()));
    }

    static int horizon(String argument) {
        if (argument.isBlank()) {
            return DEFAULT_HORIZON;
        }
        try {
            int horizon = Integer.parseInt(argument.trim());
            if (horizon >= 1 && horizon <= 1000) {
                return horizon;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new PluginException("recall's horizon (recall:HORIZON) is a number of cycles from 1 to 1000, not '"
                + argument + "'");
    }
}
