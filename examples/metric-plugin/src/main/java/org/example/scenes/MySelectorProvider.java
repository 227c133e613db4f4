package org.example.scenes;

import org.scenes.match.ActionSelector;
import org.scenes.match.Neighbour;
import org.scenes.match.SelectorProvider;
import org.scenes.plugin.PluginConfig;
import org.scenes.scene.Action;

/** {@code my-selector}: the action of the nearest stored scene that holds one. */
public final class MySelectorProvider implements SelectorProvider {
    @Override
    public String name() {
        return "my-selector";
    }

    @Override
    public String description() {
        return "the action of the nearest neighbour that has one (template plugin)";
    }

    @Override
    public ActionSelector create(PluginConfig config) {
        return (nearest, random) -> {
            for (Neighbour neighbour : nearest) { // nearest first
                Action action = neighbour.scene().primaryAction();
                if (action != null) {
                    return action;
                }
            }
            return null;
        };
    }
}
